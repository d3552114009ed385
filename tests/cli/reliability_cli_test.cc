// Issue 16 on the command line: nothing a user owns is overwritten (outputs against inputs and
// each other, output folders, journals), empty or degenerate data is refused (exit 2 naming the
// file and channel), and messages point at what the user gave.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "support/cli_runner.h"
#include "support/passat.h"
#include "support/temp_dir.h"

namespace ridefit {
namespace {

namespace fs = std::filesystem;
using testing::dataset;
using testing::run_cli;
using testing::TempDir;
using testing::text_of;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// A strut rig spec for generate-hidden (4 s at 500 Hz: quick).
std::string rig_spec(const std::string& name = "gas",
                     const std::string& rig =
                         "{amplitudes_mm: [3, 1.5], frequencies_Hz: [0.7, "
                         "2.3]}",
                     const std::string& rate = "500") {
  return "  - name: " + name +
         "\n    kind: strut_rig\n    model: " + dataset("vehicles/passat_b8_front.yaml") +
         "\n    set: {gas_stiffness_N_per_m: 15000}\n    effects: [gas_force]\n    rig: " + rig +
         "\n    duration_s: 4\n    sample_rate_Hz: " + rate + "\n    seed: 9\n";
}

// A vehicle record: 60 s at 100 Hz, a moving road and the given accelerations.
std::string vehicle_record(const TempDir& dir, const std::string& name, double body_scale,
                           double wheel_scale, double road_scale = 0.01) {
  std::string text = "time[s],road[m],body_acc[m/s^2],wheel_acc[m/s^2]\n";
  for (int k = 0; k <= 6000; ++k) {
    const double t = k / 100.0;
    const double s = std::sin(2.0 * M_PI * 1.3 * t) + 0.5 * std::sin(2.0 * M_PI * 11.0 * t + 1.0);
    text += std::to_string(t) + "," + std::to_string(road_scale * s) + "," +
            std::to_string(body_scale * s) + "," + std::to_string(wheel_scale * s) + "\n";
  }
  return dir.write(name, text);
}

// 1. An output is never an input, and an output folder holding other files is refused.

TEST(ReliabilityCli, DiagnoseNeverReplacesItsModelOrARecordInsideTheOutputFolder) {
  TempDir dir("ridefit_reliability");
  fs::create_directories(dir.path() / "out");
  const std::string model_text = text_of(dataset("hidden/baselines/passat_slip.yaml"));
  const auto model = dir.write("out/model.yaml", model_text);
  const auto record = dir.write("out/report.md", text_of(dataset("hidden/baseline_only.csv")));
  const auto run = run_cli("diagnose " + model + " " + dataset("hidden/baseline_only.csv") +
                           " -o " + (dir.path() / "out").string() + " -q");
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_TRUE(contains(run.output, "one of its inputs")) << run.output;
  EXPECT_EQ(text_of(model), model_text);
  // A record named like the report: refused as well, even with --force.
  const auto forced = run_cli("diagnose " + dataset("hidden/baselines/passat_slip.yaml") + " " +
                              record + " -o " + (dir.path() / "out").string() + " -q --force");
  EXPECT_EQ(forced.exit_code, 2) << forced.output;
  EXPECT_TRUE(contains(forced.output, "report.md")) << forced.output;
  EXPECT_EQ(text_of(model), model_text);
}

TEST(ReliabilityCli, DiagnoseRefusesAFolderHoldingOtherFilesUnlessForced) {
  TempDir dir("ridefit_reliability");
  dir.write("notes.txt", "mine");
  const auto run =
      run_cli("diagnose " + dataset("hidden/baselines/passat_slip.yaml") + " " +
              dataset("hidden/baseline_only.csv") + " -o " + dir.path().string() + " -q");
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_TRUE(contains(run.output, "notes.txt")) << run.output;
  EXPECT_TRUE(contains(run.output, "--force")) << run.output;
  EXPECT_EQ(text_of(dir.path() / "notes.txt"), "mine");
  EXPECT_FALSE(fs::exists(dir.path() / "report.md"));
}

TEST(ReliabilityCli, GenerateHiddenNeverReplacesItsSpecAndRefusesTwoDatasetsOfOneName) {
  TempDir dir("ridefit_reliability");
  const std::string spec_text = "datasets:\n" + rig_spec();
  const auto spec = dir.write("gas_truth.yaml", spec_text);
  const auto run = run_cli("generate-hidden " + spec + " -o " + dir.path().string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_TRUE(contains(run.output, "gas_truth.yaml")) << run.output;
  EXPECT_EQ(text_of(spec), spec_text);
  const auto twice = dir.write("twice.yaml", "datasets:\n" + rig_spec() + rig_spec());
  const auto out = (dir.path() / "twice").string();
  const auto run2 = run_cli("generate-hidden " + twice + " -o " + out);
  EXPECT_EQ(run2.exit_code, 2) << run2.output;
  EXPECT_TRUE(contains(run2.output, "'gas' is also the name of dataset 1")) << run2.output;
  EXPECT_FALSE(fs::exists(fs::path(out) / "gas.csv"));
}

TEST(ReliabilityCli, GenerateHiddenRewritesItsOwnFolderAndWritesBesideOtherFilesOnlyWithForce) {
  TempDir dir("ridefit_reliability");
  const auto spec = dir.write("spec.yaml", "datasets:\n" + rig_spec());
  const auto out = dir.path() / "out";
  ASSERT_EQ(run_cli("generate-hidden " + spec + " -o " + out.string()).exit_code, 0);
  // Its own earlier output (listed in the folder's manifest) is replaced.
  const auto again = run_cli("generate-hidden " + spec + " -o " + out.string());
  EXPECT_EQ(again.exit_code, 0) << again.output;
  std::ofstream(out / "mine.csv") << "time[s],x[m]\n0,1\n";
  const auto refused = run_cli("generate-hidden " + spec + " -o " + out.string());
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_TRUE(contains(refused.output, "mine.csv")) << refused.output;
  const auto forced = run_cli("generate-hidden " + spec + " -o " + out.string() + " --force");
  EXPECT_EQ(forced.exit_code, 0) << forced.output;
  EXPECT_EQ(text_of(out / "mine.csv"), "time[s],x[m]\n0,1\n");
  EXPECT_TRUE(fs::exists(out / "gas_truth.yaml"));
}

TEST(ReliabilityCli, FrictionStudyRefusesTwoExcitationsOfOneStemAndAFolderHoldingOtherFiles) {
  TempDir dir("ridefit_reliability");
  dir.write("notes.txt", "mine");
  const auto run = run_cli("friction-study " + dataset("vehicles/passat_b8_front.yaml") + " " +
                           dataset("excitations/sweep_2mm.yaml") + " --coulomb-forces 0,30 -o " +
                           dir.path().string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_TRUE(contains(run.output, "notes.txt")) << run.output;
  EXPECT_FALSE(fs::exists(dir.path() / "sweep_2mm_psd.csv"));
}

TEST(ReliabilityCli, ARecordGivenTwiceIsRefusedByFitAndDiagnose) {
  TempDir dir("ridefit_reliability");
  const std::string record = dataset("hidden/baseline_only.csv");
  const auto diagnose = run_cli("diagnose " + dataset("hidden/baselines/passat_slip.yaml") + " " +
                                record + " " + record + " -q -o " + (dir.path() / "d").string());
  EXPECT_EQ(diagnose.exit_code, 2) << diagnose.output;
  EXPECT_TRUE(contains(diagnose.output, "given twice")) << diagnose.output;
  const std::string loop = dataset("lab/shim_0mm.csv");
  const auto fit = run_cli("fit hysteresis " + loop + " " + loop + " --model " +
                           dataset("vehicles/passat_b8_front.yaml") + " --free coulomb_force_N");
  EXPECT_EQ(fit.exit_code, 2) << fit.output;
  EXPECT_TRUE(contains(fit.output, "given twice")) << fit.output;
}

// 3. A folder is replaced as a whole: a run killed midway leaves the earlier run's folder.

TEST(ReliabilityCli, AKilledRunLeavesTheEarlierFolderWholeAndTheNextRunTidiesUp) {
  TempDir dir("ridefit_reliability");
  const auto quick = dir.write("quick.yaml", "datasets:\n" + rig_spec());
  const auto out = dir.path() / "out";
  ASSERT_EQ(run_cli("generate-hidden " + quick + " -o " + out.string()).exit_code, 0);
  const std::string before = text_of(out / "gas.csv");
  // A longer run into the same folder, killed (SIGKILL) once it has written its first record.
  std::string slow_text = "datasets:\n" + rig_spec();
  slow_text.replace(slow_text.find("duration_s: 4"), 13, "duration_s: 40");
  slow_text.replace(slow_text.find("seed: 9"), 7, "seed: 10\n    records: 6");
  const auto slow = dir.write("slow.yaml", slow_text);
  const pid_t pid = fork();
  if (pid == 0) {
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, 1);
    dup2(null, 2);
    execl(RIDEFIT_CLI, RIDEFIT_CLI, "generate-hidden", slow.c_str(), "-o", out.c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  const fs::path staged = dir.path() / (".out.tmp" + std::to_string(pid));
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!fs::exists(staged / "gas.csv") && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run finished before it could be killed";
  // The folder is the earlier run's, whole: no new record beside old ones.
  EXPECT_EQ(text_of(out / "gas.csv"), before);
  EXPECT_FALSE(fs::exists(out / "gas_3.csv"));
  // The next run removes what the killed one left and writes its folder.
  ASSERT_EQ(run_cli("generate-hidden " + quick + " -o " + out.string()).exit_code, 0);
  EXPECT_FALSE(fs::exists(staged));
  EXPECT_EQ(text_of(out / "gas.csv"), before);
}

// 2. -o and --plot naming one file.

TEST(ReliabilityCli, OutputAndPlotNamingOneFileAreRefusedByEveryCommand) {
  TempDir dir("ridefit_reliability");
  const auto same = (dir.path() / "same.png").string();
  const std::string commands[] = {
      "sweep " + dataset("studies/seed001_speed.yaml") + " -o " + same + " --plot " + same,
      "fit hysteresis " + dataset("lab/triangle_3mm_1mmps.csv") + " --model " +
          dataset("vehicles/passat_b8_front.yaml") + " --free coulomb_force_N -o " + same +
          " --plot " + same,
      "fit psd " + dataset("hidden/baseline_only.csv") + " --model " +
          dataset("hidden/baselines/passat_slip.yaml") + " --free damping_Ns_per_m -o " + same +
          " --plot " + same,
      "optimise " + dataset("studies/passat_damper_tuning.yaml") + " -o " + same + " --plot " +
          same,
  };
  for (const auto& command : commands) {
    const auto run = run_cli(command);
    EXPECT_EQ(run.exit_code, 2) << command << "\n" << run.output;
    EXPECT_TRUE(contains(run.output, "give each output its own path")) << command << run.output;
    EXPECT_FALSE(fs::exists(same)) << command;
  }
}

TEST(ReliabilityCli, PerFileFitModelsNeverReplaceARecord) {
  TempDir dir("ridefit_reliability");
  // -o fit.csv with per-file Fc writes fit_<record stem>.csv: here that is the second record.
  const auto a = dir.write("a.csv", text_of(dataset("lab/shim_0mm.csv")));
  const std::string b_text = text_of(dataset("lab/shim_2mm.csv"));
  const auto b = dir.write("fit_a.csv", b_text);
  const auto run = run_cli(
      "fit hysteresis " + a + " " + b + " --model " + dataset("vehicles/passat_b8_front.yaml") +
      " --free coulomb_force_N --per-file coulomb_force_N -o " + (dir.path() / "fit.csv").string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_TRUE(contains(run.output, "input")) << run.output;
  EXPECT_EQ(text_of(b), b_text);
}

// 4. The journal.

TEST(ReliabilityCli, OptimiseRefusesToReplaceAJournalOfAnUnfinishedRunUnlessForced) {
  TempDir dir("ridefit_reliability");
  const std::string journal_text =
      "{\"format\":\"ridefit-optimise-journal-1\",\"study\":\"x\"}\n"
      "{\"variant\":\"study/search\",\"x\":[1000],\"cases\":[[1]],\"frequency_domain\":[false]}\n";
  const auto journal = dir.write("run.journal", journal_text);
  const auto study = dir.write(
      "study.yaml",
      "model: " + dataset("vehicles/passat_b8_front.yaml") +
          "\ndesign:\n  - {parameter: damping_Ns_per_m, lower: 300, upper: 6000}\nload_cases:\n"
          "  - {name: smooth, road: " +
          dataset("excitations/iso8608_class_a_50kmh.yaml") +
          "}\nobjective: {metric: body_acc_wk_rms_m_per_s2}\nevaluation: {duration_s: 10}\n"
          "friction_cost: false\n");
  const auto run = run_cli("optimise " + study + " -q --journal " + journal);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_TRUE(contains(run.output, "1 evaluations")) << run.output;
  EXPECT_TRUE(contains(run.output, "--force")) << run.output;
  EXPECT_EQ(text_of(journal), journal_text);
}

// 6. Empty and degenerate data.

TEST(ReliabilityCli, ZeroAccelerationsAndAStillRoadAreRefusedNamingFileAndChannel) {
  TempDir dir("ridefit_reliability");
  const auto zero = vehicle_record(dir, "zero.csv", 0.0, 0.0);
  const auto still = vehicle_record(dir, "still.csv", 1.0, 3.0, 0.0);
  const std::string model = dataset("hidden/baselines/passat_slip.yaml");
  for (const std::string& command :
       {"fit psd " + zero + " --model " + model + " --free damping_Ns_per_m",
        "diagnose " + model + " " + zero + " -q -o " + (dir.path() / "d").string()}) {
    const auto run = run_cli(command);
    EXPECT_EQ(run.exit_code, 2) << command << "\n" << run.output;
    EXPECT_TRUE(contains(run.output, "zero.csv: channel body_acc carries no signal")) << run.output;
    EXPECT_FALSE(contains(run.output, "nan")) << run.output;
  }
  const auto road = run_cli("fit psd " + still + " --model " + model + " --free damping_Ns_per_m");
  EXPECT_EQ(road.exit_code, 2) << road.output;
  EXPECT_TRUE(contains(road.output, "still.csv: channel road carries no signal")) << road.output;
  EXPECT_FALSE(fs::exists(dir.path() / "d" / "report.md"));
}

TEST(ReliabilityCli, AnalyseRefusesConstantData) {
  TempDir dir("ridefit_reliability");
  std::string text = "time[s],body_acc[m/s^2]\n";
  for (int k = 0; k <= 4000; ++k) text += std::to_string(k / 200.0) + ",9.81\n";
  const auto file = dir.write("constant.csv", text);
  const auto run = run_cli("analyse " + file);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_TRUE(contains(run.output, "constant.csv")) << run.output;
  EXPECT_TRUE(contains(run.output, "body_acc")) << run.output;
  const auto asked = run_cli("analyse " + file + " --channel body_acc");
  EXPECT_EQ(asked.exit_code, 2) << asked.output;
  EXPECT_TRUE(contains(asked.output, "constant.csv: channel body_acc carries no signal"))
      << asked.output;
}

TEST(ReliabilityCli, ARigTestThatDidNotMoveIsRefused) {
  TempDir dir("ridefit_reliability");
  std::string text = "time[s],displacement[mm],force[N]\n";
  for (int k = 0; k <= 2000; ++k) text += std::to_string(k / 100.0) + ",0,12.5\n";
  const auto file = dir.write("still.csv", text);
  const auto run = run_cli("fit hysteresis " + file + " --model " +
                           dataset("vehicles/passat_b8_front.yaml") + " --free coulomb_force_N");
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_TRUE(contains(run.output, "still.csv: channel displacement carries no signal"))
      << run.output;
}

// 7. Too few output samples, a rate beyond the solver.

TEST(ReliabilityCli, SimulateNeedsTwoOutputSamplesAndARateTheSolverResolves) {
  TempDir dir("ridefit_reliability");
  const auto out = (dir.path() / "out.csv").string();
  const std::string base = "simulate " + dataset("vehicles/passat_b8_front.yaml") + " " +
                           dataset("excitations/sweep_2mm.yaml") + " -o " + out;
  const auto one = run_cli(base + " --rate 0.1 --duration 2");
  EXPECT_EQ(one.exit_code, 2) << one.output;
  EXPECT_TRUE(contains(one.output, "at least two")) << one.output;
  // 1 MHz over 0.01 s is only 10001 samples (the memory limit does not apply): the rate is refused.
  const auto fast = run_cli(base + " --rate 1e6 --duration 0.01");
  EXPECT_EQ(fast.exit_code, 2) << fast.output;
  EXPECT_TRUE(contains(fast.output, "--rate")) << fast.output;
  EXPECT_FALSE(fs::exists(out));
}

// 8. Aliasing.

TEST(ReliabilityCli, GenerateHiddenRefusesFrequenciesAtOrAboveNyquist) {
  TempDir dir("ridefit_reliability");
  const auto spec = dir.write("spec.yaml", "datasets:\n" + rig_spec("gas",
                                                                    "{amplitudes_mm: [1], "
                                                                    "frequencies_Hz: [400]}"));
  const auto run = run_cli("generate-hidden " + spec + " -o " + (dir.path() / "o").string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_TRUE(contains(run.output, "Nyquist")) << run.output;
  EXPECT_TRUE(contains(run.output, "frequencies_Hz")) << run.output;
  EXPECT_FALSE(fs::exists(dir.path() / "o" / "gas.csv"));
  // A vehicle dataset driven by a sweep up to 30 Hz, recorded at 50 Hz.
  const auto sweep = dir.write(
      "sweep.yaml",
      "datasets:\n  - name: lift\n    model: " + dataset("hidden/baselines/passat_slip.yaml") +
          "\n    excitation: " + dataset("excitations/sweep_2mm.yaml") +
          "\n    duration_s: 4\n    sample_rate_Hz: 50\n");
  const auto vehicle = run_cli("generate-hidden " + sweep + " -o " + (dir.path() / "v").string());
  EXPECT_EQ(vehicle.exit_code, 2) << vehicle.output;
  EXPECT_TRUE(contains(vehicle.output, "sweeps up to 30 Hz")) << vehicle.output;
}

// 9. Duplicate forces.

TEST(ReliabilityCli, FrictionStudyRefusesARepeatedForceBeforeRunning) {
  TempDir dir("ridefit_reliability");
  const auto run = run_cli("friction-study " + dataset("vehicles/passat_b8_front.yaml") + " " +
                           dataset("excitations/sweep_2mm.yaml") + " --coulomb-forces 10,10.0 -o " +
                           (dir.path() / "o").string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_TRUE(contains(run.output, "10 N is given twice")) << run.output;
  EXPECT_FALSE(contains(run.output, "cases")) << "ran before refusing: " << run.output;
}

// 10. A bound on a fixed parameter.

TEST(ReliabilityCli, FitHysteresisRefusesABoundOnAParameterItDoesNotFit) {
  const auto run = run_cli("fit hysteresis " + dataset("lab/triangle_3mm_1mmps.csv") + " --model " +
                           dataset("vehicles/passat_b8_front.yaml") +
                           " --free coulomb_force_N --bounds damping_Ns_per_m=1:5");
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_TRUE(contains(run.output, "damping_Ns_per_m is not fitted")) << run.output;
}

// 11 and 12. Messages that point at what the user gave.

std::string study_with_design(const TempDir& dir, const std::string& parameter,
                              const std::string& extra = "") {
  return dir.write("study.yaml", "model: " + dataset("vehicles/passat_b8_front.yaml") +
                                     "\ndesign:\n  - {parameter: " + parameter +
                                     ", lower: 300, upper: 6000" + extra +
                                     "}\nload_cases:\n  - {name: smooth, road: " +
                                     dataset("excitations/iso8608_class_a_50kmh.yaml") +
                                     "}\nobjective: {metric: body_acc_wk_rms_m_per_s2}\n");
}

TEST(ReliabilityCli, OptimiseNamesAMisspeltDesignParameterAsUnknownWithTheClosestNames) {
  TempDir dir("ridefit_reliability");
  for (const std::string& extra : {std::string(), std::string(", start: 1000")}) {
    const auto run = run_cli("optimise " + study_with_design(dir, "damping_Ns_per_mm", extra));
    EXPECT_EQ(run.exit_code, 2) << run.output;
    EXPECT_TRUE(contains(run.output, "unknown parameter 'damping_Ns_per_mm'")) << run.output;
    EXPECT_TRUE(contains(run.output, "closest: damping_Ns_per_m")) << run.output;
  }
}

TEST(ReliabilityCli, SweepNamesTheClosestKeysOfAMisspeltAxisParameter) {
  TempDir dir("ridefit_reliability");
  const auto study = dir.write(
      "study.yaml", "model: " + dataset("vehicles/ajayi_half_car.yaml") +
                        "\nroads:\n  smooth: " + dataset("excitations/smooth_road_seed001.yaml") +
                        "\nvary:\n  - {parameter: front.dampng_Ns_per_m, values: [1000, 2000]}\n");
  const auto run = run_cli("sweep " + study);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_TRUE(contains(run.output, "closest: front.damping_Ns_per_m")) << run.output;
}

TEST(ReliabilityCli, LibraryMessagesDoNotNameFlagsTheCommandDoesNotHave) {
  TempDir dir("ridefit_reliability");
  const auto run = run_cli("optimise " + study_with_design(dir, "damper_state", ", start: 1000"));
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_FALSE(contains(run.output, "--set")) << run.output;
  EXPECT_FALSE(contains(run.output, "--damper-state")) << run.output;
  EXPECT_TRUE(contains(run.output, "damper_state")) << run.output;
  // generate-hidden: an unknown key under set: is located in the spec file.
  const auto spec = dir.write(
      "spec.yaml",
      "datasets:\n  - name: lift\n    model: " + dataset("hidden/baselines/passat_slip.yaml") +
          "\n    set: {tyre_lift_of: 1}\n    excitation: " +
          dataset("hidden/roads/iso8608_class_d_50kmh_30s.yaml") +
          "\n    duration_s: 4\n    sample_rate_Hz: 200\n");
  const auto hidden = run_cli("generate-hidden " + spec + " -o " + (dir.path() / "o").string());
  EXPECT_EQ(hidden.exit_code, 2) << hidden.output;
  EXPECT_FALSE(contains(hidden.output, "command line")) << hidden.output;
  EXPECT_TRUE(contains(hidden.output, spec)) << hidden.output;
  // simulate still names its own flag.
  const auto simulate =
      run_cli("simulate " + dataset("vehicles/passat_b8_front.yaml") + " " +
              dataset("excitations/sweep_2mm.yaml") + " --set damper_state=1 --duration 0.1");
  EXPECT_EQ(simulate.exit_code, 2) << simulate.output;
  EXPECT_TRUE(contains(simulate.output, "--damper-state")) << simulate.output;
}

TEST(ReliabilityCli, SweepNamesTheFileAndKeysWhenSettlingLeavesNothing) {
  TempDir dir("ridefit_reliability");
  const auto study = dir.write(
      "study.yaml", "model: " + dataset("vehicles/ajayi_half_car.yaml") +
                        "\nroads:\n  smooth: " + dataset("excitations/smooth_road_seed001.yaml") +
                        "\nmethod: time\ntime: {settle_s: 5, "
                        "duration_s: 3}\n");
  const auto run = run_cli("sweep " + study);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_TRUE(contains(run.output, study)) << run.output;
  EXPECT_TRUE(contains(run.output, "settle_s")) << run.output;
  EXPECT_TRUE(contains(run.output, "duration_s")) << run.output;
}

}  // namespace
}  // namespace ridefit

namespace ridefit {
namespace {

// Found by tools/fuzz: a model file holding only a comma hung `modes` (yaml-cpp's LoadAll), and
// `modes` printed its table header before reading the model.
TEST(ReliabilityCli, ACommaModelIsAMessageAndModesPrintsNothingBeforeIt) {
  TempDir dir("reliability_comma");
  const std::string model = (dir.path() / "comma.yaml").string();
  std::ofstream(model) << "- sprung_mass_kg\n,\n";
  const testing::CliRun run = run_cli("modes " + model);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(contains(run.output, "comma.yaml:2:1: not valid YAML")) << run.output;
  EXPECT_FALSE(contains(run.output, "natural[Hz]")) << "a table header before the error";
}

}  // namespace
}  // namespace ridefit
