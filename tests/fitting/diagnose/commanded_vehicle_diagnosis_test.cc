// A controlled damper on the road (issue 15): a vehicle record with a switching coil current,
// made by CVODE with the damper following the current, diagnosed from a passive baseline. The
// diagnosis must name command_dependence and give back the damping's slope; a record without a
// command column must not offer the effect.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "ridefit/fitting/diagnose/diagnosis.h"
#include "support/controlled_damper_record.h"
#include "support/hidden_effect_record.h"
#include "support/passat.h"

namespace ridefit::fitting::diagnose {
namespace {

double fitted(const DiagnosisResult& r, const std::string& name) {
  for (const auto& v : r.final_parameters) {
    if (v.name == name) return v.value;
  }
  ADD_FAILURE() << name << " was not fitted";
  return NAN;
}

model::QuarterCarParameters<double> passive_slip() {
  auto p = testing::passat_corner().parameters;
  p.damping_Ns_per_m = 600.0;
  p.coulomb_force_N = 0.0;
  return p;
}

TEST(CommandedVehicleDiagnosis, SwitchingCurrentOnTheRoadNamesCommandDependence) {
  // c = 600 + 1200·ū N·s/m, ū lagging the current (0–2 A, held 0.15–0.5 s) by 12 ms.
  auto truth = passive_slip();
  truth.damping_per_command_Ns_per_m = 1200.0;
  truth.command_lag_s = 0.012;
  const model::QuarterCar truth_car(model::DamperState::kSlip, truth);
  const auto first = testing::switching_command(11, 60.0, 2.0);
  const auto second = testing::switching_command(12, 60.0, 2.0);
  const DiagnosisData data{
      testing::hidden_effect_record(truth_car, road::Iso8608Class::kB, 51, 60.0, 200.0, 0.005,
                                    [&](double t) { return first(t); }),
      testing::hidden_effect_record(truth_car, road::Iso8608Class::kB, 52, 60.0, 200.0, 0.005,
                                    [&](double t) { return second(t); })};
  ASSERT_TRUE(data.training.road->has_command());
  DiagnosisOptions options;
  options.fit.segment_s = 4.0;
  options.map.segment_s = 4.0;
  options.effects = {"command_dependence", "damper_friction", "tyre_damping"};
  auto passive = passive_slip();
  passive.damping_Ns_per_m = 900.0;  // the passive sheet's damping, 50 % above the truth's 600
  const model::QuarterCar baseline(model::DamperState::kSlip, passive);
  const DiagnosisResult r = diagnose({baseline}, data, options);
  ASSERT_FALSE(r.named.empty()) << r.verdict;
  EXPECT_EQ(r.named.front(), "command_dependence") << r.verdict;
  EXPECT_NEAR(fitted(r, "damping_per_command_Ns_per_m"), 1200.0, 0.05 * 1200.0) << r.verdict;
  EXPECT_NEAR(fitted(r, "damping_Ns_per_m"), 600.0, 0.05 * 600.0) << r.verdict;
}

TEST(CommandedVehicleDiagnosis, WithoutACommandColumnTheEffectIsNotOffered) {
  DiagnosisModel m{model::QuarterCar(model::DamperState::kSlip, passive_slip())};
  const Effect& effect = find_effect("command_dependence");
  EXPECT_NE(effect.not_applicable(m).find("no command column"), std::string::npos);
  m.has_command = true;
  EXPECT_EQ(effect.not_applicable(m), "");
  const EffectChange change = effect.change(m);
  ASSERT_FALSE(change.free.empty());
  EXPECT_EQ(change.free.front().name, "damping_per_command_Ns_per_m");
  // A baseline that already follows the command has nothing to add.
  EffectChange already;
  already.set = {{"damping_per_command_Ns_per_m", 100.0}};
  EXPECT_NE(effect.not_applicable(apply(m, already)).find("already"), std::string::npos);
}

}  // namespace
}  // namespace ridefit::fitting::diagnose
