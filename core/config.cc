#include "core/config.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "core/format.h"
#include "core/output.h"

namespace vigil::config {

bool Bounds::Contains(double x) const {
  if (lo && (lo_open ? !(x > *lo) : !(x >= *lo))) return false;
  if (hi && (hi_open ? !(x < *hi) : !(x <= *hi))) return false;
  return true;
}

std::string Bounds::Describe() const {
  if (lo && hi) {
    return std::string("in ") + (lo_open ? "(" : "[") + FormatDouble(*lo) + ", " + FormatDouble(*hi) +
           (hi_open ? ")" : "]");
  }
  if (lo) return (lo_open ? "> " : ">= ") + FormatDouble(*lo);
  if (hi) return (hi_open ? "< " : "<= ") + FormatDouble(*hi);
  return "";
}

bool InBounds(double x, const Bounds& b) { return b.Contains(x); }

uint64_t ParseSeedArgument(const std::string& text) {
  int64_t value = -1;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end || value < 0)
    throw InputError("--seed: expected an integer from 0 to 9223372036854775807 (2^63 - 1), got '" + text +
                     "'");
  return static_cast<uint64_t>(value);
}

namespace {
bool ScalarText(const YAML::Node& n, std::string* text, std::string* why) {
  if (!n.IsScalar()) {
    *why = n.IsNull()       ? "empty value: give a value or remove the key"
           : n.IsSequence() ? "expected a single value, got a list"
                            : "expected a single value, got a mapping";
    return false;
  }
  *text = n.Scalar();
  return true;
}
}  // namespace

bool Decode(const YAML::Node& n, bool* out, std::string* why) {
  std::string t;
  if (!ScalarText(n, &t, why)) return false;
  if (t == "true" || t == "True" || t == "TRUE") {
    *out = true;
    return true;
  }
  if (t == "false" || t == "False" || t == "FALSE") {
    *out = false;
    return true;
  }
  *why = "expected true or false, got '" + t + "'";
  return false;
}

bool Decode(const YAML::Node& n, int64_t* out, std::string* why) {
  std::string t;
  if (!ScalarText(n, &t, why)) return false;
  if (!ParseInt64(t, out)) {
    *why = "expected an integer, got '" + t + "'";
    return false;
  }
  return true;
}

bool Decode(const YAML::Node& n, int* out, std::string* why) {
  int64_t v = 0;
  if (!Decode(n, &v, why)) return false;
  if (v < INT32_MIN || v > INT32_MAX) {
    *why = "integer out of range";
    return false;
  }
  *out = static_cast<int>(v);
  return true;
}

bool Decode(const YAML::Node& n, uint64_t* out, std::string* why) {
  int64_t v = 0;
  if (!Decode(n, &v, why)) return false;
  if (v < 0) {
    *why = "expected a non-negative integer";
    return false;
  }
  *out = static_cast<uint64_t>(v);
  return true;
}

bool Decode(const YAML::Node& n, double* out, std::string* why) {
  std::string t;
  if (!ScalarText(n, &t, why)) return false;
  if (!ParseDouble(t, out)) {
    *why = "expected a finite number, got '" + t + "'";
    return false;
  }
  return true;
}

bool Decode(const YAML::Node& n, std::string* out, std::string* why) { return ScalarText(n, out, why); }

Reader::Reader(YAML::Node node, std::string origin, bool has_lines, std::string prefix)
    : node_(std::move(node)), origin_(std::move(origin)), has_lines_(has_lines), prefix_(std::move(prefix)) {}

YAML::Node Reader::Take(const char* key) {
  known_.insert(key);
  const YAML::Node& cnode = node_;  // const access never inserts
  return cnode[key];
}

void Reader::Fail(const YAML::Node& n, const std::string& key, const std::string& why) const {
  int line = has_lines_ && n.Mark().line >= 0 ? n.Mark().line + 1 : 0;
  // An empty value has no position of its own (yaml-cpp marks where the next token starts): use the key's.
  if (has_lines_ && n.IsNull()) line = KeyLine(node_, key);
  throw InputError(Located(origin_, line, Path(key) + ": " + why));
}

void Reader::RejectUnknownKeys() const {
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    if (!it->first.IsScalar()) {
      // A null key (`~:` or `: value`) or a complex one: name it by its line (KeyLine cannot find it).
      const int line = has_lines_ && it->first.Mark().line >= 0 ? it->first.Mark().line + 1 : 0;
      throw InputError(Located(
          origin_, line,
          Path(it->first.IsNull() ? "~" : "(complex key)") + ": unknown key (a key must be a plain name)"));
    }
    const std::string key = it->first.Scalar();
    if (!known_.count(key)) Fail(it->first, key, "unknown key");
  }
}

namespace {
// Walks `node` depth first, with its ancestors in `path` (a recursive alias makes a node its own descendant).
class ShapeCheck {
 public:
  ShapeCheck(std::string where, bool has_lines) : where_(std::move(where)), has_lines_(has_lines) {}

  void Visit(const YAML::Node& node, const YAML::Node& nearest_marked) {
    const YAML::Node& at = node.Mark().line >= 0 ? node : nearest_marked;
    if (++visited_ > kMaxYamlNodes)
      Fail(at, "more than " + std::to_string(kMaxYamlNodes) + " values once aliases are expanded");
    if (!node.IsMap() && !node.IsSequence()) return;
    for (const YAML::Node& ancestor : path_)
      if (ancestor.is(node)) Fail(at, "a recursive alias (a node that contains itself)");
    if (static_cast<int>(path_.size()) >= kMaxYamlDepth)
      Fail(at, "nested deeper than " + std::to_string(kMaxYamlDepth) + " levels");
    path_.push_back(node);
    if (node.IsMap()) {
      for (auto it = node.begin(); it != node.end(); ++it) {
        Visit(it->first, at);
        Visit(it->second, it->first.Mark().line >= 0 ? it->first : at);
      }
    } else {
      for (auto it = node.begin(); it != node.end(); ++it) Visit(*it, at);
    }
    path_.pop_back();
  }

 private:
  [[noreturn]] void Fail(const YAML::Node& at, const std::string& why) const {
    const int line = has_lines_ && at.Mark().line >= 0 ? at.Mark().line + 1 : 0;
    throw InputError(Located(where_, line, why));
  }

  std::string where_;
  bool has_lines_;
  std::vector<YAML::Node> path_;
  std::size_t visited_ = 0;
};

// yaml-cpp keeps both entries of a duplicated key and lookups see only the first: refuse them.
void RejectDuplicateKeys(const YAML::Node& node, const std::string& path, const std::string& prefix) {
  if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i)
      RejectDuplicateKeys(node[i], path, prefix + "[" + std::to_string(i) + "]");
    return;
  }
  if (!node.IsMap()) return;
  std::map<std::string, int> first_line;
  for (auto it = node.begin(); it != node.end(); ++it) {
    const std::string key = it->first.IsScalar() ? it->first.Scalar() : std::string("(complex key)");
    const std::string key_path = prefix.empty() ? key : prefix + "." + key;
    const int line = it->first.Mark().line + 1;
    const auto [seen, inserted] = first_line.emplace(key, line);
    if (!inserted)
      throw InputError(Located(
          path, line,
          key_path + ": duplicate key (first at line " + std::to_string(seen->second) + "); keep one"));
    RejectDuplicateKeys(it->second, path, key_path);
  }
}
}  // namespace

YAML::Node LoadYamlFile(const std::string& path) {
  constexpr std::uintmax_t kMaxConfigBytes = 16 << 20;  // a config is a few kB
  return LoadYamlText(ReadTextFile(path, kMaxConfigBytes));
}

YAML::Node LoadYamlText(const TextFile& file) {
  YAML::Node root;
  try {
    root = YAML::Load(file.text);
  } catch (const YAML::ParserException& e) {
    throw InputError(Located(file.path, e.mark.line + 1, "YAML syntax error: " + e.msg));
  }
  CheckYamlShape(root, file.path);
  RejectDuplicateKeys(root, file.path, "");
  return root;
}

void CheckYamlShape(const YAML::Node& root, const std::string& where, bool has_lines) {
  ShapeCheck(where, has_lines).Visit(root, root);
}

int KeyLine(const YAML::Node& root, const std::string& key_path) {
  YAML::Node node = root;
  std::size_t start = 0;
  while (true) {
    if (!node.IsMap()) return 0;
    const std::size_t dot = key_path.find('.', start);
    const std::string part =
        key_path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    YAML::Node key_node, value;
    for (auto it = node.begin(); it != node.end(); ++it)
      if (it->first.IsScalar() && it->first.Scalar() == part) {
        key_node = it->first;
        value = it->second;
        break;
      }
    if (!key_node) return 0;
    if (dot == std::string::npos) return key_node.Mark().line + 1;
    node.reset(value);
    start = dot + 1;
  }
}

YAML::Node NestKey(const std::string& key_path, const YAML::Node& value) {
  YAML::Node root(YAML::NodeType::Map);
  YAML::Node cur = root;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = key_path.find('.', start);
    const std::string part =
        key_path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (part.empty()) throw InputError("--set " + key_path + ": empty key component");
    if (dot == std::string::npos) {
      cur[part] = value;
      break;
    }
    cur[part] = YAML::Node(YAML::NodeType::Map);
    cur.reset(cur[part]);  // rebind (operator= would assign into the node)
    start = dot + 1;
  }
  return root;
}

void Writer::Emit(bool v) { out_ << (v ? "true" : "false"); }
void Writer::Emit(int v) { out_ << v; }
void Writer::Emit(int64_t v) { out_ << v; }
void Writer::Emit(uint64_t v) { out_ << v; }
void Writer::Emit(double v) { out_ << FormatDouble(v); }
void Writer::Emit(const std::string& v) { out_ << v; }

std::string Describer::Show(bool v) { return v ? "true" : "false"; }
std::string Describer::Show(int v) { return std::to_string(v); }
std::string Describer::Show(int64_t v) { return std::to_string(v); }
std::string Describer::Show(uint64_t v) { return std::to_string(v); }
std::string Describer::Show(double v) { return FormatDouble(v); }
std::string Describer::Show(const std::string& v) { return v.empty() ? "\"\"" : v; }

std::string KeysMarkdownTable(const std::vector<KeyDoc>& keys) {
  std::string s = "| key | type | default | allowed | description |\n|---|---|---|---|---|\n";
  for (const auto& k : keys) {
    s += "| `" + k.path + "` | " + k.type + " | `" + k.default_value + "` | " + k.allowed + " | " + k.doc +
         " |\n";
  }
  return s;
}

}  // namespace vigil::config
