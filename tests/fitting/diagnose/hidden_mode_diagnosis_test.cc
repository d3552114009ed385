// The case for pooled band tests and peak comparison: a quarter car whose body carries a
// 30 kg engine on a 12 Hz mount, a secondary body mode no effect of the library can make. The
// record comes from a 3-mass model integrated here by classic RK4 at 20 μs (not ridefit's
// ESDIRK nor its model code); the diagnosis must say that a disagreement remains unexplained.
// A wheel mass the model gets wrong shows, end to end, as a peak shift.
// Controls: records of the baseline itself (CVODE), with 0.5 % and with 5 % sensor noise, get no
// named effect and no unexplained region. 60 s records at 200 Hz on a class A road at 50 km/h,
// split into halves (fitted, judged).
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "ridefit/fitting/diagnose/diagnosis.h"
#include "ridefit/road/iso8608.h"
#include "ridefit/road/measured_road.h"
#include "ridefit/study/sensor_model.h"
#include "support/hidden_effect_record.h"
#include "support/passat.h"

namespace ridefit::fitting::diagnose {
namespace {

constexpr double kRate_Hz = 200.0;
constexpr double kDuration_s = 60.0;
constexpr double kEngineMass_kg = 30.0;
constexpr double kEngineMount_Hz = 12.0;
constexpr double kEngineMountDamping = 0.1;

// The Passat corner as shipped: stick/slip strut (top mount in series with the damper and its
// Dahl friction, Fc = 60 N, d = 1): the baseline.
model::QuarterCar baseline() {
  return model::QuarterCar(model::DamperState::kStickSlip, testing::passat_corner().parameters);
}

road::SpatialProfileRoad class_a_road(unsigned seed) {
  road::Iso8608RoadParameters r;
  r.road_class = road::Iso8608Class::kA;
  r.random.speed_m_per_s = 50.0 / 3.6;
  r.random.duration_s = kDuration_s;
  r.random.seed = seed;
  return road::make_iso8608_road(r);
}

// The baseline's strut and tyre with the sprung mass split into a body (ms − 30 kg) and an
// engine (30 kg) on a mount of 12 Hz, ζ = 0.1, written out here. States: body, wheel, engine
// displacement; their velocities; the damper's deflection z_c and the Dahl friction force F_f
// (the top mount k_tm in series with the damper c parallel to the friction element:
// c·z_c' = k_tm·(z − z_c) − F_f, F_f' = σ0·z_c'·(1 − F_f/Fc·sgn z_c'), d = 1). RK4 at 20 μs: the
// friction state relaxes with c/σ0 ≈ 0.18 ms. Returns the record: body and wheel acceleration
// through the diagnosis tests' sensor model (0.5 % noise).
PsdMeasurement engine_mount_record(unsigned seed) {
  const auto p = baseline().parameters();
  const double ms = p.sprung_mass_kg - kEngineMass_kg, mu = p.unsprung_mass_kg;
  const double me = kEngineMass_kg;
  const double we = 2.0 * std::numbers::pi * kEngineMount_Hz;
  const double ke = me * we * we, ce = 2.0 * kEngineMountDamping * me * we;
  const double ksp = p.spring_stiffness_N_per_m * p.top_mount_spring_path_stiffness_N_per_m /
                     (p.spring_stiffness_N_per_m + p.top_mount_spring_path_stiffness_N_per_m);
  const double ktm = p.top_mount_stiffness_N_per_m, c = p.damping_Ns_per_m;
  const double kt = p.tyre_stiffness_N_per_m, ct = p.tyre_damping_Ns_per_m;
  const double sigma0 = p.dahl_sigma0_N_per_m, fc = p.coulomb_force_N;
  const auto road = class_a_road(seed);
  using State = std::array<double, 8>;  // zs, zu, ze, vs, vu, ve, zc, Ff
  // x' and the two accelerations at time t.
  auto rates = [&](double t, const State& x, double* body_acc, double* wheel_acc) {
    const road::RoadSample h = road.at(t);
    const double travel = x[0] - x[1];
    const double path = ktm * (travel - x[6]);
    const double mount = ke * (x[2] - x[0]) + ce * (x[5] - x[3]);  // pulls the body to the engine
    const double tyre = kt * (x[1] - h.elevation_m) + ct * (x[4] - h.rate_m_per_s);
    State d{};
    d[0] = x[3];
    d[1] = x[4];
    d[2] = x[5];
    d[3] = (-ksp * travel - path + mount) / ms;
    d[4] = (ksp * travel + path - tyre) / mu;
    d[5] = -mount / me;
    d[6] = (path - x[7]) / c;
    d[7] = sigma0 * (d[6] - std::abs(d[6]) * x[7] / fc);
    if (body_acc) *body_acc = d[3];
    if (wheel_acc) *wheel_acc = d[4];
    return d;
  };
  const double step_s = 2e-5;
  const int per_sample = static_cast<int>(std::lround(1.0 / (kRate_Hz * step_s)));
  const auto samples = static_cast<std::size_t>(std::lround(kDuration_s * kRate_Hz)) + 1;
  State x{};
  std::vector<double> time(samples), elevation(samples), body(samples), wheel(samples);
  for (std::size_t k = 0; k < samples; ++k) {
    const double t = static_cast<double>(k) / kRate_Hz;
    time[k] = t;
    elevation[k] = road.at(t).elevation_m;
    rates(t, x, &body[k], &wheel[k]);
    if (k + 1 == samples) break;
    for (int s = 0; s < per_sample; ++s) {
      const double ts = t + s * step_s;
      auto shifted = [&](const State& base, const State& d, double by) {
        State y;
        for (std::size_t i = 0; i < y.size(); ++i) y[i] = base[i] + by * d[i];
        return y;
      };
      const State k1 = rates(ts, x, nullptr, nullptr);
      const State k2 = rates(ts + 0.5 * step_s, shifted(x, k1, 0.5 * step_s), nullptr, nullptr);
      const State k3 = rates(ts + 0.5 * step_s, shifted(x, k2, 0.5 * step_s), nullptr, nullptr);
      const State k4 = rates(ts + step_s, shifted(x, k3, step_s), nullptr, nullptr);
      for (std::size_t i = 0; i < x.size(); ++i) {
        x[i] += step_s / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
      }
    }
  }
  PsdMeasurement m;
  m.source = "engine mount record";
  m.time_s = time;
  m.sample_rate_Hz = kRate_Hz;
  m.road = std::make_shared<road::MeasuredRoad>(time, elevation);
  std::mt19937_64 rng(500 + seed);
  study::SensorModel sensor;
  m.body_acc_m_per_s2 = study::measure(body, kRate_Hz, sensor, rng);
  m.wheel_acc_m_per_s2 = study::measure(wheel, kRate_Hz, sensor, rng);
  return m;
}

DiagnosisOptions options() {
  DiagnosisOptions o;
  o.fit.segment_s = 2.0;
  o.map.segment_s = 2.0;
  return o;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

const ChannelDisagreement& channel(const DisagreementMap& map, const std::string& name) {
  for (const auto& c : map.channels) {
    if (c.channel == name) return c;
  }
  throw std::runtime_error("no channel " + name);
}

void print_map(const char* what, const DiagnosisResult& r) {
  for (const auto& c : r.after.channels) {
    std::printf(
        "%s %s: gap %.2f dB, peak measured %.2f ± %.2f Hz, simulated %.2f ± %.2f Hz, "
        "threshold %.2f Hz%s\n",
        what, c.channel.c_str(), c.gap_dB, c.peak.measured.frequency_Hz,
        c.peak.measured.standard_error_Hz, c.peak.simulated.frequency_Hz,
        c.peak.simulated.standard_error_Hz, c.peak.threshold_Hz,
        c.peak.significant ? " (significant)" : "");
  }
  for (const auto& region : r.after.regions) {
    std::printf("%s region %s %.2f–%.2f Hz %+.2f dB evidence %d%s\n", what, region.channel.c_str(),
                region.low_Hz, region.high_Hz, region.size_dB, static_cast<int>(region.evidence),
                region.above_band ? " above band" : "");
  }
  for (const auto& round : r.rounds) {
    for (const auto& t : round.trials) {
      if (!t.skipped.empty() || !t.failed.empty()) continue;
      std::printf("%s trial %s: held-out %+.0f %%, BIC %+.1f:", what, t.id.c_str(),
                  -100.0 * t.held_out_improvement, t.bic_change);
      for (const auto& v : t.parameters) std::printf(" %s %.4g", v.name.c_str(), v.value);
      std::printf("\n");
    }
  }
  std::printf("%s verdict: %s\n", what, r.verdict.c_str());
}

// The engine's mode works as a vibration absorber on the body: the measured body acceleration
// is ~1–1.5 dB above the baseline's below 12 Hz and as much below it above, over several Hz each
// (the band's RMS gap is under 1 dB and no single bin is outside its F interval). The pooled band
// tests find both lobes, no effect of the library removes them, and the verdict names them; the
// bins-only map of the same signals finds nothing in the band.
TEST(HiddenModeDiagnosis, AnEngineOnItsMountIsAnUnexplainedDisagreement) {
  const auto start = std::chrono::steady_clock::now();
  const PsdMeasurement record = engine_mount_record(3);
  const DiagnosisData data = split_record(record);
  const DiagnosisOptions o = options();
  const DiagnosisResult r = diagnose({baseline()}, data, o);
  print_map("engine", r);
  std::printf("engine mount diagnosis: %.1f s\n", seconds_since(start));
  EXPECT_TRUE(r.named.empty()) << r.verdict;
  ASSERT_FALSE(r.unexplained.empty()) << r.verdict;
  EXPECT_NE(r.verdict.find("no effect of the library explains"), std::string::npos) << r.verdict;
  bool below = false, above = false;
  for (const auto& region : r.unexplained) {
    EXPECT_EQ(region.channel, "body_acc");
    EXPECT_EQ(region.evidence, RegionEvidence::kPooledBand);
    below = below || (region.size_dB > 1.0 && region.low_Hz < 12.0 && region.high_Hz <= 12.5 &&
                      region.high_Hz - region.low_Hz >= 2.0);
    above = above || (region.size_dB < -1.0 && region.low_Hz >= 11.5 && region.low_Hz < 14.0 &&
                      region.high_Hz - region.low_Hz >= 2.0);
  }
  EXPECT_TRUE(below) << "the body's excess below the engine's 12 Hz";
  EXPECT_TRUE(above) << "and its deficit above";
  EXPECT_LT(channel(r.after, "body_acc").gap_dB, 1.0);
  // The same comparison with single bins only: nothing in the band.
  DisagreementOptions bins_only;
  bins_only.segment_s = o.map.segment_s;
  bins_only.pooled_max_width_Hz = 0.0;
  const NoiseFloors noise = noise_floors(data.held_out, o.fit);
  const auto map = map_disagreement(
      {{"body_acc", data.held_out.body_acc_m_per_s2, r.after_body, noise.body_psd},
       {"wheel_acc", data.held_out.wheel_acc_m_per_s2, r.after_wheel, noise.wheel_psd}},
      data.held_out.sample_rate_Hz, bins_only);
  for (const auto& region : map.regions) {
    EXPECT_TRUE(region.above_band)
        << region.channel << " " << region.low_Hz << "–" << region.high_Hz;
  }
}

// The peak comparison end to end: the record's wheel is 32 kg where the model has 46.8 kg (a
// parameter the diagnosis does not free, and no effect of the library): the measured wheel mode
// sits ~2.4 Hz above the fitted model's, beyond the ~1.7 Hz the two estimates of that broad mode
// resolve, and the shift is among the unexplained disagreements. (CVODE record, 0.5 % noise.)
TEST(HiddenModeDiagnosis, AWheelMassTheModelGetsWrongShowsAsAPeakShift) {
  const auto start = std::chrono::steady_clock::now();
  auto p = testing::passat_corner().parameters;
  p.unsprung_mass_kg = 32.0;
  const model::QuarterCar truth(model::DamperState::kStickSlip, p);
  const PsdMeasurement record =
      testing::hidden_effect_record(truth, road::Iso8608Class::kA, 5, kDuration_s, kRate_Hz, 0.005);
  const DiagnosisResult r = diagnose({baseline()}, split_record(record), options());
  print_map("wheel mass", r);
  std::printf("wheel mass diagnosis: %.1f s\n", seconds_since(start));
  EXPECT_TRUE(r.named.empty()) << r.verdict;
  const DisagreementRegion* shift = nullptr;
  for (const auto& region : r.unexplained) {
    if (region.evidence == RegionEvidence::kPeakShift) shift = &region;
  }
  ASSERT_NE(shift, nullptr) << r.verdict;
  EXPECT_EQ(shift->channel, "wheel_acc");
  EXPECT_GT(shift->measured_peak_Hz - shift->simulated_peak_Hz, shift->resolution_Hz);
  EXPECT_GT(shift->measured_peak_Hz - shift->simulated_peak_Hz, 1.5);
}

void expect_quiet(double noise, unsigned seed) {
  const auto start = std::chrono::steady_clock::now();
  const auto truth = baseline();
  const PsdMeasurement record = testing::hidden_effect_record(truth, road::Iso8608Class::kA, seed,
                                                              kDuration_s, kRate_Hz, noise);
  const DiagnosisResult r = diagnose({truth}, split_record(record), options());
  print_map(noise > 0.01 ? "baseline 5 %" : "baseline 0.5 %", r);
  std::printf("baseline diagnosis (%.1f %% noise): %.1f s\n", 100.0 * noise, seconds_since(start));
  EXPECT_TRUE(r.named.empty()) << r.verdict;
  EXPECT_TRUE(r.unexplained.empty()) << r.verdict;
  EXPECT_EQ(r.verdict.rfind("no missing effect found", 0), 0u) << r.verdict;
  for (const auto& c : r.after.channels) EXPECT_FALSE(c.peak.significant) << c.channel;
}

TEST(HiddenModeDiagnosis, TheBaselinesOwnRecordStaysQuiet) { expect_quiet(0.005, 3); }

TEST(HiddenModeDiagnosis, TheBaselinesOwnRecordWithFivePercentNoiseStaysQuiet) {
  expect_quiet(0.05, 4);
}

}  // namespace
}  // namespace ridefit::fitting::diagnose
