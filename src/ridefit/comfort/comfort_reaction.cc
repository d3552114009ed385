#include "ridefit/comfort/comfort_reaction.h"

#include <fmt/format.h>

#include <cmath>

#include "ridefit/common/errors.h"

namespace ridefit::comfort {

std::vector<ComfortReaction> comfort_reactions(double total_value_m_per_s2) {
  const double a = total_value_m_per_s2;
  if (!std::isfinite(a) || a < 0.0) {
    throw InputError(fmt::format(
        "comfort reaction: total value {} m/s² is invalid; it must be a finite RMS value, at "
        "least 0",
        a));
  }
  std::vector<ComfortReaction> reactions;
  if (a < 0.315) reactions.push_back(ComfortReaction::kNotUncomfortable);
  if (a >= 0.315 && a <= 0.63) reactions.push_back(ComfortReaction::kALittleUncomfortable);
  if (a >= 0.5 && a <= 1.0) reactions.push_back(ComfortReaction::kFairlyUncomfortable);
  if (a >= 0.8 && a <= 1.6) reactions.push_back(ComfortReaction::kUncomfortable);
  if (a >= 1.25 && a <= 2.5) reactions.push_back(ComfortReaction::kVeryUncomfortable);
  if (a > 2.0) reactions.push_back(ComfortReaction::kExtremelyUncomfortable);
  return reactions;
}

const char* to_string(ComfortReaction reaction) {
  switch (reaction) {
    case ComfortReaction::kNotUncomfortable:
      return "not uncomfortable";
    case ComfortReaction::kALittleUncomfortable:
      return "a little uncomfortable";
    case ComfortReaction::kFairlyUncomfortable:
      return "fairly uncomfortable";
    case ComfortReaction::kUncomfortable:
      return "uncomfortable";
    case ComfortReaction::kVeryUncomfortable:
      return "very uncomfortable";
    case ComfortReaction::kExtremelyUncomfortable:
      return "extremely uncomfortable";
  }
  return "?";
}

}  // namespace ridefit::comfort
