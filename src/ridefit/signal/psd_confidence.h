#pragma once

#include <vector>

#include "ridefit/signal/welch_psd.h"

namespace ridefit::signal {

struct ConfidenceBounds {
  double lower = 0.0;
  double upper = 0.0;
};

// The χ² confidence interval of a spectral estimate P̂ with ν equivalent degrees of freedom
// (ν·P̂/P ~ χ²_ν): with α = 1 − confidence,
//   [ν·P̂ / χ²_ν(1 − α/2),  ν·P̂ / χ²_ν(α/2)],
// χ²_ν(p) the p-quantile (boost::math::chi_squared; ν need not be an integer). It covers the true
// density with probability `confidence`; the interval is asymmetric about P̂, constant in
// width on a logarithmic axis.
//
// Throws InputError for a non-finite or negative estimate, ν not finite and > 0, or confidence
// outside (0, 1).
ConfidenceBounds chi_squared_interval(double estimate, double degrees_of_freedom,
                                      double confidence);

struct PsdConfidenceInterval {
  std::vector<double> lower;  // per bin, [unit]²/Hz
  std::vector<double> upper;
  double confidence = 0.0;
};

// chi_squared_interval for every bin of a spectrum with its own degrees of freedom (Welch,
// averaged and/or smoothed). The coverage holds where the true spectrum is nearly flat over a
// bin's resolution (window main lobe and smoothing width); at sharp peaks the estimate is also
// biased and the interval does not account for bias.
//
// Throws InputError for a spectrum without statistics (see check_psd_statistics) or confidence
// outside (0, 1).
PsdConfidenceInterval psd_confidence_interval(const PowerSpectralDensity& spectrum,
                                              double confidence = 0.9);

}  // namespace ridefit::signal
