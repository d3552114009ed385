// FrequencyResponse: the eigenbasis and the direct LU agree with the closed form, and the
// response to one combination of inputs is H(jω)·u, also where A is defective.
#include "ridefit/simulate/frequency_response.h"

#include <gtest/gtest.h>

#include <numbers>

namespace ridefit::simulate {
namespace {

// m·ẍ + c·ẋ + k·x = k·u + c·u̇: inputs u and u̇, outputs x and ẋ. H_x = (k + jωc)/(k − mω² + jωc).
LinearStateSpace oscillator(double m, double c, double k) {
  LinearStateSpace s;
  s.A = Eigen::MatrixXd{{0.0, 1.0}, {-k / m, -c / m}};
  s.B = Eigen::MatrixXd{{0.0, 0.0}, {k / m, c / m}};
  s.C = Eigen::MatrixXd::Identity(2, 2);
  s.D = Eigen::MatrixXd::Zero(2, 2);
  return s;
}

TEST(FrequencyResponse, TheResponseToCombinedInputsIsTheClosedForm) {
  const double m = 400.0, c = 1500.0, k = 30000.0;
  const FrequencyResponse response(oscillator(m, c, k));
  ASSERT_TRUE(response.uses_eigenbasis());
  for (double f : {0.1, 1.37, 8.0, 40.0}) {
    const std::complex<double> jw(0.0, 2.0 * std::numbers::pi * f);
    Eigen::VectorXcd u(2);
    u << 1.0, jw;  // a road u = e^{jωt} and its rate
    const Eigen::VectorXcd y = response.at(f, u);
    const std::complex<double> expected = (k + jw * c) / (k + jw * jw * m + jw * c);
    EXPECT_LT(std::abs(y(0) - expected), 1e-12 * std::abs(expected)) << f;
    EXPECT_LT(std::abs(y(1) - jw * expected), 1e-12 * std::abs(jw * expected)) << f;
    const Eigen::VectorXcd full = response.at(f) * u;
    EXPECT_LT((y - full).norm(), 1e-12 * full.norm());
  }
}

TEST(FrequencyResponse, ADefectiveSystemIsSolvedDirectlyWithTheSameAnswer) {
  // A double integrator: A = [[0, 1], [0, 0]] is a Jordan block, its eigenvectors parallel.
  LinearStateSpace s;
  s.A = Eigen::MatrixXd{{0.0, 1.0}, {0.0, 0.0}};
  s.B = Eigen::MatrixXd{{0.0}, {1.0}};
  s.C = Eigen::MatrixXd{{1.0, 0.0}};
  s.D = Eigen::MatrixXd::Zero(1, 1);
  const FrequencyResponse response(s);
  EXPECT_FALSE(response.uses_eigenbasis());
  const double f = 2.0;
  const std::complex<double> jw(0.0, 2.0 * std::numbers::pi * f);
  Eigen::VectorXcd u(1);
  u << 3.0;
  EXPECT_LT(std::abs(response.at(f, u)(0) - 3.0 / (jw * jw)), 1e-12 * std::abs(3.0 / (jw * jw)));
  EXPECT_THROW(response.at(f, Eigen::VectorXcd::Zero(2)), std::invalid_argument);
}

}  // namespace
}  // namespace ridefit::simulate
