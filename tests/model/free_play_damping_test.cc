// A free play whose slack resists being crossed (StrutDamperPath::flow): inside the slack the
// damper and the play's damping c_p carry the motion in series, once the play is taken up the path
// is the dry play's, and the damper's rate solves its force balance on every branch of its law.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ridefit/io/quarter_car_file.h"
#include "ridefit/model/free_play.h"
#include "ridefit/model/strut_damper_path.h"
#include "support/input_error_message.h"
#include "support/passat.h"
#include "support/temp_dir.h"

namespace ridefit::model {
namespace {

StrutDamperPath<double> damped_play(double c, double c_p) {
  StrutDamperPath<double> path{};
  path.top_mount = {2e6, 0.0, 0.0};
  path.damper = {c, 1.0, 0.0, 0.0};
  path.friction = {3e6, 0.0, 1.0};
  path.free_play_m = 1e-3;
  path.free_play_damping_Ns_per_m = c_p;
  return path;
}

// Closed form: in the middle of the slack the mount carries nothing, so c·z_c' = c_p·(z' − z_c'):
// z_c' = c_p·z'/(c + c_p) and the force c·c_p/(c + c_p)·z', the two dampers in series.
TEST(FreePlayDamping, InsideTheSlackTheDampersCarryTheMotionInSeries) {
  const double c = 3000.0, c_p = 1000.0, rate = 0.05;
  const auto path = damped_play(c, c_p);
  const auto flow = path.flow(2e-4, rate, 0.0, 0.0);
  EXPECT_NEAR(flow.damper_rate_m_per_s, c_p * rate / (c + c_p), 1e-15);
  EXPECT_NEAR(flow.force_N, c * c_p / (c + c_p) * rate, 1e-12);
  // A locked damper's path: c_p at the travel rate.
  EXPECT_NEAR(path.stuck_force_N(2e-4, rate), c_p * rate, 1e-12);
  // A dry play carries nothing there.
  EXPECT_EQ(damped_play(c, 0.0).flow(2e-4, rate, 0.0, 0.0).force_N, 0.0);
}

// Once the play is taken up (D' = 1) its damping is gone: the flow is the dry play's, bit for bit.
TEST(FreePlayDamping, ATakenUpPlayIsTheDryPlays) {
  const auto damped = damped_play(3000.0, 1000.0);
  const auto dry = damped_play(3000.0, 0.0);
  for (const double travel : {0.002, -0.003}) {
    const auto a = damped.flow(travel, 0.1, 1e-4, 20.0);
    const auto b = dry.flow(travel, 0.1, 1e-4, 20.0);
    EXPECT_EQ(a.force_N, b.force_N);
    EXPECT_EQ(a.damper_rate_m_per_s, b.damper_rate_m_per_s);
  }
  // Across the rounded corner the damping fades with 1 − D'.
  const double corner = 0.5e-3;  // b/2: D' = 1/2
  EXPECT_NEAR(damped.slack_damping_Ns_per_m(corner), 500.0, 1e-9);
  EXPECT_EQ(damped.slack_damping_Ns_per_m(0.0), 1000.0);
}

// The damper's rate with the play's damping in parallel solves g(u) + c_q·u = F_tm + c_q·z' − F_f
// on every branch: rebound and compression, below and above the knee, with the friction's force.
TEST(FreePlayDamping, TheDampersRateSolvesItsBalanceOnEveryBranch) {
  auto path = damped_play(4000.0, 2500.0);
  path.damper = {4000.0, 0.4, 0.05, 900.0};  // asymmetric, with a knee
  for (const double z_rate : {-2.0, -0.3, -0.02, 0.0, 0.01, 0.2, 1.5}) {
    for (const double friction : {-50.0, 0.0, 80.0}) {
      for (const double deflection : {0.0, 3e-4, 4.95e-4, -5.02e-4}) {
        const auto flow = path.flow(deflection, z_rate, 0.0, friction);
        const double u = flow.damper_rate_m_per_s;
        const double c_q = path.slack_damping_Ns_per_m(deflection);
        const double spring =
            path.top_mount.force_N(free_play_deflection_m(deflection, path.free_play_m));
        SCOPED_TRACE(::testing::Message()
                     << "z' " << z_rate << ", F_f " << friction << ", delta " << deflection);
        // The force balance on both sides of the damper.
        EXPECT_NEAR(path.damper.force_N(u) + c_q * u, spring + c_q * z_rate - friction,
                    1e-9 * (1.0 + std::abs(spring) + std::abs(friction)));
        EXPECT_NEAR(flow.force_N, path.damper.force_N(u) + friction,
                    1e-9 * (1.0 + std::abs(flow.force_N)));
      }
    }
  }
}

// A model file: the damping needs free play, and its range is checked; the error names the key.
TEST(FreePlayDamping, AModelFileTakesItOnlyWithFreePlay) {
  const testing::TempDir dir("free_play_damping");
  const auto base = testing::dataset("vehicles/passat_b8_front.yaml");
  const auto with_play = io::load_quarter_car(
      base, {{"free_play_m", "0.0005"}, {"free_play_damping_Ns_per_m", "40000"}});
  EXPECT_EQ(with_play.parameters.free_play_damping_Ns_per_m, 40000.0);
  const std::string alone = testing::input_error_message([&] {
    io::load_quarter_car(base, {{"free_play_damping_Ns_per_m", "40000"}});
  });
  EXPECT_NE(alone.find("free_play_damping_Ns_per_m"), std::string::npos) << alone;
  EXPECT_NE(alone.find("free_play_m > 0"), std::string::npos) << alone;
  const std::string negative = testing::input_error_message([&] {
    io::load_quarter_car(base, {{"free_play_m", "0.0005"}, {"free_play_damping_Ns_per_m", "-1"}});
  });
  EXPECT_NE(negative.find("free_play_damping_Ns_per_m"), std::string::npos) << negative;
}

}  // namespace
}  // namespace ridefit::model
