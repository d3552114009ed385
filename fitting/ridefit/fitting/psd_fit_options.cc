#include "ridefit/fitting/psd_fit_options.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "ridefit/common/errors.h"
#include "ridefit/model/quarter_car_parameter_table.h"

namespace ridefit::fitting {
namespace {

void require_positive(double value, const char* what) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw InputError(fmt::format("{} {}: expected a finite value > 0", what, value));
  }
}

}  // namespace

void PsdFitOptions::validate(bool fitting) const {
  if (fitting && (free.empty() || free.size() > kMaxFree)) {
    throw InputError(fmt::format("free parameters: name 1 to {} parameters to fit ({} named)",
                                 kMaxFree, free.size()));
  }
  std::set<std::string> freed;
  for (const auto& name : free) {
    if (!model::quarter_car_parameter_index(name)) {
      std::string list;
      for (const auto& row : model::kQuarterCarParameters) {
        list += (list.empty() ? "" : ", ") + std::string(row.key);
      }
      throw InputError(fmt::format("'{}' is not a quarter-car parameter; one of: {}", name, list));
    }
    if (!freed.insert(name).second) {
      throw InputError(fmt::format("free parameters: '{}' is given twice", name));
    }
  }
  for (const auto& [name, prior] : priors) {
    if (fitting && std::find(free.begin(), free.end(), name) == free.end()) {
      throw InputError(
          fmt::format("prior on {}: it is not fitted (free it too, or drop the prior)", name));
    }
    if (!std::isfinite(prior.mean) || !(prior.sd > 0.0) || !std::isfinite(prior.sd)) {
      throw InputError(fmt::format(
          "prior on {}: mean {} and standard deviation {}; expected a finite mean and sd > 0", name,
          prior.mean, prior.sd));
    }
  }
  for (const auto& [name, bound] : bounds) {
    if (!(bound.first < bound.second) || !std::isfinite(bound.first) ||
        !std::isfinite(bound.second)) {
      throw InputError(fmt::format("bounds of {}: lower {} must be below upper {}, both finite",
                                   name, bound.first, bound.second));
    }
  }
  if (!(band_low_Hz > 0.0 && band_low_Hz < band_high_Hz && std::isfinite(band_high_Hz))) {
    throw InputError(fmt::format("band {}–{} Hz: expected 0 < low < high, both finite", band_low_Hz,
                                 band_high_Hz));
  }
  require_positive(segment_s, "segment length (s)");
  require_positive(loss_scale, "loss scale");
  if (!(relative_tolerance > 0.0 && relative_tolerance <= 0.1)) {
    throw InputError(
        fmt::format("relative tolerance {}: expected a value in (0, 0.1]", relative_tolerance));
  }
  if (max_iterations < 0) {  // 0: evaluate the start only
    throw InputError(fmt::format("iteration limit {}: expected at least 0", max_iterations));
  }
  if (starts < 1) throw InputError(fmt::format("starts {}: expected at least 1", starts));
}

}  // namespace ridefit::fitting
