#include "core/config.h"

#include <gtest/gtest.h>

#include "tests/core/test_util.h"

namespace vigil::config {
namespace {

enum class Mode { kA, kB };

struct Inner {
  bool enabled = true;
  double rate = 0.5;
  std::vector<double> distances = {1.0, 2.0};
  template <class V>
  void Visit(V& v) {
    v.Field("enabled", enabled, "a flag");
    v.Field("rate", rate, "a probability", Bounds::Probability());
    v.Field("distances", distances, "positive list", Bounds::Positive());
  }
};

struct Outer {
  uint64_t seed = 1;
  int count = 3;
  std::string name = "x";
  Mode mode = Mode::kA;
  Inner inner;
  template <class V>
  void Visit(V& v) {
    v.Field("seed", seed, "seed");
    v.Field("count", count, "count", Bounds::AtLeast(1));
    v.Field("name", name, "name");
    v.Enum("mode", mode, EnumNames<Mode>{{"a", Mode::kA}, {"b", Mode::kB}}, "mode");
    v.Section("inner", inner, "inner section");
  }
};

using vigil::testing::InputErrorOf;
using vigil::testing::TempDir;

TEST(Config, AbsentKeysKeepDefaultsAndPresentOnesAreRead) {
  TempDir dir;
  Outer o;
  LoadFile(dir.File("c.yaml", "count: 7\ninner:\n  rate: 0.25\nmode: b\n"), o);
  EXPECT_EQ(o.count, 7);
  EXPECT_EQ(o.mode, Mode::kB);
  EXPECT_DOUBLE_EQ(o.inner.rate, 0.25);
  EXPECT_TRUE(o.inner.enabled);
  EXPECT_EQ(o.name, "x");
}

TEST(Config, UnknownKeyIsNamedWithFileAndLine) {
  TempDir dir;
  const std::string path = dir.File("c.yaml", "count: 7\ninner:\n  rate: 0.25\n  speed: 3\n");
  Outer o;
  EXPECT_EQ(InputErrorOf([&] { LoadFile(path, o); }), path + ":4: inner.speed: unknown key");
}

TEST(Config, WrongTypeAndOutOfRangeAreRejected) {
  TempDir dir;
  Outer o;
  const std::string bad_type = dir.File("t.yaml", "count: many\n");
  EXPECT_EQ(InputErrorOf([&] { LoadFile(bad_type, o); }),
            bad_type + ":1: count: expected an integer, got 'many'");
  const std::string bad_range = dir.File("r.yaml", "\ninner: {rate: 1.5}\n");
  EXPECT_EQ(InputErrorOf([&] { LoadFile(bad_range, o); }), bad_range + ":2: inner.rate: must be in [0, 1]");
  const std::string bad_list = dir.File("l.yaml", "inner:\n  distances: [1, -2]\n");
  EXPECT_EQ(InputErrorOf([&] { LoadFile(bad_list, o); }), bad_list + ":2: inner.distances: must be > 0");
  const std::string bad_enum = dir.File("e.yaml", "mode: c\n");
  EXPECT_EQ(InputErrorOf([&] { LoadFile(bad_enum, o); }), bad_enum + ":1: mode: must be one of: a, b");
  const std::string nan = dir.File("n.yaml", "inner: {rate: .nan}\n");
  EXPECT_NE(InputErrorOf([&] { LoadFile(nan, o); }).find("expected a finite number"), std::string::npos);
}

TEST(Config, SyntaxErrorNamesTheLine) {
  TempDir dir;
  const std::string path = dir.File("s.yaml", "count: 1\ninner: [\n");
  Outer o;
  const std::string err = InputErrorOf([&] { LoadFile(path, o); });
  EXPECT_EQ(err.rfind(path + ":", 0), 0u) << err;
  EXPECT_NE(err.find("YAML syntax error"), std::string::npos);
}

TEST(Config, OverridesAreTypedByTheSchema) {
  Outer o;
  ApplyOverride("inner.distances=[3, 4.5]", o);
  ApplyOverride("inner.enabled=false", o);
  ApplyOverride("mode=b", o);
  EXPECT_EQ(o.inner.distances, (std::vector<double>{3.0, 4.5}));
  EXPECT_FALSE(o.inner.enabled);
  EXPECT_EQ(o.mode, Mode::kB);
  EXPECT_EQ(InputErrorOf([&] { ApplyOverride("inner.nope=1", o); }), "--set: inner.nope: unknown key");
  EXPECT_EQ(InputErrorOf([&] { ApplyOverride("count=0", o); }), "--set: count: must be >= 1");
  EXPECT_EQ(InputErrorOf([&] { ApplyOverride("count", o); }), "--set count: expected key.path=value");
}

TEST(Config, WrittenYamlReadsBackToTheSameValues) {
  TempDir dir;
  Outer o;
  o.seed = 42;
  o.inner.rate = 0.1;  // not exactly representable: must round-trip bit for bit
  o.inner.distances = {0.3, 1e-7};
  o.mode = Mode::kB;
  const std::string text = ToYaml(o);
  Outer back;
  LoadFile(dir.File("o.yaml", text), back);
  EXPECT_EQ(back.seed, 42u);
  EXPECT_EQ(back.inner.rate, 0.1);
  EXPECT_EQ(back.inner.distances, o.inner.distances);
  EXPECT_EQ(back.mode, Mode::kB);
  EXPECT_EQ(ToYaml(back), text);
}

TEST(Config, DescribesEveryKeyWithItsDefault) {
  Outer o;
  const auto keys = DescribeKeys(o);
  ASSERT_EQ(keys.size(), 7u);
  EXPECT_EQ(keys[3].path, "mode");
  EXPECT_EQ(keys[3].allowed, "a, b");
  EXPECT_EQ(keys[5].path, "inner.rate");
  EXPECT_EQ(keys[5].default_value, "0.5");
  EXPECT_EQ(keys[5].allowed, "in [0, 1]");
}

}  // namespace
}  // namespace vigil::config

namespace vigil::config {
namespace {
using vigil::testing::InputErrorOf;
using vigil::testing::TempDir;

TEST(Config, DuplicateKeysAreRefusedWithBothLines) {
  TempDir dir;
  Outer o;
  const std::string top = dir.File("top.yaml", "count: 7\nseed: 2\ncount: 8\n");
  EXPECT_EQ(InputErrorOf([&] { LoadFile(top, o); }),
            top + ":3: count: duplicate key (first at line 1); keep one");
  const std::string nested = dir.File("nested.yaml", "inner:\n  rate: 0.25\n  rate: 0.5\n");
  EXPECT_EQ(InputErrorOf([&] { LoadFile(nested, o); }),
            nested + ":3: inner.rate: duplicate key (first at line 2); keep one");
}

TEST(Config, AnEmptyValueIsReportedOnItsOwnLine) {
  TempDir dir;
  Outer o;
  const std::string path = dir.File("empty.yaml", "name: a\ncount:\n\n\nseed: 2\n");
  EXPECT_EQ(InputErrorOf([&] { LoadFile(path, o); }),
            path + ":2: count: empty value: give a value or remove the key");
}

TEST(Config, ADirectoryOrAFifoIsNotAConfigFile) {
  TempDir dir;
  Outer o;
  EXPECT_NE(InputErrorOf([&] { LoadFile(dir.path().string(), o); }).find("is a directory"),
            std::string::npos);
  EXPECT_NE(InputErrorOf([&] { LoadFile("/dev/zero", o); }).find("not a regular file"), std::string::npos);
}

TEST(Config, BlockScalarValuesGiveAOneLineError) {
  TempDir dir;
  Outer o;
  const std::string path = dir.File("block.yaml", "count: |\n  5\n  6\n");
  const std::string error = InputErrorOf([&] { LoadFile(path, o); });
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  EXPECT_EQ(error.rfind(path + ":1: count:", 0), 0u) << error;
}

TEST(Config, RecursiveAliasesAreRefusedWithTheirLine) {
  TempDir dir;
  Outer o;
  const std::string path = dir.File("sa.yaml", "count: 2\na: &a [*a]\n");
  EXPECT_EQ(InputErrorOf([&] { LoadFile(path, o); }),
            path + ":2: a recursive alias (a node that contains itself)");
  const std::string map = dir.File("sm.yaml", "inner: &m\n  rate: 0.5\n  self: *m\n");
  EXPECT_NE(InputErrorOf([&] { LoadFile(map, o); }).find("recursive alias"), std::string::npos);
  EXPECT_NE(InputErrorOf([&] {
              ApplyOverride("inner.distances=&a [*a]", o);
            }).find("--set inner.distances: a recursive alias"),
            std::string::npos);
}

TEST(Config, NestingDeeperThanTheLimitIsRefused) {
  TempDir dir;
  Outer o;
  const int depth = kMaxYamlDepth + 1;
  const std::string path =
      dir.File("deep.yaml", "a: " + std::string(depth, '[') + std::string(depth, ']') + "\n");
  EXPECT_NE(InputErrorOf([&] {
              LoadFile(path, o);
            }).find(":1: nested deeper than " + std::to_string(kMaxYamlDepth)),
            std::string::npos);
  // A billion laughs: few lines, far too many values once the aliases are expanded.
  std::string laughs = "a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int i = 1; i < 9; ++i)
    laughs += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " [" + std::string("*a") +
              std::to_string(i - 1) + std::string(9, ',').replace(0, 9, "") + "]\n";
  std::string wide = "a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int i = 1; i < 9; ++i) {
    wide += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " [";
    for (int k = 0; k < 10; ++k) wide += (k ? ", *a" : "*a") + std::to_string(i - 1);
    wide += "]\n";
  }
  const std::string bomb = dir.File("bomb.yaml", wide);
  EXPECT_NE(InputErrorOf([&] { LoadFile(bomb, o); }).find("values once aliases are expanded"),
            std::string::npos);
}

TEST(Config, ANullKeyIsNamedWithItsLine) {
  TempDir dir;
  Outer o;
  const std::string path = dir.File("null.yaml", "count: 2\n~: 2\n");
  EXPECT_EQ(InputErrorOf([&] { LoadFile(path, o); }),
            path + ":2: ~: unknown key (a key must be a plain name)");
}

}  // namespace
}  // namespace vigil::config
