#pragma once

namespace ridefit::simulate {

// A first-order system x' = f(t, x) as the integrators see it.
//
// Implementations are called from inside the integrators: they must not throw. They return
// false when the right-hand side cannot be evaluated (a non-finite value), which the integrator
// turns into a step-size cut or, if that does not help, a RunError naming the time.
class OdeSystem {
 public:
  virtual ~OdeSystem() = default;
  virtual int size() const = 0;
  virtual bool derivatives(double t_s, const double* x, double* xdot) const = 0;
  // Dense Jacobian ∂f/∂x, column-major n×n (SUNDIALS' dense layout).
  virtual bool jacobian(double t_s, const double* x, double* jacobian_column_major) const = 0;
  // A typical magnitude per state: absolute tolerance = relative tolerance × magnitude, so
  // positions in metres and forces in newtons are each judged on their own scale.
  virtual double typical_magnitude(int state_index) const = 0;
  // The longest step an adaptive solver may take (an input's feature size); 0 = no limit.
  virtual double max_step_s() const = 0;
  // Switching functions: where one changes sign, f is not smooth (the Dahl law's kink at a
  // damper reversal, a bump stop's contact, a damper's knee). The ESDIRK integrator ends a step
  // on each such point, so that no step straddles a kink and the error control never thrashes
  // on one. At most kMaxSwitchingFunctions.
  static constexpr int kMaxSwitchingFunctions = 8;
  virtual int switching_count() const { return 0; }
  virtual void switching(double /*t_s*/, const double* /*x*/, double* /*g*/) const {}
  // Whether a run that records its steps for tangents may finish a stage by full Newton when the
  // usual (modified) Newton reaches the ordinary accuracy but stalls short of the recorded one
  // (esdirk_integrator.cc). For systems whose Jacobian turns within a step by orders of magnitude
  // on purpose (a free play's rounded corners behind a rigid mount); elsewhere a stall means the
  // step should shrink.
  virtual bool polishes_recorded_stages() const { return false; }
};

}  // namespace ridefit::simulate
