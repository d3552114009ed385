// The rebound/compression split of the damper (AsymmetricDamper, compression_to_rebound_ratio):
// the law itself, and in the quarter car and both kinds of half-car axle. Numbers are the
// Passat corner's (c_r = 886.9 Ns/m, k_tm = 488 N/mm) and the Ajayi half car's (c_r =
// 1000 Ns/m).
#include "ridefit/model/asymmetric_damper.h"

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/io/half_car_file.h"
#include "ridefit/model/half_car.h"
#include "ridefit/model/quarter_car.h"
#include "ridefit/simulate/half_car_state_space.h"
#include "ridefit/simulate/quarter_car_modes.h"
#include "support/passat.h"
#include "support/throws_input_error.h"

namespace ridefit::model {
namespace {

io::HalfCarFile ajayi(const io::ModelOverrides& overrides = {}) {
  return io::load_half_car(testing::dataset("vehicles/ajayi_half_car.yaml"), overrides);
}

TEST(AsymmetricDamper, ReboundCoefficientInExtensionAndRatioTimesItInCompression) {
  const AsymmetricDamper<double> damper{2000.0, 0.5};
  EXPECT_EQ(damper.force_N(0.3), 600.0);    // c_r·v
  EXPECT_EQ(damper.force_N(-0.3), -300.0);  // −0.5·c_r·0.3
  EXPECT_EQ(damper.force_N(0.0), 0.0);
  EXPECT_EQ(damper.damping_Ns_per_m(0.3), 2000.0);
  EXPECT_EQ(damper.damping_Ns_per_m(-0.3), 1000.0);
  // The inverse picks its branch from the force's sign.
  EXPECT_EQ(damper.rate_m_per_s(600.0), 0.3);
  EXPECT_EQ(damper.rate_m_per_s(-300.0), -0.3);
  EXPECT_FALSE(damper.symmetric());
  const AsymmetricDamper<double> linear{2000.0};  // the default ratio
  EXPECT_TRUE(linear.symmetric());
  EXPECT_EQ(linear.force_N(-0.3), -600.0);
}

// Jets follow the branch of their value: in compression the force depends on the ratio
// (∂F/∂r = c_r·v), in rebound it does not.
TEST(AsymmetricDamper, JetDerivativeWithRespectToTheRatioIsOneSided) {
  using Jet = ceres::Jet<double, 2>;  // d/dc_r, d/dr
  const AsymmetricDamper<Jet> damper{Jet(2000.0, 0), Jet(0.5, 1)};
  const Jet compression = damper.force_N(Jet(-0.3));
  EXPECT_DOUBLE_EQ(compression.a, -300.0);
  EXPECT_DOUBLE_EQ(compression.v[0], -0.15);   // r·v
  EXPECT_DOUBLE_EQ(compression.v[1], -600.0);  // c_r·v
  const Jet rebound = damper.force_N(Jet(0.3));
  EXPECT_DOUBLE_EQ(rebound.v[0], 0.3);
  EXPECT_EQ(rebound.v[1], 0.0);
}

// Ratio 1 is the symmetric model: the derivatives equal the equations of quarter_car.h written
// out with one c, bit for bit, in extension and in compression of the damper.
TEST(AsymmetricDamper, RatioOneReproducesTheSymmetricQuarterCarExactly) {
  QuarterCarParameters<double> p = testing::passat_corner().parameters;
  p.compression_to_rebound_ratio = 1.0;
  const road::RoadSample road{1e-3, 0.02};
  const double k_sp = p.spring_path_stiffness_N_per_m();
  for (const double zc : {2e-4, -2e-4}) {
    for (const double f : {20.0, -20.0}) {
      const double x[6] = {1e-3, -2e-4, 0.03, -0.1, zc, f};
      const double travel = x[0] - x[1];
      const double path = p.top_mount_stiffness_N_per_m * (travel - zc);
      const double tyre = p.tyre_stiffness_N_per_m * (x[1] - road.elevation_m) +
                          p.tyre_damping_Ns_per_m * (x[3] - road.rate_m_per_s);
      // slip: z_c' = F_path / c
      double xdot[6] = {};
      QuarterCar(DamperState::kSlip, p).derivatives(x, road, xdot);
      EXPECT_EQ(xdot[4], path / p.damping_Ns_per_m);
      EXPECT_EQ(xdot[2], -(k_sp * travel + path) / p.sprung_mass_kg);
      EXPECT_EQ(xdot[3], (k_sp * travel + path - tyre) / p.unsprung_mass_kg);
      // stick/slip: z_c' = (F_path − F_f) / c
      QuarterCar(DamperState::kStickSlip, p).derivatives(x, road, xdot);
      const double rate = (path - f) / p.damping_Ns_per_m;
      EXPECT_EQ(xdot[4], rate);
      EXPECT_EQ(xdot[5], p.damper_path().friction.force_rate_N_per_s(f, rate));
    }
  }
}

// The half car's passive axles with ratio 1 (given explicitly) are the assembled linear model.
TEST(AsymmetricDamper, RatioOneReproducesTheSymmetricHalfCarExactly) {
  const auto file = ajayi(
      {{"front.compression_to_rebound_ratio", "1"}, {"rear.compression_to_rebound_ratio", "1"}});
  const HalfCar car = file.make_model();
  const HalfCar reference = ajayi().make_model();
  ASSERT_TRUE(car.is_linear());
  const AxleRoads roads{{1e-3, 0.05}, {-2e-3, 0.1}};
  std::vector<double> x(14);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = (i % 2 ? -1.0 : 1.0) * 1e-3 * double(i + 1);
  std::vector<double> a(14), b(14);
  car.derivatives(x.data(), roads, a.data());
  reference.derivatives(x.data(), roads, b.data());
  EXPECT_EQ(a, b);
  // And the damper force is c·v on both sides: front travel rate 0.3 m/s, then −0.3 m/s.
  std::vector<double> state(14, 0.0);
  state[kHalfCarDofs + kFrontWheel] = -0.3;  // wheel falling: extension
  EXPECT_DOUBLE_EQ(car.outputs(state.data(), {}).front_damper_force_N, 300.0);
  state[kHalfCarDofs + kFrontWheel] = 0.3;
  EXPECT_DOUBLE_EQ(car.outputs(state.data(), {}).front_damper_force_N, -300.0);
}

// Slip strut: the damper carries the path force F = k_tm·(z − z_c); the damper's rate is
// F/c_r in rebound and F/(0.5·c_r) in compression, and the damper force is c(v)·v.
TEST(AsymmetricDamper, QuarterCarStrutDamperForceIsReboundOrHalfOfIt) {
  QuarterCarParameters<double> p = testing::passat_corner().parameters;
  p.compression_to_rebound_ratio = 0.5;
  const double c_r = p.damping_Ns_per_m;  // 886.9 Ns/m
  const double v = 0.2;                   // m/s
  for (const DamperState state : {DamperState::kSlip, DamperState::kStickSlip}) {
    const QuarterCar car(state, p);
    const double friction = state == DamperState::kStickSlip ? 15.0 : 0.0;
    // Rebound at +v: k_tm·(z − z_c) − F_f = c_r·v, with z = 0.
    double x[6] = {0.0,     0.0, 0.0, 0.0, -(c_r * v + friction) / p.top_mount_stiffness_N_per_m,
                   friction};
    double xdot[6] = {};
    car.derivatives(x, road::RoadSample{}, xdot);
    EXPECT_NEAR(xdot[4], v, 1e-12) << to_string(state);
    EXPECT_NEAR(car.outputs(x, {}).damper_force_N, c_r * v, 1e-9);  // 177.38 N
    EXPECT_NEAR(car.outputs(x, {}).damper_force_N, 177.38, 1e-9);
    // Compression at −v: the path carries only −0.5·c_r·v.
    x[4] = (0.5 * c_r * v + friction) / p.top_mount_stiffness_N_per_m;
    x[5] = -friction;
    car.derivatives(x, road::RoadSample{}, xdot);
    EXPECT_NEAR(xdot[4], -v, 1e-12) << to_string(state);
    EXPECT_NEAR(car.outputs(x, {}).damper_force_N, -0.5 * c_r * v, 1e-9);  // −88.69 N
    // The same path force magnitude drives the damper twice as fast in compression.
    x[4] = -100.0 / p.top_mount_stiffness_N_per_m;
    x[5] = 0.0;
    car.derivatives(x, road::RoadSample{}, xdot);
    const double rebound_rate = xdot[4];
    x[4] = -x[4];
    car.derivatives(x, road::RoadSample{}, xdot);
    EXPECT_DOUBLE_EQ(rebound_rate, 100.0 / c_r);
    EXPECT_DOUBLE_EQ(xdot[4], -2.0 * rebound_rate);
  }
}

TEST(AsymmetricDamper, HalfCarPassiveAxleDamperForceIsReboundOrHalfOfIt) {
  const HalfCar car = ajayi({{"front.compression_to_rebound_ratio", "0.5"}}).make_model();
  const auto& p = car.parameters();
  ASSERT_EQ(p.front.damping_Ns_per_m, 1000.0);
  std::vector<double> x(14, 0.0), xdot(14);
  // Travel rate = body − wheel velocity at the front axle.
  x[kHalfCarDofs + kFrontWheel] = -0.3;  // extension at 0.3 m/s
  HalfCarOutputs out = car.outputs(x.data(), {});
  EXPECT_DOUBLE_EQ(out.front_damper_force_N, 300.0);
  EXPECT_DOUBLE_EQ(out.front_damping_Ns_per_m, 1000.0);
  x[kHalfCarDofs + kFrontWheel] = 0.3;  // compression at 0.3 m/s
  out = car.outputs(x.data(), {});
  EXPECT_DOUBLE_EQ(out.front_damper_force_N, -150.0);
  EXPECT_DOUBLE_EQ(out.front_damping_Ns_per_m, 500.0);
  // The body feels the compression force: the damper pushes it up by 150 N (and the tyre's
  // damping 350 Ns/m·0.3 m/s acts on the wheel only).
  car.derivatives(x.data(), {}, xdot.data());
  EXPECT_DOUBLE_EQ(xdot[kHalfCarDofs + kBodyHeave], 150.0 / p.body_mass_kg);
  EXPECT_DOUBLE_EQ(xdot[kHalfCarDofs + kFrontWheel], (-150.0 - 350.0 * 0.3) / 60.0);
  // The rear axle keeps its symmetric damper.
  x[kHalfCarDofs + kFrontWheel] = 0.0;
  x[kHalfCarDofs + kRearWheel] = 0.3;
  EXPECT_DOUBLE_EQ(car.outputs(x.data(), {}).rear_damper_force_N, -300.0);
}

TEST(AsymmetricDamper, HalfCarStrutAxleDamperRateIsReboundOrHalfOfIt) {
  for (const char* state : {"slip", "stick_slip"}) {
    const HalfCar car = ajayi({{"front.suspension", "strut"},
                               {"front.damper_state", state},
                               {"front.compression_to_rebound_ratio", "0.5"}})
                            .make_model();
    const auto& p = car.parameters().front;
    const bool friction = std::string(state) == "stick_slip";
    std::vector<double> x(static_cast<std::size_t>(car.state_size()), 0.0);
    std::vector<double> xdot(x.size());
    const std::size_t zc = 2 * kHalfCarDofs;  // the front strut's damper deflection
    const double f = friction ? 20.0 : 0.0;
    // Path force 120 N (travel 0, z_c = −120 N / k_tm), friction 20 N: the damper carries
    // 100 N in rebound.
    x[zc] = -120.0 / p.top_mount_stiffness_N_per_m;
    if (friction) x[zc + 1] = f;
    car.derivatives(x.data(), {}, xdot.data());
    EXPECT_NEAR(xdot[zc], (120.0 - f) / 1000.0, 1e-14) << state;
    HalfCarOutputs out = car.outputs(x.data(), {});
    EXPECT_NEAR(out.front_damper_force_N, 1000.0 * xdot[zc], 1e-9);
    EXPECT_DOUBLE_EQ(out.front_damping_Ns_per_m, 1000.0);
    // Mirror image: the damper compresses at twice the rate.
    x[zc] = -x[zc];
    if (friction) x[zc + 1] = -f;
    car.derivatives(x.data(), {}, xdot.data());
    EXPECT_NEAR(xdot[zc], -(120.0 - f) / 500.0, 1e-14) << state;
    out = car.outputs(x.data(), {});
    EXPECT_NEAR(out.front_damper_force_N, 500.0 * xdot[zc], 1e-9);
    EXPECT_DOUBLE_EQ(out.front_damping_Ns_per_m, 500.0);
  }
}

// A semi-active law sets the rebound coefficient; compression gets the ratio times it.
TEST(AsymmetricDamper, SemiActiveCommandIsScaledByTheRatioInCompression) {
  const HalfCar car = ajayi({{"control.law", "skyhook"},
                             {"control.skyhook_damping_Ns_per_m", "2000"},
                             {"control.max_damping_Ns_per_m", "4000"},
                             {"front.compression_to_rebound_ratio", "0.5"}})
                          .make_model();
  std::vector<double> x(14, 0.0);
  // Body rising 0.2 m/s over the front axle (heave only), wheel at 0.1 m/s: extension 0.1 m/s,
  // skyhook asks c = 2000·0.2/0.1 = 4000 Ns/m, 400 N.
  x[kHalfCarDofs + kBodyHeave] = 0.2;
  x[kHalfCarDofs + kFrontWheel] = 0.1;
  HalfCarOutputs out = car.outputs(x.data(), {});
  EXPECT_DOUBLE_EQ(out.front_damping_Ns_per_m, 4000.0);
  EXPECT_DOUBLE_EQ(out.front_damper_force_N, 400.0);
  // Body falling 0.05 m/s, wheel rising 0.15 m/s: compression 0.2 m/s, skyhook asks
  // 2000·0.05/0.2 = 500 Ns/m, the damper gives 0.5·500 = 250 Ns/m.
  x[kHalfCarDofs + kBodyHeave] = -0.05;
  x[kHalfCarDofs + kFrontWheel] = 0.15;
  out = car.outputs(x.data(), {});
  EXPECT_DOUBLE_EQ(out.front_damping_Ns_per_m, 250.0);
  EXPECT_DOUBLE_EQ(out.front_damper_force_N, -50.0);
  // The rear damper is symmetric: body −0.05 m/s over a still wheel asks 2000·0.05/0.05.
  EXPECT_DOUBLE_EQ(out.rear_damping_Ns_per_m, 2000.0);
}

TEST(AsymmetricDamper, AnAsymmetricDamperMakesTheModelNonlinear) {
  EXPECT_TRUE(ajayi().make_model().is_linear());
  const auto passive = ajayi({{"rear.compression_to_rebound_ratio", "0.5"}});
  EXPECT_FALSE(passive.make_model().is_linear());
  EXPECT_THROW(simulate::half_car_state_space(passive.make_model()), std::invalid_argument);
  EXPECT_THROW(assemble_mass_damping_stiffness(passive.topology, passive.parameters),
               std::invalid_argument);
  const io::ModelOverrides slip = {{"front.suspension", "strut"}, {"front.damper_state", "slip"}};
  EXPECT_TRUE(ajayi(slip).make_model().is_linear());
  auto asymmetric_slip = slip;
  asymmetric_slip.set("front.compression_to_rebound_ratio", "2");
  EXPECT_FALSE(ajayi(asymmetric_slip).make_model().is_linear());
  // A stick strut's damper is locked: its split never acts and the car stays linear.
  EXPECT_TRUE(ajayi({{"front.suspension", "strut"},
                     {"front.damper_state", "stick"},
                     {"front.compression_to_rebound_ratio", "2"}})
                  .make_model()
                  .is_linear());

  QuarterCarParameters<double> p = testing::passat_corner().parameters;
  EXPECT_TRUE(QuarterCar(DamperState::kSlip, p).is_linear());
  p.compression_to_rebound_ratio = 0.5;
  EXPECT_FALSE(QuarterCar(DamperState::kSlip, p).is_linear());
  EXPECT_FALSE(QuarterCar(DamperState::kStickSlip, p).is_linear());
  EXPECT_TRUE(QuarterCar(DamperState::kStick, p).is_linear());
  EXPECT_TRUE(testing::throws_input_error(
      [&] { simulate::quarter_car_modes(QuarterCar(DamperState::kSlip, p)); },
      "compression_to_rebound_ratio 0.5"));
  EXPECT_EQ(simulate::quarter_car_modes(QuarterCar(DamperState::kStick, p)).oscillatory.size(), 2u);
}

}  // namespace
}  // namespace ridefit::model
