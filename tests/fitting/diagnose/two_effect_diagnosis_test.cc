// Two effects hidden from a bare baseline (the case): Dahl friction and tyre damping on
// 60 s of a class A road, the baseline frictionless and without tyre damping. After the first
// effect is named, the second is refitted from the baseline's own damping too (the fitted
// baseline's damping has absorbed part of the friction), and both are named.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>

#include "ridefit/fitting/diagnose/diagnosis.h"
#include "support/hidden_effect_record.h"
#include "support/passat.h"

namespace ridefit::fitting::diagnose {
namespace {

model::QuarterCar passat(model::DamperState state, const std::map<std::string, double>& set) {
  DiagnosisModel m{model::QuarterCar(state, testing::passat_corner().parameters)};
  EffectChange change;
  change.set = set;
  return apply(m, change).car;
}

double fitted(const DiagnosisResult& r, const std::string& name) {
  for (const auto& v : r.final_parameters) {
    if (v.name == name) return v.value;
  }
  ADD_FAILURE() << name << " was not fitted";
  return NAN;
}

TEST(TwoEffectDiagnosis, FrictionAndTyreDampingFromABareBaselineBothNamedWithinEightPercent) {
  // σ0, which the friction effect keeps on spectra, a guess 2.5× below the truth's 5e6 N/m.
  const auto baseline = passat(
      model::DamperState::kSlip,
      {{"coulomb_force_N", 0.0}, {"tyre_damping_Ns_per_m", 0.0}, {"dahl_sigma0_N_per_m", 2e6}});
  const auto truth = passat(model::DamperState::kStickSlip,
                            {{"coulomb_force_N", 60.0}, {"tyre_damping_Ns_per_m", 600.0}});
  const DiagnosisData data{testing::hidden_effect_record(truth, road::Iso8608Class::kA, 41, 60.0),
                           testing::hidden_effect_record(truth, road::Iso8608Class::kA, 42, 60.0)};
  DiagnosisOptions options;
  options.fit.segment_s = 4.0;
  options.map.segment_s = 4.0;
  const DiagnosisResult r = diagnose({baseline}, data, options);
  ASSERT_EQ(r.named.size(), 2u) << r.verdict;
  EXPECT_TRUE(std::find(r.named.begin(), r.named.end(), "damper_friction") != r.named.end())
      << r.verdict;
  EXPECT_TRUE(std::find(r.named.begin(), r.named.end(), "tyre_damping") != r.named.end())
      << r.verdict;
  // Within 8 %: the σ0 held 2.5× low softens the stuck strut's series stiffness by 12 %, which
  // the fit makes up with both (measured: Fc 63.1 N, tyre damping 636 N·s/m; within 5 % when σ0
  // was held at the truth).
  EXPECT_NEAR(fitted(r, "coulomb_force_N"), 60.0, 0.08 * 60.0);
  EXPECT_NEAR(fitted(r, "tyre_damping_Ns_per_m"), 600.0, 0.08 * 600.0);
}

}  // namespace
}  // namespace ridefit::fitting::diagnose
