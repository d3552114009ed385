// The accelerometers' measuring-chain keys of a quarter-car file (model/acceleration_sensors.h):
// read when present, ideal when absent, addressable by name (fits, --set), and every bad value an
// InputError naming the key.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "ridefit/io/quarter_car_file.h"
#include "ridefit/model/quarter_car_parameter_table.h"
#include "support/passat.h"
#include "support/throws_input_error.h"

namespace ridefit::io {
namespace {

namespace fs = std::filesystem;

class QuarterCarFileSensors : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("ridefit_sensors_" + std::to_string(getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path passat_with(const std::string& extra) const {
    std::ifstream in(testing::dataset("vehicles/passat_b8_front.yaml"));
    const fs::path path = dir_ / "passat.yaml";
    std::ofstream out(path);
    out << in.rdbuf() << "\n" << extra << "\n";
    return path;
  }
  ::testing::AssertionResult rejects(const std::string& extra, const std::string& words) const {
    return testing::throws_input_error([&] { load_quarter_car(passat_with(extra)); }, words);
  }
  fs::path dir_;
};

TEST_F(QuarterCarFileSensors, ReadsTheChainKeysAndDefaultsToAnIdealSensor) {
  const auto p = load_quarter_car(passat_with("body_acc_gain: 0.9\n"
                                              "wheel_acc_gain: 1.05\n"
                                              "acc_sensor_cutoff_Hz: 15\n"
                                              "acc_sensor_order: 2"))
                     .parameters;
  EXPECT_EQ(p.sensors.body_acc_gain, 0.9);
  EXPECT_EQ(p.sensors.wheel_acc_gain, 1.05);
  EXPECT_EQ(p.sensors.acc_sensor_cutoff_Hz, 15.0);
  EXPECT_EQ(p.sensors.acc_sensor_order, 2);
  EXPECT_EQ(p.top_mount_stiffness_N_per_m, 488000.0);  // the rest unchanged
  const auto ideal = testing::passat_corner().parameters.sensors;
  EXPECT_TRUE(ideal.ideal());
  EXPECT_EQ(ideal.acc_sensor_order, 1);
  EXPECT_EQ(ideal.body_power_gain(50.0), 1.0);
  // |H|² of the two stages at the corner: (1/2)², times g².
  EXPECT_NEAR(p.sensors.body_power_gain(15.0), 0.81 * 0.25, 1e-15);
  EXPECT_NEAR(p.sensors.wheel_power_gain(30.0), 1.05 * 1.05 / 25.0, 1e-15);
  // By name, as fits and --set address them.
  const auto index = model::quarter_car_parameter_index("acc_sensor_cutoff_Hz");
  ASSERT_TRUE(index.has_value());
  EXPECT_EQ(model::quarter_car_parameter(p, *index), 15.0);
  const auto set = load_quarter_car(passat_with(""), {{"body_acc_gain", 0.8}}).parameters;
  EXPECT_EQ(set.sensors.body_acc_gain, 0.8);
}

TEST_F(QuarterCarFileSensors, RejectsBadChainValuesNamingTheKey) {
  EXPECT_TRUE(rejects("body_acc_gain: 0", "body_acc_gain"));
  EXPECT_TRUE(rejects("wheel_acc_gain: 98.1", "wheel_acc_gain"));
  EXPECT_TRUE(rejects("acc_sensor_cutoff_Hz: -5", "acc_sensor_cutoff_Hz"));
  EXPECT_TRUE(rejects("acc_sensor_cutoff_Hz: 15\nacc_sensor_order: 3", "expected 1"));
  EXPECT_TRUE(rejects("acc_sensor_order: 2", "acc_sensor_cutoff_Hz"));
  EXPECT_TRUE(rejects("acc_sensor_gain: 1", "acc_sensor_gain"));  // a typo is unknown
}

}  // namespace
}  // namespace ridefit::io
