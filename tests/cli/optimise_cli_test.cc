// `ridefit optimise`: outputs, infeasibility, kill and resume, bad input.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <thread>

#include "ridefit/io/gnuplot_figure.h"
#include "ridefit/io/half_car_file.h"
#include "ridefit/io/quarter_car_file.h"
#include "support/cli_runner.h"
#include "support/passat.h"
#include "support/temp_dir.h"

namespace ridefit {
namespace {

using testing::dataset;
using testing::run_cli;
using testing::text_of;

// The Passat corner, simulated over 10 s of two roads: fast enough for a CLI test, slow enough
// (tens of ms an evaluation) to be killed midway.
std::string passat_study(
    const std::string& constraints = "[{metric: dynamic_load_ratio, max: 0.2}]",
    const std::string& extra = "friction_cost: false\n") {
  return "model: " + dataset("vehicles/passat_b8_front.yaml") +
         "\ndesign:\n"
         "  - {parameter: damping_Ns_per_m, lower: 300, upper: 6000, scale: log}\n"
         "  - {parameter: top_mount_stiffness_N_per_m, lower: 150000, upper: 1500000, scale: log}\n"
         "load_cases:\n"
         "  - {name: smooth, road: " +
         dataset("excitations/iso8608_class_a_50kmh.yaml") +
         "}\n"
         "  - {name: gravel, road: " +
         dataset("excitations/gravel_road_seed001.yaml") +
         ", speed_km_per_h: 30, weight: 2}\n"
         "objective: {metric: body_acc_wk_rms_m_per_s2}\n"
         "constraints: " +
         constraints + "\nevaluation: {duration_s: 10}\n" + extra;
}

nlohmann::json json_of(const std::string& output) {
  const auto start = output.find('{');
  return nlohmann::json::parse(output.substr(start == std::string::npos ? 0 : start));
}

TEST(OptimiseCli, WritesResultModelAndTradeoff) {
  testing::TempDir dir("ridefit_optimise_cli");
  const auto study = dir.write(
      "study.yaml",
      passat_study("[{metric: dynamic_load_ratio, max: 0.2}, {metric: travel_peak_m, max: 0.06}]",
                   "tradeoff: {metric: dynamic_load_ratio, limits: [0.19, 0.2, 0.22]}\n"));
  const std::string plot =
      io::gnuplot_available() ? " --plot " + (dir.path() / "tuning.png").string() : "";
  const auto result = dir.path() / "result.yaml";
  const auto run = run_cli("optimise " + study + " -o " + result.string() + " --json -q" + plot);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto j = json_of(run.output);
  EXPECT_EQ(j["status"], "optimum");
  const double damping = j["variables"]["damping_Ns_per_m"];
  EXPECT_GT(damping, 300.0);
  EXPECT_LT(damping, 6000.0);
  for (const auto& c : j["constraints"]) EXPECT_TRUE(c["holds"].get<bool>()) << c.dump();
  // The optimised model loads and carries the optimum.
  const auto model = io::load_quarter_car(dir.path() / "result_model.yaml");
  EXPECT_DOUBLE_EQ(model.parameters.damping_Ns_per_m, damping);
  EXPECT_DOUBLE_EQ(model.parameters.top_mount_stiffness_N_per_m,
                   j["variables"]["top_mount_stiffness_N_per_m"].get<double>());
  // Friction is in the model, so the cost of ignoring it is reported by default.
  EXPECT_GT(j["friction_cost"]["blind_objective_with_friction"].get<double>(),
            j["objective"]["value"].get<double>());
  // The trade-off: three limits, comfort never worse for a looser limit.
  const auto& points = j["tradeoff"]["points"];
  ASSERT_EQ(points.size(), 3u);
  for (std::size_t i = 1; i < points.size(); ++i) {
    EXPECT_LE(points[i]["objective"].get<double>(),
              points[i - 1]["objective"].get<double>() * 1.002);
  }
  std::ifstream csv(dir.path() / "result_tradeoff.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("limit_dynamic_load_ratio[1],feasible[1],body_acc_wk_rms[m/s^2]", 0), 0u)
      << header;
  EXPECT_TRUE(std::filesystem::exists(result));
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "result.journal"));
  if (!plot.empty()) {
    EXPECT_GT(std::filesystem::file_size(dir.path() / "tuning.png"), 1000u);
  }
}

TEST(OptimiseCli, OptimisedModelCarriesTheStudysSettings) {
  // The half car with a slip strut at the front (linear: frequency domain) and the damper split
  // as a design variable that the model file does not have.
  testing::TempDir dir("ridefit_optimise_cli");
  const auto study =
      dir.write("study.yaml",
                "model: " + dataset("vehicles/ajayi_half_car.yaml") +
                    "\nset: {front.suspension: strut, front.damper_state: slip}\n"
                    "design:\n"
                    "  - {parameter: front.damping_Ns_per_m, lower: 300, upper: 5000, scale: log}\n"
                    "  - {parameter: rear.damping_Ns_per_m, lower: 300, upper: 5000, scale: log}\n"
                    "load_cases: [{road: " +
                    dataset("excitations/gravel_road_seed001.yaml") +
                    "}]\nobjective: {metric: seat_acc_wk_rms_m_per_s2}\n"
                    "constraints: [{metric: front_dynamic_load_ratio, max: 0.2}]\n");
  const auto run =
      run_cli("optimise " + study + " -q --json -o " + (dir.path() / "r.yaml").string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto j = json_of(run.output);
  EXPECT_EQ(j["load_cases"][0]["method"], "frequency");
  const auto model = io::load_half_car(dir.path() / "r_model.yaml");
  EXPECT_EQ(model.topology.front.suspension, model::AxleSuspension::kStrut);
  EXPECT_EQ(model.topology.front.damper_state, model::DamperState::kSlip);
  EXPECT_DOUBLE_EQ(model.parameters.front.damping_Ns_per_m,
                   j["variables"]["front.damping_Ns_per_m"].get<double>());
}

TEST(OptimiseCli, ImpossibleLimitsExitOneAndWriteNoModel) {
  testing::TempDir dir("ridefit_optimise_cli");
  const auto study =
      dir.write("study.yaml", passat_study("[{metric: dynamic_load_ratio, max: 0.01}]"));
  const auto run = run_cli("optimise " + study + " -o " + (dir.path() / "r.yaml").string() + " -q");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("INFEASIBLE"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("dynamic_load_ratio <= 0.01"), std::string::npos) << run.output;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "r_model.yaml"));
  std::ifstream result(dir.path() / "r.yaml");
  std::stringstream text;
  text << result.rdbuf();
  EXPECT_NE(text.str().find("status: infeasible"), std::string::npos) << text.str();
}

std::size_t lines_of(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::size_t n = 0;
  for (std::string line; std::getline(in, line);) ++n;
  return n;
}

TEST(OptimiseCli, KilledRunResumesToTheSameOptimumWithFewerNewEvaluations) {
  testing::TempDir dir("ridefit_optimise_cli");
  const auto study = dir.write("study.yaml", passat_study());
  const auto full = run_cli("optimise " + study + " --json -q --journal " +
                            (dir.path() / "full.journal").string());
  ASSERT_EQ(full.exit_code, 0) << full.output;
  const auto reference = json_of(full.output);
  ASSERT_GT(reference["computed_evaluations"].get<int>(), 8);

  const auto journal = dir.path() / "killed.journal";
  const pid_t pid = fork();
  if (pid == 0) {
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, 1);
    dup2(null, 2);
    execl(RIDEFIT_CLI, RIDEFIT_CLI, "optimise", study.c_str(), "--journal", journal.c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  // Kill it (SIGKILL: no chance to tidy up) once six evaluations are in the journal.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (lines_of(journal) < 7 && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run finished before it could be killed";
  const std::size_t done = lines_of(journal) - 1;
  ASSERT_GE(done, 6u);

  const auto resumed = run_cli("optimise " + study + " --json -q --resume " + journal.string());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  const auto j = json_of(resumed.output);
  // The same path, so the same optimum, bit for bit ...
  EXPECT_EQ(j["variables"], reference["variables"]);
  EXPECT_EQ(j["objective"]["value"], reference["objective"]["value"]);
  EXPECT_EQ(j["evaluations"], reference["evaluations"]);
  // ... with the finished evaluations taken from the journal instead of being repeated.
  EXPECT_GE(j["reused_evaluations"].get<int>(), static_cast<int>(done));
  EXPECT_LE(j["computed_evaluations"].get<int>() + static_cast<int>(done),
            reference["computed_evaluations"].get<int>() + 1);
}

struct BadStudy {
  std::string name;
  std::string study;
  std::string words;
};

class OptimiseBadInput : public ::testing::TestWithParam<BadStudy> {};

// Names the case in ctest's listing (gtest would print the object's bytes, which change
// from build to build).
void PrintTo(const BadStudy& c, std::ostream* os) { *os << c.name; }

TEST_P(OptimiseBadInput, ExitTwoWithAMessage) {
  testing::TempDir dir("ridefit_optimise_cli");
  const auto study = dir.write("study.yaml", GetParam().study);
  const auto run = run_cli("optimise " + study + " -q -o " + (dir.path() / "r.yaml").string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find(GetParam().words), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("study.yaml"), std::string::npos) << run.output;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "r.yaml"));
}

std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

const std::string kDamping = "{parameter: damping_Ns_per_m, lower: 300, upper: 6000, scale: log}";

INSTANTIATE_TEST_SUITE_P(
    Studies, OptimiseBadInput,
    ::testing::Values(
        BadStudy{"inverted_bounds",
                 replace(passat_study(), kDamping,
                         "{parameter: damping_Ns_per_m, lower: 6000, upper: 300}"),
                 "not below upper"},
        BadStudy{"unknown_variable",
                 replace(passat_study(), kDamping,
                         "{parameter: dampign_Ns_per_m, lower: 300, upper: 6000, start: 900}"),
                 "dampign_Ns_per_m"},
        BadStudy{"start_outside",
                 replace(passat_study(), kDamping,
                         "{parameter: damping_Ns_per_m, lower: 300, upper: 6000, start: 9000}"),
                 "outside [300, 6000]"},
        BadStudy{"unknown_metric", passat_study("[{metric: seat_acc_wk_rms_m_per_s2, max: 1}]"),
                 "unknown metric 'seat_acc_wk_rms_m_per_s2'"},
        BadStudy{"empty_load_cases",
                 replace(passat_study(), "load_cases:\n", "load_cases: []\nx_cases:\n"),
                 "load_cases' is empty"},
        BadStudy{"log_through_zero",
                 replace(passat_study(), kDamping,
                         "{parameter: damping_Ns_per_m, lower: 0, upper: 6000, scale: log}"),
                 "scale log needs lower > 0"},
        BadStudy{"value_the_model_rejects",
                 replace(passat_study(), kDamping,
                         "{parameter: damping_Ns_per_m, lower: -100, upper: 6000, start: 900}"),
                 "damping_Ns_per_m"},
        BadStudy{"both_limits", passat_study("[{metric: travel_peak_m, max: 0.1, min: 0.01}]"),
                 "exactly one of max and min"},
        BadStudy{"tradeoff_unconstrained",
                 passat_study("[{metric: dynamic_load_ratio, max: 0.2}]",
                              "tradeoff: {metric: travel_peak_m, limits: [0.01]}\n"),
                 "'travel_peak_m' is not constrained"},
        BadStudy{"unknown_algorithm",
                 passat_study("[{metric: dynamic_load_ratio, max: 0.2}]",
                              "optimiser: {algorithm: newton}\n"),
                 "newton"},
        BadStudy{"missing_road",
                 replace(passat_study(), dataset("excitations/gravel_road_seed001.yaml"),
                         "no_such_road.yaml"),
                 "no_such_road.yaml"},
        BadStudy{"friction_without_friction_element",
                 "set: {damper_state: slip}\nfriction: {coulomb_force_N: 30}\n" + passat_study(),
                 "no friction element"},
        BadStudy{"typo_in_study", passat_study() + "objectiv: {metric: x}\n", "objectiv"},
        BadStudy{"design_key_also_in_a_case",
                 replace(passat_study(), "speed_km_per_h: 30, weight: 2}",
                         "speed_km_per_h: 30, weight: 2, set: {damping_Ns_per_m: 2000}}"),
                 "which the design variable 'damping_Ns_per_m' varies"},
        BadStudy{"settle_longer_than_the_run",
                 replace(passat_study(), "evaluation: {duration_s: 10}",
                         "evaluation: {duration_s: 10, settle_s: 20}"),
                 "evaluation.settle_s is 20 s"},
        BadStudy{"run_longer_than_the_road",
                 replace(passat_study(), "evaluation: {duration_s: 10}",
                         "evaluation: {duration_s: 100}"),
                 "evaluation.duration_s is 100 s, longer than load case 'smooth'"},
        BadStudy{"rate_too_low_for_wk",
                 replace(passat_study(), "evaluation: {duration_s: 10}",
                         "evaluation: {duration_s: 10, output_rate_Hz: 100}"),
                 "evaluation.output_rate_Hz is 100 Hz"},
        BadStudy{"load_cases_not_a_list",
                 replace(passat_study(), "load_cases:\n", "load_cases: {road: x.yaml}\nx_cases:\n"),
                 "is not a list"},
        BadStudy{"cross_rule_at_a_corner",
                 "model: " + dataset("vehicles/ajayi_half_car.yaml") +
                     "\nset: {control.law: skyhook}\ndesign:\n"
                     "  - {parameter: control.min_damping_Ns_per_m, lower: 100, upper: 2500}\n"
                     "  - {parameter: control.max_damping_Ns_per_m, lower: 500, upper: 3000}\n"
                     "load_cases: [{road: " +
                     dataset("excitations/smooth_road_seed001.yaml") +
                     "}]\nobjective: {metric: seat_acc_wk_rms_m_per_s2}\n",
                 "design corner"}),
    [](const ::testing::TestParamInfo<BadStudy>& p) { return p.param.name; });

TEST(OptimiseCli, OutputsNeverReplaceInputsOrEachOther) {
  testing::TempDir dir("ridefit_optimise_cli");
  const std::string model = text_of(dataset("vehicles/passat_b8_front.yaml"));
  const auto model_path = dir.write("car.yaml", model);
  const std::string road = text_of(dataset("excitations/iso8608_class_a_50kmh.yaml"));
  const auto road_path = dir.write("road.yaml", road);
  const auto study =
      dir.write("study.yaml",
                "model: car.yaml\ndesign: [{parameter: damping_Ns_per_m, lower: 300, upper: "
                "6000}]\nload_cases: [{road: road.yaml}]\n"
                "objective: {metric: body_acc_wk_rms_m_per_s2}\nevaluation: {duration_s: 5}\n");
  for (const std::string& flags : {"-o " + road_path, "--journal " + model_path,
                                   "-o " + (dir.path() / "r.yaml").string() + " --journal " +
                                       (dir.path() / "r.yaml").string()}) {
    const auto run = run_cli("optimise " + study + " -q " + flags);
    EXPECT_EQ(run.exit_code, 2) << flags << "\n" << run.output;
  }
  EXPECT_EQ(text_of(model_path), model);
  EXPECT_EQ(text_of(road_path), road);
  // --resume on a file that is not a journal leaves it as it was.
  const auto notes = dir.write("notes.txt", "hello world");
  EXPECT_EQ(run_cli("optimise " + study + " -q --resume " + notes).exit_code, 2);
  EXPECT_EQ(text_of(notes), "hello world");
  // A study that cannot run does not replace an existing journal.
  const auto journal = (dir.path() / "keep.journal").string();
  ASSERT_EQ(run_cli("optimise " + study + " -q --journal " + journal).exit_code, 0);
  const std::string kept = text_of(journal);
  const auto broken = dir.write(
      "broken.yaml", replace(text_of(study), "duration_s: 5", "duration_s: 5, settle_s: 30"));
  EXPECT_EQ(run_cli("optimise " + broken + " -q --journal " + journal).exit_code, 2);
  EXPECT_EQ(text_of(journal), kept);
}

TEST(OptimiseCli, PlotWithFrictionAndNoConstraints) {
  if (!io::gnuplot_available()) GTEST_SKIP() << "gnuplot not installed";
  testing::TempDir dir("ridefit_optimise_cli");
  const auto study =
      dir.write("study.yaml", replace(passat_study("[]", ""), "constraints: []\n", ""));
  const auto run = run_cli("optimise " + study + " -q -o " + (dir.path() / "r.yaml").string() +
                           " --plot " + (dir.path() / "p.png").string());
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_GT(std::filesystem::file_size(dir.path() / "p.png"), 1000u);
}

TEST(OptimiseCli, ResumeRefusesAnotherStudysJournal) {
  testing::TempDir dir("ridefit_optimise_cli");
  const auto a = dir.write("a.yaml", passat_study());
  const auto b = dir.write("b.yaml", passat_study("[{metric: dynamic_load_ratio, max: 0.25}]"));
  const auto journal = (dir.path() / "a.journal").string();
  ASSERT_EQ(run_cli("optimise " + a + " -q --journal " + journal).exit_code, 0);
  const auto run = run_cli("optimise " + b + " -q --resume " + journal);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("belongs to another study"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace ridefit
