#include "ridefit/simulate/modal_analysis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "ridefit/common/errors.h"

namespace ridefit::simulate {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// x = [z, ż]: m z̈ + c ż + k z = 0.
Eigen::MatrixXd single_dof(double m, double c, double k) {
  Eigen::MatrixXd a(2, 2);
  a << 0.0, 1.0, -k / m, -c / m;
  return a;
}

TEST(ModalAnalysis, SingleDofMatchesClosedForm) {
  const double m = 350.0, c = 1800.0, k = 22'000.0;
  const ModalAnalysis modes = analyse_modes(single_dof(m, c, k), {{"body", m, 0}});
  ASSERT_EQ(modes.oscillatory.size(), 1u);
  EXPECT_TRUE(modes.real.empty());
  const OscillatoryMode& mode = modes.oscillatory[0];
  const double fn = std::sqrt(k / m) / kTwoPi;
  const double zeta = c / (2.0 * std::sqrt(k * m));
  EXPECT_NEAR(mode.natural_frequency_Hz, fn, 1e-9 * fn);
  EXPECT_NEAR(mode.damping_ratio, zeta, 1e-9 * zeta);
  EXPECT_NEAR(mode.damped_frequency_Hz, fn * std::sqrt(1.0 - zeta * zeta), 1e-9 * fn);
  EXPECT_GT(mode.eigenvalue.imag(), 0.0);
  EXPECT_EQ(mode.dominant_dof, "body");
  ASSERT_EQ(mode.energy_share.size(), 1u);
  EXPECT_DOUBLE_EQ(mode.energy_share[0], 1.0);
}

TEST(ModalAnalysis, OverdampedSingleDofGivesTwoRealModes) {
  const double m = 2.0, c = 100.0, k = 200.0;  // ζ = 2.5
  const ModalAnalysis modes = analyse_modes(single_dof(m, c, k), {{"mass", m, 0}});
  EXPECT_TRUE(modes.oscillatory.empty());
  ASSERT_EQ(modes.real.size(), 2u);
  const double wn = std::sqrt(k / m), zeta = c / (2.0 * std::sqrt(k * m));
  const double slow = wn * (-zeta + std::sqrt(zeta * zeta - 1.0));
  const double fast = wn * (-zeta - std::sqrt(zeta * zeta - 1.0));
  EXPECT_NEAR(modes.real[0].eigenvalue_per_s, slow, 1e-9 * std::abs(slow));
  EXPECT_NEAR(modes.real[1].eigenvalue_per_s, fast, 1e-9 * std::abs(fast));
  EXPECT_NEAR(modes.real[0].time_constant_s, -1.0 / slow, 1e-9 / std::abs(slow));
  EXPECT_EQ(modes.real[0].dominant_dof, "mass");
}

TEST(ModalAnalysis, UndampedQuarterCarMatchesCharacteristicRoots) {
  const double ms = 420.0, mu = 45.0, ks = 24'000.0, kt = 230'000.0;
  // x = [zs, zu, żs, żu]; suspension ks between the masses, tyre kt from wheel to ground.
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(4, 4);
  a(0, 2) = 1.0;
  a(1, 3) = 1.0;
  a(2, 0) = -ks / ms;
  a(2, 1) = ks / ms;
  a(3, 0) = ks / mu;
  a(3, 1) = -(ks + kt) / mu;
  const ModalAnalysis modes = analyse_modes(a, {{"body", ms, 0}, {"wheel", mu, 1}});
  ASSERT_EQ(modes.oscillatory.size(), 2u);
  EXPECT_TRUE(modes.real.empty());

  // ω⁴ − ω²(ks/ms + (ks+kt)/mu) + ks·kt/(ms·mu) = 0
  const double b = ks / ms + (ks + kt) / mu, c = ks * kt / (ms * mu);
  const double disc = std::sqrt(b * b - 4.0 * c);
  const double f_low = std::sqrt((b - disc) / 2.0) / kTwoPi;
  const double f_high = std::sqrt((b + disc) / 2.0) / kTwoPi;
  const OscillatoryMode& low = modes.oscillatory[0];
  const OscillatoryMode& high = modes.oscillatory[1];
  EXPECT_NEAR(low.natural_frequency_Hz, f_low, 1e-9 * f_low);
  EXPECT_NEAR(high.natural_frequency_Hz, f_high, 1e-9 * f_high);
  EXPECT_NEAR(low.damped_frequency_Hz, f_low, 1e-9 * f_low);
  EXPECT_NEAR(low.damping_ratio, 0.0, 1e-9);
  EXPECT_NEAR(high.damping_ratio, 0.0, 1e-9);
  EXPECT_EQ(low.dominant_dof, "body");
  EXPECT_EQ(high.dominant_dof, "wheel");
  EXPECT_GT(low.energy_share[0], 0.9);
  EXPECT_GT(high.energy_share[1], 0.9);
  EXPECT_NEAR(low.energy_share[0] + low.energy_share[1], 1.0, 1e-12);

  // Energy shares from the mode shape: for ω², the wheel/body amplitude ratio is
  // u = (ks − ms ω²)/ks (from the body's equation), so share_body = ms/(ms + mu u²).
  const double w2 = (b - disc) / 2.0, u = (ks - ms * w2) / ks;
  EXPECT_NEAR(low.energy_share[0], ms / (ms + mu * u * u), 1e-9);
}

TEST(ModalAnalysis, MaxwellElementGivesOneRealMode) {
  // Mass on a spring k to ground, in parallel with a Maxwell element (spring k2 in series
  // with damper c). x = [z, ż, zc]: c żc = k2 (z − zc), m z̈ = −k z − k2 (z − zc).
  const double m = 300.0, k = 20'000.0, k2 = 150'000.0, c = 3'000.0;
  Eigen::MatrixXd a(3, 3);
  a << 0.0, 1.0, 0.0,              //
      -(k + k2) / m, 0.0, k2 / m,  //
      k2 / c, 0.0, -k2 / c;
  const ModalAnalysis modes = analyse_modes(a, {{"body", m, 0}});
  ASSERT_EQ(modes.oscillatory.size(), 1u);
  ASSERT_EQ(modes.real.size(), 1u);

  // Characteristic polynomial m c s³ + m k2 s² + (k + k2) c s + k k2 = 0 at every root.
  const auto residual = [&](std::complex<double> s) {
    return std::abs(m * c * s * s * s + m * k2 * s * s + (k + k2) * c * s + k * k2) / (k * k2);
  };
  const RealMode& real = modes.real[0];
  const OscillatoryMode& osc = modes.oscillatory[0];
  EXPECT_LT(residual(real.eigenvalue_per_s), 1e-10);
  EXPECT_LT(residual(osc.eigenvalue), 1e-10);
  // Sum of the roots is the trace −k2/c.
  EXPECT_NEAR(real.eigenvalue_per_s + 2.0 * osc.eigenvalue.real(), -k2 / c, 1e-9 * k2 / c);
  EXPECT_LT(real.eigenvalue_per_s, 0.0);
  EXPECT_NEAR(real.time_constant_s, -1.0 / real.eigenvalue_per_s, 1e-15);
  // The oscillation lies between the soft (k) and stiff (k + k2) limits, and is damped.
  EXPECT_GT(osc.natural_frequency_Hz, std::sqrt(k / m) / kTwoPi);
  EXPECT_LT(osc.natural_frequency_Hz, std::sqrt((k + k2) / m) / kTwoPi);
  EXPECT_GT(osc.damping_ratio, 0.0);
  EXPECT_EQ(osc.dominant_dof, "body");
}

TEST(ModalAnalysis, FreeIntegratorHasInfiniteTimeConstantAndNoDof) {
  // A lone friction-like state with zero dynamics alongside a 1-DOF oscillator.
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(3, 3);
  a.topLeftCorner(2, 2) = single_dof(1.0, 0.0, 4.0);
  const ModalAnalysis modes = analyse_modes(a, {{"body", 1.0, 0}});
  ASSERT_EQ(modes.real.size(), 1u);
  EXPECT_EQ(modes.real[0].time_constant_s, std::numeric_limits<double>::infinity());
  EXPECT_EQ(modes.real[0].dominant_dof, "");
  EXPECT_EQ(modes.real[0].energy_share[0], 0.0);
  ASSERT_EQ(modes.oscillatory.size(), 1u);
  EXPECT_NEAR(modes.oscillatory[0].natural_frequency_Hz, 2.0 / kTwoPi, 1e-12);
}

TEST(ModalAnalysis, BadInputsThrow) {
  const Eigen::MatrixXd a = single_dof(1.0, 0.1, 1.0);
  EXPECT_THROW(analyse_modes(Eigen::MatrixXd(2, 3), {}), InputError);
  EXPECT_THROW(analyse_modes(Eigen::MatrixXd(0, 0), {}), InputError);
  Eigen::MatrixXd nan = a;
  nan(1, 0) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(analyse_modes(nan, {{"body", 1.0, 0}}), InputError);
  EXPECT_THROW(analyse_modes(a, {{"body", 0.0, 0}}), InputError);
  EXPECT_THROW(analyse_modes(a, {{"body", 1.0, 2}}), InputError);
  EXPECT_THROW(analyse_modes(a, {{"body", 1.0, -1}}), InputError);
  EXPECT_THROW(analyse_modes(a, {{"", 1.0, 0}}), InputError);
  EXPECT_THROW(analyse_modes(a, {{"body", 1.0, 0}, {"body", 1.0, 1}}), InputError);
  EXPECT_THROW(analyse_modes(a, {{"body", 1.0, 0}, {"wheel", 1.0, 0}}), InputError);
}

}  // namespace
}  // namespace ridefit::simulate
