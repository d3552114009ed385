#include "ridefit/io/path_type.h"

#include <gtest/gtest.h>

#include <string>

#include "ridefit/io/csv_table.h"
#include "ridefit/io/yaml_map.h"
#include "support/temp_dir.h"
#include "support/throws_input_error.h"

namespace ridefit::io {
namespace {

using testing::throws_input_error;

TEST(PathType, NamesWhatIsThereAndNothingWhenAbsent) {
  testing::TempDir dir("path_type");
  const std::string file = dir.write("a.yaml", "x: 1\n");
  EXPECT_EQ(path_type(file), std::filesystem::file_type::regular);
  EXPECT_EQ(path_type(dir.path()), std::filesystem::file_type::directory);
  EXPECT_EQ(path_type(dir.path() / "missing.yaml"), std::filesystem::file_type::not_found);
  // A file used as a folder: not there, as the readers' "file not found" says.
  EXPECT_EQ(path_type(std::filesystem::path(file) / "b.yaml"),
            std::filesystem::file_type::not_found);
}

// Found by tools/fuzz: a 300-character name in a study's `model:` or an excitation's `file:`
// escaped from the readers as std::filesystem's "File name too long".
TEST(PathType, ANameTheSystemCannotTakeIsAnInputErrorNamingIt) {
  testing::TempDir dir("path_type");
  const std::filesystem::path long_name = dir.path() / (std::string(300, 'x') + ".yaml");
  EXPECT_TRUE(throws_input_error([&] { (void)path_type(long_name); }, "File name too long"));
  EXPECT_TRUE(throws_input_error([&] { (void)YamlMap::load(long_name); }, "cannot be used"));
  EXPECT_TRUE(throws_input_error([&] { (void)CsvTable::read(long_name); }, "cannot be used"));
}

}  // namespace
}  // namespace ridefit::io
