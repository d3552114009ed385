#pragma once

#include <array>
#include <complex>
#include <span>
#include <vector>

namespace ridefit::signal {

// An analogue (continuous-time) second-order section
//
//   H(s) = (n0 + n1·s + n2·s²) / (d0 + d1·s + d2·s²),   s = j·2πf,
//
// coefficients in ascending powers of s (first-order sections set n2 = d2 = 0). The frequency
// at which its bilinear discretisation is pre-warped (matched exactly) travels with it because
// only the designer of the section knows which frequency matters: a pole pair's natural
// frequency for a resonant section, a cut-off for a band limit.
struct AnalogueSection {
  std::array<double, 3> numerator{1.0, 0.0, 0.0};
  std::array<double, 3> denominator{1.0, 0.0, 0.0};
  double prewarp_frequency_Hz = 0.0;
};

// H(j·2πf) of one analogue section.
std::complex<double> analogue_response(const AnalogueSection& section, double frequency_Hz);
// Product of the sections' responses.
std::complex<double> analogue_response(std::span<const AnalogueSection> sections,
                                       double frequency_Hz);

// A digital second-order section, normalised so that a0 = 1:
//
//   H(z) = (b0 + b1·z⁻¹ + b2·z⁻²) / (1 + a1·z⁻¹ + a2·z⁻²).
struct Biquad {
  double b0 = 1.0, b1 = 0.0, b2 = 0.0;
  double a1 = 0.0, a2 = 0.0;
};

// Bilinear transform with frequency pre-warping: s = c·(1 − z⁻¹)/(1 + z⁻¹) with
// c = ω_p / tan(ω_p / (2·fs)), ω_p = 2π·prewarp_frequency_Hz, so that the digital response at
// the pre-warp frequency equals the analogue one exactly. Everywhere else the digital response
// at f equals the analogue response at f_a = (ω_p / 2π)·tan(πf/fs) / tan(πf_p/fs): the
// frequency axis is compressed towards Nyquist, the only error the transform makes (it is
// stable, and maps the analogue DC and s → ∞ to z = 1 and z = −1).
//
// Throws InputError for a sample rate that is not positive and finite, or a pre-warp frequency
// outside (0, fs/2) (the tangent is not defined there), naming the rate that would do.
Biquad bilinear_transform(const AnalogueSection& section, double sample_rate_Hz);

// A cascade of biquads at one sample rate: the usual way to run a high-order IIR filter,
// because each section's poles are as insensitive to coefficient rounding as a second-order
// polynomial's can be (one high-order polynomial's are not).
class BiquadCascade {
 public:
  BiquadCascade(std::vector<Biquad> sections, double sample_rate_Hz);

  // Designs each analogue section by bilinear_transform (see its errors).
  static BiquadCascade from_analogue(std::span<const AnalogueSection> sections,
                                     double sample_rate_Hz);

  // H(e^{j·2πf/fs}) of the whole cascade.
  std::complex<double> response(double frequency_Hz) const;

  // Filters a signal from rest (zero initial state), transposed direct form II per section,
  // all sections advanced sample by sample so their recursions overlap in the CPU.
  // The input is not checked for NaN (a caller that needs that checks before, once).
  std::vector<double> filter(std::span<const double> input) const;
  void filter_in_place(std::span<double> signal) const;

  const std::vector<Biquad>& sections() const { return sections_; }
  double sample_rate_Hz() const { return sample_rate_Hz_; }

 private:
  std::vector<Biquad> sections_;
  double sample_rate_Hz_;
};

}  // namespace ridefit::signal
