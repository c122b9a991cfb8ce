#include "core/error.h"

#include <gtest/gtest.h>

namespace vigil {
namespace {

TEST(Error, MessagesStayOnOnePrintableLine) {
  EXPECT_EQ(OneLine("plain text: 1.5 m/s^2"), "plain text: 1.5 m/s^2");
  EXPECT_EQ(OneLine("a\nb\r\tc"), "a\\nb\\r\\tc");
  EXPECT_EQ(OneLine(std::string("nul\0byte", 8)), "nul\\x00byte");
  EXPECT_EQ(OneLine("\x7f\x1b[31m"), "\\x7f\\x1b[31m");
  EXPECT_EQ(OneLine("caf\xc3\xa9 \xe2\x82\xac"), "caf\xc3\xa9 \xe2\x82\xac");  // valid UTF-8 kept
  EXPECT_EQ(OneLine("\xff\xfe \xc3"), "\\xff\\xfe \\xc3");                     // invalid bytes escaped
  EXPECT_EQ(OneLine("\xc0\xaf \xed\xa0\x80"), "\\xc0\\xaf \\xed\\xa0\\x80");   // overlong, surrogate
}

TEST(Error, InputErrorIsAlwaysOneLine) {
  const InputError e(Located("a.yaml", 3, "seed: expected an integer, got '5\n'"));
  EXPECT_STREQ(e.what(), "a.yaml:3: seed: expected an integer, got '5\\n'");
}

}  // namespace
}  // namespace vigil
