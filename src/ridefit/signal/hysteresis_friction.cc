#include "ridefit/signal/hysteresis_friction.h"

#include <fmt/core.h>

#include <cmath>
#include <optional>

#include "ridefit/common/errors.h"

namespace ridefit::signal {

HysteresisFriction hysteresis_friction(std::span<const double> displacement_m,
                                       std::span<const double> force_N) {
  if (displacement_m.size() != force_N.size()) {
    throw InputError("hysteresis friction: displacement and force differ in length");
  }
  for (std::size_t i = 0; i < force_N.size(); ++i) {
    if (!std::isfinite(displacement_m[i]) || !std::isfinite(force_N[i])) {
      throw InputError(fmt::format("hysteresis friction: sample {} is not finite", i));
    }
  }
  // The force where x crosses zero between samples i and i+1, and the direction.
  HysteresisFriction result;
  std::optional<double> up;
  for (std::size_t i = 0; i + 1 < displacement_m.size(); ++i) {
    const double a = displacement_m[i], b = displacement_m[i + 1];
    const bool rising = a < 0.0 && b >= 0.0;
    const bool falling = a > 0.0 && b <= 0.0;
    if (!rising && !falling) continue;
    const double w = a / (a - b);
    const double force = (1.0 - w) * force_N[i] + w * force_N[i + 1];
    if (rising) {
      up = force;
    } else if (up) {
      result.per_cycle_N.push_back(std::abs(*up - force) / 2.0);
      up.reset();
    }
  }
  if (result.per_cycle_N.size() < 2) {
    throw InputError(fmt::format(
        "hysteresis friction: {} complete cycle(s) through zero displacement; the calibration "
        "averages cycles 2…N, so it needs at least 2",
        result.per_cycle_N.size()));
  }
  double sum = 0.0, squares = 0.0;
  for (std::size_t c = 1; c < result.per_cycle_N.size(); ++c) sum += result.per_cycle_N[c];
  result.cycles_used = static_cast<int>(result.per_cycle_N.size() - 1);
  result.mean_N = sum / result.cycles_used;
  for (std::size_t c = 1; c < result.per_cycle_N.size(); ++c) {
    squares += (result.per_cycle_N[c] - result.mean_N) * (result.per_cycle_N[c] - result.mean_N);
  }
  result.standard_deviation_N =
      result.cycles_used > 1 ? std::sqrt(squares / (result.cycles_used - 1)) : 0.0;
  return result;
}

}  // namespace ridefit::signal
