// A damper whose force above the knee grows as a power of the speed (AsymmetricDamper's
// exponent_above_knee, damping_above_knee_exponent in the model files): the law at closed-form
// points, its inverse with and without a free play's damping in parallel, its Jets against central
// differences, and the rig's force on a constant-speed ramp by CVODE and by the strut solver.
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "ridefit/model/asymmetric_damper.h"
#include "ridefit/model/strut_test.h"
#include "ridefit/simulate/strut_test_response.h"
#include "support/cvode_rig_record.h"
#include "support/rig_tangent_check.h"

namespace ridefit::model {
namespace {

// c_r 4000 N·s/m, r 0.6, knee at 0.02 m/s, 800 N·s/m above it, growing as |v|^0.5.
AsymmetricDamper<double> damper(double n) { return {4000.0, 0.6, 0.02, 800.0, n}; }

// Closed form: at v = 4·v_k with n = 1/2, F = c_r·v_k + c_h·v_k·(2 − 1)/(1/2) = 80 + 32 N.
TEST(KneeExponent, LawAtClosedFormPoints) {
  const auto d = damper(0.5);
  EXPECT_NEAR(d.force_N(0.08), 80.0 + 32.0, 1e-12);
  EXPECT_NEAR(d.force_N(-0.08), -0.6 * (80.0 + 32.0), 1e-12);
  EXPECT_EQ(d.force_N(0.01), 40.0);  // below the knee as before
  // Continuous at the knee, with the slope c_h just above it and c_h·(v/v_k)^(n−1) beyond.
  EXPECT_NEAR(d.force_N(0.02 * (1.0 + 1e-12)), 80.0, 1e-9);
  const double h = 1e-7;
  EXPECT_NEAR((d.force_N(0.02 + 2 * h) - d.force_N(0.02 + h)) / h, 800.0, 0.01);
  EXPECT_NEAR((d.force_N(0.08 + h) - d.force_N(0.08 - h)) / (2 * h), 800.0 * 0.5, 1e-4);
  // n → 0 is the logarithm: c_r·v_k + c_h·v_k·ln(v/v_k).
  EXPECT_NEAR(damper(1e-6).force_N(0.2), 80.0 + 800.0 * 0.02 * std::log(10.0), 1e-3);
  // n = 1 is the straight slope, bit for bit.
  const AsymmetricDamper<double> straight{4000.0, 0.6, 0.02, 800.0};
  for (const double v : {-0.5, -0.05, 0.03, 0.7})
    EXPECT_EQ(damper(1.0).force_N(v), straight.force_N(v));
  EXPECT_FALSE(damper(0.5).linear());
  EXPECT_FALSE((AsymmetricDamper<double>{4000.0, 1.0, 0.02, 4000.0, 0.5}.linear()));
}

// The inverse undoes the law on every branch, and with a dashpot c_q in parallel it solves
// F(u) + c_q·u = force (a damped free play's slack, strut_damper_path.h), digressive and
// progressive alike.
TEST(KneeExponent, InverseUndoesTheLawWithAndWithoutAParallelDashpot) {
  for (const double n : {0.3, 0.5, 1.0, 1.8}) {
    const auto d = damper(n);
    for (const double c_q : {0.0, 500.0, 3e4}) {
      for (const double v : {-2.0, -0.3, -0.021, -0.01, 0.0, 0.015, 0.025, 0.4, 3.0}) {
        const double force = d.force_N(v) + c_q * v;
        SCOPED_TRACE(::testing::Message() << "n " << n << ", c_q " << c_q << ", v " << v);
        EXPECT_NEAR(d.rate_m_per_s(force, c_q), v, 1e-12 * (1.0 + std::abs(v)));
      }
    }
  }
}

TEST(KneeExponent, JetDerivativesMatchCentralDifferences) {
  using Jet = ceres::Jet<double, 3>;  // d/dv_k, d/dc_h, d/dn
  const double v_k = 0.02, c_h = 800.0, n = 0.4;
  const AsymmetricDamper<Jet> jets{Jet(4000.0), Jet(0.6), Jet(v_k, 0), Jet(c_h, 1), Jet(n, 2)};
  for (const double v : {0.05, 0.6, -0.3}) {
    const Jet f = jets.force_N(Jet(v));
    const double values[3] = {v_k, c_h, n};
    for (int j = 0; j < 3; ++j) {
      double up[3] = {values[0], values[1], values[2]}, down[3] = {values[0], values[1], values[2]};
      const double step = 1e-6 * values[j];
      up[j] += step;
      down[j] -= step;
      const AsymmetricDamper<double> a{4000.0, 0.6, up[0], up[1], up[2]};
      const AsymmetricDamper<double> b{4000.0, 0.6, down[0], down[1], down[2]};
      const double fd = (a.force_N(v) - b.force_N(v)) / (2.0 * step);
      EXPECT_NEAR(f.v[j], fd, 1e-6 * (1.0 + std::abs(fd))) << "v " << v << ", parameter " << j;
    }
    // And through the inverse, with and without a parallel dashpot (Newton's root: its
    // derivative is the implicit function's, −(∂φ/∂θ)/φ').
    for (const double c_q : {0.0, 3e4}) {
      const double force = AsymmetricDamper<double>{4000.0, 0.6, v_k, c_h, n}.force_N(v) + c_q * v;
      const Jet u = jets.rate_m_per_s(Jet(force), Jet(c_q));
      EXPECT_NEAR(u.a, v, 1e-12);
      for (int j = 0; j < 3; ++j) {
        double up[3] = {v_k, c_h, n}, down[3] = {v_k, c_h, n};
        const double step = 1e-6 * up[j];
        up[j] += step;
        down[j] -= step;
        const AsymmetricDamper<double> a{4000.0, 0.6, up[0], up[1], up[2]};
        const AsymmetricDamper<double> b{4000.0, 0.6, down[0], down[1], down[2]};
        const double fd = (a.rate_m_per_s(force, c_q) - b.rate_m_per_s(force, c_q)) / (2.0 * step);
        EXPECT_NEAR(u.v[j], fd, 1e-6 * (1.0 + std::abs(fd)))
            << "inverse, v " << v << ", c_q " << c_q << ", parameter " << j;
      }
    }
  }
}

// The rig: a triangle at 0.1 m/s (five times the knee) behind a rigid mount (the quasi-static
// path: the law itself) and a compliant one (the Maxwell path: its inverse), no friction. Mid-ramp
// the force is the law's, by CVODE and by the strut solver.
TEST(KneeExponent, RigForceOnAConstantSpeedRampIsTheLaws) {
  const double speed = 0.1, amplitude = 0.01;
  auto triangle = [&](double t) {
    const double quarter = amplitude / speed;
    const double s = std::fmod(t, 4.0 * quarter);
    if (s < quarter) return speed * s;
    if (s < 3.0 * quarter) return amplitude - speed * (s - quarter);
    return -amplitude + speed * (s - 3.0 * quarter);
  };
  for (const double mount : {1e9, 5e6}) {
    StrutTestParameters<double> p{};
    p.top_mount_stiffness_N_per_m = mount;
    p.damping_Ns_per_m = 4000.0;
    p.compression_to_rebound_ratio = 0.6;
    p.damper_knee_velocity_m_per_s = 0.02;
    p.damping_above_knee_Ns_per_m = 800.0;
    p.damping_above_knee_exponent = 0.5;
    p.dahl_sigma0_N_per_m = 1e6;
    std::vector<double> t, x;
    for (int k = 0; k <= 800; ++k) {  // two periods at 2 kHz
      t.push_back(5e-4 * k);
      x.push_back(triangle(t.back()));
    }
    const auto reference = testing::cvode_rig_force(t, triangle, p);
    simulate::StrutTestSolverOptions linear;
    linear.interpolation = simulate::RigInterpolation::kLinear;
    const auto solved = simulate::strut_test_force<double>(t, x, p, p, linear);
    ASSERT_TRUE(solved.has_value());
    const auto law = damper(0.5);
    SCOPED_TRACE(::testing::Message() << "mount " << mount);
    // t = 0.25 s: the falling ramp's middle (compression, −v); t = 0.35 s: rebound (+v).
    EXPECT_NEAR(reference[500], law.force_N(-speed), 1e-3 * std::abs(law.force_N(-speed)));
    EXPECT_NEAR((*solved)[500], law.force_N(-speed), 1e-3 * std::abs(law.force_N(-speed)));
    EXPECT_NEAR(reference[700], law.force_N(speed), 1e-3 * law.force_N(speed));
    EXPECT_NEAR((*solved)[700], law.force_N(speed), 1e-3 * law.force_N(speed));
  }
}

// The fit's derivatives on the rig: the exponent's, the knee's and the slope's tangents against
// central differences of the frozen scheme, behind a compliant mount (the inverse's Newton root
// is differentiated) with a damped free play, and behind a rigid one (the law itself).
TEST(KneeExponent, RigTangentsMatchCentralDifferencesOfTheFrozenScheme) {
  for (const double mount : {1e9, 2e6}) {
    StrutTestParameters<double> p{};
    p.top_mount_stiffness_N_per_m = mount;
    p.damping_Ns_per_m = 4000.0;
    p.damper_knee_velocity_m_per_s = 0.02;
    p.damping_above_knee_Ns_per_m = 800.0;
    p.damping_above_knee_exponent = 0.4;
    p.dahl_sigma0_N_per_m = 5e6;
    p.coulomb_force_N = 100.0;
    p.free_play_m = 2e-4;
    p.free_play_damping_Ns_per_m = 3e4;
    std::vector<double> t, x;
    for (int k = 0; k <= 1000; ++k) {  // one cycle at 2 Hz, ±8 mm (to 0.1 m/s), 2 kHz
      t.push_back(5e-4 * k);
      x.push_back(0.008 * std::sin(4.0 * std::numbers::pi * t.back()));
    }
    SCOPED_TRACE(::testing::Message() << "mount " << mount);
    testing::expect_rig_tangents_match_frozen_differences(
        t, x, p,
        {"damping_above_knee_exponent", "damper_knee_velocity_m_per_s",
         "damping_above_knee_Ns_per_m"},
        1e-8);
  }
}

}  // namespace
}  // namespace ridefit::model
