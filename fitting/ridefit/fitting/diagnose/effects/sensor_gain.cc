// sensor_gain: a channel reads the true signal times a gain (a calibration error): the load cell's
// force on the rig, the body and wheel accelerometers on vehicle spectra (model/
// acceleration_sensors.h: g² on the channel's PSD).
#include <memory>

#include "ridefit/fitting/diagnose/effect.h"
#include "ridefit/model/quarter_car_parameter_table.h"
#include "ridefit/model/strut_test_parameter_table.h"

namespace ridefit::fitting::diagnose {
namespace {

namespace rows = model::quarter_car_rows;
namespace rig = model::strut_rig_rows;

class SensorGain : public Effect {
 public:
  std::string_view id() const override { return "sensor_gain"; }
  std::string_view description() const override {
    return "a gain error of a channel (load-cell or accelerometer calibration, amplifier): every "
           "measured force or acceleration is the true one times a constant, which shifts its "
           "whole spectrum by 20·log10(g) dB";
  }
  bool measurement_chain() const override { return true; }
  std::string_view identifiable_from() const override {
    return "a model whose force levels are known (free only force_offset_N): a gain trades "
           "against the damping and friction levels a fit frees";
  }
  std::string not_applicable(const DiagnosisModel& baseline) const override {
    if (baseline.kind != DataKind::kStrutLoops) {
      const auto& s = baseline.car.parameters().sensors;
      if (s.body_acc_gain != 1.0 || s.wheel_acc_gain != 1.0) {
        return "the baseline already has accelerometer gains (free body_acc_gain or "
               "wheel_acc_gain as free parameters to refit them)";
      }
      return "";
    }
    if (baseline.strut.force_gain != 1.0) return "the baseline already has a force gain";
    return "";
  }
  EffectChange change(const DiagnosisModel& baseline) const override {
    if (baseline.kind == DataKind::kStrutLoops) {
      return {{{rig::force_gain.key_string(), 0.99}},
              {},
              {{rig::force_gain.key_string(), 0.5, 2.0}},
              {}};
    }
    // Vehicle spectra: both accelerometers' gains, each from near 1. The road is measured, so
    // a gain cannot hide in the excitation: below the body mode the body follows the road
    // (transmissibility 1 whatever the masses and stiffnesses), and a gain lifts the whole
    // channel by the same dB where a physical parameter reshapes it. A channel whose level
    // agrees keeps its gain at 1.
    return {{{rows::body_acc_gain.key_string(), 0.99}, {rows::wheel_acc_gain.key_string(), 0.99}},
            {},
            {{rows::body_acc_gain.key_string(), 0.5, 2.0},
             {rows::wheel_acc_gain.key_string(), 0.5, 2.0}},
            {}};
  }
};

}  // namespace

std::unique_ptr<Effect> make_sensor_gain() { return std::make_unique<SensorGain>(); }

}  // namespace ridefit::fitting::diagnose
