// The half car's modes: read off the model's own derivatives (half_car_state_space.h), they must
// equal those of its mass and stiffness matrices assembled here by hand from the drawing of
// seed 001 (Figure 1) for the undamped car; damping turns them into decaying pairs, and a
// nonlinear car is refused.
#include "ridefit/simulate/half_car_modes.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/io/half_car_file.h"
#include "support/passat.h"

namespace ridefit::simulate {
namespace {

io::HalfCarFile ajayi() {
  return io::load_half_car(testing::dataset("vehicles/ajayi_half_car.yaml"));
}

// √eig(M⁻¹K)/2π of the car's seven coordinates [z_b, θ, z_f, z_r, z_s, z_l, z_u]: each spring
// k between two points adds k·g·gᵀ, g the points' relative displacement per coordinate.
std::vector<double> hand_frequencies_Hz(const model::HalfCarTopology& topology,
                                        const model::HalfCarParameters<double>& p) {
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(7, 7);
  auto spring = [&](double stiffness, Eigen::VectorXd g) { k += stiffness * g * g.transpose(); };
  auto g = [](std::initializer_list<double> v) {
    Eigen::VectorXd out(7);
    int i = 0;
    for (double x : v) out(i++) = x;
    return out;
  };
  const double a1 = p.front_axle_distance_m, a2 = p.rear_axle_distance_m, a3 = p.seat_distance_m;
  spring(p.front.spring_stiffness_N_per_m, g({1, a1, -1, 0, 0, 0, 0}));
  spring(p.rear.spring_stiffness_N_per_m, g({1, -a2, 0, -1, 0, 0, 0}));
  spring(p.front.tyre_stiffness_N_per_m, g({0, 0, 1, 0, 0, 0, 0}));
  spring(p.rear.tyre_stiffness_N_per_m, g({0, 0, 0, 1, 0, 0, 0}));
  spring(p.seat.stiffness_N_per_m, g({1, a3, 0, 0, -1, 0, 0}));
  spring(p.lower_body.stiffness_N_per_m, g({0, 0, 0, 0, 1, -1, 0}));
  spring(p.upper_body.stiffness_N_per_m,
         topology.upper_body_support == model::UpperBodySupport::kSeat ? g({0, 0, 0, 0, 1, 0, -1})
                                                                       : g({0, 0, 0, 0, 0, 1, -1}));
  Eigen::VectorXd m(7);
  m << p.body_mass_kg, p.pitch_inertia_kg_m2, p.front.unsprung_mass_kg, p.rear.unsprung_mass_kg,
      p.seat.mass_kg, p.lower_body.mass_kg, p.upper_body.mass_kg;
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(
      k, Eigen::MatrixXd(m.asDiagonal()));
  std::vector<double> f;
  for (int i = 0; i < 7; ++i)
    f.push_back(std::sqrt(solver.eigenvalues()(i)) / (2 * std::numbers::pi));
  std::sort(f.begin(), f.end());
  return f;
}

TEST(HalfCarModes, UndampedFrequenciesEqualThoseOfTheMassAndStiffnessMatrices) {
  for (const auto support : {model::UpperBodySupport::kSeat, model::UpperBodySupport::kLowerBody}) {
    io::HalfCarFile file = ajayi();
    file.topology.upper_body_support = support;
    for (auto* axle : {&file.parameters.front, &file.parameters.rear}) {
      axle->damping_Ns_per_m = 0.0;
      axle->tyre_damping_Ns_per_m = 0.0;
    }
    for (auto* mass :
         {&file.parameters.seat, &file.parameters.lower_body, &file.parameters.upper_body}) {
      mass->damping_Ns_per_m = 0.0;
    }
    const ModalAnalysis modes = half_car_modes(file.make_model());
    ASSERT_EQ(modes.oscillatory.size(), 7u);
    const std::vector<double> expected = hand_frequencies_Hz(file.topology, file.parameters);
    for (std::size_t i = 0; i < 7; ++i) {
      EXPECT_NEAR(modes.oscillatory[i].natural_frequency_Hz, expected[i], 1e-9 * expected[i]) << i;
      EXPECT_NEAR(modes.oscillatory[i].damping_ratio, 0.0, 1e-9) << i;
    }
  }
}

TEST(HalfCarModes, NamesTheCoordinatesAndDecaysWithDamping) {
  const ModalAnalysis modes = half_car_modes(ajayi().make_model());
  ASSERT_EQ(modes.oscillatory.size(), 7u);
  std::vector<std::string> names;
  for (const auto& m : modes.oscillatory) {
    EXPECT_GT(m.damping_ratio, 0.0) << m.dominant_dof;
    EXPECT_LT(m.damping_ratio, 1.0) << m.dominant_dof;
    names.push_back(m.dominant_dof);
  }
  // The wheels hop above the body's heave and pitch.
  for (const char* name : {"body", "pitch", "front_wheel", "rear_wheel"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
  }
  auto at = [&](const std::string& name) {
    for (const auto& m : modes.oscillatory) {
      if (m.dominant_dof == name) return m.natural_frequency_Hz;
    }
    return std::nan("");
  };
  EXPECT_GT(at("front_wheel"), 3.0 * at("body"));
}

TEST(HalfCarModes, RefusesANonlinearCar) {
  io::HalfCarFile file = ajayi();
  file.topology.front.suspension = model::AxleSuspension::kStrut;
  file.topology.front.damper_state = model::DamperState::kStickSlip;
  try {
    half_car_modes(file.make_model());
    ADD_FAILURE() << "a stick/slip strut was taken as linear";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("stick_slip"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ridefit::simulate
