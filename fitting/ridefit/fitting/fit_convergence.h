#pragma once

#include <string>

namespace ridefit::fitting {

// A fit that explains the data but stopped before it converged is a failed run: RunError
// "<what> did not converge after N iterations (<termination>); no fitted model was written.
// Try <remedy>". `remedy` says in the caller's own terms what to try (the command names its
// flags, the Python module its arguments). Nothing happens otherwise: a fit that does not
// explain the data is reported as such, converged or not.
void require_convergence(bool converged, bool explains_data, const std::string& what,
                         int iterations, const std::string& termination, const std::string& remedy);

}  // namespace ridefit::fitting
