#include "ridefit/comfort/frequency_weighting.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "ridefit/common/errors.h"

namespace ridefit::comfort {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kButterworthQ = std::numbers::sqrt2 / 2.0;  // 1/√2

// ISO 2631-1:1997 Annex A, Table A.1 (the parameters of the transfer functions of the
// principal and additional frequency weightings). Wf has its own band limits, f1 = 0.08 Hz and
// f2 = 0.63 Hz, and no a-v zero (f3 = ∞); the other five share 0.4 Hz and 100 Hz. ISO 2631-1
// has no gain column; K = 1 for all six, as ISO 8041:2005 lists them (K ≠ 1 only for ISO
// 2631-4's Wb). The order follows the Weighting enumerators.
constexpr std::array<WeightingParameters, 6> kParameters{{
    //  f1    f2     f3    f4     Q4    f5      Q5    f6    Q6    K
    {0.4, 100.0, 12.5, 12.5, 0.63, 2.37, 0.91, 3.35, 0.91, 1.0},    // Wk
    {0.4, 100.0, 2.0, 2.0, 0.63, kInf, 1.0, kInf, 1.0, 1.0},        // Wd
    {0.08, 0.63, kInf, 0.25, 0.86, 0.0625, 0.80, 0.10, 0.80, 1.0},  // Wf
    {0.4, 100.0, 8.0, 8.0, 0.63, kInf, 1.0, kInf, 1.0, 1.0},        // Wc
    {0.4, 100.0, 1.0, 1.0, 0.63, kInf, 1.0, kInf, 1.0, 1.0},        // We
    {0.4, 100.0, kInf, kInf, 1.0, 3.75, 0.91, 5.32, 0.91, 1.0},     // Wj
}};

constexpr std::array<const char*, 6> kNames{"Wk", "Wd", "Wf", "Wc", "We", "Wj"};

}  // namespace

const WeightingParameters& weighting_parameters(Weighting weighting) {
  return kParameters[static_cast<std::size_t>(weighting)];
}

const char* to_string(Weighting weighting) { return kNames[static_cast<std::size_t>(weighting)]; }

Weighting parse_weighting(std::string_view name) {
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (std::size_t i = 0; i < kNames.size(); ++i) {
    std::string candidate(kNames[i]);
    candidate[0] = 'w';
    if (lower == candidate) return static_cast<Weighting>(i);
  }
  throw InputError(fmt::format(
      "unknown frequency weighting '{}'; accepted (ISO 2631-1, case-insensitive): Wk, Wd, Wf, "
      "Wc, We, Wj",
      name));
}

std::vector<signal::AnalogueSection> weighting_sections(Weighting weighting) {
  const WeightingParameters& p = weighting_parameters(weighting);
  const double w1 = kTwoPi * p.f1_Hz, w2 = kTwoPi * p.f2_Hz;
  std::vector<signal::AnalogueSection> sections;
  // H_h = s² / (s² + ω1·s/Q + ω1²)
  sections.push_back({.numerator = {0.0, 0.0, 1.0},
                      .denominator = {w1 * w1, w1 / kButterworthQ, 1.0},
                      .prewarp_frequency_Hz = p.f1_Hz});
  // H_l = ω2² / (s² + ω2·s/Q + ω2²)
  sections.push_back({.numerator = {w2 * w2, 0.0, 0.0},
                      .denominator = {w2 * w2, w2 / kButterworthQ, 1.0},
                      .prewarp_frequency_Hz = p.f2_Hz});
  if (std::isfinite(p.f4_Hz)) {
    const double w4 = kTwoPi * p.f4_Hz;
    const double zero = std::isfinite(p.f3_Hz) ? 1.0 / (kTwoPi * p.f3_Hz) : 0.0;
    sections.push_back({.numerator = {1.0, zero, 0.0},
                        .denominator = {1.0, 1.0 / (p.q4 * w4), 1.0 / (w4 * w4)},
                        .prewarp_frequency_Hz = p.f4_Hz});
  }
  if (std::isfinite(p.f5_Hz) && std::isfinite(p.f6_Hz)) {
    const double w5 = kTwoPi * p.f5_Hz, w6 = kTwoPi * p.f6_Hz;
    sections.push_back({.numerator = {p.gain_k * w5 * w5, p.gain_k * w5 / p.q5, p.gain_k},
                        .denominator = {w6 * w6, w6 / p.q6, 1.0},
                        .prewarp_frequency_Hz = std::sqrt(p.f5_Hz * p.f6_Hz)});
  } else if (p.gain_k != 1.0) {
    sections.push_back({.numerator = {p.gain_k, 0.0, 0.0},
                        .denominator = {1.0, 0.0, 0.0},
                        .prewarp_frequency_Hz = p.f1_Hz});
  }
  return sections;
}

std::complex<double> weighting_response(Weighting weighting, double frequency_Hz) {
  if (!std::isfinite(frequency_Hz) || frequency_Hz < 0.0) {
    throw InputError(fmt::format(
        "{} weighting: frequency {} Hz is invalid; it must be a finite number of Hz, at least 0",
        to_string(weighting), frequency_Hz));
  }
  return signal::analogue_response(weighting_sections(weighting), frequency_Hz);
}

double weighting_magnitude(Weighting weighting, double frequency_Hz) {
  return std::abs(weighting_response(weighting, frequency_Hz));
}

}  // namespace ridefit::comfort
