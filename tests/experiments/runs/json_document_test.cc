#include "experiments/runs/json_document.h"

#include <gtest/gtest.h>

#include "tests/core/test_util.h"

namespace vigil::experiments {
namespace {
using testing::InputErrorOf;

TEST(JsonDocument, EveryValueHasTheLineItEndsOn) {
  const JsonDocument doc("f.json", "{\n  \"a\": 1,\n  \"b\": [\n    true,\n    {\"c\": \"x\"}\n  ]\n}\n");
  EXPECT_EQ(doc.root()["b"][1]["c"], "x");
  EXPECT_EQ(doc.LineOf("/a"), 2);
  EXPECT_EQ(doc.LineOf("/b/0"), 4);
  EXPECT_EQ(doc.LineOf("/b/1/c"), 5);
  EXPECT_EQ(doc.LineOf("/missing"), 0);
}

TEST(JsonDocument, ASyntaxErrorNamesItsLineInOneLine) {
  const std::string error = InputErrorOf([] { JsonDocument("f.json", "{\n  \"a\": 1,\n  \"b\": tru\n}\n"); });
  EXPECT_EQ(error.rfind("f.json:3: not valid JSON: ", 0), 0u) << error;
  EXPECT_EQ(error.find("json.exception"), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

TEST(JsonDocument, DeepNestingIsRefused) {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  EXPECT_NE(InputErrorOf([&] { JsonDocument("f.json", deep); }).find("nested deeper than"),
            std::string::npos);
}

TEST(JsonDocument, FailNamesTheKeyPathAndItsLine) {
  const JsonDocument doc("f.json", "{\"cells\": [\n {\"value\": -1}\n]}");
  const std::string error = InputErrorOf([&] { doc.Fail("/cells/0/value", "must be >= 0"); });
  EXPECT_EQ(error, "f.json:2: cells[0].value: must be >= 0");
  // A missing value is placed at its nearest enclosing one.
  EXPECT_EQ(InputErrorOf([&] { doc.Fail("/cells/0/metric", "missing"); }),
            "f.json:2: cells[0].metric: missing");
}

}  // namespace
}  // namespace vigil::experiments
