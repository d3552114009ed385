// The strut rig model with a Stribeck level in its Dahl element: the hand-written Newton
// Jacobian still matches the templated equations (against CVODE, and its tangents against central
// differences, for the new parameters too), and the loop's friction share falls with the stroke
// speed, which a constant level cannot show.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <unsupported/Eigen/AutoDiff>
#include <vector>

#include "ridefit/simulate/esdirk_integrator.h"
#include "ridefit/simulate/integrator.h"
#include "ridefit/simulate/ode_system.h"
#include "ridefit/simulate/strut_test_response.h"
#include "ridefit/simulate/strut_test_system.h"
#include "support/cvode_rig_record.h"

namespace ridefit::simulate {
namespace {

// The Passat strut (σ0 5e6 N/m, Fc 60 N, k_tm 488 N/mm, c 887 Ns/m, no gas or offset) breaking
// away at Fs = 90 N and sliding at Fc above v_s = 5 mm/s.
model::StrutTestParameters<double> stribeck_strut(double dahl_exponent = 1.0) {
  auto p = model::dahl_strut_on_rig(5e6, 60.0, dahl_exponent, 488000.0, 887.0);
  p.static_friction_force_N = 90.0;
  p.stribeck_velocity_m_per_s = 0.005;
  return p;
}

TEST(StrutTestStribeck, FollowsCvodeOnTheSameEquations) {
  for (const double d : {1.0, 1.5}) {
    const auto p = stribeck_strut(d);
    std::vector<double> t, x;
    for (int k = 0; k <= 2100; ++k) {  // two cycles of 3 mm at 6 rad/s, 1 kHz
      t.push_back(k * 1e-3);
      x.push_back(std::sin(6.0 * t.back()) * 3e-3);
    }
    const std::vector<double> reference = testing::cvode_rig_force(
        t, [](double time) { return std::sin(6.0 * time) * 3e-3; }, p);
    // ESDIRK: the error falls with the tolerance; at the default it is within 2 % of Fc even at
    // the sharp breakaway after each reversal (the spline between the 1 kHz samples adds its
    // own small part there).
    std::vector<double> worst;
    for (const double rtol : {1e-5, 1e-7, 1e-9}) {
      StrutTestSolverOptions solver;
      solver.relative_tolerance = rtol;
      const auto force = strut_test_force<double>(t, x, p, p, solver);
      ASSERT_TRUE(force.has_value());
      double error = 0.0;
      for (std::size_t k = 1000; k < t.size(); ++k) {
        error = std::max(error, std::abs((*force)[k] - reference[k]));
      }
      worst.push_back(error);
    }
    EXPECT_LT(worst[1], 0.02 * p.coulomb_force_N) << "d " << d << ": " << worst[1];
    EXPECT_LT(worst[1], 0.2 * worst[0]) << "d " << d;
    EXPECT_LT(worst[2], std::max(0.2 * worst[1], 1e-3)) << "d " << d;
  }
}

// d(force)/d(Fs, v_s, Fc, c) through the implicit steps against central differences of the same
// discrete scheme: the Newton Jacobian's Stribeck terms are right (a wrong G would give wrong
// implicit-function tangents).
TEST(StrutTestStribeck, DerivativesMatchCentralDifferences) {
  using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, 4, 1>>;
  for (const double d : {1.0, 1.5}) {
    const auto p = stribeck_strut(d);
    std::vector<double> t, x;
    for (int k = 0; k <= 600; ++k) {
      t.push_back(k * 2e-3);
      x.push_back(std::sin(6.0 * t.back()) * 3e-3);
    }
    auto pa = p.cast<AD>();
    pa.coulomb_force_N = AD(p.coulomb_force_N, 4, 2);
    pa.damping_Ns_per_m = AD(p.damping_Ns_per_m, 4, 3);
    pa.static_friction_force_N = AD(p.static_friction_force_N, 4, 0);
    pa.stribeck_velocity_m_per_s = AD(p.stribeck_velocity_m_per_s, 4, 1);
    const auto jets = strut_test_force<AD>(t, x, pa, p);
    ASSERT_TRUE(jets.has_value());
    // Central differences of the same discrete map: the unperturbed run's steps, frozen.
    StrutTestSolverOptions frozen;
    const EsdirkStepHistory steps = strut_test_steps(t, x, p, frozen);
    frozen.frozen_steps = &steps;
    auto frozen_force = [&](const model::StrutTestParameters<double>& q) {
      return *strut_test_force<double>(t, x, q, q, frozen);
    };
    for (int j = 0; j < 4; ++j) {
      auto plus = p, minus = p;
      double* up[4] = {&plus.static_friction_force_N, &plus.stribeck_velocity_m_per_s,
                       &plus.coulomb_force_N, &plus.damping_Ns_per_m};
      double* down[4] = {&minus.static_friction_force_N, &minus.stribeck_velocity_m_per_s,
                         &minus.coulomb_force_N, &minus.damping_Ns_per_m};
      const double step = 1e-5 * *up[j];
      *up[j] += step;
      *down[j] -= step;
      const auto f_up = frozen_force(plus);
      const auto f_down = frozen_force(minus);
      double scale = 0.0, worst = 0.0;
      for (std::size_t k = 0; k < t.size(); ++k) {
        const double fd = (f_up[k] - f_down[k]) / (2.0 * step);
        const double exact =
            (*jets)[k].derivatives().size() == 4 ? (*jets)[k].derivatives()[j] : 0.0;
        scale = std::max(scale, std::abs(exact));
        worst = std::max(worst, std::abs(fd - exact));
      }
      EXPECT_GT(scale, 0.0) << "parameter " << j;
      EXPECT_LT(worst, 1e-5 * scale) << "parameter " << j << ", d " << d;
    }
  }
}

// On a triangle wave the damper slides at the stroke speed v between reversals, and the rig
// force settles on the plateau c·v + Fc(v). The classic element's friction share Fc is the same
// at every speed; with the Stribeck level it is Fs-like at a slow stroke (2 mm/s: 60 + 30·e^−0.16
// = 85.6 N) and Fc at a fast one (16 mm/s: 60.0 N): the loop is taller at low speed by more than
// its damping share explains.
TEST(StrutTestStribeck, SlowStrokesSeeMoreFriction) {
  const auto plateau = [](const model::StrutTestParameters<double>& p, double speed_m_per_s) {
    // ±2 mm at `speed`, two periods; the plateau at the middle of the second rising stroke.
    const double half_period_s = 0.004 / speed_m_per_s;
    std::vector<double> t, x;
    for (int k = 0; k <= 4000; ++k) {
      t.push_back(k * half_period_s / 1000.0);
      const double phase_s = std::fmod(t.back(), 2.0 * half_period_s);
      x.push_back(-0.002 + speed_m_per_s *
                               (phase_s < half_period_s ? phase_s : 2.0 * half_period_s - phase_s));
    }
    const auto force = strut_test_force<double>(t, x, p, p);
    EXPECT_TRUE(force.has_value());
    return (*force)[2500];
  };
  auto classic = stribeck_strut();
  classic.stribeck_velocity_m_per_s = 0.0;
  const auto stribeck = stribeck_strut();
  const double c = stribeck.damping_Ns_per_m;
  for (const double v : {0.002, 0.016}) {
    const double level = 60.0 + 30.0 * std::exp(-(v / 0.005) * (v / 0.005));
    EXPECT_NEAR(plateau(classic, v), c * v + 60.0, 0.3) << v;
    EXPECT_NEAR(plateau(stribeck, v), c * v + level, 0.3) << v;
  }
  // The friction share (plateau − c·v) falls with speed only with the Stribeck level.
  EXPECT_GT(plateau(stribeck, 0.002) - c * 0.002, plateau(stribeck, 0.016) - c * 0.016 + 20.0);
  EXPECT_NEAR(plateau(classic, 0.002) - c * 0.002, plateau(classic, 0.016) - c * 0.016, 0.3);
}

}  // namespace
}  // namespace ridefit::simulate
