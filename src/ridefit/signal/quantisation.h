#pragma once

#include <span>
#include <string>

namespace ridefit::signal {

// The step q of a quantised series (an ADC's or a print format's least step): the common
// spacing of its distinct values, or 0 when they do not lie on one lattice. Rule: the distinct
// values' gaps; q is the median of those within 1.5× the smallest (rounding to a coarser print
// format makes them 3.0 and 3.1 µm for a 3.05 µm ADC step), refined by least squares over the
// gaps' multiples, and the series counts as quantised when at least 95 % of the gaps lie within
// 10 % of q of a whole
// multiple of q and it holds at least
// 8 distinct values. Gaps under 1e-12 of the range are float round-off of one level, not gaps.
// Not found: an ADC step printed to a digit a third of it (3.05 µm to 1 µm: gaps of 3 and 4 µm
// lie on no common step), as in the MR press's files.
double quantisation_step(std::span<const double> series);

// Whether and where to low-pass a quantised displacement before it is differentiated: a step q
// is white noise of variance q²/12 (one-sided density N = q²/(6·fs)), and its difference
// quotient, the velocity a model feels, has the density N·(2·fs·sin(πf/fs))², rising with f: the
// velocity spikes of quantisation. The record's own velocity (its forward difference) is
// compared with that floor in Welch bins (Hann, 8 segments): the content ends at the lowest
// frequency above which the record's velocity power is at most twice the floor's (what remains
// is the steps' own noise), and the cut-off is ten times that (after the forward-backward pass
// of zero_phase_low_pass the content keeps 0.9999 of its amplitude). Not filtered: a series that
// is not quantised, whose content reaches 0.04·fs (cut-off above 0.4·fs; also a record whose
// sensor noise lies above its quantisation floor), that is too
// short (under 64 samples), or whose time steps vary by more than ±25 % around their mean (the
// filter assumes the mean step).
struct QuantisationLowPass {
  double step = 0.0;              // q, in the series' unit (0: not quantised)
  double content_up_to_Hz = 0.0;  // where the record's content ends (0: not examined)
  double cutoff_Hz = 0.0;         // 0: not filtered
  // The quantisation's velocity noise (RMS of its forward difference), in the series' unit per
  // second: unfiltered, q·fs/√6; filtered, the same density under |H|⁴.
  double velocity_noise_rms_before = 0.0;
  double velocity_noise_rms_after = 0.0;
  std::string reason;  // why not filtered ("" when it is)
};

// time_s: the samples' times (seconds, increasing), one per sample of series.
QuantisationLowPass choose_quantisation_low_pass(std::span<const double> time_s,
                                                 std::span<const double> series);

}  // namespace ridefit::signal
