// sensor_band_limit: the force channel is low-passed (a load-cell amplifier's or anti-alias
// filter's band limit).
#include <memory>

#include "ridefit/fitting/diagnose/effect.h"

namespace ridefit::fitting::diagnose {
namespace {

class SensorBandLimit : public Effect {
 public:
  std::string_view id() const override { return "sensor_band_limit"; }
  std::string_view description() const override {
    return "a band limit of the force channel (amplifier or anti-alias filter, first order): "
           "fast force changes arrive attenuated and late";
  }
  bool measurement_chain() const override { return true; }
  std::string not_applicable(const DiagnosisModel& baseline) const override {
    if (baseline.kind != DataKind::kStrutLoops) {
      return "for rig records: on vehicle spectra a sensor low-pass is not in the library yet";
    }
    if (baseline.strut.force_sensor_cutoff_Hz > 0.0) return "the baseline already has one";
    return "";
  }
  EffectChange change(const DiagnosisModel&) const override {
    return {{{"force_sensor_cutoff_Hz", 100.0}},
            {},
            {{"force_sensor_cutoff_Hz", 1.0, 1e4}},
            {{{"force_sensor_cutoff_Hz", 20.0}}}};
  }
};

}  // namespace

std::unique_ptr<Effect> make_sensor_band_limit() { return std::make_unique<SensorBandLimit>(); }

}  // namespace ridefit::fitting::diagnose
