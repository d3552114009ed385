#pragma once

#include <vector>

#include "ridefit/simulate/esdirk_tableau.h"
#include "ridefit/simulate/integrator.h"
#include "ridefit/simulate/ode_system.h"

namespace ridefit::simulate {

// Every accepted step of an ESDIRK run, for the tangent replay (esdirk_tangents.h): its start
// and length and the converged values of its implicit stages.
struct EsdirkStepHistory {
  int state_size = 0;
  std::vector<double> start_s;
  std::vector<double> length_s;
  // (kStages − 1)·n values per step: stages 2..s, stage after stage.
  std::vector<double> stages;
  static constexpr int kImplicitStages = EsdirkTableau::kStages - 1;
  std::size_t step_count() const { return start_s.size(); }
  const double* stage(std::size_t step, int implicit_stage) const {
    return stages.data() +
           (step * kImplicitStages + static_cast<std::size_t>(implicit_stage)) * state_size;
  }
};

// The integrator settings of a replayed run's options (StrutTestSolverOptions,
// AccelerationSolverOptions: a relative tolerance and a step budget per simulated second).
template <typename ReplayedRunOptions>
IntegratorOptions esdirk_options(const ReplayedRunOptions& options) {
  IntegratorOptions integrator;
  integrator.relative_tolerance = options.relative_tolerance;
  integrator.max_steps_per_s = options.max_steps_per_s;
  return integrator;
}

// The adaptive ESDIRK3(2)4L[2]SA integrator (esdirk_tableau.h), ridefit's default.
//
// - Error control: the embedded solution's difference, filtered by (I − γhJ)⁻¹ (the stiff
//   components' estimate, as in Hairer & Wanner's RADAU5), in the weighted RMS norm with
//   rtol·|y| + rtol·typical_magnitude per state (OdeSystem); a PI step-size controller
//   (Gustafsson: exponents 0.7/3 and 0.4/3, safety 0.9, growth at most 5, no growth straight
//   after a rejection).
// - Stages: simplified Newton on G = I − γhJ, the exact autodiff Jacobian J kept across steps
//   while Newton converges quickly (refreshed after a slow iteration, every 50 steps, and at the
//   Newton iterate after a failure), the factorisation redone when γh moves by more than 20 %.
//   A stage counts as converged when both the update and the stage equation's residual are
//   within the tolerance (a stale G can make the update small while the residual is not).
// - Kinks: the system's switching functions are continued on the last step's interpolant to
//   predict a kink ahead, and compared at both ends of each attempted step to locate one inside
//   it (Illinois); the step then ends 2 % of its length past the root, so no accepted step
//   straddles a kink and no stage sits on one.
// - Output: cubic Hermite interpolation between the step's ends (y and f at both: third order,
//   as the method), so the step sequence never depends on the output grid.
//
// Fixed-size Eigen storage (per state count): no heap allocation inside the step loop. With
// `history`, every accepted step is recorded for the tangent replay (its stages then converged
// to 1e-5 of the tolerance). Gives up (RunError) past max_steps_per_s steps per simulated second.
Trajectory integrate_esdirk(const OdeSystem& system, const std::vector<double>& x0,
                            const std::vector<double>& output_times_s,
                            const IntegratorOptions& options, EsdirkStepHistory* history = nullptr);

// The same method on a given step sequence (another run's history), each stage's Newton
// converged to round-off, without error control or events: the discrete
// map whose derivative replay_esdirk computes, for checking it by finite differences.
Trajectory integrate_esdirk_on_steps(const OdeSystem& system, const std::vector<double>& x0,
                                     const std::vector<double>& output_times_s,
                                     const IntegratorOptions& options,
                                     const EsdirkStepHistory& steps);

// A replayed run's two uses of the integrator, with `frozen` (a history, or null) choosing
// between the adaptive run and the frozen-step map: the trajectory in doubles, and the history
// the replay in T follows (recorded into `own` unless frozen).
inline Trajectory integrate_esdirk_or_frozen(const OdeSystem& system, const std::vector<double>& x0,
                                             const std::vector<double>& output_times_s,
                                             const IntegratorOptions& options,
                                             const EsdirkStepHistory* frozen) {
  return frozen != nullptr ? integrate_esdirk_on_steps(system, x0, output_times_s, options, *frozen)
                           : integrate_esdirk(system, x0, output_times_s, options);
}

inline const EsdirkStepHistory& esdirk_steps_or_frozen(const OdeSystem& system,
                                                       const std::vector<double>& x0,
                                                       const std::vector<double>& output_times_s,
                                                       const IntegratorOptions& options,
                                                       const EsdirkStepHistory* frozen,
                                                       EsdirkStepHistory& own) {
  if (frozen != nullptr) return *frozen;
  integrate_esdirk(system, x0, output_times_s, options, &own);
  return own;
}

}  // namespace ridefit::simulate
