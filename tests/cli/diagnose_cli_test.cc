// `ridefit diagnose`: a quick run's outputs, and bad input (exit code 2, nothing written).
#include <gtest/gtest.h>

#include <fmt/core.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "ridefit/io/quarter_car_file.h"
#include "support/cli_runner.h"
#include "support/passat.h"
#include "support/temp_dir.h"

namespace ridefit {
namespace {

using testing::dataset;
using testing::run_cli;

// A 20 s record of the Passat corner on a class A road at 200 Hz, made by `ridefit simulate`
// (time, road, body_acc, wheel_acc and more columns).
std::string simulate_record(const testing::TempDir& dir, const std::string& name,
                            const std::string& model) {
  const std::string out = (dir.path() / name).string();
  const auto run =
      run_cli("simulate " + model + " " + dataset("excitations/iso8608_class_a_50kmh.yaml") +
              " --duration 20 --rate 200 -o " + out);
  EXPECT_EQ(run.exit_code, 0) << run.output;
  return out;
}

nlohmann::json json_of(const std::string& output) {
  const auto start = output.find('{');
  return nlohmann::json::parse(output.substr(start == std::string::npos ? 0 : start));
}

TEST(DiagnoseCli, QuickRunWritesReportModelAndJson) {
  testing::TempDir dir("ridefit_diagnose_cli");
  const std::string model = dataset("vehicles/passat_b8_front.yaml");
  const std::string record = simulate_record(dir, "record.csv", model);
  const std::string out = (dir.path() / "diagnosis").string();
  const auto run = run_cli("diagnose " + model + " " + record +
                           " --effects tyre_lift_off,bump_stop --segment 2 --json -o " + out);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto j = json_of(run.output);
  // The data come from the model itself: nothing is missing.
  EXPECT_EQ(j["verdict"], "no missing effect found") << run.output;
  EXPECT_TRUE(j["named"].empty());
  EXPECT_LT(j["gap_before_dB"].get<double>(), 0.5);
  ASSERT_EQ(j["rounds"].size(), 1u);
  EXPECT_EQ(j["rounds"][0]["effects"].size(), 2u);
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "diagnosis" / "report.md"));
  // The output model loads and equals the input where nothing was added.
  const auto written = io::load_quarter_car(dir.path() / "diagnosis" / "model.yaml");
  const auto input = io::load_quarter_car(model);
  EXPECT_EQ(written.parameters.bump_stop_stiffness_N_per_m, 0.0);
  EXPECT_EQ(written.damper_state, input.damper_state);
}

struct BadDiagnosis {
  std::string name;
  std::string arguments;  // after "diagnose MODEL", with {record}, {short}, {bare}, {dir}
  std::string expected;   // in the message
};

class DiagnoseBadInput : public ::testing::TestWithParam<BadDiagnosis> {};

TEST_P(DiagnoseBadInput, ExitTwoWithAClearMessageAndNoOutput) {
  testing::TempDir dir("ridefit_diagnose_bad");
  const std::string model = dataset("vehicles/passat_b8_front.yaml");
  const std::string record = simulate_record(dir, "record.csv", model);
  // 10 s at 100 Hz of: the road alone; the road and wheel_acc; the accelerations without a road.
  std::string bare_text = "time[s],road[m]\n", wheel_text = "time[s],road[m],wheel_acc[m/s^2]\n",
              roadless_text = "time[s],body_acc[m/s^2],wheel_acc[m/s^2]\n";
  for (int k = 0; k <= 1000; ++k) {
    const double t = 0.01 * k, h = 0.001 * std::sin(7.0 * t), a = std::sin(3.0 * t);
    bare_text += fmt::format("{},{}\n", t, h);
    wheel_text += fmt::format("{},{},{}\n", t, h, a);
    roadless_text += fmt::format("{},{},{}\n", t, a, a);
  }
  const std::string bare = dir.write("bare.csv", bare_text);
  const std::string wheel_only = dir.write("wheel_only.csv", wheel_text);
  const std::string roadless = dir.write("roadless.csv", roadless_text);
  std::string arguments = GetParam().arguments;
  auto substitute = [&](const std::string& key, const std::string& value) {
    for (auto at = arguments.find(key); at != std::string::npos; at = arguments.find(key)) {
      arguments.replace(at, key.size(), value);
    }
  };
  substitute("{record}", record);
  substitute("{bare}", bare);
  substitute("{wheel_only}", wheel_only);
  substitute("{model}", model);
  substitute("{roadless}", roadless);
  substitute("{long_road}", dataset("excitations/iso8608_class_a_50kmh.yaml"));
  const std::string out = (dir.path() / "out").string();
  const auto run = run_cli("diagnose " + model + " " + arguments + " -o " + out);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find(GetParam().expected), std::string::npos) << run.output;
  EXPECT_FALSE(std::filesystem::exists(out)) << "an output folder was made";
}

INSTANTIATE_TEST_SUITE_P(
    Cases, DiagnoseBadInput,
    ::testing::Values(
        BadDiagnosis{"NoAccelerationChannel", "{bare}", "no body_acc or wheel_acc column"},
        BadDiagnosis{"ExcitationLongerThanRecord", "{roadless} --excitation {long_road}",
                     "the excitation lasts 60 s but the record"},
        BadDiagnosis{"UnknownEffect", "{record} --effects tyre_damping,gas_spring",
                     "unknown effect 'gas_spring'; the library has: bump_stop"},
        BadDiagnosis{"ThreeRecords", "{record} {record} {record}", "give one record"},
        BadDiagnosis{"BandAboveNyquist", "{record} --band 0.5,150", "Nyquist"},
        BadDiagnosis{"BandInverted", "{record} --band 30,0.5", "LOW < HIGH"},
        BadDiagnosis{"RecordsWithDifferentChannels", "{record} {wheel_only}",
                     "hold different channels"},
        BadDiagnosis{"UnknownFreeParameter", "{record} --free damping", "'damping' is not"},
        BadDiagnosis{"RecordTooShortForItsSegments", "{record} --segment 8",
                     "fewer than two 8 s segments"},
        BadDiagnosis{"ExcitationCountMismatch",
                     "{record} {record} --excitation {long_road} --excitation {long_road} "
                     "--excitation {long_road}",
                     "one for all records or one per record"}),
    [](const ::testing::TestParamInfo<BadDiagnosis>& param_info) { return param_info.param.name; });

TEST(DiagnoseCli, OutputFolderMayNotBeAnInput) {
  testing::TempDir dir("ridefit_diagnose_cli");
  const std::string model = dataset("vehicles/passat_b8_front.yaml");
  const std::string record = simulate_record(dir, "record.csv", model);
  const auto run = run_cli("diagnose " + model + " " + record + " -o " + record);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("that is an input"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace ridefit
