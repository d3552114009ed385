#include "ridefit/simulate/solver_statistics_json.h"

namespace ridefit::simulate {

nlohmann::json to_json(const SolverStatistics& statistics) {
  return {{"method", statistics.method},
          {"steps", statistics.steps},
          {"rhs_evaluations", statistics.rhs_evaluations},
          {"jacobian_evaluations", statistics.jacobian_evaluations},
          {"error_test_failures", statistics.error_test_failures},
          {"nonlinear_convergence_failures", statistics.nonlinear_convergence_failures},
          {"events", statistics.events}};
}

}  // namespace ridefit::simulate
