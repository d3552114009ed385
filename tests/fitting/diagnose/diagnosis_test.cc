// The diagnosis names the effect hidden in data from a richer truth, recovers its parameters,
// and closes the gap; it names nothing on data from the baseline itself, and it reports a
// disagreement no effect explains as unexplained. Records: 20 s at 200 Hz on ISO 8608 roads at
// 50 km/h with 0.5 % sensor noise (support/hidden_effect_record.h); the second record (another
// road realisation and noise) judges.
#include "ridefit/fitting/diagnose/diagnosis.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>

#include "ridefit/study/sensor_model.h"
#include "support/hidden_effect_record.h"
#include "support/passat.h"

namespace ridefit::fitting::diagnose {
namespace {

using model::DamperState;

model::QuarterCar passat(DamperState state, const std::map<std::string, double>& set = {}) {
  DiagnosisModel m{model::QuarterCar(state, testing::passat_corner().parameters)};
  EffectChange change;
  change.set = set;
  return apply(m, change).car;
}

// The slip strut without friction: the baseline most effects are hidden from. Its σ0, which a
// friction effect added to it keeps (spectra do not determine it), is the truth's 5e6 N/m ÷ 2.5,
// as an engineer's guess would be off.
model::QuarterCar slip_baseline(const std::map<std::string, double>& set = {}) {
  auto all = set;
  all.emplace("coulomb_force_N", 0.0);
  all.emplace("dahl_sigma0_N_per_m", 2e6);
  return passat(DamperState::kSlip, all);
}

DiagnosisOptions quick_options() {
  DiagnosisOptions o;
  o.fit.segment_s = 2.0;
  o.map.segment_s = 2.0;
  return o;
}

DiagnosisData records(const model::QuarterCar& truth, road::Iso8608Class road, unsigned seed = 1) {
  return {testing::hidden_effect_record(truth, road, seed),
          testing::hidden_effect_record(truth, road, seed + 1)};
}

struct HiddenEffect {
  std::string id;
  model::QuarterCar baseline;
  model::QuarterCar truth;
  road::Iso8608Class road;
};

void PrintTo(const HiddenEffect& h, std::ostream* os) { *os << h.id; }

class HiddenEffectIsNamed : public ::testing::TestWithParam<HiddenEffect> {};

TEST_P(HiddenEffectIsNamed, RankedFirstParametersRecoveredGapShrinks) {
  const HiddenEffect& h = GetParam();
  const DiagnosisResult r = diagnose({h.baseline}, records(h.truth, h.road), quick_options());
  ASSERT_FALSE(r.rounds.empty());
  const EffectTrial& first = r.rounds[0].trials.front();
  EXPECT_EQ(first.id, h.id) << r.verdict;
  ASSERT_EQ(r.named.size(), 1u) << r.verdict;
  EXPECT_EQ(r.named[0], h.id);
  // Each of the effect's parameters within 10 % of the truth or within 2 standard errors, never
  // more than 25 % (measured: within 2.1 %, the knee 19 % with an SE of 21 %). A parameter the
  // records do not determine must say so by its standard error (over half its truth: the
  // stiffening's transition deflection on a class A road, 9.5 mm ± 1.9 m for 0.5 mm).
  for (const auto& p : r.final_parameters) {
    const double truth = parameter_value(h.truth, p.name);
    if (parameter_value(h.baseline, p.name) == truth) continue;  // a baseline parameter
    if (p.standard_error && *p.standard_error > 0.5 * std::abs(truth)) continue;
    const double tolerance =
        std::min(std::max(0.1 * std::abs(truth), p.standard_error ? 2.0 * *p.standard_error : 0.0),
                 0.25 * std::abs(truth));
    EXPECT_NEAR(p.value, truth, tolerance)
        << h.id << " " << p.name << " SE " << (p.standard_error ? *p.standard_error : -1.0);
  }
  // The gap (RMS over the band of the log-PSD ratio, dB) shrinks by at least 70 %.
  EXPECT_LT(r.after.gap_dB, 0.3 * r.before.gap_dB) << r.before.gap_dB << " -> " << r.after.gap_dB;
  EXPECT_TRUE(r.unexplained.empty()) << r.verdict;
}

INSTANTIATE_TEST_SUITE_P(
    Library, HiddenEffectIsNamed,
    ::testing::Values(
        HiddenEffect{"tyre_damping", slip_baseline({{"tyre_damping_Ns_per_m", 0.0}}),
                     slip_baseline({{"tyre_damping_Ns_per_m", 300.0}}), road::Iso8608Class::kC},
        HiddenEffect{"damper_friction", slip_baseline(), passat(DamperState::kStickSlip),
                     road::Iso8608Class::kC},
        HiddenEffect{"top_mount_compliance", slip_baseline({{"top_mount_stiffness_N_per_m", 1e9}}),
                     slip_baseline(), road::Iso8608Class::kC},
        HiddenEffect{"damper_asymmetry", slip_baseline(),
                     slip_baseline({{"compression_to_rebound_ratio", 0.4}}),
                     road::Iso8608Class::kC},
        HiddenEffect{"damper_digressive", slip_baseline(),
                     slip_baseline({{"damper_knee_velocity_m_per_s", 0.1},
                                    {"damping_above_knee_Ns_per_m", 300.0}}),
                     road::Iso8608Class::kD},
        HiddenEffect{
            "bump_stop", slip_baseline(),
            slip_baseline({{"bump_stop_stiffness_N_per_m", 1e5}, {"bump_stop_clearance_m", 0.03}}),
            road::Iso8608Class::kD},
        HiddenEffect{"tyre_lift_off", slip_baseline(), slip_baseline({{"tyre_lift_off", 1.0}}),
                     road::Iso8608Class::kD},
        HiddenEffect{"top_mount_amplitude_stiffening", passat(DamperState::kStickSlip),
                     passat(DamperState::kStickSlip,
                            {{"top_mount_small_amplitude_stiffness_N_per_m", 707000.0},
                             {"top_mount_transition_deflection_m", 5e-4}}),
                     road::Iso8608Class::kA}),
    [](const ::testing::TestParamInfo<HiddenEffect>& param_info) { return param_info.param.id; });

// Seed 000 Section 4.2.2: the stick model puts the wheel mode at 21.4 Hz, the car shows ~24 Hz
// because its top mount is stiffer (707 against 488 N/mm) at the small amplitudes of driving.
TEST(Diagnosis, SeedCaseTopMountStiffeningClosesTheWheelPeakError) {
  const auto baseline = passat(DamperState::kStick);
  const auto truth =
      passat(DamperState::kStick, {{"top_mount_small_amplitude_stiffness_N_per_m", 707000.0},
                                   {"top_mount_transition_deflection_m", 5e-3}});
  const DiagnosisResult r =
      diagnose({baseline}, records(truth, road::Iso8608Class::kA, 7), quick_options());
  ASSERT_EQ(r.named, std::vector<std::string>{"top_mount_amplitude_stiffening"}) << r.verdict;
  auto wheel = [](const DisagreementMap& map) {
    return *std::find_if(map.channels.begin(), map.channels.end(),
                         [](const auto& c) { return c.channel == "wheel_acc"; });
  };
  const auto before = wheel(r.before), after = wheel(r.after);
  EXPECT_GT(before.measured_peak_Hz, 22.5);
  EXPECT_GT(std::abs(before.measured_peak_Hz - before.simulated_peak_Hz), 1.5);
  EXPECT_LT(std::abs(after.measured_peak_Hz - after.simulated_peak_Hz), 1.0);
}

TEST(Diagnosis, TwoHiddenEffectsAreNamedInTwoRounds) {
  const auto baseline = slip_baseline({{"tyre_damping_Ns_per_m", 0.0}});
  const auto truth = slip_baseline({{"tyre_damping_Ns_per_m", 300.0},
                                    {"bump_stop_stiffness_N_per_m", 1e5},
                                    {"bump_stop_clearance_m", 0.03}});
  const DiagnosisResult r =
      diagnose({baseline}, records(truth, road::Iso8608Class::kD, 3), quick_options());
  ASSERT_EQ(r.named.size(), 2u) << r.verdict;
  EXPECT_TRUE(std::find(r.named.begin(), r.named.end(), "tyre_damping") != r.named.end());
  EXPECT_TRUE(std::find(r.named.begin(), r.named.end(), "bump_stop") != r.named.end());
  EXPECT_LT(r.after.gap_dB, 0.3 * r.before.gap_dB);
}

// 20 pairs of 12 s records (shorter than the others: twenty diagnoses must stay quick).
TEST(Diagnosis, NoFalseAlarmsOnDataFromTheBaselineItself) {
  const auto baseline = slip_baseline();
  int quiet = 0;
  std::string alarms;
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const DiagnosisResult r = diagnose(
        {baseline}, records(baseline, road::Iso8608Class::kC, 100 + 2 * seed), quick_options());
    if (r.named.empty() && r.verdict.rfind("no missing effect found", 0) == 0) {
      ++quiet;
    } else {
      alarms += "seed " + std::to_string(seed) + ": " + r.verdict + "\n";
    }
  }
  EXPECT_GE(quiet, 18) << alarms;
  std::printf("no missing effect found on %d of 20 baseline datasets\n", quiet);
}

// The body accelerometer on a panel with a mode at 12 Hz (study/sensor_model.h): no quarter-car
// effect can make that, so the diagnosis must say the disagreement is unexplained and name
// nothing.
TEST(Diagnosis, AnEffectOutsideTheLibraryIsReportedAsUnexplained) {
  const auto baseline = slip_baseline();
  auto data = records(baseline, road::Iso8608Class::kC, 11);
  std::mt19937_64 rng(5);
  study::SensorModel panel;
  panel.noise_fraction = 0.005;
  panel.mount = study::SensorMount{12.0, 0.05};
  for (auto* m : {&data.training, &data.held_out}) {
    // The same true signal (the record's without its noise is not kept: re-measure the
    // measured one; its 0.5 % noise only doubles).
    m->body_acc_m_per_s2 = study::measure(m->body_acc_m_per_s2, m->sample_rate_Hz, panel, rng);
  }
  const DiagnosisResult r = diagnose({baseline}, data, quick_options());
  EXPECT_TRUE(r.named.empty()) << r.verdict;
  ASSERT_FALSE(r.unexplained.empty()) << r.verdict;
  const auto& region = r.unexplained.front();
  EXPECT_EQ(region.channel, "body_acc");
  EXPECT_LE(region.low_Hz, 12.5);
  EXPECT_GE(region.high_Hz, 11.5);
  EXPECT_NE(r.verdict.find("no effect of the library explains"), std::string::npos) << r.verdict;
  // The ratio's shape is weighed beside the library's explanations, and the verdict's p is that
  // the library lacks it.
  ASSERT_FALSE(r.spectral_shape.terms.empty()) << r.verdict;
  EXPECT_TRUE(reports_outside_library(r));
  EXPECT_GT(reported_probability(r), 0.9) << r.verdict;
  EXPECT_NE(r.verdict.find("that the library lacks it"), std::string::npos) << r.verdict;
}

}  // namespace
}  // namespace ridefit::fitting::diagnose
