#include "ridefit/io/yaml_map.h"

#include <gtest/gtest.h>

#include <string>

#include "support/temp_dir.h"
#include "support/throws_input_error.h"

namespace ridefit::io {
namespace {

using testing::throws_input_error;

// yaml-cpp 0.7's LoadAll() never returns on these (it finds empty documents at the comma for
// ever, allocating about 1 GB/s); found by tools/fuzz. Each must be a message naming the line.
TEST(YamlMap, ACommaWhereAValueShouldStartIsASyntaxErrorNotAHang) {
  testing::TempDir dir("yaml_map");
  const struct {
    const char* text;
    const char* where;
  } cases[] = {
      {",", ":1:1: not valid YAML: a value cannot start with ','"},
      {", initial", ":1:1: not valid YAML: a value cannot start with ','"},
      {"- a\n,", ":2:1: not valid YAML: a value cannot start with ','"},
      {"---\n,", ":2:1: not valid YAML"},
      {"# a comment\n  ,x", ":2:3: not valid YAML"},
      {"a: 1\n...\n,", ":3:1: not valid YAML"},
      {"&anchor ,", ":1:9: not valid YAML"},
      {"\xEF\xBB\xBF,", "not valid YAML: a value cannot start with ','"},
  };
  for (const auto& c : cases) {
    const std::string path = dir.write("comma.yaml", c.text);
    EXPECT_TRUE(throws_input_error([&] { (void)YamlMap::load(path); }, c.where)) << c.text;
  }
}

// Found by tools/fuzz: a `?` key escaped as yaml-cpp's "bad conversion" when the unknown keys
// were listed.
TEST(YamlMap, AKeyThatIsNotANameIsRefusedWithItsLine) {
  testing::TempDir dir("yaml_map");
  EXPECT_TRUE(throws_input_error(
      [&] { (void)YamlMap::load(dir.write("k.yaml", "mass_kg: 1\n? [a, b]\n: 2\n")); },
      ":2: a key must be a name such as `mass_kg`, not a YAML sequence"));
  EXPECT_TRUE(throws_input_error(
      [&] { YamlMap::load(dir.write("k.yaml", "mass_kg: 1\n? 3.5 Hz\n")).finish(); }, "'3.5 Hz'"));
}

TEST(YamlMap, StillCountsRealDocumentsAndReadsOne) {
  testing::TempDir dir("yaml_map");
  EXPECT_TRUE(throws_input_error(
      [&] { (void)YamlMap::load(dir.write("two.yaml", "a: 1\n---\nb: 2\n---\nc: 3\n")); },
      "holds 3 YAML documents"));
  EXPECT_TRUE(throws_input_error([&] { (void)YamlMap::load(dir.write("empty.yaml", "")); },
                                 "expected a YAML mapping"));
  const YamlMap map = YamlMap::load(dir.write("one.yaml", "---\nnote: a, b\nvalue_m: 2.5\n"));
  EXPECT_TRUE(map.has("value_m"));
}

}  // namespace
}  // namespace ridefit::io
