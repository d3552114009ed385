// .mat measurements through the `ridefit` program: the shipped lab record as .mat (written by
// scipy, tools/csv_to_mat.py) gives the results of its CSV; `simulate -o out.mat` writes a file
// `analyse` reads back to the CSV's numbers; a rig record as .mat is diagnosed like its CSV; a bad
// .mat is exit 2 with the file named.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "ridefit/io/csv_table.h"
#include "ridefit/io/measurement_file.h"
#include "support/cli_runner.h"
#include "support/passat.h"

namespace ridefit {
namespace {

namespace fs = std::filesystem;
using testing::CliRun;
using testing::run_cli;

// Every number equal (to `relative`); strings equal except the file names, which differ by
// their extension.
void expect_same_results(const nlohmann::json& csv, const nlohmann::json& mat,
                         const std::string& where, double relative) {
  ASSERT_EQ(csv.type(), mat.type()) << where;
  if (csv.is_object()) {
    ASSERT_EQ(csv.size(), mat.size()) << where;
    for (const auto& [key, value] : csv.items()) {
      ASSERT_TRUE(mat.contains(key)) << where << "." << key;
      expect_same_results(value, mat[key], where + "." + key, relative);
    }
  } else if (csv.is_array()) {
    ASSERT_EQ(csv.size(), mat.size()) << where;
    for (std::size_t i = 0; i < csv.size(); ++i) {
      expect_same_results(csv[i], mat[i], where + "[" + std::to_string(i) + "]", relative);
    }
  } else if (csv.is_number()) {
    const double a = csv.get<double>();
    const double b = mat.get<double>();
    EXPECT_NEAR(a, b, relative * std::abs(a)) << where;
  } else if (csv.is_string()) {
    std::string a = csv.get<std::string>();
    const std::string b = mat.get<std::string>();
    for (std::size_t p = a.find(".csv"); p != std::string::npos; p = a.find(".csv", p)) {
      a.replace(p, 4, ".mat");
    }
    EXPECT_EQ(a, b) << where;
  } else {
    EXPECT_EQ(csv, mat) << where;
  }
}

class MatCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("ridefit_mat_cli_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static nlohmann::json json_of(const std::string& arguments) {
    const CliRun run = run_cli(arguments + " --json");
    EXPECT_EQ(run.exit_code, 0) << arguments << "\n" << run.output;
    return run.exit_code == 0 ? nlohmann::json::parse(run.output) : nlohmann::json();
  }

  fs::path dir_;
};

TEST_F(MatCli, ShippedTriangleAsMatIsFittedToTheCsvResult) {
  const std::string model = testing::dataset("vehicles/passat_b8_front.yaml");
  const std::string fit =
      " --model " + model + " --free coulomb_force_N,force_offset_N --interpolation linear";
  const auto csv =
      json_of("fit hysteresis " + testing::dataset("lab/triangle_3mm_1mmps.csv") + fit);
  const auto mat =
      json_of("fit hysteresis " + testing::dataset("lab/triangle_3mm_1mmps.mat") + fit);
  ASSERT_FALSE(csv.is_null());
  ASSERT_FALSE(mat.is_null());
  // The same doubles reach the fit (scipy stored what the CSV's text parses to).
  expect_same_results(csv, mat, "fit", 1e-9);
}

TEST_F(MatCli, ShippedTriangleAsMatIsAnalysedLikeTheCsv) {
  const auto csv = json_of("analyse " + testing::dataset("lab/triangle_3mm_1mmps.csv"));
  const auto mat = json_of("analyse " + testing::dataset("lab/triangle_3mm_1mmps.mat"));
  ASSERT_FALSE(csv.is_null());
  ASSERT_EQ(mat["recordings"][0]["channels"].size(), 2u) << mat.dump(1);
  expect_same_results(csv, mat, "analyse", 1e-12);
}

TEST_F(MatCli, SimulateWritesAMatThatAnalyseReadsLikeItsCsv) {
  const std::string sweep = (dir_ / "sweep.yaml").string();
  { std::ofstream(sweep) << "type: log_sweep\ninitial_amplitude_m: 0.002\nduration_s: 4\n"; }
  const std::string simulate =
      "simulate " + testing::dataset("vehicles/passat_b8_front.yaml") + " " + sweep;
  const fs::path csv = dir_ / "run.csv";
  const fs::path mat = dir_ / "run.mat";
  ASSERT_EQ(run_cli(simulate + " -o " + csv.string()).exit_code, 0);
  const CliRun written = run_cli(simulate + " -o " + mat.string());
  ASSERT_EQ(written.exit_code, 0) << written.output;
  const auto from_csv = json_of("analyse " + csv.string() + " --channel body_acc --channel travel");
  const auto from_mat = json_of("analyse " + mat.string() + " --channel body_acc --channel travel");
  ASSERT_FALSE(from_mat.is_null());
  // The CSV holds each double's shortest exact text: both files carry the same values.
  expect_same_results(from_csv, from_mat, "analyse", 0.0);
}

TEST_F(MatCli, RigRecordAsMatIsDiagnosedLikeItsCsv) {
  // A .mat has no header line: diagnose must still see a rig test (displacement, force).
  const fs::path mat = dir_ / "shim_0mm.mat";
  io::write_measurement_table(io::CsvTable::read(testing::dataset("lab/shim_0mm.csv")), mat);
  const std::string diagnose = "diagnose " + testing::dataset("vehicles/passat_b8_front.yaml") +
                               " --effects gas_force --threads 1 -q ";
  auto from_csv =
      json_of(diagnose + testing::dataset("lab/shim_0mm.csv") + " -o " + (dir_ / "csv").string());
  auto from_mat = json_of(diagnose + mat.string() + " -o " + (dir_ / "mat").string());
  ASSERT_FALSE(from_mat.is_null());
  EXPECT_EQ(from_mat["data"], "strut_loops");
  for (auto* j : {&from_csv, &from_mat}) {
    j->erase("model");  // the output folders differ
    j->erase("report");
  }
  expect_same_results(from_csv, from_mat, "diagnose", 1e-12);
}

TEST_F(MatCli, RoadProfileAsMatIsClassifiedLikeItsCsvAndSpectraAreWrittenAsMat) {
  const std::string csv = testing::dataset("excitations/profile_example.csv");
  const fs::path mat = dir_ / "profile_example.mat";
  io::write_measurement_table(io::CsvTable::read(csv), mat);
  const fs::path psd = dir_ / "road_psd.mat";
  const auto from_csv = json_of("road " + csv);
  const auto from_mat = json_of("road " + mat.string() + " --psd " + psd.string());
  ASSERT_FALSE(from_mat.is_null());
  auto without_files = [](nlohmann::json j) {
    j.erase("psd_file");
    j.erase("profile");  // the files' paths
    return j;
  };
  expect_same_results(without_files(from_csv), without_files(from_mat), "road", 0.0);
  const io::CsvTable spectrum = io::read_measurement_table(psd);
  EXPECT_EQ(spectrum.column("spatial_frequency").unit, "cycles/m");
  EXPECT_EQ(spectrum.column("psd").unit, "m^3");
  EXPECT_GT(spectrum.rows(), 10u);

  const fs::path analyse_psd = dir_ / "analyse_psd.mat";
  const CliRun run = run_cli("analyse " + testing::dataset("lab/triangle_3mm_1mmps.mat") +
                             " --psd " + analyse_psd.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(io::read_measurement_table(analyse_psd).column("force_psd").unit, "N^2/Hz");
}

TEST_F(MatCli, BadMatIsExitTwoNamingFileAndVariable) {
  const std::string bad = std::string(RIDEFIT_SOURCE_DIR) + "/tests/data/mat/bad_no_unit.mat";
  const fs::path psd = dir_ / "psd.csv";
  const CliRun run = run_cli("analyse " + bad + " --psd " + psd.string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find(bad + ": variable 'body_acc' has no unit"), std::string::npos)
      << run.output;
  EXPECT_FALSE(fs::exists(psd));
  const CliRun fit =
      run_cli("fit hysteresis " + bad + " --model " +
              testing::dataset("vehicles/passat_b8_front.yaml") + " --free coulomb_force_N");
  EXPECT_EQ(fit.exit_code, 2) << fit.output;
  EXPECT_NE(fit.output.find("bad_no_unit.mat"), std::string::npos) << fit.output;
}

TEST_F(MatCli, SimulateToAMatInAMissingFolderIsExitTwoAndWritesNothing) {
  const std::string sweep = (dir_ / "sweep.yaml").string();
  { std::ofstream(sweep) << "type: log_sweep\ninitial_amplitude_m: 0.002\nduration_s: 1\n"; }
  const CliRun run = run_cli("simulate " + testing::dataset("vehicles/passat_b8_front.yaml") + " " +
                             sweep + " -o " + (dir_ / "no/run.mat").string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_FALSE(fs::exists(dir_ / "no"));
}

}  // namespace
}  // namespace ridefit
