// The shape of a disagreement no library effect explains: a force the model lacks, hidden in a
// rig's records beside correlated noise, is named by the term that makes it, with its sign and
// size; noise alone names nothing.
#include "ridefit/fitting/diagnose/residual_shape.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "ridefit/common/errors.h"
#include "support/scatter.h"

namespace ridefit::fitting::diagnose {
namespace {

// The rig's motion at one sample, for a hidden force.
struct Motion {
  double x, v, a;
};
using HiddenForce = std::function<double(const Motion&)>;

// 10 s at 500 Hz of three sines (8, 3, 1 mm at 0.9, 2.7, 7.3 Hz, phases drawn from `seed`),
// exact velocity and acceleration; a model force of a strut (damping, a spring, a friction
// level); the missing force `hidden` plus AR(1) noise (ρ 0.9, 2 N RMS) and a load-cell offset.
ShapeSamples record(unsigned seed, const HiddenForce& hidden) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * std::numbers::pi);
  const double amplitude[] = {8e-3, 3e-3, 1e-3}, frequency[] = {0.9, 2.7, 7.3};
  double phase[3];
  for (double& p : phase) p = angle(rng);
  const double rho = 0.9;
  std::normal_distribution<double> innovation(0.0, 2.0 * std::sqrt(1.0 - rho * rho));
  double noise = 0.0;
  ShapeSamples s;
  for (int k = 0; k < 5000; ++k) {
    const double t = k / 500.0;
    Motion m{0.0, 0.0, 0.0};
    for (int i = 0; i < 3; ++i) {
      const double w = 2.0 * std::numbers::pi * frequency[i];
      m.x += amplitude[i] * std::sin(w * t + phase[i]);
      m.v += amplitude[i] * w * std::cos(w * t + phase[i]);
      m.a -= amplitude[i] * w * w * std::sin(w * t + phase[i]);
    }
    noise = rho * noise + innovation(rng);
    s.displacement_m.push_back(m.x);
    s.velocity_m_per_s.push_back(m.v);
    s.acceleration_m_per_s2.push_back(m.a);
    s.model_force_N.push_back(1500.0 * m.v + 2e4 * m.x + 60.0 * std::tanh(m.v / 0.005));
    s.missing_force_N.push_back((hidden ? hidden(m) : 0.0) + noise + 3.0);
  }
  return s;
}

ResidualShape shape_of(const HiddenForce& hidden, unsigned seed = 1) {
  return residual_shape({record(seed, hidden)}, {record(seed + 100, hidden)});
}

TEST(ResidualShape, NamesAnEvenForceByTheSquareOfTravel) {
  // 4 N/mm² · x²: an even force in travel (loop_diagnosis_test's outside case).
  const ResidualShape s = shape_of([](const Motion& m) { return 4e6 * m.x * m.x; });
  ASSERT_FALSE(s.terms.empty());
  EXPECT_EQ(s.terms[0].id, "travel_squared") << describe(s);
  EXPECT_NEAR(s.terms[0].coefficient, 4e6, 0.1e6) << describe(s);
  EXPECT_NE(s.terms[0].words.find("tension"), std::string::npos);
  EXPECT_EQ(coefficient_text(s.terms[0]).rfind("+4", 0), 0u) << coefficient_text(s.terms[0]);
  EXPECT_NE(coefficient_text(s.terms[0]).find("N/mm²"), std::string::npos);
  EXPECT_GT(s.judged_share, 0.95);
}

TEST(ResidualShape, NamesAStopByTravelBeyondPartOfTheStroke) {
  // 50 N/mm beyond ±6 mm (the stroke is about ±12 mm).
  const ResidualShape s = shape_of([](const Motion& m) {
    return 5e4 * (m.x > 0 ? 1.0 : -1.0) * std::max(std::abs(m.x) - 6e-3, 0.0);
  });
  ASSERT_FALSE(s.terms.empty());
  // The stroke is about ±11.5 mm about its middle: the knee at half of it is the stop's.
  EXPECT_EQ(s.terms[0].id, "travel_beyond_half_stroke") << describe(s);
  EXPECT_NEAR(0.5 * s.half_stroke_m, 6e-3, 0.6e-3);
  EXPECT_GT(s.terms[0].coefficient, 0.0) << describe(s);
  EXPECT_NE(s.terms[0].words.find("a stop"), std::string::npos) << s.terms[0].words;
  EXPECT_GT(s.judged_share, 0.8) << describe(s);
}

TEST(ResidualShape, NamesDampingThatGrowsWithSpeed) {
  const ResidualShape s = shape_of([](const Motion& m) { return 2000.0 * m.v * std::abs(m.v); });
  ASSERT_FALSE(s.terms.empty());
  EXPECT_EQ(s.terms[0].id, "velocity_squared") << describe(s);
  EXPECT_NEAR(s.terms[0].coefficient, 2000.0, 100.0) << describe(s);
}

TEST(ResidualShape, NamesLessDampingWithItsSign) {
  const ResidualShape s = shape_of([](const Motion& m) { return -300.0 * m.v; });
  ASSERT_FALSE(s.terms.empty());
  EXPECT_EQ(s.terms[0].id, "velocity") << describe(s);
  EXPECT_NEAR(s.terms[0].coefficient, -300.0, 15.0) << describe(s);
  EXPECT_EQ(s.terms[0].words.rfind("less damping", 0), 0u) << s.terms[0].words;
}

TEST(ResidualShape, NamesAMovingMassByTheRigsAcceleration) {
  const ResidualShape s = shape_of([](const Motion& m) { return 12.0 * m.a; });
  ASSERT_FALSE(s.terms.empty());
  EXPECT_EQ(s.terms[0].id, "acceleration") << describe(s);
  EXPECT_NEAR(s.terms[0].coefficient, 12.0, 0.2) << describe(s);
  EXPECT_NE(describe(s).find("kg"), std::string::npos);
}

// The standard errors say how far the coefficient scatters: over 60 seeded pairs of records the
// moving mass' spread and the mean of its reported errors agree within a third.
TEST(ResidualShape, StandardErrorsMatchTheScatter) {
  std::vector<double> mass, error;
  for (unsigned seed = 0; seed < 60; ++seed) {
    const ResidualShape s = shape_of([](const Motion& m) { return 12.0 * m.a; }, 500 + seed);
    ASSERT_FALSE(s.terms.empty());
    ASSERT_EQ(s.terms[0].id, "acceleration");
    mass.push_back(s.terms[0].coefficient);
    error.push_back(s.terms[0].standard_error);
  }
  EXPECT_NEAR(testing::spread_over_reported_error(mass, error), 1.0, 1.0 / 3.0);
}

// Correlated noise and an offset alone: nothing named in at least 95 % of 40 seeded pairs of
// records.
TEST(ResidualShape, NamesNothingInNoise) {
  int quiet = 0;
  for (unsigned seed = 0; seed < 40; ++seed) {
    const ResidualShape s = shape_of({}, 1000 + seed);
    if (s.terms.empty()) ++quiet;
    EXPECT_EQ(describe(s).empty(), s.terms.empty());
  }
  EXPECT_GE(quiet, 38);
}

TEST(ResidualShape, RefusesBadOptionsAndRecords) {
  SparseSelectionOptions options;
  options.max_terms = 0;
  EXPECT_THROW(options.validate(), InputError);
  options = {};
  options.min_share = 1.0;
  EXPECT_THROW(options.validate(), InputError);
  options = {};
  options.min_z = NAN;
  EXPECT_THROW(options.validate(), InputError);
  const ShapeSamples good = record(1, {});
  EXPECT_THROW(residual_shape({}, {good}), InputError);
  ShapeSamples short_one = good;
  short_one.velocity_m_per_s.pop_back();
  try {
    residual_shape({good}, {short_one});
    ADD_FAILURE() << "columns of different lengths were taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("judging record 1"), std::string::npos) << e.what();
  }
  // A sample that is not finite is left out, not spread as NaN.
  ShapeSamples gap = record(2, [](const Motion& m) { return 12.0 * m.a; });
  gap.missing_force_N[100] = NAN;
  const ResidualShape s =
      residual_shape({gap}, {record(3, [](const Motion& m) { return 12.0 * m.a; })});
  ASSERT_FALSE(s.terms.empty());
  EXPECT_TRUE(std::isfinite(s.terms[0].coefficient));
}

}  // namespace
}  // namespace ridefit::fitting::diagnose
