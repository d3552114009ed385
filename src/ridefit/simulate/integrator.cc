#include "ridefit/simulate/integrator.h"

#include <arkode/arkode_butcher.h>
#include <arkode/arkode_erkstep.h>
#include <cvode/cvode.h>
#include <fmt/core.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <memory>

#include "ridefit/io/input_error.h"

namespace ridefit::simulate {
namespace {

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

const char* to_string(Method method) { return method == Method::kCvodeBdf ? "cvode" : "rk4"; }

Trajectory integrate(const OdeSystem& system, const std::vector<double>& x0,
                     const std::vector<double>& output_times_s, const IntegratorOptions& options) {
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

  SundialsSession session(n);
  CallbackData data{&system, &session};
  double* y = N_VGetArrayPointer(session.y);
  for (int i = 0; i < n; ++i) y[i] = x0[static_cast<std::size_t>(i)];
  const double t0 = output_times_s.front();

  Trajectory trajectory;
  trajectory.state_size = n;
  trajectory.statistics.method = to_string(options.method);
  trajectory.time_s = output_times_s;
  trajectory.states.resize(output_times_s.size() * static_cast<std::size_t>(n));
  std::copy(y, y + n, trajectory.states.begin());

  if (options.method == Method::kCvodeBdf) {
    if (!(options.relative_tolerance > 0.0)) throw InputError("relative tolerance must be > 0");
    session.memory = CVodeCreate(CV_BDF, session.context);
    if (session.memory == nullptr) throw RunError("SUNDIALS: CVodeCreate failed");
    check(CVodeSetErrHandlerFn(session.memory, error_handler, &session), "CVodeSetErrHandlerFn");
    check(CVodeInit(session.memory, rhs_callback, t0, session.y), "CVodeInit");
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
    check(CVodeSetMaxNumSteps(session.memory, options.max_steps), "CVodeSetMaxNumSteps");
    if (options.max_step_s > 0.0)
      check(CVodeSetMaxStep(session.memory, options.max_step_s), "CVodeSetMaxStep");
    const double t_end = output_times_s.back();
    check(CVodeSetStopTime(session.memory, t_end), "CVodeSetStopTime");
    for (std::size_t k = 1; k < output_times_s.size(); ++k) {
      double t_reached = 0.0;
      const int flag = CVode(session.memory, output_times_s[k], session.y, &t_reached, CV_NORMAL);
      if (flag < 0) {
        double t_last = t_reached;
        CVodeGetCurrentTime(session.memory, &t_last);
        throw RunError(fmt::format("CVODE failed at t = {:.6g} s: {} ({})", t_last,
                                   CVodeGetReturnFlagName(flag), session.last_error));
      }
      std::copy(y, y + n, trajectory.states.begin() + static_cast<long>(k) * n);
    }
    long value = 0;
    CVodeGetNumSteps(session.memory, &value);
    trajectory.statistics.steps = value;
    CVodeGetNumRhsEvals(session.memory, &value);
    trajectory.statistics.rhs_evaluations = value;
    CVodeGetNumJacEvals(session.memory, &value);
    trajectory.statistics.jacobian_evaluations = value;
    CVodeGetNumErrTestFails(session.memory, &value);
    trajectory.statistics.error_test_failures = value;
    CVodeGetNumNonlinSolvConvFails(session.memory, &value);
    trajectory.statistics.nonlinear_convergence_failures = value;
  } else {
    if (!(options.fixed_step_s > 0.0)) throw InputError("fixed step must be > 0");
    session.arkode = true;
    session.memory = ERKStepCreate(rhs_callback, t0, session.y, session.context);
    if (session.memory == nullptr) throw RunError("SUNDIALS: ERKStepCreate failed");
    check(ERKStepSetErrHandlerFn(session.memory, error_handler, &session),
          "ERKStepSetErrHandlerFn");
    session.table = classic_rk4_table();
    check(ERKStepSetTable(session.memory, session.table), "ERKStepSetTable");
    check(ERKStepSetUserData(session.memory, &data), "ERKStepSetUserData");
    check(ERKStepSetFixedStep(session.memory, options.fixed_step_s), "ERKStepSetFixedStep");
    check(ERKStepSetMaxNumSteps(session.memory, options.max_steps), "ERKStepSetMaxNumSteps");
    check(ERKStepSetStopTime(session.memory, output_times_s.back()), "ERKStepSetStopTime");
    for (std::size_t k = 1; k < output_times_s.size(); ++k) {
      double t_reached = 0.0;
      const int flag =
          ERKStepEvolve(session.memory, output_times_s[k], session.y, &t_reached, ARK_NORMAL);
      if (flag < 0) {
        double t_last = t_reached;
        ERKStepGetCurrentTime(session.memory, &t_last);
        throw RunError(fmt::format("ARKODE RK4 failed at t = {:.6g} s: {} ({})", t_last,
                                   ERKStepGetReturnFlagName(flag), session.last_error));
      }
      std::copy(y, y + n, trajectory.states.begin() + static_cast<long>(k) * n);
    }
    long value = 0;
    ERKStepGetNumSteps(session.memory, &value);
    trajectory.statistics.steps = value;
    ERKStepGetNumRhsEvals(session.memory, &value);
    trajectory.statistics.rhs_evaluations = value;
  }
  return trajectory;
}

}  // namespace ridefit::simulate
