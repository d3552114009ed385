// `ridefit batch` in one process: the summary and the job folders, a failed record among good
// ones, the numbers of the single commands, re-runs into the same folder, and bad job files
// (exit 2 before anything runs, nothing written). The runs over ranks: tests/mpi/.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_runner.h"
#include "support/passat.h"
#include "support/temp_dir.h"

namespace ridefit {
namespace {

namespace fs = std::filesystem;
using testing::dataset;
using testing::run_cli;
using testing::text_of;

const char* kFree = "dahl_sigma0_N_per_m,coulomb_force_N,dahl_exponent,force_offset_N";

// Fits of the shipped shim rig tests (3 triangle cycles each, a fraction of a second a fit).
std::string shim_jobs(const std::string& jobs) {
  return "defaults:\n"
         "  command: fit hysteresis\n"
         "  model: " +
         dataset("lab/passat_strut_datasheet.yaml") +
         "\n"
         "  options: {free: [dahl_sigma0_N_per_m, coulomb_force_N, dahl_exponent, force_offset_N], "
         "interpolation: linear}\n"
         "jobs:\n" +
         jobs;
}

nlohmann::json json_of(const fs::path& path) { return nlohmann::json::parse(text_of(path)); }

// The CSV's rows as fields (no quoted commas in the fields compared here).
std::vector<std::vector<std::string>> csv_rows(const fs::path& path) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream text(text_of(path));
  for (std::string line; std::getline(text, line);) {
    std::vector<std::string> fields;
    std::istringstream in(line);
    for (std::string field; std::getline(in, field, ',');) fields.push_back(field);
    rows.push_back(fields);
  }
  return rows;
}

TEST(BatchCli, FailedRecordIsReportedAndTheOthersComplete) {
  testing::TempDir dir("ridefit_batch_cli");
  dir.write("garbage.csv", "time[s],displacement[mm],force[N]\n0,1,2\nnot,a,number\n");
  const auto jobs = dir.write("jobs.yaml", shim_jobs("  - records: " + dataset("lab/shim_*.csv") +
                                                     "\n"
                                                     "  - record: garbage.csv\n"
                                                     "    name: broken\n"));
  const auto out = dir.path() / "out";
  const auto run = run_cli("batch " + jobs + " -o " + out.string() + " -q");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("1 of 4 jobs failed"), std::string::npos) << run.output;

  const auto rows = csv_rows(out / "summary.csv");
  ASSERT_EQ(rows.size(), 5u) << text_of(out / "summary.csv");
  EXPECT_EQ(rows[0][0], "job[1]");
  const std::vector<std::string> names = {"shim_0mm", "shim_2mm", "shim_4mm", "broken"};
  for (std::size_t i = 0; i < names.size(); ++i) {
    EXPECT_EQ(rows[i + 1][1], names[i]);
    EXPECT_EQ(rows[i + 1][2], "fit hysteresis");
    EXPECT_EQ(rows[i + 1][4], i < 3 ? "ok" : "failed");
  }
  // Truths 40 and 60 N, less the held data-sheet damping's 0.31 N (docs/fitting.md).
  EXPECT_NE(rows[1][5].find("coulomb_force_N=39.69"), std::string::npos) << rows[1][5];
  EXPECT_NE(rows[3][5].find("coulomb_force_N=59.70"), std::string::npos) << rows[3][5];

  const auto summary = json_of(out / "summary.json");
  EXPECT_EQ(summary["ok"], 3);
  EXPECT_EQ(summary["failed"], 1);
  EXPECT_EQ(summary["not_run"], 0);
  const auto& broken = summary["jobs"][3];
  EXPECT_EQ(broken["status"], "failed");
  EXPECT_NE(broken["message"].get<std::string>().find("garbage.csv: row 3"), std::string::npos)
      << broken["message"];
  const auto& shim = summary["jobs"][0];
  EXPECT_LT(shim["nrmse_percent"].get<double>(), 3.0);
  ASSERT_EQ(shim["parameters"].size(), 4u);  // σ0, Fc, d, offset
  EXPECT_EQ(shim["parameters"][1]["name"], "coulomb_force_N");
  EXPECT_GT(shim["parameters"][1]["standard_error"].get<double>(), 0.0);
  EXPECT_GE(shim["wall_time_s"].get<double>(), 0.0);

  for (const auto& name : {"shim_0mm", "shim_2mm", "shim_4mm"}) {
    EXPECT_TRUE(fs::exists(out / name / "model.yaml")) << name;
    EXPECT_TRUE(fs::exists(out / name / "result.json")) << name;
  }
  EXPECT_FALSE(fs::exists(out / "broken"));

  // Again into the same folder: its own files are replaced; --json prints the summary.
  const auto again = run_cli("batch " + jobs + " -o " + out.string() + " --json");
  EXPECT_EQ(again.exit_code, 1) << again.output;
  const auto printed = nlohmann::json::parse(again.output.substr(0, again.output.rfind('}') + 1));
  EXPECT_EQ(printed["jobs"].size(), 4u);
  EXPECT_EQ(printed["ok"], 3);
}

TEST(BatchCli, AJobThatNowFailsKeepsNoOldResults) {
  testing::TempDir dir("ridefit_batch_cli");
  fs::copy_file(dataset("lab/shim_0mm.csv"), dir.path() / "record.csv");
  const auto jobs = dir.write("jobs.yaml", shim_jobs("  - record: record.csv\n"));
  const auto out = dir.path() / "out";
  ASSERT_EQ(run_cli("batch " + jobs + " -o " + out.string() + " -q").exit_code, 0);
  ASSERT_TRUE(fs::exists(out / "record" / "model.yaml"));
  dir.write("record.csv", "time[s],displacement[mm],force[N]\n0,1,2\nnot,a,number\n");
  const auto run = run_cli("batch " + jobs + " -o " + out.string() + " -q");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_EQ(json_of(out / "summary.json")["jobs"][0]["status"], "failed");
  EXPECT_FALSE(fs::exists(out / "record" / "model.yaml"));
  EXPECT_FALSE(fs::exists(out / "record" / "result.json"));
}

TEST(BatchCli, JobGivesTheSingleCommandsNumbersAndFiles) {
  testing::TempDir dir("ridefit_batch_cli");
  const std::string record = dataset("lab/shim_2mm.csv");
  const auto jobs = dir.write("jobs.yaml", shim_jobs("  - record: " + record + "\n"));
  const auto out = dir.path() / "out";
  const auto run = run_cli("batch " + jobs + " -o " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("1 ok, 0 failed"), std::string::npos) << run.output;

  const auto single_model = dir.path() / "single.yaml";
  const auto single = run_cli("fit hysteresis " + record + " --model " +
                              dataset("lab/passat_strut_datasheet.yaml") + " --free " + kFree +
                              " --interpolation linear --json -o " + single_model.string());
  ASSERT_EQ(single.exit_code, 0) << single.output;
  auto expected = nlohmann::json::parse(single.output);
  expected.erase("written");  // the single command's paths
  EXPECT_EQ(json_of(out / "shim_2mm" / "result.json"), expected);
  EXPECT_EQ(text_of(out / "shim_2mm" / "model.yaml"), text_of(single_model));
  EXPECT_EQ(json_of(out / "summary.json")["jobs"][0]["parameters"][0]["value"],
            expected["parameters"][0]["value"]);
}

TEST(BatchCli, PsdFitAndDiagnosisJobs) {
  testing::TempDir dir("ridefit_batch_cli");
  const std::string model = dataset("hidden/baselines/passat_slip.yaml");
  const std::string record = dataset("hidden/baseline_only.csv");
  const auto jobs = dir.write(
      "jobs.yaml", "defaults: {model: " + model +
                       "}\n"
                       "jobs:\n"
                       "  - {record: " +
                       record +
                       ", command: fit psd, name: psd, options: {free: damping_Ns_per_m}}\n"
                       "  - record: " +
                       dataset("lab/shim_2mm.csv") +
                       "\n"
                       "    name: loops\n"
                       "    command: diagnose\n"
                       "    model: " +
                       dataset("vehicles/passat_b8_front.yaml") +
                       "\n"
                       "    options: {effects: gas_force, free: [damping_Ns_per_m, "
                       "force_offset_N, coulomb_force_N]}\n");
  const auto out = dir.path() / "out";
  const auto run = run_cli("batch " + jobs + " -o " + out.string() + " -q --threads 1");
  ASSERT_EQ(run.exit_code, 0) << run.output;

  const auto single =
      run_cli("fit psd " + record + " --model " + model + " --free damping_Ns_per_m --json");
  ASSERT_EQ(single.exit_code, 0) << single.output;
  EXPECT_EQ(json_of(out / "psd" / "result.json"), nlohmann::json::parse(single.output));
  EXPECT_TRUE(fs::exists(out / "psd" / "model.yaml"));

  for (const auto& file : {"report.md", "model.yaml", "result.json"}) {
    EXPECT_TRUE(fs::exists(out / "loops" / file)) << file;
  }
  const auto loops = json_of(out / "summary.json")["jobs"][1];
  EXPECT_EQ(loops["command"], "diagnose");
  EXPECT_EQ(loops["gap_unit"], "%");
  EXPECT_EQ(loops["gap_before"],
            json_of(out / "loops" / "result.json")["gap_before_nrmse_percent"]);
}

TEST(BatchCli, ShippedJobFileRuns) {
  testing::TempDir dir("ridefit_batch_cli");
  const auto out = dir.path() / "lab_fits";
  const auto run =
      run_cli("batch " + dataset("studies/lab_batch.yaml") + " -o " + out.string() + " -q");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("5 ok, 0 failed"), std::string::npos) << run.output;
  const auto summary = json_of(out / "summary.json");
  EXPECT_EQ(summary["jobs"][0]["name"], "triangle");
  // Truth 60 N, less the held data-sheet damping's 0.31 N (docs/fitting.md).
  EXPECT_NEAR(summary["jobs"][0]["parameters"][1]["value"].get<double>(), 59.69, 0.05);
  EXPECT_EQ(summary["jobs"][4]["command"], "diagnose");
}

// A bad job file: exit 2 naming the file, the job and the key, and nothing written.
struct BadJobs {
  const char* name;
  std::string jobs;      // the job file; {shim} is a shipped rig test
  std::string expected;  // a fragment of the message
};

class BatchBadInput : public ::testing::TestWithParam<BadJobs> {};

// Names the case in ctest's listing (gtest would print the object's bytes, which change
// from build to build).
void PrintTo(const BadJobs& c, std::ostream* os) { *os << c.name; }

TEST_P(BatchBadInput, ExitsTwoBeforeAnythingRuns) {
  testing::TempDir dir("ridefit_batch_bad");
  std::string text = GetParam().jobs;
  for (std::size_t at; (at = text.find("{shim}")) != std::string::npos;) {
    text.replace(at, 6, dataset("lab/shim_0mm.csv"));
  }
  const auto jobs = dir.write("jobs.yaml", text);
  const auto out = dir.path() / "out";
  const bool clash = text.find("out/clash/model.yaml") != std::string::npos;
  if (clash) {  // a job's input where the job's folder would be
    fs::create_directories(out / "clash");
    fs::copy_file(dataset("vehicles/passat_b8_front.yaml"), out / "clash" / "model.yaml");
  }
  const auto run = run_cli("batch " + jobs + " -o " + out.string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find(GetParam().expected), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("jobs.yaml"), std::string::npos) << run.output;
  if (clash) {
    EXPECT_FALSE(fs::exists(out / "summary.csv")) << run.output;
    EXPECT_EQ(text_of(out / "clash" / "model.yaml"),
              text_of(dataset("vehicles/passat_b8_front.yaml")));
  } else {
    EXPECT_FALSE(fs::exists(out)) << run.output;
  }
}

INSTANTIATE_TEST_SUITE_P(
    JobFiles, BatchBadInput,
    ::testing::Values(
        BadJobs{"UnknownTopKey", shim_jobs("  - record: {shim}\n") + "job: []\n",
                "unknown key 'job'"},
        BadJobs{"UnknownJobKey", shim_jobs("  - record: {shim}\n    nmae: a\n"),
                "job 1 (shim_0mm): unknown key 'nmae'"},
        BadJobs{"MissingRecord", shim_jobs("  - record: {shim}\n  - record: lab/missing.csv\n"),
                "job 2 (missing): key 'record':"},
        BadJobs{"GlobMatchesNothing", shim_jobs("  - records: lab/*.csv\n"),
                "job 1: key 'records':"},
        BadJobs{"NoRecord", shim_jobs("  - name: a\n"), "job 1 (a): give `record:`"},
        BadJobs{"DuplicateName",
                shim_jobs("  - record: {shim}\n    name: a\n  - record: {shim}\n    name: a\n"),
                "job 2 (a): key 'name': 'a' is also job 1's name"},
        BadJobs{"NameNotAFolder", shim_jobs("  - record: {shim}\n    name: ../up\n"),
                "key 'name': '../up' cannot name a folder"},
        BadJobs{"UnknownOption", shim_jobs("  - record: {shim}\n    options: {fre: [a]}\n"),
                "job 1 (shim_0mm): key 'options.fre': not an option of this command"},
        BadJobs{"BatchOption", shim_jobs("  - record: {shim}\n    options: {plot: a.png}\n"),
                "job 1 (shim_0mm): key 'options.plot': set by the batch"},
        BadJobs{"BadOptionValue",
                shim_jobs("  - record: {shim}\n    options: {interpolation: cubic}\n"),
                "job 1 (shim_0mm): options: --interpolation"},
        BadJobs{"UnknownCommand", shim_jobs("  - record: {shim}\n    command: fit loops\n"),
                "key 'jobs[1].command' is 'fit loops', expected one of"},
        BadJobs{"NoModel", "defaults: {command: diagnose}\njobs:\n  - record: {shim}\n",
                "job 1 (shim_0mm): key 'model' is missing"},
        // Found by the batch_jobs_yaml fuzzer: a name too long for the system escaped as
        // std::filesystem's error.
        BadJobs{"ModelNameTooLong",
                "defaults: {command: diagnose, model: " + std::string(300, 'm') +
                    ".yaml}\njobs:\n  - record: {shim}\n",
                "job 1 (shim_0mm): key 'model': "},
        BadJobs{"RecordNameTooLong",
                shim_jobs("  - record: {shim}\n  - record: lab/" + std::string(300, 'r') + "\n"),
                "job 2 (" + std::string(300, 'r') + "): key 'record': "},
        BadJobs{"OutputIsAnInput",
                shim_jobs("  - record: {shim}\n    name: clash\n    model: out/clash/model.yaml\n"),
                "job 1 (clash): -o " /* the folder */}),
    [](const ::testing::TestParamInfo<BadJobs>& param) { return std::string(param.param.name); });

}  // namespace
}  // namespace ridefit
