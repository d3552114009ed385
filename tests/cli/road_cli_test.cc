// `ridefit road`: the ISO 8608 class and IRI of a profile CSV; bad input is exit 2.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "support/cli_runner.h"
#include "support/temp_dir.h"

namespace ridefit {
namespace {

namespace fs = std::filesystem;
using testing::CliRun;
using testing::run_cli;

// 1 km of a 5 mm, 10 m sine plus a 1 mm, 1.5 m one, every 0.1 m.
std::string sine_profile_csv() {
  std::string csv = "distance[m],elevation[mm]\n";
  for (int k = 0; k <= 10000; ++k) {
    const double x = 0.1 * k;
    const double y = 5.0 * std::sin(2.0 * std::numbers::pi * x / 10.0) +
                     1.0 * std::sin(2.0 * std::numbers::pi * x / 1.5);
    csv += std::to_string(x) + "," + std::to_string(y) + "\n";
  }
  return csv;
}

TEST(RoadCli, PrintsClassAndIriPerSegment) {
  testing::TempDir dir("road_cli");
  const std::string profile = dir.write("profile.csv", sine_profile_csv());
  const fs::path psd = dir.path() / "psd.csv";
  const CliRun run = run_cli("road " + profile + " --segment 250 --psd " + psd.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("ISO 8608 class"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("IRI"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("750.0"), std::string::npos) << run.output;  // 4 segments of 250 m
  std::ifstream in(psd);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "spatial_frequency[cycles/m],psd[m^3],psd_lower[m^3],psd_upper[m^3]");

  const CliRun json = run_cli("road " + profile + " --json");
  ASSERT_EQ(json.exit_code, 0) << json.output;
  EXPECT_NE(json.output.find("\"iri_m_per_km\""), std::string::npos) << json.output;
  EXPECT_NE(json.output.find("\"class\""), std::string::npos) << json.output;
}

TEST(RoadCli, BadProfileIsExitTwo) {
  testing::TempDir dir("road_cli");
  const std::string reversed =
      dir.write("reversed.csv", "distance[m],elevation[m]\n0,0\n1,0\n1,0\n2,0\n3,0\n");
  CliRun run = run_cli("road " + reversed);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("distance"), std::string::npos) << run.output;

  const std::string short_profile =
      dir.write("short.csv", "distance[m],elevation[m]\n0,0\n10,0.01\n20,0\n30,0.01\n40,0\n");
  run = run_cli("road " + short_profile);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("short.csv"), std::string::npos) << run.output;

  const std::string profile = dir.write("profile.csv", sine_profile_csv());
  run = run_cli("road " + profile + " --psd " + profile);  // would overwrite its input
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("--psd"), std::string::npos) << run.output;

  run = run_cli("road " + (dir.path() / "missing.csv").string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
}

}  // namespace
}  // namespace ridefit
