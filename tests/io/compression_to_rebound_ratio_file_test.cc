// The optional model key compression_to_rebound_ratio in quarter- and half-car files: its
// default, its range, and overrides of it whether or not the file has it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "ridefit/io/half_car_file.h"
#include "ridefit/io/quarter_car_file.h"
#include "support/passat.h"
#include "support/throws_input_error.h"

namespace ridefit::io {
namespace {

namespace fs = std::filesystem;

class CompressionToReboundRatioFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("ridefit_ratio_" + std::to_string(getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  // A copy of a dataset's vehicle with `extra` appended (top-level lines) or with `after`'s
  // line followed by `extra` (inside a section).
  fs::path vehicle(const std::string& dataset, const std::string& extra,
                   const std::string& after = "") const {
    std::ifstream in(testing::dataset("vehicles/" + dataset));
    const fs::path path = dir_ / dataset;
    std::ofstream out(path);
    std::string line;
    while (std::getline(in, line)) {
      out << line << "\n";
      if (!after.empty() && line.rfind(after, 0) == 0) out << extra << "\n";
    }
    if (after.empty()) out << extra << "\n";
    return path;
  }
  fs::path dir_;
};

TEST_F(CompressionToReboundRatioFile, QuarterCarDefaultsToOneAndReadsTheKey) {
  EXPECT_EQ(testing::passat_corner().parameters.compression_to_rebound_ratio, 1.0);
  const auto file =
      load_quarter_car(vehicle("passat_b8_front.yaml", "compression_to_rebound_ratio: 0.45"));
  EXPECT_EQ(file.parameters.compression_to_rebound_ratio, 0.45);
  EXPECT_EQ(file.parameters.damping_Ns_per_m, 886.9);  // the rebound coefficient, unchanged
  // An override adds it to a file that leaves it out.
  EXPECT_EQ(load_quarter_car(testing::dataset("vehicles/passat_b8_front.yaml"),
                             {{"compression_to_rebound_ratio", 0.6}})
                .parameters.compression_to_rebound_ratio,
            0.6);
}

TEST_F(CompressionToReboundRatioFile, QuarterCarRejectsRatiosOutsideZeroToTen) {
  for (const char* bad : {"0", "-0.5", "10.5"}) {
    EXPECT_TRUE(testing::throws_input_error(
        [&] {
          load_quarter_car(
              vehicle("passat_b8_front.yaml", std::string("compression_to_rebound_ratio: ") + bad));
        },
        "key 'compression_to_rebound_ratio' is"))
        << bad;
  }
  EXPECT_TRUE(testing::throws_input_error(
      [&] {
        load_quarter_car(vehicle("passat_b8_front.yaml", "compression_to_rebound_ratio: abc"));
      },
      "key 'compression_to_rebound_ratio' is 'abc', expected a number"));
  EXPECT_TRUE(testing::throws_input_error(
      [&] {
        load_quarter_car(testing::dataset("vehicles/passat_b8_front.yaml"),
                         {{"compression_to_rebound_ratio", 0.0}});
      },
      "(given as an override compression_to_rebound_ratio=0)"));
  EXPECT_EQ(load_quarter_car(vehicle("passat_b8_front.yaml", "compression_to_rebound_ratio: 10"))
                .parameters.compression_to_rebound_ratio,
            10.0);
}

TEST_F(CompressionToReboundRatioFile, HalfCarDefaultsToOnePerAxleAndReadsTheKey) {
  const auto ajayi = load_half_car(testing::dataset("vehicles/ajayi_half_car.yaml"));
  EXPECT_EQ(ajayi.parameters.front.compression_to_rebound_ratio, 1.0);
  EXPECT_EQ(ajayi.parameters.rear.compression_to_rebound_ratio, 1.0);
  const auto file =
      load_half_car(vehicle("ajayi_half_car.yaml", "  compression_to_rebound_ratio: 0.3", "rear:"));
  EXPECT_EQ(file.parameters.rear.compression_to_rebound_ratio, 0.3);
  EXPECT_EQ(file.parameters.front.compression_to_rebound_ratio, 1.0);
  // Present in the file: an override replaces it.
  EXPECT_EQ(
      load_half_car(vehicle("ajayi_half_car.yaml", "  compression_to_rebound_ratio: 0.3", "rear:"),
                    {{"rear.compression_to_rebound_ratio", "0.7"}})
          .parameters.rear.compression_to_rebound_ratio,
      0.7);
}

// The dataset leaves the key out; a dotted override (--set, or a study's vary) still sets it,
// and the sweep's key check accepts it. Typos stay errors.
TEST_F(CompressionToReboundRatioFile, HalfCarOverrideSetsTheKeyTheFileLeavesOut) {
  const std::string path = testing::dataset("vehicles/ajayi_half_car.yaml");
  const auto file = load_half_car(path, {{"front.compression_to_rebound_ratio", "0.4"}});
  EXPECT_EQ(file.parameters.front.compression_to_rebound_ratio, 0.4);
  EXPECT_EQ(file.parameters.rear.compression_to_rebound_ratio, 1.0);
  EXPECT_EQ(load_half_car(path, {{"front.suspension", "strut"},
                                 {"front.compression_to_rebound_ratio", "0.4"}})
                .parameters.front.damper_path()
                .damper.compression_to_rebound_ratio,
            0.4);
  EXPECT_TRUE(half_car_has_key(path, "front.compression_to_rebound_ratio"));
  EXPECT_TRUE(half_car_has_key(path, "rear.compression_to_rebound_ratio"));
  EXPECT_FALSE(half_car_has_key(path, "seat.compression_to_rebound_ratio"));
  EXPECT_FALSE(half_car_has_key(path, "front.compression_to_rebound_ratios"));
  EXPECT_FALSE(half_car_has_key(path, "compression_to_rebound_ratio"));
  EXPECT_TRUE(testing::throws_input_error(
      [&] {
        load_half_car(path, {{"front.compression_to_rebound_ratios", "0.4"}});
      },
      "an override front.compression_to_rebound_ratios: not a key of"));
  EXPECT_TRUE(testing::throws_input_error(
      [&] {
        load_half_car(path, {{"seat.compression_to_rebound_ratio", "0.4"}});
      },
      "an override seat.compression_to_rebound_ratio: not a key of"));
}

TEST_F(CompressionToReboundRatioFile, HalfCarRejectsRatiosOutsideZeroToTenNamingTheDottedKey) {
  const std::string path = testing::dataset("vehicles/ajayi_half_car.yaml");
  for (const char* bad : {"0", "-1", "11"}) {
    EXPECT_TRUE(testing::throws_input_error(
        [&] {
          load_half_car(path, {{"rear.compression_to_rebound_ratio", bad}});
        },
        "key 'rear.compression_to_rebound_ratio' is"))
        << bad;
  }
  EXPECT_TRUE(testing::throws_input_error(
      [&] {
        load_half_car(path, {{"front.compression_to_rebound_ratio", "abc"}});
      },
      "key 'front.compression_to_rebound_ratio' is 'abc', expected a number"));
  EXPECT_TRUE(testing::throws_input_error(
      [&] {
        load_half_car(path, {{"front.compression_to_rebound_ratio", "abc"}}, "--set");
      },
      "(given as --set front.compression_to_rebound_ratio=abc)"));
  EXPECT_TRUE(testing::throws_input_error(
      [&] {
        load_half_car(
            vehicle("ajayi_half_car.yaml", "  compression_to_rebound_ratio: -0.2", "front:"));
      },
      "ajayi_half_car.yaml: key 'front.compression_to_rebound_ratio' is -0.2"));
}

}  // namespace
}  // namespace ridefit::io
