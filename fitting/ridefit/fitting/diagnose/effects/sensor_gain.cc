// sensor_gain: the load cell reads the force times a gain (a calibration error).
#include <memory>

#include "ridefit/fitting/diagnose/effect.h"

namespace ridefit::fitting::diagnose {
namespace {

class SensorGain : public Effect {
 public:
  std::string_view id() const override { return "sensor_gain"; }
  std::string_view description() const override {
    return "a gain error of the force channel (load-cell calibration or amplifier): every "
           "measured force is the true one times a constant";
  }
  bool measurement_chain() const override { return true; }
  std::string_view identifiable_from() const override {
    return "a model whose force levels are known (free only force_offset_N): a gain trades "
           "against the damping and friction levels a fit frees";
  }
  std::string not_applicable(const DiagnosisModel& baseline) const override {
    if (baseline.kind != DataKind::kStrutLoops) {
      return "for rig records: on vehicle spectra a channel gain trades off against the masses "
             "and stiffnesses the fit frees";
    }
    if (baseline.strut.force_gain != 1.0) return "the baseline already has a force gain";
    return "";
  }
  EffectChange change(const DiagnosisModel&) const override {
    return {{{"force_gain", 0.99}}, {}, {{"force_gain", 0.5, 2.0}}, {}};
  }
};

}  // namespace

std::unique_ptr<Effect> make_sensor_gain() { return std::make_unique<SensorGain>(); }

}  // namespace ridefit::fitting::diagnose
