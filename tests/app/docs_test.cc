// The documentation against the tree and the built `vigil`: every relative link of README.md and docs/**/*.md
// points at a file (and, with #anchor, a heading) inside the repository, and every command and flag that
// docs/cli.md and the README's command table name in code spans is one that `vigil --help` and
// `vigil CMD --help` list.
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "tests/app/vigil_cli.h"

namespace vigil {
namespace {
namespace fs = std::filesystem;

const fs::path kRoot = fs::weakly_canonical(VIGIL_SOURCE_DIR);

std::string ReadText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// One line of Markdown with its place: inside a fenced block (and the fence's info string) or prose. A prose
// line carries the lines that continue its paragraph, joined with spaces, so that a code span or a link
// broken across lines reads whole; headings and table rows stay lines of their own, and a list item starts a
// new one.
struct MarkdownLine {
  int number = 0;  // of the first line
  std::string text;
  bool fenced = false;
  std::string fence_info;
};

std::vector<MarkdownLine> ParseLines(const std::string& text) {
  std::vector<MarkdownLine> out;
  bool fenced = false;
  bool continues = false;  // the last prose line's paragraph goes on
  std::string info;
  int number = 0;
  for (const std::string& line : Lines(text)) {
    ++number;
    const size_t first = line.find_first_not_of(' ');
    if (first != std::string::npos && line.compare(first, 3, "```") == 0) {
      fenced = !fenced;
      info = fenced ? line.substr(first + 3) : "";
      continues = false;
      continue;
    }
    const bool blank = first == std::string::npos;
    const bool own_line = !blank && (line[first] == '#' || line[first] == '|');
    const bool list_item = !blank && std::regex_search(line.substr(first), std::regex(R"(^(-|\d+\.) )"));
    if (!fenced && continues && !blank && !own_line && !list_item) {
      out.back().text += " " + line.substr(first);
      continue;
    }
    out.push_back({number, line, fenced, info});
    continues = !fenced && !blank && !own_line;
  }
  return out;
}

// Inline code spans of a prose line, with GitHub's table escape `\|` read as `|`.
std::vector<std::string> CodeSpans(const std::string& line) {
  std::vector<std::string> spans;
  static const std::regex span("`([^`]+)`");
  for (auto it = std::sregex_iterator(line.begin(), line.end(), span); it != std::sregex_iterator(); ++it) {
    spans.push_back(std::regex_replace((*it)[1].str(), std::regex(R"(\\\|)"), "|"));
  }
  return spans;
}

std::string WithoutCodeSpans(const std::string& line) {
  return std::regex_replace(line, std::regex("`[^`]*`"), "``");
}

// GitHub's anchor of a heading: lower case, punctuation dropped, spaces to hyphens; repeats get -1, -2, ...
std::set<std::string> HeadingAnchors(const std::string& markdown) {
  std::set<std::string> anchors;
  std::map<std::string, int> seen;
  for (const MarkdownLine& line : ParseLines(markdown)) {
    if (line.fenced || line.text.empty() || line.text[0] != '#') continue;
    const size_t start = line.text.find_first_not_of('#');
    if (start == std::string::npos || line.text[start] != ' ') continue;
    std::string slug;
    for (const char c : line.text.substr(start + 1)) {
      const auto u = static_cast<unsigned char>(c);
      if (std::isalnum(u) || c == '-' || c == '_' || u >= 0x80) {
        slug += static_cast<char>(std::tolower(u));
      } else if (c == ' ') {
        slug += '-';
      }
    }
    const int repeats = seen[slug]++;
    anchors.insert(repeats == 0 ? slug : slug + "-" + std::to_string(repeats));
  }
  return anchors;
}

std::vector<fs::path> DocumentationFiles() {
  std::vector<fs::path> files = {kRoot / "README.md"};
  if (fs::is_directory(kRoot / "docs")) {
    for (const auto& entry : fs::recursive_directory_iterator(kRoot / "docs")) {
      if (entry.is_regular_file() && entry.path().extension() == ".md") files.push_back(entry.path());
    }
  }
  return files;
}

// "FILE:LINE: target: reason" for every relative link of `file` that points at nothing or outside `root`.
std::vector<std::string> BrokenLinks(const fs::path& file, const fs::path& root = kRoot) {
  std::vector<std::string> broken;
  static const std::regex inline_link(R"(\]\(([^)\s]+)(\s+"[^"]*")?\))");
  static const std::regex reference_link(R"(^\s*\[[^\]]+\]:\s*(\S+))");
  const std::string text = ReadText(file);
  for (const MarkdownLine& line : ParseLines(text)) {
    if (line.fenced) continue;
    const std::string prose = WithoutCodeSpans(line.text);
    std::vector<std::string> targets;
    for (auto it = std::sregex_iterator(prose.begin(), prose.end(), inline_link);
         it != std::sregex_iterator(); ++it) {
      targets.push_back((*it)[1].str());
    }
    std::smatch m;
    if (std::regex_search(prose, m, reference_link)) targets.push_back(m[1].str());
    for (const std::string& target : targets) {
      if (target.find("://") != std::string::npos || target.rfind("mailto:", 0) == 0) continue;
      const std::string where =
          file.lexically_relative(root).string() + ":" + std::to_string(line.number) + ": " + target + ": ";
      const size_t hash = target.find('#');
      const std::string path_part = target.substr(0, hash);
      const std::string anchor = hash == std::string::npos ? "" : target.substr(hash + 1);
      const fs::path resolved =
          path_part.empty() ? file : fs::weakly_canonical(file.parent_path() / path_part);
      const std::string relative = resolved.lexically_relative(root).string();
      if (relative.empty() || relative.rfind("..", 0) == 0) {
        broken.push_back(where + "points outside the repository");
      } else if (!fs::exists(resolved)) {
        broken.push_back(where + "no such file");
      } else if (!anchor.empty() && resolved.extension() == ".md" &&
                 HeadingAnchors(ReadText(resolved)).count(anchor) == 0) {
        broken.push_back(where + "no heading with this anchor");
      }
    }
  }
  return broken;
}

// What `vigil ARGS --help` prints.
std::string Help(const std::string& args) {
  return testing::RunShell(std::string(VIGIL_BINARY) + " " + args + " --help 2>&1").out;
}

// The names of a help's "Subcommands:" section.
std::set<std::string> Subcommands(const std::string& help) {
  std::set<std::string> names;
  bool in_section = false;
  static const std::regex entry(R"(^  ([a-z][a-z0-9_-]*)\s)");
  for (const std::string& line : Lines(help)) {
    if (line == "Subcommands:") {
      in_section = true;
    } else if (in_section) {
      std::smatch m;
      if (std::regex_search(line, m, entry)) names.insert(m[1].str());
    }
  }
  return names;
}

// The flags of a help's option lines ("  -o,--output TEXT REQUIRED   ...": -o and --output).
std::set<std::string> Flags(const std::string& help) {
  std::set<std::string> flags;
  static const std::regex flag(R"((^|[ ,])(--?[A-Za-z][A-Za-z0-9_-]*))");
  for (const std::string& line : Lines(help)) {
    if (line.rfind("  -", 0) != 0) continue;
    const size_t gap = line.find("  ", 2);
    const std::string column = line.substr(2, gap == std::string::npos ? std::string::npos : gap - 2);
    for (auto it = std::sregex_iterator(column.begin(), column.end(), flag); it != std::sregex_iterator();
         ++it) {
      flags.insert((*it)[2].str());
    }
  }
  return flags;
}

// Every command of the built binary (plot's subcommands as "plot run", ...) with its flags.
class CommandLine {
 public:
  CommandLine() {
    const std::string top = Help("");
    top_flags_ = Flags(top);
    all_flags_ = top_flags_;
    for (const std::string& command : Subcommands(top)) {
      const std::string help = Help(command);
      flags_[command] = Flags(help);
      for (const std::string& sub : Subcommands(help)) {
        const std::set<std::string> sub_flags = Flags(Help(command + " " + sub));
        subcommands_[command].insert(sub);
        flags_[command + " " + sub] = sub_flags;
        flags_[command].insert(sub_flags.begin(), sub_flags.end());
      }
      all_flags_.insert(flags_[command].begin(), flags_[command].end());
    }
  }

  bool Empty() const { return flags_.empty(); }
  bool HasCommand(const std::string& name) const { return flags_.count(name) != 0; }
  bool HasSubcommand(const std::string& command, const std::string& sub) const {
    const auto it = subcommands_.find(command);
    return it != subcommands_.end() && it->second.count(sub) != 0;
  }
  bool HasSubcommands(const std::string& command) const { return subcommands_.count(command) != 0; }
  bool HasFlag(const std::string& command, const std::string& flag) const {
    const auto it = flags_.find(command);
    return it != flags_.end() && it->second.count(flag) != 0;
  }
  bool AnyCommandHasFlag(const std::string& flag) const { return all_flags_.count(flag) != 0; }

 private:
  std::set<std::string> top_flags_, all_flags_;
  std::map<std::string, std::set<std::string>> flags_;
  std::map<std::string, std::set<std::string>> subcommands_;
};

// Asked once per test program: each help is a process start.
const CommandLine& Cli() {
  static const CommandLine cli;
  return cli;
}

// "vigil CMD ..." invocations of one code span or shell line, each with the flags written after it (up to the
// next invocation or shell separator); reasons for every command or flag the binary does not have.
std::vector<std::string> UnknownCommandsAndFlags(const CommandLine& cli, const std::string& code) {
  std::vector<std::string> unknown;
  static const std::regex invocation(R"((^|[\s/(])vigil\s+([a-z][a-z0-9_-]*)(?=$|[\s:]))");
  static const std::regex flag(R"((^|[\s\[|(])(--?[A-Za-z][A-Za-z0-9_-]*))");
  static const std::regex separator(R"(&&|;|\s\|\s|\s#|\$\()");
  std::vector<std::smatch> calls;
  for (auto it = std::sregex_iterator(code.begin(), code.end(), invocation); it != std::sregex_iterator();
       ++it) {
    calls.push_back(*it);
  }
  if (calls.empty()) {
    std::smatch m;
    if (std::regex_match(code, m, std::regex(R"((--?[A-Za-z][A-Za-z0-9_-]*)([ =].*)?)")) &&
        !cli.AnyCommandHasFlag(m[1].str())) {
      unknown.push_back("`" + code + "`: no command has " + m[1].str());
    }
    return unknown;
  }
  for (size_t i = 0; i < calls.size(); ++i) {
    const std::string command = calls[i][2].str();
    const size_t begin = calls[i].position(0) + calls[i].length(0);
    const size_t end = i + 1 < calls.size() ? calls[i + 1].position(0) : code.size();
    std::string rest = code.substr(begin, end - begin);
    std::smatch stop;
    if (std::regex_search(rest, stop, separator)) rest = rest.substr(0, stop.position(0));
    if (!cli.HasCommand(command)) {
      unknown.push_back("`" + code + "`: no command " + command);
      continue;
    }
    std::string scope = command;
    if (cli.HasSubcommands(command)) {
      std::smatch sub;
      if (std::regex_search(rest, sub, std::regex(R"(^\s+([a-z][a-z|]*)(?=$|\s))"))) {
        std::istringstream names(sub[1].str());
        std::vector<std::string> subs;
        for (std::string name; std::getline(names, name, '|');) subs.push_back(name);
        for (const std::string& name : subs) {
          if (!cli.HasSubcommand(command, name))
            unknown.push_back("`" + code + "`: no " + command + " " + name);
        }
        if (subs.size() == 1) scope = command + " " + subs[0];
      }
    }
    for (auto it = std::sregex_iterator(rest.begin(), rest.end(), flag); it != std::sregex_iterator(); ++it) {
      const std::string name = (*it)[2].str();
      if (!cli.HasFlag(scope, name)) unknown.push_back("`" + code + "`: vigil " + scope + " has no " + name);
    }
  }
  return unknown;
}

// A row of the README's command table: it starts with a `vigil ...` span.
bool IsCommandRow(const MarkdownLine& line) { return !line.fenced && line.text.rfind("| `vigil ", 0) == 0; }

// Reasons for every command that the command table of `markdown` (README.md) lists in more than one row.
std::vector<std::string> RepeatedTableCommands(const std::string& markdown) {
  static const std::regex command(R"(^\| `vigil ([a-z][a-z0-9_-]*))");
  std::map<std::string, int> first_row;
  std::vector<std::string> repeated;
  for (const MarkdownLine& line : ParseLines(markdown)) {
    std::smatch m;
    if (!IsCommandRow(line) || !std::regex_search(line.text, m, command)) continue;
    const auto [first, inserted] = first_row.emplace(m[1].str(), line.number);
    if (!inserted)
      repeated.push_back("README.md:" + std::to_string(line.number) + ": vigil " + m[1].str() +
                         " is listed again (first at line " + std::to_string(first->second) + ")");
  }
  return repeated;
}

TEST(Documentation, EveryRelativeLinkPointsAtAFileInTheRepository) {
  ASSERT_TRUE(fs::is_regular_file(kRoot / "docs" / "README.md")) << "docs/README.md (the index) is missing";
  std::vector<std::string> broken;
  for (const fs::path& file : DocumentationFiles()) {
    for (const std::string& reason : BrokenLinks(file)) broken.push_back(reason);
  }
  std::string report;
  for (const std::string& reason : broken) report += reason + "\n";
  EXPECT_TRUE(broken.empty()) << report;
}

TEST(Documentation, EveryDocumentedCommandAndFlagExists) {
  const CommandLine& cli = Cli();
  ASSERT_FALSE(cli.Empty()) << "`" << VIGIL_BINARY << " --help` lists no commands";
  std::vector<std::string> unknown;
  const auto check = [&](const fs::path& file, const MarkdownLine& line, const std::string& code) {
    for (const std::string& reason : UnknownCommandsAndFlags(cli, code)) {
      unknown.push_back(file.lexically_relative(kRoot).string() + ":" + std::to_string(line.number) + ": " +
                        reason);
    }
  };
  // docs/cli.md: every code span, and the lines of its shell blocks.
  const fs::path cli_page = kRoot / "docs" / "cli.md";
  ASSERT_TRUE(fs::is_regular_file(cli_page));
  for (const MarkdownLine& line : ParseLines(ReadText(cli_page))) {
    if (!line.fenced) {
      for (const std::string& span : CodeSpans(line.text)) check(cli_page, line, span);
    } else if (line.fence_info == "sh" || line.fence_info == "bash") {
      check(cli_page, line, line.text);
    }
  }
  // README.md: the command table's rows (those that start with a `vigil ...` span).
  const fs::path readme = kRoot / "README.md";
  int rows = 0;
  for (const MarkdownLine& line : ParseLines(ReadText(readme))) {
    if (!IsCommandRow(line)) continue;
    ++rows;
    for (const std::string& span : CodeSpans(line.text)) check(readme, line, span);
  }
  EXPECT_GT(rows, 0) << "README.md has no command table";
  std::string report;
  for (const std::string& reason : unknown) report += reason + "\n";
  EXPECT_TRUE(unknown.empty()) << report;
}

TEST(Documentation, TheReadmeCommandTableListsEachCommandOnce) {
  std::string report;
  for (const std::string& reason : RepeatedTableCommands(ReadText(kRoot / "README.md")))
    report += reason + "\n";
  EXPECT_TRUE(report.empty()) << report;
}

// The checks themselves: a broken link, a missing anchor, an unknown flag and a repeated row are found.
TEST(Documentation, TheChecksFindWhatIsWrong) {
  const fs::path dir =
      fs::weakly_canonical(fs::temp_directory_path()) / ("vigil_docs_test_" + std::to_string(::getpid()));
  fs::create_directories(dir / "docs");
  std::ofstream(dir / "docs" / "a.md") << "# A page\n\n## Two words\n";
  const fs::path page = dir / "docs" / "b.md";
  std::ofstream(page)
      << "[ok](a.md#two-words) [top](../docs/) [here](#a-heading) `[code](x.md)`\n\n"
      << "[gone](missing.md) [anchor](a.md#three-words) [out](../../elsewhere/spec.md)\n"
      << "[web](https://example.org/x.md)\n\n# A heading\n```text\n[fenced](nowhere.md)\n```\n";
  const std::vector<std::string> broken = BrokenLinks(page, dir);
  fs::remove_all(dir);
  ASSERT_EQ(broken.size(), 3u);
  EXPECT_EQ(broken[0], "docs/b.md:3: missing.md: no such file");
  EXPECT_EQ(broken[1], "docs/b.md:3: a.md#three-words: no heading with this anchor");
  EXPECT_EQ(broken[2], "docs/b.md:3: ../../elsewhere/spec.md: points outside the repository");

  const std::vector<MarkdownLine> lines =
      ParseLines("Run `vigil run\nCONFIG --force` now.\n# Heading\nnext\n- item\n  goes on\n");
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[3].text, "- item goes on");
  EXPECT_EQ(CodeSpans(lines[0].text), (std::vector<std::string>{"vigil run CONFIG --force"}));
  EXPECT_EQ(lines[2].number, 4);

  EXPECT_EQ(HeadingAnchors("# Run directory\n## `vigil run` (one run)\n# Run directory\n"),
            (std::set<std::string>{"run-directory", "vigil-run-one-run", "run-directory-1"}));

  EXPECT_EQ(RepeatedTableCommands(
                "| command | what |\n|---|---|\n| `vigil run CONFIG` | one |\n"
                "| `vigil plot run\\|sweep DIR` | figures |\n| `vigil run CONFIG -o DIR` | again |\n"
                "```text\n| `vigil run CONFIG` | fenced |\n```\n"),
            (std::vector<std::string>{"README.md:5: vigil run is listed again (first at line 3)"}));

  const CommandLine& cli = Cli();
  EXPECT_TRUE(UnknownCommandsAndFlags(cli, "vigil run CONFIG -o DIR --force").empty());
  EXPECT_TRUE(UnknownCommandsAndFlags(cli, "vigil plot run|sweep|dataset DIR --width W").empty());
  EXPECT_EQ(UnknownCommandsAndFlags(cli, "vigil run CONFIG --no-such-flag").size(), 1u);
  EXPECT_EQ(UnknownCommandsAndFlags(cli, "vigil frobnicate DIR").size(), 1u);
  EXPECT_EQ(UnknownCommandsAndFlags(cli, "vigil plot movie DIR").size(), 1u);
  EXPECT_EQ(UnknownCommandsAndFlags(cli, "--no-such-flag").size(), 1u);
  EXPECT_TRUE(
      UnknownCommandsAndFlags(cli, "build/vigil sweep S -o D && build/vigil regress D --baseline B").empty());
}

}  // namespace
}  // namespace vigil
