// The diagnosis option structs check themselves (validate()), so a library caller that builds
// them in memory gets the same clear refusal the command line gives, before any fit runs.
#include <gtest/gtest.h>

#include <cmath>

#include "ridefit/fitting/diagnose/diagnosis.h"
#include "ridefit/fitting/diagnose/diagnosis_options.h"
#include "ridefit/fitting/diagnose/loop_diagnosis.h"
#include "ridefit/fitting/diagnose/loop_diagnosis_options.h"
#include "support/throws_input_error.h"

namespace ridefit::fitting::diagnose {
namespace {

using testing::throws_input_error;

TEST(DiagnosisOptions, DefaultsHoldAndEachBadOptionIsNamed) {
  EXPECT_NO_THROW(DiagnosisOptions{}.validate());
  auto refused = [](auto change, const char* text) {
    DiagnosisOptions o;
    change(o);
    return throws_input_error([&] { o.validate(); }, text);
  };
  EXPECT_TRUE(refused([](auto& o) { o.baseline_free = {"damping"}; },
                      "'damping' is not a quarter-car parameter"));
  EXPECT_TRUE(refused(
      [](auto& o) {
        o.baseline_free = {"damping_Ns_per_m", "damping_Ns_per_m"};
      },
      "given twice"));
  EXPECT_TRUE(refused([](auto& o) { o.effects = {"no_such_effect"}; }, "no_such_effect"));
  EXPECT_TRUE(refused(
      [](auto& o) {
        o.effects = {"bump_stop", "bump_stop"};
      },
      "effects: 'bump_stop' is given twice"));
  EXPECT_TRUE(refused([](auto& o) { o.fit.band_high_Hz = 0.1; }, "band"));
  EXPECT_TRUE(refused([](auto& o) { o.screening_relative_tolerance = 0.5; }, "screening relative"));
  EXPECT_TRUE(refused([](auto& o) { o.final_relative_tolerance = 0.0; }, "final relative"));
  EXPECT_TRUE(refused([](auto& o) { o.screening_iterations = 0; }, "screening iteration"));
  EXPECT_TRUE(refused([](auto& o) { o.map.confidence = 1.0; }, "confidence 1"));
  EXPECT_TRUE(refused([](auto& o) { o.map.min_region_bins = 0; }, "smallest region 0 bins"));
  EXPECT_TRUE(
      refused([](auto& o) { o.selection.min_held_out_improvement = 1.5; }, "held-out improvement"));
  EXPECT_TRUE(refused([](auto& o) { o.selection.max_effects = -1; }, "effects per diagnosis"));
  EXPECT_TRUE(refused([](auto& o) { o.unexplained_dB = std::nan(""); }, "unexplained size"));
}

TEST(DiagnosisOptions, TheDiagnosisRefusesBadOptionsBeforeFitting) {
  DiagnosisOptions o;
  o.effects = {"no_such_effect"};
  // No data is needed: the options are checked first.
  EXPECT_TRUE(throws_input_error([&] { diagnose({}, {}, o); }, "no_such_effect"));
}

TEST(LoopDiagnosisOptions, DefaultsHoldAndEachBadOptionIsNamed) {
  EXPECT_NO_THROW(LoopDiagnosisOptions{}.validate());
  auto refused = [](auto change, const char* text) {
    LoopDiagnosisOptions o;
    change(o);
    return throws_input_error([&] { o.validate(); }, text);
  };
  EXPECT_TRUE(refused([](auto& o) { o.baseline_free = {"sprung_mass_kg"}; }, "sprung_mass_kg"));
  EXPECT_TRUE(refused(
      [](auto& o) {
        o.baseline_tolerances = {{"sprung_mass_kg", 0.03}};
      },
      "'sprung_mass_kg' is not a strut-test parameter"));
  EXPECT_TRUE(refused(
      [](auto& o) {
        o.baseline_tolerances = {{"damping_Ns_per_m", 0.0}};
      },
      "baseline tolerance of damping_Ns_per_m: 0 of its value"));
  EXPECT_TRUE(refused(
      [](auto& o) {
        o.baseline_tolerances = {{"damping_Ns_per_m", std::nan("")}};
      },
      "expected a share in (0, 10]"));
  EXPECT_TRUE(refused(
      [](auto& o) {
        o.baseline_free = {"force_offset_N", "force_offset_N"};
      },
      "twice"));
  EXPECT_TRUE(refused([](auto& o) { o.max_iterations = -1; }, "iteration limit -1"));
  EXPECT_TRUE(refused([](auto& o) { o.solver.relative_tolerance = 1.0; }, "relative tolerance"));
  EXPECT_TRUE(refused([](auto& o) { o.solver.max_steps_per_s = 0.0; }, "step limit"));
  EXPECT_TRUE(refused([](auto& o) { o.map.bins = 1; }, "bins 1"));
  EXPECT_TRUE(refused([](auto& o) { o.map.significance_sigmas = 0.0; }, "significance"));
  EXPECT_TRUE(refused([](auto& o) { o.selection.threads = 5000; }, "threads 5000"));
  EXPECT_TRUE(refused([](auto& o) { o.unexplained_share = 1.0; }, "unexplained share"));
  LoopDiagnosisOptions o;
  o.map.bins = 0;
  EXPECT_TRUE(throws_input_error([&] { diagnose_loops({}, {}, o); }, "bins 0"));
}

}  // namespace
}  // namespace ridefit::fitting::diagnose
