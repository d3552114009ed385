// ridefit's ESDIRK integrator: its tableau against SUNDIALS' and the order conditions, its
// observed order against a closed form, and every model against CVODE at rtol 1e-10 (a
// different method, so the comparison measures something) at the default tolerance.
#include "ridefit/simulate/esdirk_integrator.h"

#include <arkode/arkode_butcher_dirk.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/io/half_car_file.h"
#include "ridefit/road/iso8608.h"
#include "ridefit/signal/statistics.h"
#include "ridefit/signal/welch_psd.h"
#include "ridefit/simulate/half_car_simulation.h"
#include "ridefit/simulate/quarter_car_simulation.h"
#include "support/passat.h"

namespace ridefit::simulate {
namespace {

using T = EsdirkTableau;

TEST(EsdirkTableau, MatchesSundialsTable) {
  ARKodeButcherTable table = ARKodeButcherTable_LoadDIRK(ARKODE_ESDIRK324L2SA_4_2_3);
  ASSERT_NE(table, nullptr);
  EXPECT_EQ(table->stages, T::kStages);
  EXPECT_EQ(table->q, T::kOrder);
  EXPECT_EQ(table->p, T::kEmbeddedOrder);
  for (int i = 0; i < T::kStages; ++i) {
    EXPECT_DOUBLE_EQ(table->c[i], T::c[i]);
    EXPECT_DOUBLE_EQ(table->b[i], T::a[T::kStages - 1][i]) << "stiffly accurate: b = last row";
    EXPECT_DOUBLE_EQ(table->d[i], T::b_embedded[i]);
    for (int j = 0; j < T::kStages; ++j) EXPECT_DOUBLE_EQ(table->A[i][j], T::a[i][j]);
  }
  ARKodeButcherTable_Free(table);
}

TEST(EsdirkTableau, SatisfiesTheOrderConditionsAndLStability) {
  const auto& b = T::a[T::kStages - 1];
  double sum_b = 0, sum_bc = 0, sum_bc2 = 0, sum_bac = 0, sum_d = 0, sum_dc = 0;
  for (int i = 0; i < T::kStages; ++i) {
    double row = 0.0, ac = 0.0;
    for (int j = 0; j < T::kStages; ++j) {
      row += T::a[i][j];
      ac += T::a[i][j] * T::c[j];
    }
    EXPECT_NEAR(row, T::c[i], 1e-15) << "row sum of stage " << i;
    sum_b += b[i];
    sum_bc += b[i] * T::c[i];
    sum_bc2 += b[i] * T::c[i] * T::c[i];
    sum_bac += b[i] * ac;
    sum_d += T::b_embedded[i];
    sum_dc += T::b_embedded[i] * T::c[i];
  }
  EXPECT_NEAR(sum_b, 1.0, 1e-15);
  EXPECT_NEAR(sum_bc, 0.5, 1e-15);
  EXPECT_NEAR(sum_bc2, 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(sum_bac, 1.0 / 6.0, 1e-15);
  EXPECT_NEAR(sum_d, 1.0, 1e-15);
  EXPECT_NEAR(sum_dc, 0.5, 1e-14);
  // L-stability of a stiffly accurate DIRK with an explicit first stage: R(∞) = 0 needs the
  // explicit stage's weight to vanish from the limit, which the stiffly accurate form gives
  // when γ solves the third-order L-stability polynomial γ³ − 3γ² + 1.5γ − 1/6 = 0.
  const double g = T::kGamma;
  EXPECT_NEAR(g * g * g - 3 * g * g + 1.5 * g - 1.0 / 6.0, 0.0, 1e-14);
}

// x'' + 2ζω x' + ω² x = 0 from x = 1, x' = 0: a closed form to measure the order against.
class DampedOscillator : public OdeSystem {
 public:
  explicit DampedOscillator(double magnitude = 1.0) : magnitude_(magnitude) {}
  static constexpr double kOmega = 2.0 * 3.141592653589793 * 1.5, kZeta = 0.1;
  int size() const override { return 2; }
  bool derivatives(double, const double* x, double* xdot) const override {
    xdot[0] = x[1];
    xdot[1] = -2 * kZeta * kOmega * x[1] - kOmega * kOmega * x[0];
    return true;
  }
  bool jacobian(double, const double*, double* j) const override {
    j[0] = 0.0;
    j[1] = -kOmega * kOmega;
    j[2] = 1.0;
    j[3] = -2 * kZeta * kOmega;
    return true;
  }
  double typical_magnitude(int) const override { return magnitude_; }
  double max_step_s() const override { return 0.0; }
  double magnitude_;
  static double exact(double t) {
    const double wd = kOmega * std::sqrt(1 - kZeta * kZeta);
    return std::exp(-kZeta * kOmega * t) *
           (std::cos(wd * t) + kZeta * kOmega / wd * std::sin(wd * t));
  }
};

// With an absolute tolerance far above the solution the error test always passes, so every
// step is max_step (after a short ramp from the first guess): halving it shows the global order.
TEST(EsdirkIntegrator, ObservedOrderIsThree) {
  const DampedOscillator system(1e6);
  std::vector<double> times;
  for (int k = 0; k <= 50; ++k) times.push_back(0.04 * k);
  std::vector<double> errors;
  for (const double h : {0.02, 0.01, 0.005, 0.0025}) {
    IntegratorOptions o;
    o.relative_tolerance = 0.1;
    o.max_step_s = h;
    const Trajectory tr = integrate_esdirk(system, {1.0, 0.0}, times, o);
    double worst = 0.0;
    for (std::size_t k = 0; k < times.size(); ++k) {
      worst = std::max(worst, std::abs(tr.state_at(k)[0] - DampedOscillator::exact(times[k])));
    }
    errors.push_back(worst);
  }
  for (std::size_t k = 1; k < errors.size(); ++k) {
    const double order = std::log2(errors[k - 1] / errors[k]);
    EXPECT_NEAR(order, 3.0, 0.2) << "between steps " << k - 1 << " and " << k;
  }
}

TEST(EsdirkIntegrator, TightToleranceMeetsTheClosedForm) {
  const DampedOscillator system;
  std::vector<double> times;
  for (int k = 0; k <= 400; ++k) times.push_back(0.01 * k);
  IntegratorOptions o;
  o.relative_tolerance = 1e-9;
  const Trajectory tr = integrate_esdirk(system, {1.0, 0.0}, times, o);
  double worst = 0.0;  // includes the dense output between steps
  for (std::size_t k = 0; k < times.size(); ++k) {
    worst = std::max(worst, std::abs(tr.state_at(k)[0] - DampedOscillator::exact(times[k])));
  }
  EXPECT_LT(worst, 1e-7);
}

TEST(EsdirkIntegrator, BadRequestsAreInputErrors) {
  const DampedOscillator system;
  IntegratorOptions o;
  EXPECT_THROW(integrate_esdirk(system, {1.0}, {0.0, 1.0}, o), InputError);
  EXPECT_THROW(integrate_esdirk(system, {1.0, 0.0}, {0.0, 1.0, 0.5}, o), InputError);
  o.relative_tolerance = 0.0;
  EXPECT_THROW(integrate_esdirk(system, {1.0, 0.0}, {0.0, 1.0}, o), InputError);
}

const road::RoadInput& class_a_10s() {
  static const road::SpatialProfileRoad road = [] {
    road::Iso8608RoadParameters p;
    p.road_class = road::Iso8608Class::kA;
    p.random.speed_m_per_s = 50.0 / 3.6;
    p.random.duration_s = 10.0;
    p.random.seed = 7;
    return road::make_iso8608_road(p);
  }();
  return road;
}

// The largest |difference| in dB between two records' Welch PSDs over 0.5–30 Hz (1 s Hann
// segments, 50 % overlap: the same segments of the same road, so only the integrators differ).
double worst_psd_difference_dB(const std::vector<double>& a, const std::vector<double>& b) {
  signal::WelchOptions w;
  w.segment_length_s = 2.0;
  const auto pa = signal::welch_psd(a, 1000.0, w), pb = signal::welch_psd(b, 1000.0, w);
  double worst = 0.0;
  for (std::size_t k = 0; k < pa.psd.size(); ++k) {
    const double f = pa.frequency_Hz[k];
    if (f < 0.5 || f > 30.0) continue;
    worst = std::max(worst, std::abs(10.0 * std::log10(pa.psd[k] / pb.psd[k])));
  }
  return worst;
}

struct QuarterCarCase {
  std::string name;
  model::DamperState state;
  std::vector<std::pair<std::string, double>> keys;
};

void PrintTo(const QuarterCarCase& c, std::ostream* os) { *os << c.name; }

class QuarterCarAgainstCvode : public ::testing::TestWithParam<QuarterCarCase> {};

TEST_P(QuarterCarAgainstCvode, AccelerationRmsAndPsdAtTheDefaultTolerance) {
  auto file = testing::passat_corner();
  auto& p = file.parameters;
  p.coulomb_force_N = 60.0;
  for (const auto& [key, value] : GetParam().keys) {
    if (key == "ratio") p.compression_to_rebound_ratio = value;
    if (key == "knee") {
      p.damper_knee_velocity_m_per_s = value;
      p.damping_above_knee_Ns_per_m = 0.4 * p.damping_Ns_per_m;
    }
    if (key == "bump_stop") {
      p.bump_stop_stiffness_N_per_m = 1e5;
      p.bump_stop_clearance_m = value;
    }
    if (key == "lift_off") {
      p.tyre_lift_off = true;
      p.sprung_mass_kg *= value;  // light corner: the wheel leaves the road now and then
      p.unsprung_mass_kg *= value;
    }
    if (key == "stiffening") {
      p.top_mount_small_amplitude_stiffness_N_per_m = 707e3;
      p.top_mount_transition_deflection_m = value;
    }
    if (key == "stribeck") {
      p.static_friction_force_N = 90.0;
      p.stribeck_velocity_m_per_s = value;
    }
  }
  const model::QuarterCar car(GetParam().state, p);
  SimulationOptions reference_options;
  reference_options.integrator.method = Method::kCvodeBdf;
  reference_options.integrator.relative_tolerance = 1e-10;
  const auto reference = simulate(car, class_a_10s(), reference_options);
  const auto response = simulate(car, class_a_10s(), SimulationOptions{});
  EXPECT_EQ(response.statistics.method, "esdirk");
  for (const auto channel :
       {&QuarterCarResponse::body_acc_m_per_s2, &QuarterCarResponse::wheel_acc_m_per_s2}) {
    const double rms_ref = signal::rms(reference.*channel);
    const double rms = signal::rms(response.*channel);
    EXPECT_NEAR(rms, rms_ref, 1e-3 * rms_ref);
    EXPECT_LT(worst_psd_difference_dB(response.*channel, reference.*channel), 0.05);
  }
  // The kinks are located, not thrashed on: few rejected steps.
  const auto& stats = response.statistics;
  EXPECT_LT(stats.error_test_failures + stats.nonlinear_convergence_failures, stats.steps / 10);
}

INSTANTIATE_TEST_SUITE_P(
    EveryTopologyAndEffect, QuarterCarAgainstCvode,
    ::testing::Values(
        QuarterCarCase{"slip", model::DamperState::kSlip, {}},
        QuarterCarCase{"stick", model::DamperState::kStick, {}},
        QuarterCarCase{"stick_slip", model::DamperState::kStickSlip, {}},
        QuarterCarCase{"asymmetric", model::DamperState::kStickSlip, {{"ratio", 0.5}}},
        QuarterCarCase{"knee", model::DamperState::kSlip, {{"knee", 0.02}}},
        QuarterCarCase{"bump_stop", model::DamperState::kStickSlip, {{"bump_stop", 0.004}}},
        QuarterCarCase{"lift_off", model::DamperState::kSlip, {{"lift_off", 0.02}}},
        QuarterCarCase{"stiffening", model::DamperState::kStickSlip, {{"stiffening", 5e-4}}},
        QuarterCarCase{"stribeck", model::DamperState::kStickSlip, {{"stribeck", 0.004}}}),
    [](const ::testing::TestParamInfo<QuarterCarCase>& case_info) { return case_info.param.name; });

TEST(HalfCarAgainstCvode, StrutFrictionAtTheDefaultTolerance) {
  const model::HalfCar car =
      io::load_half_car(testing::dataset("vehicles/ajayi_half_car.yaml"),
                        {{"front.suspension", "strut"}, {"front.damper_state", "stick_slip"}})
          .make_model();
  HalfCarSimulationOptions reference_options;
  reference_options.integrator.method = Method::kCvodeBdf;
  reference_options.integrator.relative_tolerance = 1e-10;
  const auto reference = simulate(car, class_a_10s(), reference_options);
  const auto response = simulate(car, class_a_10s(), HalfCarSimulationOptions{});
  auto channel = [](const HalfCarResponse& r, double model::HalfCarOutputs::*member) {
    std::vector<double> v;
    for (const auto& s : r.samples) v.push_back(s.*member);
    return v;
  };
  for (const auto member :
       {&model::HalfCarOutputs::body_acc_m_per_s2, &model::HalfCarOutputs::front_wheel_acc_m_per_s2,
        &model::HalfCarOutputs::rear_wheel_acc_m_per_s2,
        &model::HalfCarOutputs::seat_acc_m_per_s2}) {
    const auto a = channel(response, member), b = channel(reference, member);
    EXPECT_NEAR(signal::rms(a), signal::rms(b), 1e-3 * signal::rms(b));
    EXPECT_LT(worst_psd_difference_dB(a, b), 0.05);
  }
}

}  // namespace
}  // namespace ridefit::simulate
