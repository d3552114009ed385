#pragma once

#include <complex>
#include <string_view>
#include <vector>

#include "ridefit/signal/biquad_cascade.h"

namespace ridefit::comfort {

// The ISO 2631-1:1997 frequency weightings (Annex A).
enum class Weighting {
  kWk,  // z-axis, seat surface, standing, recumbent (except head): health, comfort, perception
  kWd,  // x- and y-axis, seat surface, standing, recumbent; seat back y, z
  kWf,  // z-axis, motion sickness
  kWc,  // x-axis, seat back
  kWe,  // rotational (roll, pitch, yaw), seat surface; input in rad/s², output in rad/s²
  kWj,  // x-axis under the head of a recumbent person
};

// Parameters of Annex A's product H = H_h·H_l·H_t·H_s (s = j2πf, ω_i = 2πf_i):
//   band-limiting high-pass   H_h = 1 / (1 + √2·ω1/s + (ω1/s)²)               (Q = 1/√2)
//   band-limiting low-pass    H_l = 1 / (1 + √2·s/ω2 + (s/ω2)²)               (Q = 1/√2)
//   a-v transition            H_t = (1 + s/ω3) / (1 + s/(Q4·ω4) + (s/ω4)²)
//   upward step               H_s = K·(s² + ω5·s/Q5 + ω5²) / (s² + ω6·s/Q6 + ω6²)
// (H_s has gain K far above f6 and K·(f5/f6)² far below f5: the step is upward from low to
// high frequency). An infinite f3 removes H_t's zero, infinite f4 (with f3) removes H_t,
// infinite f5 and f6 remove H_s; frequencies in Hz.
struct WeightingParameters {
  double f1_Hz, f2_Hz;          // band limits
  double f3_Hz, f4_Hz, q4;      // acceleration–velocity transition
  double f5_Hz, q5, f6_Hz, q6;  // upward step
  double gain_k;                // K
};

const WeightingParameters& weighting_parameters(Weighting weighting);

// "Wk", "Wd", "Wf", "Wc", "We", "Wj".
const char* to_string(Weighting weighting);
// Inverse of to_string, case-insensitive; throws InputError listing the accepted names.
Weighting parse_weighting(std::string_view name);

// The analogue weighting as second-order sections (H_h, H_l, then H_t and H_s where present),
// each carrying its pre-warp frequency: f1, f2, f4 (the a-v transition's pole pair; f3 = f4
// where both are finite) and √(f5·f6) (the step's centre, between its zero and pole pairs).
std::vector<signal::AnalogueSection> weighting_sections(Weighting weighting);

// Complex response and magnitude of the analogue weighting at frequency_Hz ≥ 0 (dimensionless
// factor, the quantity ISO 2631-1 Tables 3 and 4 tabulate ×1000).
std::complex<double> weighting_response(Weighting weighting, double frequency_Hz);
double weighting_magnitude(Weighting weighting, double frequency_Hz);

}  // namespace ridefit::comfort
