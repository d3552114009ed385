#pragma once

#include <functional>
#include <string>
#include <vector>

#include "ridefit/simulate/ode_system.h"

namespace ridefit::simulate {

enum class Method {
  kEsdirk,     // ridefit's adaptive ESDIRK3(2)4L[2]SA (esdirk_integrator.h): the default
  kCvodeBdf,   // SUNDIALS CVODE: variable-order BDF, Newton with the dense Jacobian (reference)
  kArkodeRk4,  // SUNDIALS ARKODE ERKStep: classic 4-stage RK4 at a fixed step (seed's ode4)
};

struct IntegratorOptions {
  Method method = Method::kEsdirk;
  // ESDIRK and CVODE: the local error of each state is held below rtol·|x_i| + rtol·m_i, with
  // m_i the state's typical magnitude (OdeSystem: 1 mm for positions, 10 mm/s for velocities,
  // Fc for a friction force), so one number sets the accuracy of every state on its own scale.
  // The default 1e-5 keeps body and wheel acceleration RMS within 0.06 % (0.004 % but for the
  // locked damper's wheel) and PSDs over 0.5–30 Hz within 0.008 dB of CVODE at 1e-10 on 10 s of
  // class A road, every topology and effect (tests/simulate/esdirk_integrator_test.cc asks 0.1 %
  // and 0.05 dB; at 1e-4 the locked damper's wheel PSD was 0.07 dB off).
  double relative_tolerance = 1e-5;
  double max_step_s = 0.0;     // ESDIRK and CVODE; 0 = only the system's own limit
  double fixed_step_s = 1e-4;  // RK4
  // ESDIRK and CVODE give up (a RunError) after this many steps per simulated second, so a run
  // whose steps collapse fails with a message instead of running for hours. The Passat corner on
  // class A road needs about 2 000 at rtol 1e-5, 4 000 at 1e-6.
  double max_steps_per_s = 200'000;
  // ESDIRK: end a step on every output time, for systems driven by an input with a kink at each
  // sample (a rig record's displacement by a C1 cubic, a command by straight lines): a step
  // across one tends to fail the error test (the NEES random record's first half: 19 139 error-
  // test failures across the samples, 2 994 with its steps ending on them).
  bool steps_end_on_outputs = false;
  // Called after each output sample with its time (may be empty).
  std::function<void(double time_s)> progress;
};

struct SolverStatistics {
  std::string method;
  long steps = 0;
  long rhs_evaluations = 0;
  long jacobian_evaluations = 0;
  long error_test_failures = 0;
  long nonlinear_convergence_failures = 0;
  long events = 0;  // ESDIRK: steps ended on a kink (a switching function's root)
};

// States at the requested output times.
struct Trajectory {
  std::vector<double> time_s;
  std::vector<double> states;  // row-major: states[k * n + i] is state i at time_s[k]
  int state_size = 0;
  SolverStatistics statistics;
  const double* state_at(std::size_t k) const { return states.data() + k * state_size; }
};

// Integrates from x0 at output_times_s.front() through every output time (increasing).
// Throws RunError, naming the time and the solver's reason, when the solver fails, and
// InputError for settings that cannot work (a fixed step longer than the output interval,
// or one that would take more than kMaxFixedSteps steps).
constexpr double kMaxFixedSteps = 1e9;
Trajectory integrate(const OdeSystem& system, const std::vector<double>& x0,
                     const std::vector<double>& output_times_s, const IntegratorOptions& options);

// The checks every method makes on a request (InputError: x0's size, no or non-increasing
// output times), and the trajectory they all start from: x0 at the first output time.
Trajectory start_trajectory(const OdeSystem& system, const std::vector<double>& x0,
                            const std::vector<double>& output_times_s, Method method);

// "esdirk" | "cvode" | "rk4".
const char* to_string(Method method);

}  // namespace ridefit::simulate
