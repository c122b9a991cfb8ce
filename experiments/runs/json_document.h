// A JSON input file (a baseline, a run's metrics.json) parsed together with the line of every value, so that
// a reader that refuses a value can say where it is: "FILE:LINE: key.path: reason", like the YAML readers.
// nlohmann's parser reports byte offsets only; this one counts the lines as it reads.
#pragma once

#include <map>
#include <string>

#include <nlohmann/json.hpp>

namespace vigil::experiments {

// JSON nested deeper than this (objects and arrays) is refused: vigil's files are a few levels deep.
inline constexpr int kMaxJsonDepth = 32;

class JsonDocument {
 public:
  // Parses `text` (read from `path`); InputError "path:LINE: not valid JSON: reason" on a syntax error, and
  // "path:LINE: nested deeper than N levels" beyond kMaxJsonDepth.
  JsonDocument(std::string path, const std::string& text);

  const nlohmann::json& root() const { return root_; }
  const std::string& path() const { return path_; }
  // The 1-based line where the value at `pointer` ("/cells/3/value") ends; 0 when there is no such value.
  int LineOf(const std::string& pointer) const;
  // Throws InputError "path:LINE: KEY: why", KEY the pointer written as a key path ("cells[3].value"),
  // LINE that of the value at `pointer` (or of its nearest enclosing value).
  [[noreturn]] void Fail(const std::string& pointer, const std::string& why) const;

 private:
  std::string path_;
  nlohmann::json root_;
  std::map<std::string, int> lines_;
};

// `key` as one token of a JSON pointer ('~' written "~0", '/' written "~1"): "/a/" + PointerToken(key).
std::string PointerToken(const std::string& key);

// "/cells/3/value" -> "cells[3].value" ("(top level)" for the root).
std::string PointerAsKey(const std::string& pointer);

}  // namespace vigil::experiments
