#pragma once

#include <string>
#include <vector>

#include "ridefit/comfort/vibration_metrics.h"

namespace ridefit::comfort {

// ISO 2631-1:1997 clause 6 (6.2.1, 6.3): the basic evaluation (weighted RMS) is normally
// sufficient for crest factors up to 9; for crest factors above 9, or when
//   MTVV / a_w > 1.5               (eq. 6)    or    VDV / (a_w · T^¼) > 1.75   (eq. 7),
// the basic method may underestimate the effect of occasional shocks, and the additional
// method(s) (running RMS / MTVV, or VDV) must be reported as well as a_w.
// The limits are strict inequalities, as the standard writes them.
struct AdditionalMethodsCheck {
  static constexpr double kCrestFactorLimit = 9.0;
  static constexpr double kMtvvRatioLimit = 1.5;
  static constexpr double kVdvRatioLimit = 1.75;

  double crest_factor = 0.0;
  double mtvv_ratio = 0.0;  // MTVV / a_w
  double vdv_ratio = 0.0;   // VDV / (a_w · T^¼)
  bool crest_factor_exceeded = false;
  bool mtvv_ratio_exceeded = false;
  bool vdv_ratio_exceeded = false;
  // One sentence per exceeded limit, naming the value and the limit; empty when none is.
  std::vector<std::string> reasons;

  bool additional_methods_required() const {
    return crest_factor_exceeded || mtvv_ratio_exceeded || vdv_ratio_exceeded;
  }
};

// Applies the rule to metrics from vibration_metrics(). For a record with a_w = 0 (no
// vibration) all ratios are 0 and nothing is flagged.
AdditionalMethodsCheck check_additional_methods(const VibrationMetrics& metrics);

}  // namespace ridefit::comfort
