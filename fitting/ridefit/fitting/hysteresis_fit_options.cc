#include "ridefit/fitting/hysteresis_fit_options.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "ridefit/common/errors.h"

namespace ridefit::fitting {

RecordWeighting parse_record_weighting(const std::string& text) {
  if (text == "newtons") return RecordWeighting::kNewtons;
  if (text == "relative") return RecordWeighting::kRelative;
  throw InputError(fmt::format(
      "record weights '{}': expected newtons (every residual in N) or relative (each record over "
      "its own force's spread)",
      text));
}

void HysteresisFitOptions::validate() const {
  if (free.empty()) {
    throw InputError("free parameters: name at least one parameter to fit, e.g. coulomb_force_N");
  }
  std::set<std::size_t> freed;
  for (const auto& name : free) {
    if (!freed.insert(strut_parameter_index(name)).second) {
      throw InputError(fmt::format("free parameters: '{}' is given twice", name));
    }
  }
  for (const auto& name : per_file) {
    if (!freed.count(strut_parameter_index(name))) {
      throw InputError(
          fmt::format("per-file parameters: '{}' is not among the free parameters", name));
    }
  }
  for (const auto& [name, bound] : bounds) {
    strut_parameter_index(name);
    if (!(bound.first < bound.second) || !std::isfinite(bound.first) ||
        !std::isfinite(bound.second)) {
      throw InputError(fmt::format("bounds of {}: lower {} must be below upper {}, both finite",
                                   name, bound.first, bound.second));
    }
  }
  if (!(loss_scale_N > 0.0) || !std::isfinite(loss_scale_N)) {
    throw InputError(fmt::format("loss scale {} N: expected a finite value > 0", loss_scale_N));
  }
  if (max_iterations < 0) {  // 0: evaluate the start only
    throw InputError(fmt::format("iteration limit {}: expected at least 0", max_iterations));
  }
  if (!(max_nrmse_percent > 0.0)) {
    throw InputError(fmt::format("NRMSE threshold {} %: expected a value > 0", max_nrmse_percent));
  }
}

std::array<std::pair<double, double>, kStrutParameters.size()>
HysteresisFitOptions::resolved_bounds() const {
  std::array<std::pair<double, double>, kStrutParameters.size()> resolved;
  for (std::size_t i = 0; i < kStrutParameters.size(); ++i) {
    resolved[i] = {kStrutParameters[i].lower, kStrutParameters[i].upper};
  }
  // Force levels scale with the records' force: [lower, upper] widened to ±5× the largest force.
  namespace qc = model::quarter_car_rows;
  namespace rig = model::strut_rig_rows;
  const double level = 5.0 * force_scale_N;
  for (const model::ParameterInfo* row :
       {&qc::coulomb_force_N, &qc::static_friction_force_N, &qc::coulomb_force_per_command_N,
        &rig::gas_force_N, &rig::force_offset_N}) {
    auto& [lo, hi] = resolved[strut_parameter_index(row->key)];
    hi = std::max(hi, level);
    if (lo < 0.0) lo = std::min(lo, -level);
  }
  for (const auto& [name, bound] : bounds) resolved[strut_parameter_index(name)] = bound;
  return resolved;
}

}  // namespace ridefit::fitting
