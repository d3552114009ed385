// damper_digressive: a blow-off knee in the damper's force over velocity.
#include <algorithm>
#include <memory>

#include "ridefit/fitting/diagnose/effect.h"
#include "ridefit/model/quarter_car_parameter_table.h"

namespace ridefit::fitting::diagnose {
namespace {

namespace rows = model::quarter_car_rows;

class DamperDigressive : public Effect {
 public:
  std::string_view id() const override { return "damper_digressive"; }
  std::string_view description() const override {
    return "a digressive damper (blow-off valve opening at a knee velocity): less damping on "
           "rough roads than the linear coefficient predicts";
  }
  std::string not_applicable(const DiagnosisModel& baseline) const override {
    // On the rig the damper path is the car's (StrutParameters::damper_path): its knee acts there.
    if (baseline.kind == DataKind::kStrutLoops) {
      return baseline.strut.damper_knee_velocity_m_per_s > 0.0
                 ? "the baseline's damper already has a knee"
                 : "";
    }
    if (baseline.car.damper_state() == model::DamperState::kStick) {
      return "the baseline's damper is locked (stick): its valving cannot act";
    }
    if (baseline.car.parameters().damper_knee_velocity_m_per_s > 0.0) {
      return "the baseline's damper already has a knee";
    }
    return "";
  }
  EffectChange change(const DiagnosisModel& baseline) const override {
    const double c = baseline.kind == DataKind::kStrutLoops
                         ? baseline.strut.damping_Ns_per_m
                         : baseline.car.parameters().damping_Ns_per_m;
    // A knee shows only within the stroke speeds the records reach: start it at a third of their
    // RMS (a valve opens well inside the speeds it meets; from the RMS itself the fit of a
    // 20 s class D record ended in the low-knee valley and friction was named instead).
    const double knee = baseline.damper_speed_rms_m_per_s > 0.0
                            ? std::clamp(0.3 * baseline.damper_speed_rms_m_per_s, 0.01, 1.0)
                            : 0.1;
    return {{{rows::damper_knee_velocity_m_per_s.key_string(), knee},
             {rows::damping_above_knee_Ns_per_m.key_string(), 0.5 * c}},
            std::nullopt,
            {{rows::damper_knee_velocity_m_per_s.key_string(), 0.005, 2.0},
             {rows::damping_above_knee_Ns_per_m.key_string(), 0.02 * c, c}},
            // A second start with the damping split around the baseline's fitted value: from the
            // first alone the fit could slide down the knee–damping valley (a low knee with a
            // stiff damper below it) that a short record barely tells from the truth.
            {{{rows::damper_knee_velocity_m_per_s.key_string(), knee},
              {rows::damping_above_knee_Ns_per_m.key_string(), 0.8 * c},
              {rows::damping_Ns_per_m.key_string(), 2.0 * c}}}};
  }
};

}  // namespace

std::unique_ptr<Effect> make_damper_digressive() { return std::make_unique<DamperDigressive>(); }

}  // namespace ridefit::fitting::diagnose
