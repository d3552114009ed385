#pragma once

#include <cstddef>
#include <span>

namespace ridefit::fitting::diagnose {

// A spectral peak's frequency with its standard error. The peak is the largest bin of the
// 3-bin smoothed PSD; its frequency the vertex of a least-squares parabola in ln PSD through the
// contiguous bins around it within 3 dB (half power) of the smoothed maximum, at least two on each
// side. A mode's PSD near its peak is close to a parabola in ln P, and the whole half-power
// width informs the vertex, so a broad mode (the wheel hop, ζ ≈ 0.3) is located far better than
// its largest bin. The standard error follows from the regression: each bin's ln P̂ scatters
// with variance ψ'(ν/2), inflated by 1 + 2·Σ_d ρ(d) for the correlation of adjacent bins
// (`bin_correlation`, as in pooled_bands.h), through the delta method on −b/(2c).
struct PeakEstimate {
  double frequency_Hz = 0.0;
  double standard_error_Hz = 0.0;  // infinite when the bins show no curvature (no peak)
};
PeakEstimate estimate_peak(std::span<const double> frequency_Hz, std::span<const double> psd,
                           double degrees_of_freedom, std::span<const double> bin_correlation);

// Measured against simulated peak of one channel.
struct PeakComparison {
  PeakEstimate measured;
  PeakEstimate simulated;
  // The shift that counts: the larger of two bin widths (the estimate's resolution) and
  // z(1 − α/2)·√(se_m² + se_s²) (the two estimates' scatter, taken as independent: when both
  // are driven by the same road they scatter together, so this errs large).
  double threshold_Hz = 0.0;
  bool significant = false;  // |measured − simulated| > threshold_Hz
};
PeakComparison compare_peaks(const PeakEstimate& measured, const PeakEstimate& simulated,
                             double bin_width_Hz, double alpha);

}  // namespace ridefit::fitting::diagnose
