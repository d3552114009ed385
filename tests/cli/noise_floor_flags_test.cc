// --body-noise-psd and --wheel-noise-psd on `fit psd` and `diagnose`: a level >= 0 in
// (m/s^2)^2/Hz or exit code 2 naming the flag, before any output; a given level is used as
// given, a missing one is estimated from the record.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "support/cli_runner.h"
#include "support/passat.h"
#include "support/temp_dir.h"

namespace ridefit {
namespace {

using testing::dataset;
using testing::run_cli;

TEST(NoiseFloorFlags, BadLevelsAreRefusedWithExitCode2AndNoOutput) {
  testing::TempDir dir("ridefit_noise_floor_flags");
  const std::string model = dataset("vehicles/passat_b8_front.yaml");
  const std::string out = (dir.path() / "out.yaml").string();
  const std::string commands[] = {
      "fit psd " + dataset("hidden/damper_friction.csv") + " --model " + model +
          " --free coulomb_force_N -o " + out,
      "diagnose " + model + " " + dataset("hidden/damper_friction.csv") + " -o " +
          (dir.path() / "d").string(),
  };
  for (const std::string& command : commands) {
    for (const char* flag : {"--body-noise-psd", "--wheel-noise-psd"}) {
      for (const char* value : {"-1e-6", "abc", "inf"}) {
        const auto run = run_cli(command + " " + flag + " " + value);
        EXPECT_EQ(run.exit_code, 2) << command << " " << flag << " " << value << "\n" << run.output;
        EXPECT_NE(run.output.find(flag), std::string::npos) << run.output;
        EXPECT_NE(run.output.find("noise PSD level >= 0"), std::string::npos) << run.output;
      }
    }
  }
  // A band reaching 0.45·fs leaves no room above it to estimate the floor from (200 Hz record).
  const auto run = run_cli(commands[1] + " --band 0.5,95");
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("leaves no room below the Nyquist frequency"), std::string::npos)
      << run.output;
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "d"));
}

TEST(NoiseFloorFlags, AGivenLevelIsUsedAMissingOneEstimated) {
  const auto run = run_cli("fit psd " + dataset("hidden/tyre_damping.csv") + " --model " +
                           dataset("vehicles/passat_b8_front.yaml") +
                           " --free coulomb_force_N --json --wheel-noise-psd 2.5e-6");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto j = nlohmann::json::parse(run.output.substr(run.output.find('{')));
  EXPECT_EQ(j["noise_psd"]["wheel_acc"].get<double>(), 2.5e-6);
  // Estimated from the record (0.5 % sensor noise): above zero, far below the band's levels.
  const double body = j["noise_psd"]["body_acc"].get<double>();
  EXPECT_GT(body, 0.0);
  EXPECT_LT(body, 1e-5);
}

}  // namespace
}  // namespace ridefit
