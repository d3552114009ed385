// .mat measurements: files written by independent writers (scipy.io.savemat for v5, h5py for
// v7.3; tests/data/mat/make_mat_files.py) checked against the closed forms they were written
// from, a write → read round trip, and the message of every bad file.
#include "ridefit/io/mat_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <ostream>
#include <random>
#include <string>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/io/measurement_file.h"

namespace ridefit::io {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t kSamples = 200;  // make_mat_files.py: N
constexpr double kG = 9.80665;

fs::path data(const std::string& name) {
  return fs::path(RIDEFIT_SOURCE_DIR) / "tests/data/mat" / name;
}

// The generator's closed forms, in SI.
double time_s(std::size_t k) { return static_cast<double>(k) / 1000.0; }
double body_acc_m_per_s2(std::size_t k) {
  return kG * 0.1 * std::sin(2.0 * std::numbers::pi * 5.0 * time_s(k));
}
double travel_m(std::size_t k) {
  // Stored as float32 in mm: the value is the float nearest to 10 cos(...).
  const auto mm = static_cast<float>(10.0 * std::cos(2.0 * std::numbers::pi * 2.0 * time_s(k)));
  return 1e-3 * static_cast<double>(mm);
}

void expect_closed_forms(const CsvTable& table, bool with_travel) {
  ASSERT_EQ(table.rows(), kSamples);
  ASSERT_TRUE(table.has("time"));
  ASSERT_TRUE(table.has("body_acc"));
  EXPECT_EQ(table.column("time").unit, "s");
  EXPECT_EQ(table.column("body_acc").unit, "m/s^2");
  for (std::size_t k = 0; k < kSamples; ++k) {
    EXPECT_NEAR(table.column("time").values[k], time_s(k), 1e-15) << "sample " << k;
    EXPECT_NEAR(table.column("body_acc").values[k], body_acc_m_per_s2(k), 1e-14) << k;
  }
  EXPECT_EQ(table.has("travel"), with_travel);
  if (with_travel) {
    EXPECT_EQ(table.column("travel").unit, "m");
    for (std::size_t k = 0; k < kSamples; ++k) {
      EXPECT_NEAR(table.column("travel").values[k], travel_m(k), 1e-15) << k;
    }
  }
  EXPECT_NO_THROW(table.time_s());
}

TEST(MatFile, ReadsTopLevelRowVectorsWithAUnitsStructV5Uncompressed) {
  const CsvTable table = read_mat_table(data("variables_v5.mat"));
  expect_closed_forms(table, true);
  // int8 0/1 converted to double, unit 1.
  const CsvColumn& stuck = table.column("stuck");
  EXPECT_EQ(stuck.unit, "1");
  for (std::size_t k = 0; k < kSamples; ++k) EXPECT_EQ(stuck.values[k], double(k % 2));
  EXPECT_EQ(table.columns().front().name, "time") << "the file's order is kept";
}

TEST(MatFile, ReadsALogicalChannelAsZeroAndOne) {
  const CsvTable table = read_mat_table(data("logical_v5.mat"));
  expect_closed_forms(table, false);
  const CsvColumn& stuck = table.column("stuck");
  EXPECT_EQ(stuck.unit, "1");
  for (std::size_t k = 0; k < kSamples; ++k) EXPECT_EQ(stuck.values[k], k % 3 == 0 ? 1.0 : 0.0);
}

TEST(MatFile, ReadsTheFieldsOfOneStructWithACellDescriptionV5Compressed) {
  // time is int32 in ms; units come from description = {'time[ms]', 'body_acc[g]', ...}.
  expect_closed_forms(read_mat_table(data("struct_v5_compressed.mat")), true);
}

TEST(MatFile, ReadsACharMatrixDescription) {
  expect_closed_forms(read_mat_table(data("description_v5.mat")), true);
}

TEST(MatFile, ReadsAUnitsStructInsideTheChannelStruct) {
  expect_closed_forms(read_mat_table(data("struct_units_v5.mat")), false);
}

TEST(MatFile, ReadsV73TopLevelVariablesAndUnitsStruct) {
  expect_closed_forms(read_mat_table(data("variables_v73.mat")), true);
}

TEST(MatFile, ReadsV73DeflatedStructWithAStringDescription) {
  expect_closed_forms(read_mat_table(data("struct_v73_deflated.mat")), false);
}

TEST(MatFile, MeasurementFileDispatchesOnTheExtension) {
  EXPECT_TRUE(is_mat_file("a/b.mat"));
  EXPECT_TRUE(is_mat_file("B.MAT"));
  EXPECT_FALSE(is_mat_file("b.csv"));
  EXPECT_FALSE(is_mat_file("mat"));
  expect_closed_forms(read_measurement_table(data("variables_v73.mat")), true);
}

class MatFileWrite : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           (std::string("ridefit_mat_") + info->name() + "_" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(MatFileWrite, RoundTripKeepsEveryBitAndTheSiUnits) {
  std::mt19937 rng(18);  // seeded: the same values every run
  std::normal_distribution<double> noise(0.0, 1.0);
  CsvTable table;
  std::vector<double> t(1000), acc(1000), road(1000);
  for (std::size_t k = 0; k < t.size(); ++k) {
    t[k] = 0.002 * static_cast<double>(k);
    acc[k] = noise(rng);
    road[k] = 1e3 * noise(rng);
  }
  table.add("time", "s", t);
  table.add("body_acc", "g", acc);  // stored in m/s^2
  table.add("road", "mm", road);    // stored in m
  const fs::path path = dir_ / "out.mat";
  write_measurement_table(table, path);
  const CsvTable back = read_measurement_table(path);
  ASSERT_EQ(back.columns().size(), 3u);
  for (std::size_t c = 0; c < 3; ++c) {
    EXPECT_EQ(back.columns()[c].name, table.columns()[c].name);
    EXPECT_EQ(back.columns()[c].unit, table.columns()[c].unit);
    EXPECT_EQ(back.columns()[c].values, table.columns()[c].values) << "bit for bit";
  }
  // Only the file: the temporary was renamed into place.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
}

TEST_F(MatFileWrite, NonFiniteValueOrBadNameWritesNothing) {
  CsvTable table;
  table.add("time", "s", {0.0, 1.0});
  table.add("body_acc", "m/s^2", {0.0, NAN});
  EXPECT_THROW(write_mat_table(table, dir_ / "nan.mat"), RunError);
  CsvTable bad_name;
  bad_name.add("2nd", "s", {0.0, 1.0});
  try {
    write_mat_table(bad_name, dir_ / "name.mat");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'2nd' cannot be a MATLAB variable name"),
              std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(fs::is_empty(dir_)) << "no half-written file";
}

TEST_F(MatFileWrite, AFailedWriteKeepsTheOldFile) {
  const fs::path path = dir_ / "keep.mat";
  std::ofstream(path) << "old";
  CsvTable table;
  table.add("time", "s", {0.0, INFINITY});
  EXPECT_THROW(write_mat_table(table, path), RunError);
  std::ifstream in(path);
  std::string content;
  in >> content;
  EXPECT_EQ(content, "old");
}

struct BadFile {
  std::string file;
  std::vector<std::string> fragments;
};

// gtest names the case by its file (it would print the struct's bytes).
void PrintTo(const BadFile& bad, std::ostream* os) { *os << bad.file; }

class MatFileBad : public ::testing::TestWithParam<BadFile> {};

TEST_P(MatFileBad, IsAnInputErrorNamingFileAndVariable) {
  const BadFile& bad = GetParam();
  try {
    read_mat_table(data(bad.file)).time_s();
    ADD_FAILURE() << bad.file << ": no InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(data(bad.file).string()), std::string::npos) << message;
    for (const auto& fragment : bad.fragments) {
      EXPECT_NE(message.find(fragment), std::string::npos)
          << "message lacks '" << fragment << "': " << message;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Messages, MatFileBad,
    ::testing::Values(
        BadFile{"bad_complex.mat", {"variable 'body_acc'", "is complex"}},
        BadFile{"bad_sparse.mat", {"variable 'body_acc'", "sparse", "full(x)"}},
        BadFile{"bad_cell.mat", {"variable 'body_acc'", "is a cell array"}},
        BadFile{"bad_char_channel.mat", {"variable 'body_acc'", "is a char array"}},
        BadFile{"bad_matrix.mat", {"variable 'body_acc'", "2x200 matrix"}},
        BadFile{"bad_empty.mat", {"variable 'body_acc'", "is empty"}},
        BadFile{"bad_nan.mat", {"variable 'body_acc'", "row 8 is nan"}},
        BadFile{"bad_mismatched.mat", {"'body_acc' has 199 samples but 'time' has 200"}},
        BadFile{"bad_unknown_unit.mat",
                {"variable 'body_acc'", "units.body_acc", "unknown unit 'furlong'", "m/s^2"}},
        BadFile{"bad_no_unit.mat",
                {"variable 'body_acc' has no unit", "units.body_acc = 'm/s^2'", "body_acc[m/s^2]"}},
        BadFile{"bad_typo_unit.mat", {"units.body_ac names no channel", "time, body_acc"}},
        BadFile{"bad_conflict.mat",
                {"units.body_acc says 'g'", "description entry 'body_acc[m/s^2]' says 'm/s^2'"}},
        BadFile{"bad_time_not_increasing.mat",
                {"row 51, column 'time'", "must be strictly increasing"}},
        BadFile{"bad_two_structs.mat", {"2 structs ('a', 'b'"}},
        BadFile{"bad_struct_beside_channels.mat",
                {"struct 'meta' beside the top-level variable 'time'"}},
        BadFile{"bad_no_channels.mat", {"no channels"}},
        BadFile{"bad_v4.mat", {"MAT v4", "v5 or v7.3"}},
        BadFile{"bad_not_a_mat.mat", {"not a MATLAB .mat file", "scipy.io.savemat"}},
        BadFile{"bad_damaged_dimensions.mat",
                {"variable 'time' claims 1728053448x1 values", "the file is damaged"}},
        BadFile{"missing.mat", {"file not found"}}),
    [](const ::testing::TestParamInfo<BadFile>& param) {
      std::string name = fs::path(param.param.file).stem().string();
      for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
      return name;
    });

}  // namespace
}  // namespace ridefit::io
