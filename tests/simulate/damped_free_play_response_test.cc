// A damped free play on the rig (free_play_damping_Ns_per_m): the plateau after each reversal
// that an MR damper on a press shows, against its closed form, by CVODE at rtol 1e-10 and by the
// strut solver; and its tangents against central differences of the solver's own scheme.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "ridefit/model/strut_test.h"
#include "ridefit/simulate/strut_test_response.h"
#include "support/cvode_rig_record.h"
#include "support/rig_tangent_check.h"

namespace ridefit::simulate {
namespace {

using model::StrutTestParameters;

constexpr double kSpeed = 0.02;      // m/s, the triangle's ramps
constexpr double kAmplitude = 2e-3;  // m
constexpr double kDamping = 6000.0;  // c
constexpr double kPlayDamping = 3000.0;
constexpr double kPlay = 4e-4;  // b

// A triangle from 0 up to +A, down to −A and back, at constant speed.
double triangle(double t) {
  const double quarter = kAmplitude / kSpeed;
  const double s = std::fmod(t, 4.0 * quarter);
  if (s < quarter) return kSpeed * s;
  if (s < 3.0 * quarter) return kAmplitude - kSpeed * (s - quarter);
  return -kAmplitude + kSpeed * (s - 3.0 * quarter);
}

StrutTestParameters<double> play_behind(double mount_N_per_m) {
  StrutTestParameters<double> p{};
  p.top_mount_stiffness_N_per_m = mount_N_per_m;
  p.damping_Ns_per_m = kDamping;
  p.dahl_sigma0_N_per_m = 1e6;
  p.coulomb_force_N = 0.0;  // no friction: the closed form is the dampers' alone
  p.free_play_m = kPlay;
  p.free_play_damping_Ns_per_m = kPlayDamping;
  return p;
}

struct Mount {
  const char* name;
  double stiffness_N_per_m;
};

class DampedFreePlay : public ::testing::TestWithParam<Mount> {};

// Closed form on the falling ramp after the top reversal (−v): while the slack (width b) is
// crossed the damper and c_p carry the motion in series, F = −v·c·c_p/(c + c_p) = −40 N, and the
// rig travels b·(c + c_p)/c = 0.6 mm before the play is taken up; then F = −c·v = −120 N. A
// rigid mount (1e9 N/m, the quasi-static path) and a compliant one (2e6 N/m, relaxation 3 ms).
TEST_P(DampedFreePlay, PlateauAfterAReversalIsTheDampersInSeries) {
  const auto p = play_behind(GetParam().stiffness_N_per_m);
  std::vector<double> t, x;
  for (int k = 0; k <= 800; ++k) {  // two periods at 1 kHz
    t.push_back(1e-3 * k);
    x.push_back(triangle(t.back()));
  }
  const auto reference = testing::cvode_rig_force(t, triangle, p);
  StrutTestSolverOptions linear;
  linear.interpolation = RigInterpolation::kLinear;  // the triangle's corners are at samples
  const auto solved = strut_test_force<double>(t, x, p, p, linear);
  ASSERT_TRUE(solved.has_value());
  const double plateau = -kSpeed * kDamping * kPlayDamping / (kDamping + kPlayDamping);
  const double sliding = -kSpeed * kDamping;
  const double take_up_m = kAmplitude - kPlay * (kDamping + kPlayDamping) / kDamping;
  for (const auto* force : {&reference, &*solved}) {
    SCOPED_TRACE(force == &reference ? "CVODE" : "ESDIRK");
    // Mid-plateau (x = 1.7 mm, t = 0.515 s) and well after the take-up (t = 0.58 s).
    EXPECT_NEAR((*force)[515], plateau, 0.01 * std::abs(plateau));
    EXPECT_NEAR((*force)[580], sliding, 0.01 * std::abs(sliding));
    // Where the force passes halfway between the two: the play is taken up there.
    double crossing_m = 0.0;
    for (std::size_t k = 501; k < 600; ++k) {
      const double half = 0.5 * (plateau + sliding);
      if ((*force)[k - 1] > half && (*force)[k] <= half) {
        const double share = ((*force)[k - 1] - half) / ((*force)[k - 1] - (*force)[k]);
        crossing_m = x[k - 1] + share * (x[k] - x[k - 1]);
        break;
      }
    }
    // Behind a rigid mount the play is taken up where the closed form says. A compliant mount
    // first unloads (c/k = 3 ms) before the slack opens and loads after it closes, which moves
    // the crossing by about 2·v·(c/k)·ln 2 more (0.1 mm): the solvers agree with each other there.
    if (GetParam().stiffness_N_per_m > 1e8) {
      EXPECT_NEAR(crossing_m, take_up_m, 1e-5) << crossing_m;
    }
  }
  // Everywhere but at the corners' own samples, where the rig's velocity jumps and a rigid path's
  // force with it (each solver takes another side of the jump).
  double worst = 0.0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (k % 100 == 0) continue;
    worst = std::max(worst, std::abs((*solved)[k] - reference[k]));
  }
  EXPECT_LT(worst, 0.005 * std::abs(sliding)) << worst;
  // A dry play carries nothing in its slack.
  auto dry = p;
  dry.free_play_damping_Ns_per_m = 0.0;
  const auto dry_force = strut_test_force<double>(t, x, dry, dry, linear);
  ASSERT_TRUE(dry_force.has_value());
  EXPECT_LT(std::abs((*dry_force)[515]), 0.02 * std::abs(plateau));
}

// The fit's derivatives: the Jets' tangents of the play's damping, its width and the damping
// match central differences of the same discrete scheme (steps frozen), with Dahl friction, on a
// sine behind a rigid mount (the press's setting: the quasi-static path) and a compliant one.
TEST_P(DampedFreePlay, TangentsMatchCentralDifferencesOfTheFrozenScheme) {
  StrutTestParameters<double> p = play_behind(GetParam().stiffness_N_per_m);
  p.coulomb_force_N = 150.0;
  p.dahl_sigma0_N_per_m = 5e6;
  p.dahl_exponent = 1.0;
  p.free_play_damping_Ns_per_m = 4e4;
  std::vector<double> t, x;
  for (int k = 0; k <= 1000; ++k) {  // one cycle at 1 Hz, ±5 mm, 1 kHz
    t.push_back(1e-3 * k);
    x.push_back(0.005 * std::sin(2.0 * std::numbers::pi * t.back()));
  }
  testing::expect_rig_tangents_match_frozen_differences(
      t, x, p, {"free_play_damping_Ns_per_m", "free_play_m", "damping_Ns_per_m"}, 1e-8);
}

INSTANTIATE_TEST_SUITE_P(Mounts, DampedFreePlay,
                         ::testing::Values(Mount{"rigid", 1e9}, Mount{"compliant", 2e6}),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

}  // namespace
}  // namespace ridefit::simulate
