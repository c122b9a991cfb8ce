#include "experiments/runs/json_document.h"

#include <algorithm>
#include <cctype>
#include <iterator>
#include <vector>

#include "core/error.h"

namespace vigil::experiments {
namespace {
using nlohmann::json;

// A character iterator that records how far the parser has read (the parser copies its iterators).
class TrackedIterator {
 public:
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  TrackedIterator(const char* p, const char** furthest) : p_(p), furthest_(furthest) {}
  reference operator*() const { return *p_; }
  TrackedIterator& operator++() {
    *furthest_ = ++p_;
    return *this;
  }
  TrackedIterator operator++(int) {
    TrackedIterator before = *this;
    ++*this;
    return before;
  }
  bool operator==(const TrackedIterator& o) const { return p_ == o.p_; }
  bool operator!=(const TrackedIterator& o) const { return p_ != o.p_; }

 private:
  const char* p_;
  const char** furthest_;
};

// Builds the document (as nlohmann's own DOM parser does) and notes the line of each value's pointer.
class LineSax : public nlohmann::json_sax<json> {
 public:
  LineSax(const std::string& path, const std::string& text, json* root, std::map<std::string, int>* lines)
      : path_(path),
        begin_(text.data()),
        furthest_(text.data()),
        counted_(text.data()),
        root_(root),
        lines_(lines) {}
  const char** furthest() { return &furthest_; }

  bool null() override { return Value(nullptr); }
  bool boolean(bool v) override { return Value(v); }
  bool number_integer(number_integer_t v) override { return Value(v); }
  bool number_unsigned(number_unsigned_t v) override { return Value(v); }
  bool number_float(number_float_t v, const string_t&) override { return Value(v); }
  bool string(string_t& v) override { return Value(v); }
  bool binary(binary_t&) override { return Fail("binary values are not JSON"); }
  bool start_object(std::size_t) override { return Open(json::object()); }
  bool end_object() override { return Close(); }
  bool start_array(std::size_t) override { return Open(json::array()); }
  bool end_array() override { return Close(); }
  bool key(string_t& k) override {
    key_ = k;
    return true;
  }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& e) override {
    // "[json.exception.parse_error.101] parse error at line 1, column 2: syntax error ..." -> the reason.
    std::string why = e.what();
    const std::size_t column = why.find(", column ");
    const std::size_t colon = column == std::string::npos ? why.find("] ") : why.find(": ", column);
    if (colon != std::string::npos) why = why.substr(colon + 2);
    throw InputError(
        Located(path_, LineAt(begin_ + (position > 0 ? position - 1 : 0)), "not valid JSON: " + why));
  }

 private:
  // The line of the character before the furthest one read (the lexer reads one past a number).
  int Line() { return LineAt(furthest_ > begin_ ? furthest_ - 1 : furthest_); }
  int LineAt(const char* at) {
    if (at < counted_) {  // only for an error behind the parser's position: count again
      counted_ = begin_;
      line_ = 1;
    }
    for (; counted_ < at; ++counted_)
      if (*counted_ == '\n') ++line_;
    return line_;
  }
  std::string ChildPointer() const {
    if (stack_.empty()) return "";
    const Frame& f = stack_.back();
    if (f.node->is_array()) return f.pointer + "/" + std::to_string(f.node->size());
    return f.pointer + "/" + PointerToken(key_);
  }
  json* Place(json v, const std::string& pointer) {
    (*lines_)[pointer] = Line();
    if (stack_.empty()) {
      *root_ = std::move(v);
      return root_;
    }
    json* parent = stack_.back().node;
    if (parent->is_array()) {
      parent->push_back(std::move(v));
      return &parent->back();
    }
    json& slot = (*parent)[key_];
    slot = std::move(v);
    return &slot;
  }
  bool Value(json v) {
    Place(std::move(v), ChildPointer());
    return true;
  }
  bool Open(json container) {
    if (static_cast<int>(stack_.size()) >= kMaxJsonDepth)
      throw InputError(
          Located(path_, Line(), "nested deeper than " + std::to_string(kMaxJsonDepth) + " levels"));
    const std::string pointer = ChildPointer();
    json* node = Place(std::move(container), pointer);
    stack_.push_back({node, pointer});
    return true;
  }
  bool Close() {
    stack_.pop_back();
    return true;
  }
  bool Fail(const std::string& why) { throw InputError(Located(path_, Line(), why)); }

  struct Frame {
    json* node;
    std::string pointer;
  };
  const std::string& path_;
  const char* begin_;
  const char* furthest_;
  const char* counted_;
  int line_ = 1;
  json* root_;
  std::map<std::string, int>* lines_;
  std::vector<Frame> stack_;
  std::string key_;
};

}  // namespace

JsonDocument::JsonDocument(std::string path, const std::string& text) : path_(std::move(path)) {
  LineSax sax(path_, text, &root_, &lines_);
  const char* end = text.data() + text.size();
  json::sax_parse(TrackedIterator(text.data(), sax.furthest()), TrackedIterator(end, sax.furthest()), &sax);
}

int JsonDocument::LineOf(const std::string& pointer) const {
  const auto it = lines_.find(pointer);
  return it == lines_.end() ? 0 : it->second;
}

void JsonDocument::Fail(const std::string& pointer, const std::string& why) const {
  std::string at = pointer;
  int line = LineOf(at);
  while (line == 0 && !at.empty()) {
    at = at.substr(0, at.rfind('/'));
    line = LineOf(at);
  }
  throw InputError(Located(path_, line, PointerAsKey(pointer) + ": " + why));
}

std::string PointerToken(const std::string& key) {
  std::string escaped;
  for (char c : key) escaped += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
  return escaped;
}

std::string PointerAsKey(const std::string& pointer) {
  if (pointer.empty()) return "(top level)";
  std::string key;
  std::size_t start = 1;
  while (start <= pointer.size()) {
    std::size_t slash = pointer.find('/', start);
    if (slash == std::string::npos) slash = pointer.size();
    std::string part = pointer.substr(start, slash - start);
    for (std::size_t i = 0; (i = part.find('~', i)) != std::string::npos; ++i)
      part.replace(i, 2, part.compare(i, 2, "~1") == 0 ? "/" : "~");
    const bool index = !part.empty() &&
                       std::all_of(part.begin(), part.end(), [](unsigned char c) { return std::isdigit(c); });
    key += index ? "[" + part + "]" : (key.empty() ? "" : ".") + part;
    start = slash + 1;
  }
  return key;
}

}  // namespace vigil::experiments
