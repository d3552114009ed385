#include "ridefit/fitting/fit_convergence.h"

#include <fmt/core.h>

#include "ridefit/common/errors.h"

namespace ridefit::fitting {

void require_convergence(bool converged, bool explains_data, const std::string& what,
                         int iterations, const std::string& termination,
                         const std::string& remedy) {
  if (converged || !explains_data) return;
  throw RunError(fmt::format(
      "{} did not converge after {} iterations ({}); no fitted model was written. Try {}", what,
      iterations, termination, remedy));
}

}  // namespace ridefit::fitting
