#pragma once

#include <filesystem>
#include <string>

namespace ridefit::road {

// Limits on user-given road parameters, and checks shared by the roads. Outside them a road would
// exhaust memory, keep an adaptive integrator busy for hours (it may not step further than
// max_step_s()), or make no sense for a road vehicle; every check throws an InputError that names
// the YAML key.

// The most samples of any sampled road (profile, spline, FFT) and the most steps of
// max_step_s() a road may demand over its duration. 2e7 doubles are 160 MB (the spline's
// coefficients as much again, the FFT of a random road about 1 GB at the limit); 2e7 covers
// an hour at 150 m/s with the default 0.05 m spacing, or 2.8 h of a 500 Hz sweep. The same
// figure as the simulation's output-sample limit.
inline constexpr double kMaxRoadSamples = 2e7;

// The fastest a road is driven: 150 m/s = 540 km/h, above any road vehicle's top speed.
inline constexpr double kMaxSpeed_m_per_s = 150.0;

// The highest frequency of a sweep: a quarter car's wheel hop is at 10–15 Hz and its tyre and
// bushing models mean nothing above a few hundred Hz.
inline constexpr double kMaxSweepFrequency_Hz = 500.0;

// The shortest excitation: one output sample at the default 1 kHz output rate.
inline constexpr double kMinRoadDuration_s = 1e-3;

// Throws an InputError naming `key` unless 0 < speed_m_per_s <= kMaxSpeed_m_per_s (finite).
// The message gives the speed in m/s and km/h.
void check_speed_m_per_s(double speed_m_per_s, const std::string& key = "speed_m_per_s");

// Throws an InputError naming `path` if it is a directory or another non-regular file (a
// device, a pipe: reading one would never end), saying it expected `expected`. A missing file
// passes: the CSV reader says "file not found".
void check_data_file(const std::filesystem::path& path, const std::string& expected);

}  // namespace ridefit::road
