#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "ridefit/fitting/psd_fit.h"

namespace ridefit::fitting {

// Whether a fitted model explains the data it was fitted to, for every fit: the NRMSE of the
// fitted output, the free parameters that ended on a bound, and the verdict. A fit is flagged
// when the NRMSE is above a threshold, or when parameters end on bounds while the data leave
// some parameters undetermined: a collapsed fit (the model gave up a mechanism to imitate
// another, e.g. friction driven to 0 and the damping made huge).
struct FitAdequacy {
  double nrmse_percent = 0.0;
  std::vector<std::string> on_bounds;  // "name = value (lower bound)"
  bool explains_data = true;
  std::string note;  // why not, in words, with the suggestion to diagnose ("" when it does)
};

// The verdict from its parts; `output` names what the NRMSE is of ("force", "acceleration
// spectra").
FitAdequacy judge_fit(double nrmse_percent, std::vector<std::string> on_bounds,
                      const std::vector<std::string>& unidentifiable, double max_nrmse_percent,
                      std::string_view output);

// "name = value (lower|upper bound)" when `value` sits on a bound (within 1e-4 of it, relative;
// absolute 1e-6 of the range for a bound of 0), else "".
std::string on_bound(std::string_view name, double value, double lower, double upper);

// A PSD fit's adequacy. Its NRMSE is that of the amplitude spectra, RMS over the band's bins and
// both channels of √(P_fit/P_meas) − 1 (an amplitude error, comparable with the NRMSE of a time
// signal), in %; the bounds are the fit's (PsdFitOptions::bounds, else a decade either side of
// the start value, as fit_psd uses).
FitAdequacy assess_psd_fit(const PsdFitResult& fit,
                           const model::QuarterCarParameters<double>& start,
                           const PsdFitOptions& options, double max_nrmse_percent = 10.0);

}  // namespace ridefit::fitting
