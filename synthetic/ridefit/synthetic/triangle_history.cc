#include "ridefit/synthetic/triangle_history.h"

#include <fmt/core.h>

#include <cmath>

#include "ridefit/common/errors.h"

namespace ridefit::synthetic {

TriangleHistory::TriangleHistory(double amplitude_m, double speed_m_per_s)
    : amplitude_m_(amplitude_m), period_s_(4.0 * amplitude_m / speed_m_per_s) {
  if (!(amplitude_m > 0.0) || !(speed_m_per_s > 0.0) || !std::isfinite(period_s_)) {
    throw InputError(fmt::format(
        "triangle history: amplitude {:g} m at {:g} m/s; give a finite amplitude > 0 and speed > 0",
        amplitude_m, speed_m_per_s));
  }
}

double TriangleHistory::operator()(double time_s) const {
  // In the phase p of the cycle: rising 4A·p, falling 2A − 4A·p, rising again −4A + 4A·p (4A and
  // 2A are exact multiples, so 3 mm gives the shipped records' 0.012 and 0.006 to the bit).
  const double phase = std::fmod(time_s, period_s_) / period_s_;
  const double slope = 4.0 * amplitude_m_;
  return phase < 0.25   ? slope * phase
         : phase < 0.75 ? 2.0 * amplitude_m_ - slope * phase
                        : -slope + slope * phase;
}

}  // namespace ridefit::synthetic
