// tools/demo's steps as regression tests: each test runs the `ridefit` commands of one step of
// the demo (on the same files, with --json) and compares their key numbers with an answer file,
// tests/data/demo/STEP.yaml. An answer file holds, per command run, a list of checks:
//
//   run_name:
//     - {at: /json/pointer, value: 1.3, rtol: 0.01}          # |x − value| <= rtol·|value| + atol
//     - {at: /json/pointer, value: 0, rtol: 0.02, atol: 1e-3} # atol (default 0) for values near 0
//     - {at: /json/pointer, text: body}                      # exact: a string, true or false
//
// `at` is a JSON pointer (RFC 6901) into the command's --json output. The values come from a run
// of the build and each file says why they make physical sense; a failure prints the value found,
// so an intended change of a result is an edit of one number.
//
// DemoSteps (label cli) are the demo's quick steps, a few seconds together; DemoStepsSlow (label
// slow-cli) are the Passat tuning and the seed model's diagnosis, about a minute and half a minute.
// The demo's other diagnoses (the rig's Stribeck friction, the stick/slip chain and its tuning)
// are left out for time: tests/cli/shipped_diagnosis_test.cc runs their datasets already.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <yaml-cpp/yaml.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/passat.h"
#include "support/temp_dir.h"

namespace ridefit {
namespace {

namespace fs = std::filesystem;
using testing::dataset;

struct JsonRun {
  int exit_code = -1;
  nlohmann::json json;  // null when stdout was not JSON
  std::string output;   // stdout, then stderr
};

// Runs `ridefit ARGUMENTS --json`: stdout is the JSON summary, stderr (progress, notes) goes to
// a file in `dir` and is kept for the failure message.
JsonRun run_json(const std::string& arguments, const fs::path& dir) {
  const fs::path errors = dir / "stderr.txt";
  const std::string command =
      std::string(RIDEFIT_CLI) + " " + arguments + " --json 2>" + errors.string();
  JsonRun run;
  std::string out;
  if (FILE* pipe = popen(command.c_str(), "r")) {
    std::array<char, 4096> buffer{};
    while (fgets(buffer.data(), buffer.size(), pipe) != nullptr) out += buffer.data();
    const int status = pclose(pipe);
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  run.output = "ridefit " + arguments + "\n" + out + testing::text_of(errors);
  run.json = nlohmann::json::parse(out, nullptr, /*allow_exceptions=*/false);
  if (run.json.is_discarded()) run.json = nullptr;
  return run;
}

// Checks `run` against the checks listed under `name` in tests/data/demo/`file`.
void expect_answers(const JsonRun& run, const std::string& file, const std::string& name) {
  ASSERT_EQ(run.exit_code, 0) << run.output;
  ASSERT_TRUE(run.json.is_object()) << "no JSON on stdout:\n" << run.output;
  const std::string path = std::string(RIDEFIT_SOURCE_DIR) + "/tests/data/demo/" + file;
  const YAML::Node checks = YAML::LoadFile(path)[name];
  ASSERT_TRUE(checks && checks.IsSequence() && checks.size() > 0)
      << path << ": no checks for the run '" << name << "'";
  for (const YAML::Node& check : checks) {
    const std::string at = check["at"].as<std::string>();
    const std::string where = path + " [" + name + "] " + at;
    const nlohmann::json::json_pointer pointer(at);
    if (!run.json.contains(pointer)) {
      ADD_FAILURE() << where << ": not in the output of\n" << run.output;
      continue;
    }
    const nlohmann::json& found = run.json.at(pointer);
    if (check["text"]) {
      EXPECT_EQ(found.is_string() ? found.get<std::string>() : found.dump(),
                check["text"].as<std::string>())
          << where;
      continue;
    }
    if (!found.is_number()) {
      ADD_FAILURE() << where << ": " << found.dump() << " is not a number";
      continue;
    }
    const double value = found.get<double>();
    const double answer = check["value"].as<double>();
    const double rtol = check["rtol"].as<double>();
    const double atol = check["atol"] ? check["atol"].as<double>() : 0.0;
    EXPECT_LE(std::abs(value - answer), rtol * std::abs(answer) + atol)
        << where << ": " << value << " against the answer " << answer << " (rtol " << rtol
        << ", atol " << atol << ")";
  }
}

const std::string kPassat = dataset("vehicles/passat_b8_front.yaml");
const std::string kClassA = dataset("excitations/iso8608_class_a_50kmh.yaml");

// == Modes of the Passat corner (seed 000: slip 1.3 / 13.3 Hz, stick 3.4 / 21.4 Hz).
TEST(DemoSteps, ModesOfTheSlipAndStickModels) {
  testing::TempDir dir("ridefit_demo_steps");
  expect_answers(run_json("modes " + kPassat, dir.path()), "modes.yaml", "modes");
}

// == Friction study, seed 000 Section 3.2: Fc = 0 … 120 N on the 2 mm and 10 mm log sweeps.
TEST(DemoSteps, FrictionStudyOnTheLogSweeps) {
  testing::TempDir dir("ridefit_demo_steps");
  const auto run =
      run_json("friction-study " + kPassat + " " + dataset("excitations/sweep_2mm.yaml") + " " +
                   dataset("excitations/sweep_10mm.yaml") + " --coulomb-forces 0,12,30,60,120 -o " +
                   (dir.path() / "out").string(),
               dir.path());
  expect_answers(run, "friction_study.yaml", "friction_study");
}

// == Ride comfort against friction on ISO 8608 class A at 50 km/h (seed 000 Section 4.3).
TEST(DemoSteps, RideComfortAgainstFrictionOnTheSmoothRoad) {
  testing::TempDir dir("ridefit_demo_steps");
  std::string recordings;
  for (const std::string fc : {"0", "30", "60", "120"}) {
    const std::string csv = (dir.path() / ("class_a_Fc" + fc + "N.csv")).string();
    const auto run = run_json(
        "simulate " + kPassat + " " + kClassA + " --set coulomb_force_N=" + fc + " -o " + csv,
        dir.path());
    expect_answers(run, "class_a_friction.yaml", "simulate_Fc" + fc + "N");
    recordings += " " + csv;
  }
  const auto analysis = run_json("analyse" + recordings +
                                     " --channel body_acc --channel wheel_acc --channel tyre_force "
                                     "--channel travel --model " +
                                     kPassat +
                                     " --segment 10 --smooth 3 --levels 0,30,60,120 "
                                     "--level-name coulomb_force_N",
                                 dir.path());
  expect_answers(analysis, "class_a_friction.yaml", "analyse");
}

// == Impact hardness over the 20 mm semicircular cleat at 40 km/h (seed 000 Figure 17).
TEST(DemoSteps, ImpactHardnessOverTheCleat) {
  testing::TempDir dir("ridefit_demo_steps");
  std::string recordings;
  for (const std::string fc : {"0", "60"}) {
    const std::string csv = (dir.path() / ("cleat_Fc" + fc + "N.csv")).string();
    const auto run =
        run_json("simulate " + kPassat + " " + dataset("excitations/cleat_semicircular_20mm.yaml") +
                     " --set coulomb_force_N=" + fc + " -o " + csv,
                 dir.path());
    ASSERT_EQ(run.exit_code, 0) << run.output;
    recordings += " " + csv;
  }
  expect_answers(
      run_json("analyse" + recordings + " --channel body_acc --impact --band 0.5,30", dir.path()),
      "cleat_impact.yaml", "analyse");
}

// == Seed 001's half car on its smooth road at 20 km/h: passive, front strut, skyhook.
TEST(DemoSteps, HalfCarPassiveWithStrutAndSkyhook) {
  testing::TempDir dir("ridefit_demo_steps");
  const std::string base = "simulate " + dataset("vehicles/ajayi_half_car.yaml") + " " +
                           dataset("excitations/smooth_road_seed001.yaml");
  expect_answers(run_json(base, dir.path()), "half_car.yaml", "passive");
  expect_answers(run_json(base + " --set front.suspension=strut", dir.path()), "half_car.yaml",
                 "front_strut");
  expect_answers(run_json(base + " --set control.law=skyhook", dir.path()), "half_car.yaml",
                 "skyhook");
}

// == Seed 001 Figures 5-6: discomfort against speed on its three roads (frequency domain).
TEST(DemoSteps, Seed001SpeedStudy) {
  testing::TempDir dir("ridefit_demo_steps");
  const auto run = run_json("sweep " + dataset("studies/seed001_speed.yaml") + " -o " +
                                (dir.path() / "seed001_speed.csv").string(),
                            dir.path());
  expect_answers(run, "seed001_speed.yaml", "sweep");
}

// == Strut friction from the rig tests of datasets/lab, every fit from the data sheet's values
// (off the truth), and the strut fitted on the dynamic test on the road.
TEST(DemoSteps, StrutFitsFromTheLabRigTests) {
  testing::TempDir dir("ridefit_demo_steps");
  const std::string datasheet = dataset("lab/passat_strut_datasheet.yaml");
  const std::string fitted = (dir.path() / "passat_fitted.yaml").string();
  expect_answers(
      run_json("fit hysteresis " + dataset("lab/triangle_3mm_1mmps.csv") + " --model " + datasheet +
                   " --free dahl_sigma0_N_per_m,coulomb_force_N,dahl_exponent,"
                   "force_offset_N --interpolation linear -o " +
                   (dir.path() / "passat_triangle.yaml").string(),
               dir.path()),
      "lab_fits.yaml", "triangle");
  expect_answers(
      run_json("fit hysteresis " + dataset("lab/shim_0mm.csv") + " " + dataset("lab/shim_2mm.csv") +
                   " " + dataset("lab/shim_4mm.csv") + " --model " + datasheet +
                   " --free dahl_sigma0_N_per_m,coulomb_force_N,dahl_exponent,force_offset_N "
                   "--per-file coulomb_force_N --compression 0,2,4 "
                   "--interpolation linear",
               dir.path()),
      "lab_fits.yaml", "shims");
  expect_answers(
      run_json("fit hysteresis " + dataset("lab/dynamic_60s.csv") + " --model " + datasheet +
                   " --free dahl_sigma0_N_per_m,coulomb_force_N,dahl_exponent,"
                   "top_mount_stiffness_N_per_m,damping_Ns_per_m,force_offset_N -o " +
                   fitted,
               dir.path()),
      "lab_fits.yaml", "dynamic");
  expect_answers(run_json("simulate " + fitted + " " + kClassA, dir.path()), "lab_fits.yaml",
                 "fitted_strut_on_class_a");
}

// == Comfort against road holding: seed 001's linear half car tuned in the frequency domain.
TEST(DemoSteps, Seed001LinearHalfCarTuning) {
  testing::TempDir dir("ridefit_demo_steps");
  const auto run = run_json("optimise " + dataset("studies/seed001_damper_tuning_linear.yaml") +
                                " -q -o " + (dir.path() / "seed001_tuning.yaml").string(),
                            dir.path());
  expect_answers(run, "seed001_tuning.yaml", "optimise");
}

// == Damper tuning under friction: the Passat corner on three load cases (about a minute), and
// the optimised corner on the smooth road.
TEST(DemoStepsSlow, PassatTuningUnderFriction) {
  testing::TempDir dir("ridefit_demo_steps");
  const fs::path result = dir.path() / "passat_tuning.yaml";
  expect_answers(run_json("optimise " + dataset("studies/passat_damper_tuning.yaml") + " -q -o " +
                              result.string(),
                          dir.path()),
                 "passat_tuning.yaml", "optimise");
  expect_answers(
      run_json("simulate " + (dir.path() / "passat_tuning_model.yaml").string() + " " + kClassA,
               dir.path()),
      "passat_tuning.yaml", "optimised_corner_on_class_a");
}

// == Diagnosis (seed 000 Section 4.2.2): what is the seed's stick model missing?
TEST(DemoStepsSlow, DiagnosisOfTheSeedStickModel) {
  testing::TempDir dir("ridefit_demo_steps");
  const auto run = run_json("diagnose " + dataset("hidden/baselines/passat_stick.yaml") + " " +
                                dataset("hidden/seed_top_mount_stiffening.csv") + " " +
                                dataset("hidden/seed_top_mount_stiffening_2.csv") + " -q -o " +
                                (dir.path() / "diagnosis_seed").string(),
                            dir.path());
  expect_answers(run, "diagnosis.yaml", "seed_stick_model");
}

}  // namespace
}  // namespace ridefit
