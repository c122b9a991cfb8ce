// Typed configuration: options structs bound to YAML through one description of their fields.
//
// An options struct describes its fields once, in a Visit() member template:
//
//   struct ImuOptions {
//     double rate_hz = 200.0;                       // the default is written here, and only here
//     NoiseOptions noise;
//     template <class V> void Visit(V& v) {
//       v.Field("rate_hz", rate_hz, "IMU sampling rate [Hz]", Bounds::Positive());
//       v.Section("noise", noise, "IMU noise model");
//     }
//   };
//
// The visitors below use that description to load YAML (Reader: unknown keys, wrong types and out-of-range
// values are InputErrors "file:line: key.path: reason"), to apply `--set key.path=value` overrides
// (ApplyOverride), to write the fully resolved config (ToYaml) and to document every key (DescribeKeys).
//
// Supported field types: bool, int, int64_t, uint64_t, double, std::string, std::vector<double>,
// std::vector<int>, std::vector<std::string>; enumerations through Enum() / EnumList() with their names.
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "core/error.h"
#include "core/output.h"

namespace vigil::config {

// Allowed range of a numeric field (for lists: of every element).
struct Bounds {
  std::optional<double> lo, hi;
  bool lo_open = false, hi_open = false;

  static Bounds Any() { return {}; }
  static Bounds Positive() { return {0.0, std::nullopt, true, false}; }
  static Bounds NonNegative() { return {0.0, std::nullopt, false, false}; }
  static Bounds AtLeast(double lo) { return {lo, std::nullopt, false, false}; }
  static Bounds Closed(double lo, double hi) { return {lo, hi, false, false}; }
  static Bounds Probability() { return Closed(0.0, 1.0); }

  bool Contains(double x) const;
  // "> 0", "in [0, 1]", ... ; empty when unbounded.
  std::string Describe() const;
};

// Names of an enumeration's values, in documentation order.
template <class E>
using EnumNames = std::vector<std::pair<std::string, E>>;

// The name of `e` ("?" when it has none).
template <class E>
std::string EnumNameOf(E e, const EnumNames<E>& names) {
  for (const auto& [name, v] : names)
    if (v == e) return name;
  return "?";
}
// The value named `name`, if any.
template <class E>
std::optional<E> EnumFromName(const std::string& name, const EnumNames<E>& names) {
  for (const auto& [n, v] : names)
    if (n == name) return v;
  return std::nullopt;
}
// "a, b, c": the names, for help texts and errors.
template <class E>
std::string EnumChoices(const EnumNames<E>& names) {
  std::string s;
  for (const auto& nv : names) s += (s.empty() ? "" : ", ") + nv.first;
  return s;
}

// ---------------------------------------------------------------------------------------------------------
// Loading.

// Scalar decoding shared by the reader; each returns false with a reason.
bool Decode(const YAML::Node& n, bool* out, std::string* why);
bool Decode(const YAML::Node& n, int* out, std::string* why);
bool Decode(const YAML::Node& n, int64_t* out, std::string* why);
bool Decode(const YAML::Node& n, uint64_t* out, std::string* why);
bool Decode(const YAML::Node& n, double* out, std::string* why);
bool Decode(const YAML::Node& n, std::string* out, std::string* why);
template <class T>
bool Decode(const YAML::Node& n, std::vector<T>* out, std::string* why) {
  if (!n.IsSequence()) {
    *why = "expected a list, e.g. [1, 2]";
    return false;
  }
  std::vector<T> values(n.size());
  for (std::size_t i = 0; i < n.size(); ++i) {
    if (!Decode(n[i], &values[i], why)) {
      *why = "element " + std::to_string(i) + ": " + *why;
      return false;
    }
  }
  *out = std::move(values);
  return true;
}

bool InBounds(double x, const Bounds& b);
template <class T>
bool InBounds(const T& x, const Bounds& b) {
  if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) {
    return InBounds(static_cast<double>(x), b);
  } else if constexpr (std::is_same_v<T, std::vector<double>> || std::is_same_v<T, std::vector<int>>) {
    for (auto v : x)
      if (!InBounds(static_cast<double>(v), b)) return false;
    return true;
  } else {
    return true;
  }
}

// Loads the keys present in a YAML mapping into an options struct; absent keys keep their defaults.
class Reader {
 public:
  // `origin` names the source in errors: a file path (with line numbers from the YAML marks) or, with
  // `has_lines` false, something like "--set".
  Reader(YAML::Node node, std::string origin, bool has_lines = true, std::string prefix = "");

  template <class T>
  void Field(const char* key, T& value, const char* /*doc*/, const Bounds& bounds = {}) {
    const YAML::Node n = Take(key);
    if (!n) return;
    std::string why;
    if (!Decode(n, &value, &why)) Fail(n, key, why);
    if (!InBounds(value, bounds)) Fail(n, key, "must be " + bounds.Describe());
  }

  template <class E>
  void Enum(const char* key, E& value, const EnumNames<E>& names, const char* /*doc*/) {
    const YAML::Node n = Take(key);
    if (!n) return;
    value = DecodeEnum(n, key, names);
  }

  template <class E>
  void EnumList(const char* key, std::vector<E>& values, const EnumNames<E>& names, const char* /*doc*/) {
    const YAML::Node n = Take(key);
    if (!n) return;
    if (!n.IsSequence()) Fail(n, key, "expected a list, e.g. [" + names.front().first + "]");
    std::vector<E> out;
    for (std::size_t i = 0; i < n.size(); ++i) out.push_back(DecodeEnum(n[i], key, names));
    values = std::move(out);
  }

  template <class S>
  void Section(const char* key, S& section, const char* /*doc*/) {
    const YAML::Node n = Take(key);
    if (!n || n.IsNull()) return;
    if (!n.IsMap()) Fail(n, key, "expected a mapping of keys");
    Reader sub(n, origin_, has_lines_, Path(key) + ".");
    section.Visit(sub);
    sub.RejectUnknownKeys();
  }

  // Fails on the first key of the mapping that no Field/Section/Enum claimed.
  void RejectUnknownKeys() const;

  [[noreturn]] void Fail(const YAML::Node& n, const std::string& key, const std::string& why) const;

 private:
  YAML::Node Take(const char* key);
  std::string Path(const std::string& key) const { return prefix_ + key; }
  template <class E>
  E DecodeEnum(const YAML::Node& n, const char* key, const EnumNames<E>& names) const {
    if (n.IsScalar())
      if (const std::optional<E> e = EnumFromName(n.Scalar(), names)) return *e;
    Fail(n, key, "must be one of: " + EnumChoices(names));
  }

  YAML::Node node_;
  std::string origin_;
  bool has_lines_;
  std::string prefix_;
  std::set<std::string> known_;
};

// The shape every YAML input must have (docs/safety.md): no alias that refers to a node containing it (a
// recursive alias), nesting at most kMaxYamlDepth mappings/sequences deep, and at most kMaxYamlNodes values
// once aliases are expanded.
inline constexpr int kMaxYamlDepth = 32;
inline constexpr std::size_t kMaxYamlNodes = 1 << 20;
// InputError "where:line: reason" (no line when `where` has none, e.g. a --set) when `root` breaks the shape.
void CheckYamlShape(const YAML::Node& root, const std::string& where, bool has_lines = true);

// Parses a YAML file into a node; InputError "file:line: reason" on a syntax error, a recursive alias or too
// deep a nesting (CheckYamlShape), "file: ..." if unreadable.
YAML::Node LoadYamlFile(const std::string& path);
// The same on a file already in memory (errors name file.path).
YAML::Node LoadYamlText(const TextFile& file);

// The 1-based line of the key `key_path` ("imu.rate_hz") in a mapping loaded from a file; 0 when absent.
int KeyLine(const YAML::Node& root, const std::string& key_path);

// Loads `path` into `options` (defaults for absent keys); rejects unknown keys.
template <class Options>
void LoadFile(const std::string& path, Options& options) {
  const YAML::Node root = LoadYamlFile(path);
  if (root.IsNull()) return;
  Reader reader(root, path);
  if (!root.IsMap()) reader.Fail(root, "(top level)", "expected a mapping of keys");
  options.Visit(reader);
  reader.RejectUnknownKeys();
}

// Loads an already parsed YAML mapping (for example a section of a sweep file) into `options`.
template <class Options>
void LoadNode(const YAML::Node& node, const std::string& origin, Options& options) {
  Reader reader(node, origin);
  options.Visit(reader);
  reader.RejectUnknownKeys();
}

// Turns "a.b.c" and a value node into the nested mapping {a: {b: {c: value}}}.
YAML::Node NestKey(const std::string& key_path, const YAML::Node& value);

// The `--seed` argument of every command, read one way: a decimal integer from 0 to 2^63 - 1 and nothing
// else (no sign, no spaces); InputError "--seed: expected ..., got 'TEXT'" otherwise.
uint64_t ParseSeedArgument(const std::string& text);

// Applies one `key.path=value` override (the value is read as a YAML scalar or flow sequence).
// Errors name the override: "--set glitch.mean: must be ...".
template <class Options>
void ApplyOverride(const std::string& assignment, Options& options) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--set " + assignment + ": expected key.path=value");
  const std::string key = assignment.substr(0, eq);
  YAML::Node value;
  try {
    value = YAML::Load(assignment.substr(eq + 1));
  } catch (const YAML::Exception& e) {
    throw InputError("--set " + key + ": cannot parse value: " + e.msg);
  }
  CheckYamlShape(value, "--set " + key, /*has_lines=*/false);
  Reader reader(NestKey(key, value), "--set", /*has_lines=*/false);
  options.Visit(reader);
  reader.RejectUnknownKeys();
}

// ---------------------------------------------------------------------------------------------------------
// Writing and documenting.

// Emits every field (the fully resolved configuration) as YAML.
class Writer {
 public:
  explicit Writer(YAML::Emitter& out) : out_(out) {}
  template <class T>
  void Field(const char* key, T& value, const char*, const Bounds& = {}) {
    out_ << YAML::Key << key << YAML::Value;
    Emit(value);
  }
  template <class E>
  void Enum(const char* key, E& value, const EnumNames<E>& names, const char*) {
    out_ << YAML::Key << key << YAML::Value << EnumNameOf(value, names);
  }
  template <class E>
  void EnumList(const char* key, std::vector<E>& values, const EnumNames<E>& names, const char*) {
    out_ << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq;
    for (const E& e : values) out_ << EnumNameOf(e, names);
    out_ << YAML::EndSeq;
  }
  template <class S>
  void Section(const char* key, S& section, const char*) {
    out_ << YAML::Key << key << YAML::Value << YAML::BeginMap;
    section.Visit(*this);
    out_ << YAML::EndMap;
  }

 private:
  void Emit(bool v);
  void Emit(int v);
  void Emit(int64_t v);
  void Emit(uint64_t v);
  void Emit(double v);
  void Emit(const std::string& v);
  template <class T>
  void Emit(const std::vector<T>& v) {
    out_ << YAML::Flow << YAML::BeginSeq;
    for (const auto& x : v) Emit(x);
    out_ << YAML::EndSeq;
  }
  YAML::Emitter& out_;
};

// The fully resolved configuration as YAML text (every key, defaults included).
template <class Options>
std::string ToYaml(Options& options) {
  YAML::Emitter out;
  out << YAML::BeginMap;
  Writer writer(out);
  options.Visit(writer);
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

// One documented key.
struct KeyDoc {
  std::string path, type, default_value, allowed, doc;
};

// Lists every key with its type, default, allowed values and description.
class Describer {
 public:
  explicit Describer(std::vector<KeyDoc>* keys, std::string prefix = "")
      : keys_(keys), prefix_(std::move(prefix)) {}
  template <class T>
  void Field(const char* key, T& value, const char* doc, const Bounds& bounds = {}) {
    keys_->push_back({prefix_ + key, TypeName(value), Show(value), bounds.Describe(), doc});
  }
  template <class E>
  void Enum(const char* key, E& value, const EnumNames<E>& names, const char* doc) {
    keys_->push_back({prefix_ + key, "enum", EnumNameOf(value, names), EnumChoices(names), doc});
  }
  template <class E>
  void EnumList(const char* key, std::vector<E>& values, const EnumNames<E>& names, const char* doc) {
    std::string shown;
    for (const E& e : values) shown += (shown.empty() ? "" : ", ") + EnumNameOf(e, names);
    keys_->push_back(
        {prefix_ + key, "list of enum", "[" + shown + "]", "each of " + EnumChoices(names), doc});
  }
  template <class S>
  void Section(const char* key, S& section, const char*) {
    Describer sub(keys_, prefix_ + key + ".");
    section.Visit(sub);
  }

 private:
  static std::string TypeName(bool) { return "bool"; }
  static std::string TypeName(int) { return "int"; }
  static std::string TypeName(int64_t) { return "int"; }
  static std::string TypeName(uint64_t) { return "unsigned int"; }
  static std::string TypeName(double) { return "number"; }
  static std::string TypeName(const std::string&) { return "string"; }
  static std::string TypeName(const std::vector<double>&) { return "list of numbers"; }
  static std::string TypeName(const std::vector<int>&) { return "list of int"; }
  static std::string TypeName(const std::vector<std::string>&) { return "list of strings"; }
  static std::string Show(bool v);
  static std::string Show(int v);
  static std::string Show(int64_t v);
  static std::string Show(uint64_t v);
  static std::string Show(double v);
  static std::string Show(const std::string& v);
  template <class T>
  static std::string Show(const std::vector<T>& v) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : ", ") + Show(x);
    return "[" + s + "]";
  }
  std::vector<KeyDoc>* keys_;
  std::string prefix_;
};

template <class Options>
std::vector<KeyDoc> DescribeKeys(Options& options) {
  std::vector<KeyDoc> keys;
  Describer d(&keys);
  options.Visit(d);
  return keys;
}

// A Markdown table of every key (used for configs/README.md and `vigil config --keys`).
std::string KeysMarkdownTable(const std::vector<KeyDoc>& keys);

}  // namespace vigil::config
