#include "ridefit/model/dahl_friction.h"

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include <cmath>
#include <numbers>

#include "ridefit/simulate/integrator.h"

namespace ridefit::model {
namespace {

constexpr double kSigma0 = 5.0e6;
constexpr double kFc = 60.0;

// Friction force under a prescribed displacement x(t) = X·sin(ωt) (or x = v·t).
class DrivenDahl : public simulate::OdeSystem {
 public:
  DrivenDahl(DahlFriction<double> dahl, double amplitude_m, double omega, bool ramp)
      : dahl_(dahl), amplitude_m_(amplitude_m), omega_(omega), ramp_(ramp) {}
  double displacement(double t) const {
    return ramp_ ? amplitude_m_ * t : amplitude_m_ * std::sin(omega_ * t);
  }
  double velocity(double t) const {
    return ramp_ ? amplitude_m_ : amplitude_m_ * omega_ * std::cos(omega_ * t);
  }
  int size() const override { return 1; }
  double max_step_s() const override { return 0.0; }
  bool derivatives(double t, const double* x, double* xdot) const override {
    xdot[0] = dahl_.force_rate_N_per_s(x[0], velocity(t));
    return true;
  }
  bool jacobian(double t, const double* x, double* j) const override {
    using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, 1, 1>>;
    const DahlFriction<AD> dahl{AD(dahl_.sigma0_N_per_m), AD(dahl_.coulomb_force_N),
                                AD(dahl_.exponent)};
    const AD rate = dahl.force_rate_N_per_s(AD(x[0], 1, 0), AD(velocity(t)));
    j[0] = rate.derivatives().size() == 1 ? rate.derivatives()[0] : 0.0;
    return true;
  }
  double typical_magnitude(int) const override { return kFc; }

 private:
  DahlFriction<double> dahl_;
  double amplitude_m_, omega_;
  bool ramp_;
};

TEST(DahlFriction, PreSlidingCurveFromRestMatchesClosedForm) {
  const DahlFriction<double> dahl{kSigma0, kFc, 1.0};
  const double velocity = 1e-3;  // 1 mm/s, the seed's quasi-static test speed
  const DrivenDahl system(dahl, velocity, 0.0, /*ramp=*/true);
  std::vector<double> times;
  for (int k = 0; k <= 200; ++k) times.push_back(k * 1e-4);  // up to 20 µm of travel
  simulate::IntegratorOptions options;
  options.relative_tolerance = 1e-10;
  const auto trajectory = simulate::integrate(system, {0.0}, times, options);
  for (std::size_t k = 0; k < times.size(); ++k) {
    const double x = velocity * times[k];
    const double expected = kFc * (1.0 - std::exp(-kSigma0 * x / kFc));
    ASSERT_NEAR(trajectory.state_at(k)[0], expected, 1e-6 * kFc) << "x = " << x;
  }
  // The initial slope is σ0 and the force tends to Fc.
  EXPECT_NEAR(dahl.force_rate_N_per_s(0.0, 1.0), kSigma0, 1e-9 * kSigma0);
  EXPECT_NEAR(trajectory.states.back(), kFc * (1.0 - std::exp(-kSigma0 * 20e-6 / kFc)), 1e-4);
}

TEST(DahlFriction, SteadyLoopTurningForceAndEnergyMatchClosedForm) {
  // d = 1 is rate independent; on a steady loop of amplitude X the turning force is
  // Fc·tanh(σ0·X/Fc) and the energy per cycle
  // 2·[2·X·Fc − (Fc + F_t)·(Fc/σ0)·(1 − exp(−2σ0X/Fc))].
  const DahlFriction<double> dahl{kSigma0, kFc, 1.0};
  const double amplitude = 20e-6;  // comparable to Fc/σ0 = 12 µm so the loop is rounded
  const double omega = 2.0 * std::numbers::pi;
  const DrivenDahl system(dahl, amplitude, omega, false);
  const int per_cycle = 4000;
  const int cycles = 4;
  std::vector<double> times;
  for (int k = 0; k <= per_cycle * cycles; ++k) times.push_back(k * 1.0 / per_cycle);
  simulate::IntegratorOptions options;
  options.relative_tolerance = 1e-10;
  const auto trajectory = simulate::integrate(system, {0.0}, times, options);

  const double turning = kFc * std::tanh(kSigma0 * amplitude / kFc);
  const double energy =
      2.0 * (2.0 * amplitude * kFc - (kFc + turning) * (kFc / kSigma0) *
                                         (1.0 - std::exp(-2.0 * kSigma0 * amplitude / kFc)));
  // Turning point of the last cycle: x = +X at t = (cycles − 1 + 1/4) s.
  const std::size_t k_turn = static_cast<std::size_t>((cycles - 1) * per_cycle + per_cycle / 4);
  EXPECT_NEAR(trajectory.state_at(k_turn)[0], turning, 1e-4 * kFc);
  double work = 0.0;
  for (std::size_t k = static_cast<std::size_t>((cycles - 1) * per_cycle); k < times.size() - 1;
       ++k) {
    const double dx = system.displacement(times[k + 1]) - system.displacement(times[k]);
    work += 0.5 * (trajectory.state_at(k)[0] + trajectory.state_at(k + 1)[0]) * dx;
  }
  EXPECT_NEAR(work, energy, 2e-3 * energy);
  EXPECT_GT(work, 0.0);
}

TEST(DahlFriction, KinkAtZeroVelocityIsContinuousWithOneSidedSlopes) {
  const DahlFriction<double> dahl{kSigma0, kFc, 1.0};
  const double force = 20.0;
  const double eps = 1e-9;
  // Continuous: both sides tend to zero.
  EXPECT_DOUBLE_EQ(dahl.force_rate_N_per_s(force, 0.0), 0.0);
  EXPECT_NEAR(dahl.force_rate_N_per_s(force, eps), 0.0, 1e-2);
  EXPECT_NEAR(dahl.force_rate_N_per_s(force, -eps), 0.0, 1e-2);
  // Slopes: σ0(1 − F/Fc) for v > 0, σ0(1 + F/Fc) for v < 0.
  EXPECT_NEAR(dahl.force_rate_N_per_s(force, eps) / eps, kSigma0 * (1.0 - force / kFc), 1.0);
  EXPECT_NEAR(dahl.force_rate_N_per_s(force, -eps) / -eps, kSigma0 * (1.0 + force / kFc), 1.0);
  // The exact derivative at v = 0 takes the v > 0 branch, as documented.
  using AD = Eigen::AutoDiffScalar<Eigen::Vector2d>;
  const DahlFriction<AD> dahl_ad{AD(kSigma0), AD(kFc), AD(1.0)};
  const AD rate = dahl_ad.force_rate_N_per_s(AD(force, 2, 0), AD(0.0, 2, 1));
  EXPECT_NEAR(rate.derivatives()[1], kSigma0 * (1.0 - force / kFc), 1e-6 * kSigma0);
  EXPECT_DOUBLE_EQ(rate.derivatives()[0], 0.0);
}

TEST(DahlFriction, ExponentShapesTheApproachToCoulombForce) {
  // With d = 2 the force still tends to Fc but approaches it faster at first
  // (|1 − F/Fc|² < |1 − F/Fc|) — and a force above Fc is driven back.
  const DahlFriction<double> d1{kSigma0, kFc, 1.0};
  const DahlFriction<double> d2{kSigma0, kFc, 2.0};
  EXPECT_NEAR(d2.force_rate_N_per_s(30.0, 1.0), kSigma0 * 0.25, 1e-6 * kSigma0);
  EXPECT_LT(d2.force_rate_N_per_s(30.0, 1.0), d1.force_rate_N_per_s(30.0, 1.0));
  EXPECT_LT(d1.force_rate_N_per_s(66.0, 1.0), 0.0);
  EXPECT_LT(d2.force_rate_N_per_s(66.0, 1.0), 0.0);
  // No friction at Fc = 0.
  const DahlFriction<double> none{kSigma0, 0.0, 1.0};
  EXPECT_DOUBLE_EQ(none.force_rate_N_per_s(0.0, 1.0), 0.0);
}

}  // namespace
}  // namespace ridefit::model
