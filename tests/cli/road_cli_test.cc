// `ridefit road`: the ISO 8608 class and IRI of a profile CSV or an OpenCRG track; bad input is
// exit 2.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "ridefit/io/gnuplot_figure.h"
#include "ridefit/road/opencrg_file.h"
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

double whole_iri(const CliRun& run) {
  return nlohmann::json::parse(run.output).at("iri").at("iri_m_per_km").get<double>();
}

// An OpenCRG grid (KDBI, 8-byte reals) of two long sections at v = -1 and +1 m: the track at
// v = 0.5 is 3/4 of the left one and 1/4 of the right, and `ridefit road` of the grid equals
// `ridefit road` of that track written as a CSV.
TEST(RoadCli, AnOpenCrgTrackIsEvaluatedLikeTheSameProfileAsCsv) {
  testing::TempDir dir("road_cli");
  road::CrgGrid grid;
  grid.u_increment_m = 0.1;
  grid.v_m = {-1.0, 1.0};
  std::string csv = "distance[m],elevation[m]\n";
  for (int k = 0; k <= 5000; ++k) {
    const double x = 0.1 * k;
    const double right = 0.004 * std::sin(2.0 * std::numbers::pi * x / 12.0);
    const double left = 0.002 * std::sin(2.0 * std::numbers::pi * x / 3.0 + 1.0);
    grid.z_m.insert(grid.z_m.end(), {right, left});
    csv += fmt::format("{},{}\n", x, 0.25 * right + 0.75 * left);
  }
  grid.u_end_m = 500.0;
  const fs::path crg = dir.path() / "road.crg";
  road::write_opencrg(grid, crg, road::CrgFormat::kKdbi);
  const std::string profile = dir.write("track.csv", csv);

  const CliRun from_crg = run_cli("road " + crg.string() + " --lateral-offset 0.5 --json");
  const CliRun from_csv = run_cli("road " + profile + " --json");
  ASSERT_EQ(from_crg.exit_code, 0) << from_crg.output;
  ASSERT_EQ(from_csv.exit_code, 0) << from_csv.output;
  EXPECT_NEAR(whole_iri(from_crg), whole_iri(from_csv), 1e-9 * whole_iri(from_csv));
  EXPECT_GT(whole_iri(from_crg), 0.1);

  const CliRun outside = run_cli("road " + crg.string() + " --lateral-offset 1.5");
  EXPECT_EQ(outside.exit_code, 2) << outside.output;
  EXPECT_NE(outside.output.find("outside the long sections"), std::string::npos) << outside.output;
  const CliRun csv_offset = run_cli("road " + profile + " --lateral-offset 0.5");
  EXPECT_EQ(csv_offset.exit_code, 2) << csv_offset.output;

  if (io::gnuplot_available()) {
    const fs::path figure = dir.path() / "road.png";
    const CliRun plotted = run_cli("road " + crg.string() + " --plot " + figure.string());
    ASSERT_EQ(plotted.exit_code, 0) << plotted.output;
    EXPECT_GT(fs::file_size(figure), 1000u);
  }
}

// The road channel of a simulated drive (CVODE's output at 1 kHz of a `type: profile` road at
// 72 km/h, a different path from the profile's own samples) evaluates as the profile driven.
TEST(RoadCli, AVehicleRecordsRoadChannelIsEvaluatedAtItsSpeed) {
  testing::TempDir dir("road_cli");
  const std::string profile = dir.write("profile.csv", sine_profile_csv());
  const std::string excitation =
      dir.write("drive.yaml", "type: profile\nfile: profile.csv\nspeed_km_per_h: 72\n");
  const fs::path record = dir.path() / "record.csv";
  const CliRun drive =
      run_cli(fmt::format("simulate {}/datasets/vehicles/passat_b8_front.yaml {} -o {}",
                          RIDEFIT_SOURCE_DIR, excitation, record.string()));
  ASSERT_EQ(drive.exit_code, 0) << drive.output;

  const CliRun from_record = run_cli("road " + record.string() + " --speed 72km/h --json");
  const CliRun from_profile = run_cli("road " + profile + " --json");
  ASSERT_EQ(from_record.exit_code, 0) << from_record.output;
  ASSERT_EQ(from_profile.exit_code, 0) << from_profile.output;
  EXPECT_NEAR(whole_iri(from_record), whole_iri(from_profile), 0.01 * whole_iri(from_profile));
  const auto road_class = [](const CliRun& run) {
    return nlohmann::json::parse(run.output).at("iso8608").at("class").get<std::string>();
  };
  EXPECT_EQ(road_class(from_record), road_class(from_profile));
  // The same speed in m/s.
  const CliRun in_m_per_s = run_cli("road " + record.string() + " --speed 20m/s --json");
  ASSERT_EQ(in_m_per_s.exit_code, 0) << in_m_per_s.output;
  EXPECT_DOUBLE_EQ(whole_iri(in_m_per_s), whole_iri(from_record));

  const auto refused = [](const std::string& args, const std::string& expected) {
    const CliRun run = run_cli("road " + args);
    EXPECT_EQ(run.exit_code, 2) << args << "\n" << run.output;
    EXPECT_NE(run.output.find(expected), std::string::npos) << args << "\n" << run.output;
  };
  refused(record.string(), "--speed");                        // no speed
  refused(record.string() + " --speed 72", "with its unit");  // no unit
  refused(record.string() + " --speed -3m/s", "0 < speed");   // not a speed
  refused(record.string() + " --speed 72km/h --channel body_acc", "expected a length");
  refused(record.string() + " --speed 72km/h --channel tyre", "road channel 'tyre'");
  refused(profile + " --speed 72km/h", "only to a vehicle record");  // over distance already
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
