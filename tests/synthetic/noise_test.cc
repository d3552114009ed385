// Seeded noise and the load cell's reading of a force.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

#include "ridefit/synthetic/gaussian_noise.h"
#include "ridefit/synthetic/load_cell.h"
#include "support/throws_input_error.h"

namespace ridefit::synthetic {
namespace {

TEST(SyntheticNoise, ReproducibleFromItsSeedWithTheRequestedRms) {
  std::mt19937_64 a(7), b(7), c(8);
  const auto x = gaussian_noise(100000, 0.6, a);
  EXPECT_EQ(x, gaussian_noise(100000, 0.6, b));
  EXPECT_NE(x, gaussian_noise(100000, 0.6, c));
  const double mean = std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size());
  const double rms = std::sqrt(std::inner_product(x.begin(), x.end(), x.begin(), 0.0) /
                               static_cast<double>(x.size()));
  EXPECT_NEAR(rms, 0.6, 0.02 * 0.6);
  EXPECT_NEAR(mean, 0.0, 0.01);
}

TEST(SyntheticNoise, ZeroSigmaGivesZerosWithoutDrawing) {
  std::mt19937_64 used(5), fresh(5);
  EXPECT_EQ(gaussian_noise(10, 0.0, used), std::vector<double>(10, 0.0));
  EXPECT_EQ(used(), fresh());
  EXPECT_TRUE(testing::throws_input_error([&] { gaussian_noise(3, -1.0, used); }, ">= 0"));
}

TEST(SyntheticLoadCell, ReadingIsQuantisedAndNoisyAroundTheForce) {
  const LoadCell cell{0.6, 10000.0 / 65536.0};
  const std::vector<double> force(20000, 123.456);
  std::mt19937_64 rng(1);
  const auto reading = read_load_cell(force, cell, rng);
  double sum = 0.0, square = 0.0;
  for (double f : reading) {
    const double steps = f / cell.quantum_N;
    EXPECT_NEAR(steps, std::round(steps), 1e-9);  // on the converter's grid
    sum += f - 123.456;
    square += (f - 123.456) * (f - 123.456);
  }
  const double n = static_cast<double>(reading.size());
  EXPECT_NEAR(sum / n, 0.0, 0.02);
  // Noise and rounding add: σ² + q²/12.
  EXPECT_NEAR(std::sqrt(square / n), std::sqrt(0.36 + cell.quantum_N * cell.quantum_N / 12.0),
              0.03 * 0.6);
  std::mt19937_64 unused(1);
  const auto exact = read_load_cell(force, LoadCell{}, unused);
  EXPECT_EQ(exact, force);
}

}  // namespace
}  // namespace ridefit::synthetic
