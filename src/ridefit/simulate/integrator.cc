#include "ridefit/simulate/integrator.h"

#include <arkode/arkode_butcher.h>
#include <arkode/arkode_erkstep.h>
#include <cvode/cvode.h>
#include <fmt/core.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>

#include "ridefit/common/errors.h"
#include "ridefit/simulate/esdirk_integrator.h"

namespace ridefit::simulate {
namespace {

// SUNDIALS' *GetReturnFlagName hand back a malloc'd string the caller frees (AddressSanitizer's
// leak check found the lost ones).
std::string owned_flag_name(char* name) {
  std::string text = name != nullptr ? name : "unknown flag";
  std::free(name);
  return text;
}

// Owns SUNDIALS objects for the length of one integration.
struct SundialsSession {
  SUNContext context = nullptr;
  N_Vector y = nullptr;
  N_Vector absolute_tolerance = nullptr;
  SUNMatrix matrix = nullptr;
  SUNLinearSolver linear_solver = nullptr;
  void* memory = nullptr;
  ARKodeButcherTable table = nullptr;
  bool arkode = false;
  std::string last_error;

  explicit SundialsSession(int n) {
    if (SUNContext_Create(nullptr, &context) != 0)
      throw RunError("SUNDIALS: cannot create context");
    y = N_VNew_Serial(n, context);
    absolute_tolerance = N_VNew_Serial(n, context);
  }
  ~SundialsSession() {
    if (memory != nullptr) {
      if (arkode) {
        ERKStepFree(&memory);
      } else {
        CVodeFree(&memory);
      }
    }
    if (table != nullptr) ARKodeButcherTable_Free(table);
    if (linear_solver != nullptr) SUNLinSolFree(linear_solver);
    if (matrix != nullptr) SUNMatDestroy(matrix);
    if (absolute_tolerance != nullptr) N_VDestroy(absolute_tolerance);
    if (y != nullptr) N_VDestroy(y);
    if (context != nullptr) SUNContext_Free(&context);
  }
  SundialsSession(const SundialsSession&) = delete;
  SundialsSession& operator=(const SundialsSession&) = delete;
};

struct CallbackData {
  const OdeSystem* system;
  SundialsSession* session;
};

int rhs_callback(sunrealtype t, N_Vector y, N_Vector ydot, void* user_data) {
  const auto* data = static_cast<CallbackData*>(user_data);
  // A recoverable failure (1) lets the solver retry with a smaller step.
  return data->system->derivatives(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot)) ? 0 : 1;
}

int jacobian_callback(sunrealtype t, N_Vector y, N_Vector /*fy*/, SUNMatrix jacobian,
                      void* user_data, N_Vector, N_Vector, N_Vector) {
  const auto* data = static_cast<CallbackData*>(user_data);
  return data->system->jacobian(t, N_VGetArrayPointer(y), SUNDenseMatrix_Data(jacobian)) ? 0 : 1;
}

void error_handler(int /*code*/, const char* /*module*/, const char* function, char* message,
                   void* user_data) {
  auto* session = static_cast<SundialsSession*>(user_data);
  session->last_error = fmt::format("{}: {}", function, message);
}

// Why a solver failure happened, in words a user can act on.
std::string explain(int flag, bool fixed_step) {
  if (flag == CV_REPTD_RHSFUNC_ERR || flag == CV_UNREC_RHSFUNC_ERR || flag == CV_RHSFUNC_FAIL ||
      flag == ARK_REPTD_RHSFUNC_ERR || flag == ARK_UNREC_RHSFUNC_ERR || flag == ARK_RHSFUNC_FAIL) {
    return fixed_step
               ? "the state became non-finite: the step is beyond RK4's stability limit for this "
                 "model and road (friction with a large sigma0 is stiff); use a smaller step "
                 "or the cvode method"
               : "the state became non-finite; check the model for extreme parameter values";
  }
  if (flag == CV_TOO_MUCH_WORK) {
    return "too many steps: the solution varies faster than the tolerance can follow";
  }
  return "solver failure";
}

void check(int flag, const char* what) {
  if (flag < 0) throw RunError(fmt::format("SUNDIALS set-up failed in {} (flag {})", what, flag));
}

// The classic 4-stage, 4th-order Runge-Kutta tableau (MATLAB/Simulink ode4).
ARKodeButcherTable classic_rk4_table() {
  const sunrealtype c[4] = {0.0, 0.5, 0.5, 1.0};
  const sunrealtype a[16] = {0.0, 0.0, 0.0, 0.0,  //
                             0.5, 0.0, 0.0, 0.0,  //
                             0.0, 0.5, 0.0, 0.0,  //
                             0.0, 0.0, 1.0, 0.0};
  const sunrealtype b[4] = {1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0};
  return ARKodeButcherTable_Create(4, 4, 0, const_cast<sunrealtype*>(c),
                                   const_cast<sunrealtype*>(a), const_cast<sunrealtype*>(b),
                                   nullptr);
}

}  // namespace

const char* to_string(Method method) {
  switch (method) {
    case Method::kEsdirk:
      return "esdirk";
    case Method::kCvodeBdf:
      return "cvode";
    case Method::kArkodeRk4:
      return "rk4";
  }
  return "?";
}

namespace {

// Steps the prepared solver through every output time, copying the states out.
template <typename Advance>
void step_through(const std::vector<double>& output_times_s, SundialsSession& session,
                  const IntegratorOptions& options, Trajectory& trajectory, Advance advance) {
  const int n = trajectory.state_size;
  const double* y = N_VGetArrayPointer(session.y);
  for (std::size_t k = 1; k < output_times_s.size(); ++k) {
    advance(output_times_s[k]);
    std::copy(y, y + n, trajectory.states.begin() + static_cast<long>(k) * n);
    if (options.progress) options.progress(output_times_s[k]);
  }
}

void run_cvode(const OdeSystem& system, const std::vector<double>& output_times_s,
               const IntegratorOptions& options, SundialsSession& session, CallbackData& data,
               Trajectory& trajectory) {
  const int n = system.size();
  if (!(options.relative_tolerance > 0.0 && options.relative_tolerance <= 0.1)) {
    throw InputError(fmt::format("relative tolerance {}: expected a value in (0, 0.1]",
                                 options.relative_tolerance));
  }
  session.memory = CVodeCreate(CV_BDF, session.context);
  if (session.memory == nullptr) throw RunError("SUNDIALS: CVodeCreate failed");
  check(CVodeSetErrHandlerFn(session.memory, error_handler, &session), "CVodeSetErrHandlerFn");
  check(CVodeInit(session.memory, rhs_callback, output_times_s.front(), session.y), "CVodeInit");
  double* atol = N_VGetArrayPointer(session.absolute_tolerance);
  for (int i = 0; i < n; ++i) atol[i] = options.relative_tolerance * system.typical_magnitude(i);
  check(CVodeSVtolerances(session.memory, options.relative_tolerance, session.absolute_tolerance),
        "CVodeSVtolerances");
  check(CVodeSetUserData(session.memory, &data), "CVodeSetUserData");
  session.matrix = SUNDenseMatrix(n, n, session.context);
  session.linear_solver = SUNLinSol_Dense(session.y, session.matrix, session.context);
  check(CVodeSetLinearSolver(session.memory, session.linear_solver, session.matrix),
        "CVodeSetLinearSolver");
  check(CVodeSetJacFn(session.memory, jacobian_callback), "CVodeSetJacFn");
  // CVODE applies the step limit between two output times.
  const double interval_s =
      (output_times_s.back() - output_times_s.front()) /
      static_cast<double>(std::max<std::size_t>(1, output_times_s.size() - 1));
  const long max_steps =
      std::max(1000L, static_cast<long>(std::ceil(options.max_steps_per_s * interval_s)));
  check(CVodeSetMaxNumSteps(session.memory, max_steps), "CVodeSetMaxNumSteps");
  double max_step = options.max_step_s;
  if (system.max_step_s() > 0.0 && (max_step <= 0.0 || system.max_step_s() < max_step)) {
    max_step = system.max_step_s();
  }
  if (max_step > 0.0) check(CVodeSetMaxStep(session.memory, max_step), "CVodeSetMaxStep");
  check(CVodeSetStopTime(session.memory, output_times_s.back()), "CVodeSetStopTime");

  step_through(output_times_s, session, options, trajectory, [&](double t_out) {
    double t_reached = 0.0;
    const int flag = CVode(session.memory, t_out, session.y, &t_reached, CV_NORMAL);
    if (flag < 0) {
      double t_last = t_reached;
      CVodeGetCurrentTime(session.memory, &t_last);
      throw RunError(fmt::format("CVODE failed at t = {:.6g} s: {}: {} ({})", t_last,
                                 owned_flag_name(CVodeGetReturnFlagName(flag)),
                                 explain(flag, false), session.last_error));
    }
  });
  auto& stats = trajectory.statistics;
  CVodeGetNumSteps(session.memory, &stats.steps);
  CVodeGetNumRhsEvals(session.memory, &stats.rhs_evaluations);
  CVodeGetNumJacEvals(session.memory, &stats.jacobian_evaluations);
  CVodeGetNumErrTestFails(session.memory, &stats.error_test_failures);
  CVodeGetNumNonlinSolvConvFails(session.memory, &stats.nonlinear_convergence_failures);
}

void run_rk4(const std::vector<double>& output_times_s, const IntegratorOptions& options,
             SundialsSession& session, CallbackData& data, Trajectory& trajectory) {
  const double h = options.fixed_step_s;
  const double span_s = output_times_s.back() - output_times_s.front();
  const double interval_s =
      span_s / static_cast<double>(std::max<std::size_t>(1, output_times_s.size() - 1));
  if (!(h > 0.0) || !std::isfinite(h)) {
    throw InputError(fmt::format("RK4 step {} s: expected a finite step > 0", h));
  }
  if (h > interval_s * (1.0 + 1e-9)) {
    throw InputError(fmt::format(
        "RK4 step {} s is longer than the output interval {} s; use a step of at most {} s or a "
        "lower output rate",
        h, interval_s, interval_s));
  }
  if (span_s / h > kMaxFixedSteps) {
    throw InputError(fmt::format(
        "RK4 step {} s over {} s would take {:.3g} steps (at most {:g}); use a larger step or "
        "the cvode method",
        h, span_s, span_s / h, kMaxFixedSteps));
  }
  session.arkode = true;
  session.memory = ERKStepCreate(rhs_callback, output_times_s.front(), session.y, session.context);
  if (session.memory == nullptr) throw RunError("SUNDIALS: ERKStepCreate failed");
  check(ERKStepSetErrHandlerFn(session.memory, error_handler, &session), "ERKStepSetErrHandlerFn");
  session.table = classic_rk4_table();
  check(ERKStepSetTable(session.memory, session.table), "ERKStepSetTable");
  check(ERKStepSetUserData(session.memory, &data), "ERKStepSetUserData");
  check(ERKStepSetFixedStep(session.memory, h), "ERKStepSetFixedStep");
  check(ERKStepSetMaxNumSteps(session.memory, static_cast<long>(std::ceil(interval_s / h)) + 10),
        "ERKStepSetMaxNumSteps");
  check(ERKStepSetStopTime(session.memory, output_times_s.back()), "ERKStepSetStopTime");

  step_through(output_times_s, session, options, trajectory, [&](double t_out) {
    double t_reached = 0.0;
    const int flag = ERKStepEvolve(session.memory, t_out, session.y, &t_reached, ARK_NORMAL);
    if (flag < 0) {
      double t_last = t_reached;
      ERKStepGetCurrentTime(session.memory, &t_last);
      throw RunError(fmt::format("ARKODE RK4 failed at t = {:.6g} s: {}: {}", t_last,
                                 owned_flag_name(ERKStepGetReturnFlagName(flag)),
                                 explain(flag, true)));
    }
  });
  ERKStepGetNumSteps(session.memory, &trajectory.statistics.steps);
  ERKStepGetNumRhsEvals(session.memory, &trajectory.statistics.rhs_evaluations);
}

}  // namespace

Trajectory start_trajectory(const OdeSystem& system, const std::vector<double>& x0,
                            const std::vector<double>& output_times_s, Method method) {
  const int n = system.size();
  if (static_cast<int>(x0.size()) != n) {
    throw InputError(
        fmt::format("initial state has {} values, the model has {} states", x0.size(), n));
  }
  if (output_times_s.empty()) throw InputError("no output times requested");
  for (std::size_t k = 1; k < output_times_s.size(); ++k) {
    if (!(output_times_s[k] > output_times_s[k - 1])) {
      throw InputError(fmt::format("output times must increase (sample {})", k));
    }
  }
  Trajectory trajectory;
  trajectory.state_size = n;
  trajectory.statistics.method = to_string(method);
  trajectory.time_s = output_times_s;
  trajectory.states.resize(output_times_s.size() * static_cast<std::size_t>(n));
  std::copy(x0.begin(), x0.end(), trajectory.states.begin());
  return trajectory;
}

Trajectory integrate(const OdeSystem& system, const std::vector<double>& x0,
                     const std::vector<double>& output_times_s, const IntegratorOptions& options) {
  if (options.method == Method::kEsdirk) {
    return integrate_esdirk(system, x0, output_times_s, options);
  }
  Trajectory trajectory = start_trajectory(system, x0, output_times_s, options.method);
  const int n = trajectory.state_size;
  SundialsSession session(n);
  CallbackData data{&system, &session};
  std::copy(x0.begin(), x0.end(), N_VGetArrayPointer(session.y));
  if (output_times_s.size() == 1) return trajectory;

  if (options.method == Method::kCvodeBdf) {
    run_cvode(system, output_times_s, options, session, data, trajectory);
  } else {
    run_rk4(output_times_s, options, session, data, trajectory);
  }
  return trajectory;
}

}  // namespace ridefit::simulate
