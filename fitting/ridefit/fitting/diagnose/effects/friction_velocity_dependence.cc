// friction_velocity_dependence: a Stribeck level for the Dahl element (model/stribeck_curve.h):
// seals break away at a higher force than they slide with.
#include <memory>

#include "ridefit/fitting/diagnose/effect.h"
#include "ridefit/model/quarter_car_parameter_table.h"

namespace ridefit::fitting::diagnose {
namespace {

namespace rows = model::quarter_car_rows;

class FrictionVelocityDependence : public Effect {
 public:
  std::string_view id() const override { return "friction_velocity_dependence"; }
  std::string_view description() const override {
    return "Stribeck friction: the seals' friction is higher near zero velocity (breakaway) and "
           "falls to the Coulomb level as the rod speeds up, so the loop overshoots after each "
           "reversal";
  }
  std::string_view identifiable_from() const override {
    return "records with sliding velocities around v_s (from about 0.1 to 10 v_s): a triangle at "
           "one speed shows one friction level";
  }
  std::string not_applicable(const DiagnosisModel& baseline) const override {
    if (baseline.kind != DataKind::kStrutLoops) {
      return "for strut rig loops: on the road the rod rarely dwells at the low velocities where "
             "the Stribeck hump differs from Coulomb friction";
    }
    if (!(baseline.strut.coulomb_force_N > 0.0)) {
      return "the baseline has no friction whose level could depend on velocity (see "
             "damper_friction)";
    }
    if (baseline.strut.stribeck_velocity_m_per_s > 0.0) {
      return "the baseline's friction already depends on velocity";
    }
    return "";
  }
  EffectChange change(const DiagnosisModel& baseline) const override {
    const double fc = baseline.strut.coulomb_force_N;
    // Starts at twice and 2.5 times the sliding level, neither near the 1.5·Fc of the tests'
    // truths. (From just above Fc, 1.05·Fc, a one-speed triangle's fit wandered to a hump wider
    // than the test's speed, Fc halved, and the effect was no longer seen as undetermined there.)
    return {{{rows::static_friction_force_N.key_string(), 2.0 * fc},
             {rows::stribeck_velocity_m_per_s.key_string(), 0.01}},
            std::nullopt,
            {{rows::static_friction_force_N.key_string(), 1.001 * fc, 5.0 * fc},
             {rows::stribeck_velocity_m_per_s.key_string(), 1e-4, 0.5}},
            // The hump's width and height trade off: start also narrow and tall.
            {{{rows::static_friction_force_N.key_string(), 2.5 * fc},
              {rows::stribeck_velocity_m_per_s.key_string(), 0.002}}}};
  }
};

}  // namespace

std::unique_ptr<Effect> make_friction_velocity_dependence() {
  return std::make_unique<FrictionVelocityDependence>();
}

}  // namespace ridefit::fitting::diagnose
