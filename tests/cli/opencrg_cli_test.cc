// `ridefit simulate` over an OpenCRG road (type: opencrg): the shipped example drives the
// Passat corner, and a track outside the grid is bad input (exit 2, the key named, no output).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/cli_runner.h"
#include "support/passat.h"
#include "support/temp_dir.h"

namespace ridefit {
namespace {

namespace fs = std::filesystem;
using testing::CliRun;
using testing::run_cli;

TEST(OpenCrgCli, SimulatesTheShippedOpenCrgExcitation) {
  testing::TempDir dir("opencrg_cli");
  const fs::path out = dir.path() / "run.csv";
  const CliRun run = run_cli("simulate " + testing::dataset("vehicles/passat_b8_front.yaml") + " " +
                             testing::dataset("excitations/opencrg_handmade_straight.yaml") +
                             " --duration 1 --rate 200 -o " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  std::ifstream in(out);
  std::string line;
  std::size_t rows = 0;
  double peak_road_m = 0.0;
  std::getline(in, line);
  while (std::getline(in, line)) {
    ++rows;
    const std::size_t comma = line.find(',');
    peak_road_m = std::max(peak_road_m, std::stod(line.substr(comma + 1)));
  }
  EXPECT_EQ(rows, 201u);          // 1 s at 200 Hz, both ends
  EXPECT_GT(peak_road_m, 0.011);  // the grid's 11.1 mm bumps within the first 8.3 m
  EXPECT_LT(peak_road_m, 0.03);
}

TEST(OpenCrgCli, TrackOutsideTheGridIsBadInput) {
  testing::TempDir dir("opencrg_cli");
  fs::copy_file(testing::dataset("roads/opencrg/handmade_straight.crg"), dir.path() / "r.crg");
  const std::string excitation = dir.write(
      "e.yaml", "type: opencrg\nfile: r.crg\nlateral_offset_m: 1.75\nspeed_km_per_h: 30\n");
  const fs::path out = dir.path() / "run.csv";
  const CliRun run = run_cli("simulate " + testing::dataset("vehicles/passat_b8_front.yaml") + " " +
                             excitation + " -o " + out.string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("lateral_offset_m"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("e.yaml"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace ridefit
