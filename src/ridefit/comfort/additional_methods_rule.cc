#include "ridefit/comfort/additional_methods_rule.h"

#include <fmt/format.h>

#include <cmath>

namespace ridefit::comfort {

AdditionalMethodsCheck check_additional_methods(const VibrationMetrics& metrics) {
  AdditionalMethodsCheck check;
  const double aw = metrics.weighted_rms_m_per_s2;
  // Below 1 µm/s² there is no vibration to judge (a constant record weights to round-off, whose
  // ratios are meaningless), far under the 0.01 m/s² where perception starts (ISO 2631-1 C.3).
  if (!(aw > 1e-6)) return check;
  check.crest_factor = metrics.crest_factor;
  check.mtvv_ratio = metrics.mtvv_m_per_s2 / aw;
  check.vdv_ratio = metrics.vdv_m_per_s1_75 / (aw * std::pow(metrics.duration_s, 0.25));

  check.crest_factor_exceeded = check.crest_factor > AdditionalMethodsCheck::kCrestFactorLimit;
  check.mtvv_ratio_exceeded = check.mtvv_ratio > AdditionalMethodsCheck::kMtvvRatioLimit;
  check.vdv_ratio_exceeded = check.vdv_ratio > AdditionalMethodsCheck::kVdvRatioLimit;
  if (check.crest_factor_exceeded) {
    check.reasons.push_back(fmt::format(
        "crest factor {:.3g} exceeds {}: the weighted RMS may underestimate shocks; report MTVV "
        "and VDV (ISO 2631-1 6.2.1)",
        check.crest_factor, AdditionalMethodsCheck::kCrestFactorLimit));
  }
  if (check.mtvv_ratio_exceeded) {
    check.reasons.push_back(fmt::format(
        "MTVV/a_w = {:.3g} exceeds {}: report the running RMS and MTVV (ISO 2631-1 6.3, eq. 6)",
        check.mtvv_ratio, AdditionalMethodsCheck::kMtvvRatioLimit));
  }
  if (check.vdv_ratio_exceeded) {
    check.reasons.push_back(fmt::format(
        "VDV/(a_w·T^1/4) = {:.3g} exceeds {}: report the vibration dose value (ISO 2631-1 6.3, "
        "eq. 7)",
        check.vdv_ratio, AdditionalMethodsCheck::kVdvRatioLimit));
  }
  return check;
}

}  // namespace ridefit::comfort
