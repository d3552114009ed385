// The diagnosis from a baseline whose values are off as a data sheet's are (drawn from seeded
// uniform errors: masses ±3 %, tyre and spring ±8 %, damping ±12 %, top mount ±15 %, Fc ±25 %,
// σ0 a factor 2; support/datasheet_baseline.h), on records made by CVODE with the sensor chain:
// it names exactly the hidden effect (nothing on a control), and the values it refits under the
// sheet's priors (DiagnosisOptions::baseline_tolerances) move towards the truth.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "ridefit/fitting/diagnose/diagnosis.h"
#include "support/datasheet_baseline.h"
#include "support/hidden_effect_record.h"
#include "support/passat.h"

namespace ridefit::fitting::diagnose {
namespace {

using model::DamperState;

model::QuarterCar passat(DamperState state, const std::map<std::string, double>& set) {
  DiagnosisModel m{model::QuarterCar(state, testing::passat_corner().parameters)};
  EffectChange change;
  change.set = set;
  return apply(m, change).car;
}

struct SheetCase {
  std::string id;                              // the hidden effect, "" for none
  std::map<std::string, double> baseline_set;  // the truth without the effect (Passat + these)
  std::map<std::string, double> effect_set;    // what the truth adds
  DamperState truth_state;
  road::Iso8608Class road;
  unsigned seed;  // of the sheet's errors and (×10) of the records
};

void PrintTo(const SheetCase& c, std::ostream* os) { *os << (c.id.empty() ? "none" : c.id); }

class DatasheetBaselineDiagnosis : public ::testing::TestWithParam<SheetCase> {};

TEST_P(DatasheetBaselineDiagnosis, NamesExactlyTheHiddenEffectAndRefitsTheSheetTowardsTheTruth) {
  const SheetCase& c = GetParam();
  const model::QuarterCar without = passat(DamperState::kSlip, c.baseline_set);
  auto truth_set = c.baseline_set;
  for (const auto& [name, value] : c.effect_set) truth_set[name] = value;
  const model::QuarterCar truth = passat(c.truth_state, truth_set);
  const model::QuarterCar sheet = testing::datasheet_baseline(without, c.seed);
  const DiagnosisData data{testing::hidden_effect_record(truth, c.road, 10 * c.seed),
                           testing::hidden_effect_record(truth, c.road, 10 * c.seed + 1)};
  DiagnosisOptions options;
  options.baseline_tolerances = datasheet_tolerances();
  options.fit.segment_s = 2.0;
  options.map.segment_s = 2.0;
  const DiagnosisResult r = diagnose({sheet}, data, options);
  EXPECT_EQ(r.named, c.id.empty() ? std::vector<std::string>{} : std::vector<std::string>{c.id})
      << r.verdict;
  EXPECT_TRUE(r.unexplained.empty()) << r.verdict;
  // The values the spectra determine best come back towards the truth: the spring and the tyre
  // (the body and wheel modes' stiffnesses) wherever the sheet had them over 3 % off.
  ASSERT_FALSE(r.sheet_values.empty());
  for (const auto& v : r.sheet_values) {
    if (v.name != "spring_stiffness_N_per_m" && v.name != "tyre_stiffness_N_per_m") continue;
    const double true_value = parameter_value(truth, v.name);
    if (std::abs(v.sheet / true_value - 1.0) < 0.03) continue;
    EXPECT_LT(std::abs(v.fitted - true_value), 0.5 * std::abs(v.sheet - true_value))
        << v.name << ": sheet " << v.sheet << ", fitted " << v.fitted << ", truth " << true_value;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Library, DatasheetBaselineDiagnosis,
    ::testing::Values(
        SheetCase{
            "", {{"coulomb_force_N", 0.0}}, {}, DamperState::kSlip, road::Iso8608Class::kC, 101},
        SheetCase{"tyre_damping",
                  {{"coulomb_force_N", 0.0}, {"tyre_damping_Ns_per_m", 0.0}},
                  {{"tyre_damping_Ns_per_m", 400.0}},
                  DamperState::kSlip,
                  road::Iso8608Class::kC,
                  102},
        SheetCase{"damper_asymmetry",
                  {{"coulomb_force_N", 0.0}},
                  {{"compression_to_rebound_ratio", 0.4}},
                  DamperState::kSlip,
                  road::Iso8608Class::kC,
                  103},
        SheetCase{"damper_digressive",
                  {{"coulomb_force_N", 0.0}},
                  {{"damper_knee_velocity_m_per_s", 0.1}, {"damping_above_knee_Ns_per_m", 300.0}},
                  DamperState::kSlip,
                  road::Iso8608Class::kD,
                  104},
        SheetCase{"damper_friction",
                  {{"coulomb_force_N", 0.0}},
                  {{"coulomb_force_N", 60.0}},
                  DamperState::kStickSlip,
                  road::Iso8608Class::kC,
                  105},
        SheetCase{"bump_stop",
                  {{"coulomb_force_N", 0.0}},
                  {{"bump_stop_stiffness_N_per_m", 1e5}, {"bump_stop_clearance_m", 0.03}},
                  DamperState::kSlip,
                  road::Iso8608Class::kD,
                  106}),
    [](const ::testing::TestParamInfo<SheetCase>& case_info) {
      return case_info.param.id.empty() ? std::string("none") : case_info.param.id;
    });

}  // namespace
}  // namespace ridefit::fitting::diagnose
