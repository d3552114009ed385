#include "ridefit/road/log_sweep.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <string>

#include "ridefit/common/errors.h"
#include "support/input_error_message.h"

namespace ridefit::road {
namespace {

LogSweepParameters seed_sweep(double initial_amplitude_m) {
  LogSweepParameters p;
  p.initial_amplitude_m = initial_amplitude_m;
  p.end_amplitude_m = initial_amplitude_m / 100.0;
  return p;
}

// The zero crossing of h in [a, b] (h changes sign there), by bisection.
double zero_crossing(const LogSweep& sweep, double a, double b) {
  for (int i = 0; i < 100; ++i) {
    const double m = 0.5 * (a + b);
    if ((sweep.at(a).elevation_m > 0) == (sweep.at(m).elevation_m > 0)) {
      a = m;
    } else {
      b = m;
    }
  }
  return 0.5 * (a + b);
}

TEST(RoadLogSweep, DefaultsAreTheSeedsSweep) {
  const LogSweepParameters p;
  EXPECT_EQ(p.start_frequency_Hz, 0.1);
  EXPECT_EQ(p.end_frequency_Hz, 30.0);
  EXPECT_EQ(p.duration_s, 60.0);
  EXPECT_DOUBLE_EQ(p.end_amplitude_m, p.initial_amplitude_m / 100.0);
}

TEST(RoadLogSweep, FrequencyAndAmplitudeFollowTheExponentialLaw) {
  const LogSweep sweep(seed_sweep(0.01));
  EXPECT_DOUBLE_EQ(sweep.duration_s(), 60.0);
  EXPECT_DOUBLE_EQ(sweep.instantaneous_frequency_Hz(0.0), 0.1);
  EXPECT_NEAR(sweep.instantaneous_frequency_Hz(30.0), std::sqrt(0.1 * 30.0), 1e-12);
  EXPECT_NEAR(sweep.instantaneous_frequency_Hz(60.0), 30.0, 1e-12);
  EXPECT_NEAR(sweep.instantaneous_frequency_Hz(20.0), 0.1 * std::pow(300.0, 1.0 / 3.0), 1e-12);
  EXPECT_DOUBLE_EQ(sweep.amplitude_m(0.0), 0.01);
  EXPECT_NEAR(sweep.amplitude_m(30.0), 1e-3, 1e-15);
  EXPECT_NEAR(sweep.amplitude_m(60.0), 1e-4, 1e-16);
  // log A is linear in log f: A = A0·(f/f0)^p with p = ln(0.01)/ln(300) = −0.8074.
  const double p = std::log(0.01) / std::log(300.0);
  EXPECT_NEAR(p, -0.8074, 1e-4);
  for (double t : {3.0, 17.0, 41.0, 59.0}) {
    EXPECT_NEAR(sweep.amplitude_m(t), 0.01 * std::pow(sweep.instantaneous_frequency_Hz(t) / 0.1, p),
                1e-15)
        << t;
  }
}

TEST(RoadLogSweep, SignalOscillatesAtTheInstantaneousFrequency) {
  const LogSweep sweep(seed_sweep(0.002));
  // Two successive zero crossings are half a local period apart.
  for (double t : {12.0, 30.0, 45.0, 57.0}) {
    const double half_period = 0.5 / sweep.instantaneous_frequency_Hz(t);
    double a = t;
    while ((sweep.at(a).elevation_m > 0) == (sweep.at(a + 0.05 * half_period).elevation_m > 0)) {
      a += 0.05 * half_period;
    }
    const double z1 = zero_crossing(sweep, a, a + 0.05 * half_period);
    double b = z1 + 0.5 * half_period;
    while ((sweep.at(b).elevation_m > 0) == (sweep.at(b + 0.05 * half_period).elevation_m > 0)) {
      b += 0.05 * half_period;
    }
    const double z2 = zero_crossing(sweep, b, b + 0.05 * half_period);
    // The phase advances by π between crossings, so the mean of f over them is 0.5/(z2 − z1);
    // for f = f0·e^(bt) that mean is (f(z2) − f(z1))/(b·(z2 − z1)).
    const double measured_Hz = 0.5 / (z2 - z1);
    const double rate_per_s = std::log(300.0) / 60.0;
    const double mean_Hz =
        (sweep.instantaneous_frequency_Hz(z2) - sweep.instantaneous_frequency_Hz(z1)) /
        (rate_per_s * (z2 - z1));
    EXPECT_NEAR(measured_Hz / mean_Hz, 1.0, 1e-9) << t;
    EXPECT_NEAR(measured_Hz / sweep.instantaneous_frequency_Hz(0.5 * (z1 + z2)), 1.0, 1.5e-3) << t;
    // The peak between the crossings reaches the local amplitude.
    double peak = 0.0;
    double t_peak = z1;
    for (double s = z1; s < z2; s += (z2 - z1) / 2000.0) {
      if (std::abs(sweep.at(s).elevation_m) > peak) {
        peak = std::abs(sweep.at(s).elevation_m);
        t_peak = s;
      }
    }
    EXPECT_NEAR(peak / sweep.amplitude_m(t_peak), 1.0, 2e-3) << t;
  }
}

TEST(RoadLogSweep, StartsFromAFlatRoadAndHasTheAnalyticRate) {
  const LogSweep sweep(seed_sweep(0.01));
  EXPECT_EQ(sweep.at(-1.0).elevation_m, 0.0);
  EXPECT_EQ(sweep.at(-1.0).rate_m_per_s, 0.0);
  EXPECT_EQ(sweep.at(0.0).elevation_m, 0.0);
  EXPECT_NEAR(sweep.at(0.0).rate_m_per_s, 2 * std::numbers::pi * 0.1 * 0.01, 1e-15);
  // Continues smoothly past the end.
  const double h = 1e-7;
  const double central =
      (sweep.at(60.0 + h).elevation_m - sweep.at(60.0 - h).elevation_m) / (2 * h);
  EXPECT_NEAR(sweep.at(60.0).rate_m_per_s, central, 1e-7);
}

TEST(RoadLogSweep, ConstantFrequencyIsAPlainSine) {
  LogSweepParameters p;
  p.start_frequency_Hz = p.end_frequency_Hz = 2.0;
  p.initial_amplitude_m = p.end_amplitude_m = 0.003;
  const LogSweep sweep(p);
  for (double t : {0.1, 1.3, 7.7}) {
    EXPECT_NEAR(sweep.at(t).elevation_m, 0.003 * std::sin(4 * std::numbers::pi * t), 1e-15);
  }
}

TEST(RoadLogSweep, InvalidParametersNameTheKey) {
  auto expect_key = [](LogSweepParameters p, const std::string& key) {
    try {
      LogSweep sweep(p);
      ADD_FAILURE() << key;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("'" + key + "'"), std::string::npos) << e.what();
    }
  };
  LogSweepParameters p;
  p.start_frequency_Hz = 0.0;
  expect_key(p, "start_frequency_Hz");
  p = {};
  p.end_amplitude_m = -1e-3;
  expect_key(p, "end_amplitude_m");
  p = {};
  p.duration_s = std::nan("");
  expect_key(p, "duration_s");
}

TEST(RoadLogSweep, MaxStepIsAQuarterOfTheShortestPeriod) {
  const LogSweep up(seed_sweep(0.01));  // 0.1 → 30 Hz
  EXPECT_GT(up.max_step_s(), 0.0);
  EXPECT_TRUE(std::isfinite(up.max_step_s()));
  EXPECT_DOUBLE_EQ(up.max_step_s(), 0.25 / 30.0);
  LogSweepParameters down = seed_sweep(0.01);  // a downward sweep: f0 is the highest
  down.start_frequency_Hz = 40.0;
  down.end_frequency_Hz = 2.0;
  EXPECT_DOUBLE_EQ(LogSweep(down).max_step_s(), 0.25 / 40.0);
}

TEST(RoadLogSweep, AbsurdFrequenciesAndDurationsAreInputErrors) {
  auto message = [](const LogSweepParameters& p) {
    return testing::input_error_message([&] { LogSweep sweep(p); });
  };
  LogSweepParameters p;
  p.end_frequency_Hz = 1e6;  // hung the integrator
  EXPECT_THROW(LogSweep{p}, InputError);
  EXPECT_NE(message(p).find("'end_frequency_Hz'"), std::string::npos) << message(p);
  EXPECT_NE(message(p).find("500 Hz"), std::string::npos) << message(p);
  p = {};
  p.start_frequency_Hz = 501.0;
  EXPECT_NE(message(p).find("'start_frequency_Hz'"), std::string::npos) << message(p);
  p = {};
  p.start_frequency_Hz = p.end_frequency_Hz = 500.0;  // the limit itself is fine
  EXPECT_NO_THROW(LogSweep{p});
  p = {};
  p.duration_s = 1e9;  // 1.2e11 quarter periods of 30 Hz
  EXPECT_THROW(LogSweep{p}, InputError);
  EXPECT_NE(message(p).find("'duration_s'"), std::string::npos) << message(p);
  p.duration_s = 0.999 * 2e7 * 0.25 / 30.0;  // just inside the step limit
  EXPECT_NO_THROW(LogSweep{p});
  p.duration_s = 1e-6;
  EXPECT_NE(message(p).find("'duration_s'"), std::string::npos) << message(p);
}

}  // namespace
}  // namespace ridefit::road
