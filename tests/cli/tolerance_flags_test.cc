// Every integrator tolerance flag refuses what no integrator accepts (0, negative, above 0.1,
// not a number) with exit code 2 and a message naming the flag, before any work or output.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/cli_runner.h"
#include "support/passat.h"
#include "support/temp_dir.h"

namespace ridefit {
namespace {

using testing::dataset;
using testing::run_cli;

TEST(ToleranceFlags, OutOfRangeIsRefusedWithExitCode2AndNoOutput) {
  testing::TempDir dir("ridefit_tolerance_flags");
  const std::string model = dataset("vehicles/passat_b8_front.yaml");
  const std::string out = (dir.path() / "out.csv").string();
  const std::string commands[] = {
      "simulate " + model + " " + dataset("excitations/iso8608_class_a_50kmh.yaml") + " -o " + out +
          " --rtol ",
      "fit hysteresis " + dataset("lab/triangle_3mm_1mmps.csv") + " --model " + model +
          " --free coulomb_force_N -o " + out + " --rtol ",
      "fit psd " + dataset("hidden/damper_friction.csv") + " --model " + model +
          " --free coulomb_force_N -o " + out + " --rtol ",
      "diagnose " + model + " " + dataset("hidden/damper_friction.csv") + " -o " +
          (dir.path() / "d").string() + " --rtol ",
      "diagnose " + model + " " + dataset("hidden/damper_friction.csv") + " -o " +
          (dir.path() / "d").string() + " --screening-rtol ",
  };
  for (const std::string& command : commands) {
    for (const char* value : {"0", "-1e-6", "0.2", "abc"}) {
      const auto run = run_cli(command + value);
      EXPECT_EQ(run.exit_code, 2) << command << value << "\n" << run.output;
      EXPECT_NE(run.output.find("rtol"), std::string::npos) << run.output;
      EXPECT_NE(run.output.find("(0, 0.1]"), std::string::npos) << run.output;
    }
  }
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "d"));
}

}  // namespace
}  // namespace ridefit
