#pragma once

#include <optional>
#include <span>

namespace ridefit::fitting {

struct HysteresisFitResult;  // hysteresis_fit.h

// Seed 000's Figure 4: the Coulomb force grows with the spring's compression (the side load on
// the strut's guide). A straight line Fc = Fc0 + S·compression through per-file fitted friction
// values, weighted by 1/SE² where the fit gave standard errors (else equally), with the line's
// uncertainty: the parameter covariance (XᵀWX)⁻¹ scaled by the reduced χ² of the line (so an
// underestimated SE does not shrink the line's error), which needs three points or more.
struct FrictionCompressionLine {
  double intercept_N = 0.0;    // Fc at zero compression
  double slope_N_per_m = 0.0;  // S
  std::optional<double> intercept_se_N;
  std::optional<double> slope_se_N_per_m;
};

// InputError for fewer than 2 points, mismatched lengths, non-finite values, all compressions
// equal, or a standard error <= 0.
FrictionCompressionLine fit_friction_compression(std::span<const double> compression_m,
                                                 std::span<const double> coulomb_force_N,
                                                 std::span<const double> standard_error_N = {});

// The line through a hysteresis fit's per-file coulomb_force_N values (in file order) against
// each file's compression, weighted when the fit gave every value a standard error. InputError
// as above (also when the fit has no per-file friction values).
FrictionCompressionLine fit_friction_compression(const HysteresisFitResult& fit,
                                                 std::span<const double> compression_m);

}  // namespace ridefit::fitting
