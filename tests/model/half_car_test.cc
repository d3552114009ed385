// The 7-DOF half car: assembly from elements against hand calculations, and the model's
// derivatives against the assembled matrices.
#include "ridefit/model/half_car.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/io/half_car_file.h"
#include "ridefit/road/road_input.h"
#include "support/input_error_message.h"
#include "support/passat.h"

namespace ridefit::model {
namespace {

constexpr double kG = 9.80665;

io::HalfCarFile ajayi(const io::ModelOverrides& overrides = {}) {
  return io::load_half_car(testing::dataset("vehicles/ajayi_half_car.yaml"), overrides);
}

TEST(HalfCar, AssembledMatricesAreSymmetricAndStiffnessIsPositiveDefinite) {
  const auto file = ajayi();
  const auto m = assemble_mass_damping_stiffness(file.topology, file.parameters);
  EXPECT_TRUE(m.stiffness.isApprox(m.stiffness.transpose(), 1e-14));
  EXPECT_TRUE(m.damping.isApprox(m.damping.transpose(), 1e-14));
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 7, 7>> eig(m.stiffness);
  EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0);
  // Seed 001's K (Eq. 1) in our coordinates: the body–seat coupling k_se·a3 and the pitch
  // diagonal k_sf·a1² + k_sr·a2² + k_se·a3², signs as the elements give them.
  const auto& p = file.parameters;
  EXPECT_DOUBLE_EQ(m.stiffness(kBodyPitch, kBodyPitch),
                   p.front.spring_stiffness_N_per_m * 1.4 * 1.4 +
                       p.rear.spring_stiffness_N_per_m * 1.4 * 1.4 +
                       p.seat.stiffness_N_per_m * 0.65 * 0.65);
  EXPECT_DOUBLE_EQ(m.stiffness(kSeat, kBodyPitch), -p.seat.stiffness_N_per_m * 0.65);
  EXPECT_DOUBLE_EQ(m.stiffness(kUpperBody, kSeat), -p.upper_body.stiffness_N_per_m);
  EXPECT_DOUBLE_EQ(m.stiffness(kUpperBody, kLowerBody), 0.0);  // both segments on the seat
}

TEST(HalfCar, StaticDeflectionUnderGravityMatchesAHandCalculation) {
  const auto file = ajayi();
  const auto& p = file.parameters;
  const auto m = assemble_mass_damping_stiffness(file.topology, file.parameters);
  Eigen::Matrix<double, 7, 1> weight;
  weight << -kG * p.body_mass_kg, 0.0, -kG * p.front.unsprung_mass_kg,
      -kG * p.rear.unsprung_mass_kg, -kG * p.seat.mass_kg, -kG * p.lower_body.mass_kg,
      -kG * p.upper_body.mass_kg;
  const Eigen::Matrix<double, 7, 1> q = m.stiffness.ldlt().solve(weight);

  // By hand: the occupant's weight W_o sits at a3 on the body; statics of the body beam give
  // the spring forces, springs and tyres in series give the deflections.
  const double a1 = 1.4, a2 = 1.4, a3 = 0.65, length = a1 + a2;
  const double occupant = kG * (p.seat.mass_kg + p.lower_body.mass_kg + p.upper_body.mass_kg);
  const double front = kG * p.body_mass_kg * a2 / length + occupant * (a2 + a3) / length;
  const double rear = kG * p.body_mass_kg * a1 / length + occupant * (a1 - a3) / length;
  const double front_wheel = -(front + kG * p.front.unsprung_mass_kg) / 190000.0;
  const double rear_wheel = -(rear + kG * p.rear.unsprung_mass_kg) / 190000.0;
  const double front_body = front_wheel - front / 16812.0;
  const double rear_body = rear_wheel - rear / 16812.0;
  const double pitch = (front_body - rear_body) / length;
  const double heave = front_body - a1 * pitch;
  const double seat = heave + a3 * pitch - occupant / p.seat.stiffness_N_per_m;
  EXPECT_NEAR(q[kFrontWheel], front_wheel, 1e-12);
  EXPECT_NEAR(q[kRearWheel], rear_wheel, 1e-12);
  EXPECT_NEAR(q[kBodyHeave], heave, 1e-12);
  EXPECT_NEAR(q[kBodyPitch], pitch, 1e-12);
  EXPECT_NEAR(q[kSeat], seat, 1e-12);
  EXPECT_NEAR(q[kLowerBody], seat - kG * 5.5 / 144000.0, 1e-12);
  EXPECT_NEAR(q[kUpperBody], seat - kG * 36.0 / 20000.0, 1e-12);
  EXPECT_LT(pitch, 0.0);  // the occupant ahead of the centre of gravity sinks the nose
}

// Eigenfrequencies of a reduced case: wheels and seat held, the body alone bounces and pitches
// on its suspension springs and the seat spring; by hand from the 2×2 problem.
TEST(HalfCar, BodyModesWithWheelsAndSeatHeldMatchTheTwoByTwoProblem) {
  const auto file = ajayi();
  const auto m = assemble_mass_damping_stiffness(file.topology, file.parameters);
  const Eigen::Matrix2d k = m.stiffness.block<2, 2>(0, 0);
  const Eigen::Matrix2d mass = m.mass.block<2, 2>(0, 0);
  const double ks = 16812.0, kse = 35700.0, a = 1.4, a3 = 0.65;
  // k = [[2ks + kse, kse·a3], [kse·a3, 2ks·a² + kse·a3²]] (a1 = a2 = a, equal springs)
  EXPECT_DOUBLE_EQ(k(0, 0), 2 * ks + kse);
  EXPECT_DOUBLE_EQ(k(0, 1), kse * a3);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> eig(k, mass);
  const double mb = 575.0, j = 769.0;
  const double k11 = 2 * ks + kse, k12 = kse * a3, k22 = 2 * ks * a * a + kse * a3 * a3;
  // det(K − ω²M) = 0: mb·J·ω⁴ − (k11·J + k22·mb)·ω² + (k11·k22 − k12²) = 0
  const double b = k11 * j + k22 * mb, c = k11 * k22 - k12 * k12;
  const double disc = std::sqrt(b * b - 4 * mb * j * c);
  const double w1 = std::sqrt((b - disc) / (2 * mb * j));
  const double w2 = std::sqrt((b + disc) / (2 * mb * j));
  EXPECT_NEAR(std::sqrt(eig.eigenvalues()[0]), w1, 1e-9 * w1);
  EXPECT_NEAR(std::sqrt(eig.eigenvalues()[1]), w2, 1e-9 * w2);
  // The occupant's segments on a held seat: sqrt(k/m) each.
  EXPECT_NEAR(std::sqrt(m.stiffness(kUpperBody, kUpperBody) / m.mass(kUpperBody, kUpperBody)),
              std::sqrt(20000.0 / 36.0), 1e-12);
}

// The state-space form the model's derivatives give (autodiff is exact for a linear model; here
// central differences, step-independent for a linear function) is [[0, I], [−M⁻¹K, −M⁻¹C]].
TEST(HalfCar, DerivativesAgreeWithTheAssembledMatrices) {
  const auto file = ajayi();
  const HalfCar car = file.make_model();
  ASSERT_TRUE(car.is_linear());
  const auto m = assemble_mass_damping_stiffness(file.topology, file.parameters);
  const int n = car.state_size();
  ASSERT_EQ(n, 14);
  Eigen::MatrixXd a(n, n);
  const AxleRoads flat{};
  for (int j = 0; j < n; ++j) {
    std::vector<double> x(static_cast<std::size_t>(n), 0.0), f(static_cast<std::size_t>(n));
    x[static_cast<std::size_t>(j)] = 1e-3;
    car.derivatives(x.data(), flat, f.data());
    for (int i = 0; i < n; ++i) a(i, j) = f[static_cast<std::size_t>(i)] / 1e-3;
  }
  const Eigen::Matrix<double, 7, 7> minv = m.mass.inverse();
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(n, n);
  expected.block(0, 7, 7, 7).setIdentity();
  expected.block(7, 0, 7, 7) = -minv * m.stiffness;
  expected.block(7, 7, 7, 7) = -minv * m.damping;
  EXPECT_LT((a - expected).cwiseAbs().maxCoeff(), 1e-9 * expected.cwiseAbs().maxCoeff());
}

TEST(HalfCar, StrutAndControllerAddStatesAndBreakLinearity) {
  const auto strut = ajayi({{"front.suspension", "strut"}});
  const HalfCar car = strut.make_model();
  EXPECT_EQ(car.state_size(), 16);  // z_c and F_f of the front strut
  EXPECT_FALSE(car.is_linear());
  EXPECT_EQ(car.state_names().back(), "front_friction_force");
  const auto slip =
      ajayi({{"front.suspension", "strut"}, {"front.damper_state", "slip"}}).make_model();
  EXPECT_EQ(slip.state_size(), 15);
  EXPECT_TRUE(slip.is_linear());
  EXPECT_THROW(assemble_mass_damping_stiffness(strut.topology, strut.parameters),
               std::invalid_argument);
}

TEST(SemiActiveControl, LawsClipToTheDamperLimits) {
  SemiActiveControl c;
  c.law = ControlLaw::kSkyhook;
  c.min_damping_Ns_per_m = 300;
  c.max_damping_Ns_per_m = 4000;
  c.skyhook_damping_Ns_per_m = 2000;
  // Body rising (0.2 m/s), suspension extending (0.1 m/s): c = 2000·0.2/0.1 = 4000.
  EXPECT_DOUBLE_EQ(c.damping(0.2, 0.1, 1000.0), 4000.0);
  EXPECT_DOUBLE_EQ(c.damping(0.05, -0.15, 1000.0), 500.0);  // 2000·0.05/0.2
  EXPECT_DOUBLE_EQ(c.damping(0.2, 0.3, 1000.0), 300.0);     // not achievable: c_min
  EXPECT_DOUBLE_EQ(c.damping(1.0, 0.0, 1000.0), 2000.0);
  c.law = ControlLaw::kGroundhook;
  c.groundhook_damping_Ns_per_m = 2000;
  EXPECT_DOUBLE_EQ(c.damping(0.1, -0.1, 1000.0), 1000.0);  // −2000·(−0.1)/0.2
  EXPECT_DOUBLE_EQ(c.damping(0.1, 0.05, 1000.0), 300.0);
  c.law = ControlLaw::kHybrid;
  c.skyhook_share = 0.5;
  EXPECT_DOUBLE_EQ(c.damping(0.1, -0.1, 1000.0), 0.5 * 1000.0 + 0.5 * 1000.0);
  c.law = ControlLaw::kPassive;
  EXPECT_DOUBLE_EQ(c.damping(0.1, -0.1, 1234.0), 1234.0);
}

TEST(HalfCarFile, BadFilesAndOverridesNameTheKey) {
  EXPECT_NE(testing::input_error_message([] {
              ajayi({{"front.dampng_Ns_per_m", "1"}});
            }).find("front.dampng_Ns_per_m"),
            std::string::npos);
  EXPECT_NE(testing::input_error_message([] {
              ajayi({{"front.damping_Ns_per_m", "-5"}});
            }).find("front.damping_Ns_per_m"),
            std::string::npos);
  const std::string limits = testing::input_error_message([] {
    ajayi({{"control.law", "skyhook"}, {"control.min_damping_Ns_per_m", "5000"}});
  });
  EXPECT_NE(limits.find("control.min_damping_Ns_per_m"), std::string::npos) << limits;
  EXPECT_NE(limits.find("c_min <= c_max"), std::string::npos) << limits;
  EXPECT_DOUBLE_EQ(
      ajayi({{"rear.spring_stiffness_N_per_m", "20000"}}).parameters.rear.spring_stiffness_N_per_m,
      20000.0);
}

}  // namespace
}  // namespace ridefit::model
