#pragma once

#include <functional>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "ridefit/model/strut_test.h"
#include "ridefit/road/uniform_spline.h"
#include "ridefit/simulate/ode_system.h"

namespace ridefit::simulate {

// How a rig record's displacement continues between its samples.
enum class RigInterpolation {
  // A C2 cubic spline (uniform records; error O(step⁴)) for smooth motions: linear
  // interpolation would miss a 20 Hz motion sampled at 1 kHz by 0.2 % between samples and its
  // velocity, which the damper feels, by several per cent. Records whose time steps vary (as
  // exported records with rounded time stamps do) get a C1 cubic of their own steps instead
  // (modified Akima: no overshoot at a quantisation step or a corner).
  kSpline,
  // Straight lines between samples: exact for piecewise-linear commands (triangle waves), where
  // a spline would overshoot at each corner, just where the pre-sliding stiffness shows.
  kLinear,
};

// The displacement a rig imposed, as a function of time between its samples. With a measured
// velocity (one value per sample) the curve is the cubic Hermite through each sample with that
// slope: the velocity the damper feels is the rig's own, not a difference of quantised
// displacements. Records under five samples are interpolated linearly whatever is asked.
class RigDisplacement {
 public:
  RigDisplacement(std::span<const double> time_s, std::span<const double> displacement_m,
                  RigInterpolation interpolation = RigInterpolation::kSpline,
                  std::span<const double> velocity_m_per_s = {});
  // A displacement known at every instant (reference data: strut_test_reference.h).
  explicit RigDisplacement(std::function<double(double)> exact_m) : exact_m_(std::move(exact_m)) {}
  double at(double time_s) const;
  // The rig's velocity x'(t) [m/s]: the interpolant's own slope (a central difference of the exact
  // displacement for reference data).
  double rate_at(double time_s) const;
  // Whether the velocity jumps in slope at the samples: linear pieces, the modified Akima of
  // uneven steps and the Hermite of a measured velocity are C1 (C0 for linear) there, the uniform
  // spline is C2 and an exact motion smooth. An integrator should end its steps on such samples.
  bool kinks_at_samples() const { return !spline_.has_value() && !exact_m_ && time_s_.size() > 1; }

 private:
  double interpolate(double time_s) const;
  double interpolate_rate(double time_s) const;
  // Newton iterations and the Jacobian ask for one stage time again and again (the spline's
  // slope alone took an eighth of a loop diagnosis). One RigDisplacement serves one integration
  // (not shared between threads).
  mutable double cached_time_s_ = -1e300;
  mutable double cached_m_ = 0.0;
  mutable double cached_rate_time_s_ = -1e300;
  mutable double cached_rate_m_per_s_ = 0.0;
  std::vector<double> time_s_;
  std::vector<double> displacement_m_;
  std::optional<road::UniformSpline> spline_;
  // Non-uniform steps (modified Akima) or a measured velocity (cubic Hermite): the slope at each
  // sample; between two samples the curve is the cubic Hermite of their values and slopes.
  std::vector<double> slope_m_per_s_;
  // The segment the last time fell in: an integrator asks for nearby times, so the next one is
  // found in a step or two. Boost's interpolators search the whole record on every call, a sixth
  // of a fit of a 12 000-sample record with a velocity column.
  mutable std::size_t segment_ = 0;
  std::size_t segment_of(double time_s) const;
  double hermite_m(double time_s) const;
  double hermite_rate_m_per_s(double time_s) const;
  std::function<double(double)> exact_m_;
};

// The strut on the rig (model::StrutTest) as a first-order system for the integrators:
// states [z_c, F_f] (and ū for a controlled damper with a lag), the rig's displacement imposed
// and, for a controlled damper, the command read from `command` (null: a command of 0). Its
// switching functions are the kinks the integrator locates: the damper's sliding velocity (the
// Dahl law's kink) when the strut has friction, and its rate at the blow-off knee in rebound and
// compression when it has one (as the quarter car's; a stage across a kink would make the
// discrete map, and so the fit's Jacobian, non-smooth in the knee velocity).
class StrutTestSystem : public OdeSystem {
 public:
  StrutTestSystem(const model::StrutTestParameters<double>& parameters,
                  const RigDisplacement& displacement, const RigDisplacement* command = nullptr)
      : p_(parameters), x_(displacement), u_(command) {}
  int size() const override { return model::StrutTest::state_count(p_); }
  // The command at t (0 without a command signal).
  double command_at(double t_s) const { return u_ != nullptr ? u_->at(t_s) : 0.0; }
  bool derivatives(double t_s, const double* y, double* ydot) const override;
  bool jacobian(double t_s, const double* y, double* jacobian_column_major) const override;
  // z_c on the scale of a rig stroke (1 mm), F_f on the scale of Fc.
  double typical_magnitude(int state_index) const override;
  double max_step_s() const override { return 0.0; }
  // The kinks a step should end on: the friction's reversal, the knee's two speeds, and the free
  // play's four rounded corners (where D' starts and stops changing: inside them the Jacobian
  // moves by k_tm, and a step across one rarely converges).
  int switching_count() const override {
    return (has_friction() ? 1 : 0) + (p_.damper_knee_velocity_m_per_s > 0.0 ? 2 : 0) +
           (p_.free_play_m > 0.0 ? 4 : 0);
  }
  void switching(double t_s, const double* y, double* g) const override;
  // A quasi-static path with free play: inside a rounded corner of the slack the rate's
  // Jacobian moves by k_tm (1e9 N/m behind a rigid mount) within a step.
  bool polishes_recorded_stages() const override {
    return p_.free_play_m > 0.0 && model::StrutTest::quasi_static(p_);
  }

 private:
  bool has_friction() const {
    return p_.coulomb_force_N > 0.0 || p_.coulomb_force_per_command_N != 0.0;
  }
  // The Jacobian by forward autodiff of model::StrutTest: a controlled damper (its states and the
  // command's lag are few), free play or direction-dependent friction; the plain passive law is
  // written out by hand in jacobian().
  bool autodiff_jacobian(double t_s, const double* y, double* jacobian_column_major) const;

  model::StrutTestParameters<double> p_;
  const RigDisplacement& x_;
  const RigDisplacement* u_;
};

}  // namespace ridefit::simulate
