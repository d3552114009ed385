// sensor_band_limit: a channel is low-passed (an amplifier's or anti-alias filter's band limit):
// the load cell's force on the rig, both accelerometers on vehicle spectra (model/
// acceleration_sensors.h: |H(f)|² on the simulated PSDs).
#include <memory>

#include "ridefit/fitting/diagnose/effect.h"
#include "ridefit/model/quarter_car_parameter_table.h"
#include "ridefit/model/strut_test_parameter_table.h"

namespace ridefit::fitting::diagnose {
namespace {

namespace rows = model::quarter_car_rows;
namespace rig = model::strut_rig_rows;

class SensorBandLimit : public Effect {
 public:
  std::string_view id() const override { return "sensor_band_limit"; }
  std::string_view description() const override {
    return "a band limit of the measuring chain (amplifier or anti-alias filter, first order or "
           "two first-order stages): fast force or acceleration changes arrive attenuated, the "
           "spectrum falls away above the corner frequency";
  }
  bool measurement_chain() const override { return true; }
  std::string not_applicable(const DiagnosisModel& baseline) const override {
    if (baseline.kind != DataKind::kStrutLoops) {
      if (baseline.car.parameters().sensors.acc_sensor_cutoff_Hz > 0.0) {
        return "the baseline already has an accelerometer low-pass (free acc_sensor_cutoff_Hz "
               "to refit it)";
      }
      return "";
    }
    if (baseline.strut.force_sensor_cutoff_Hz > 0.0) return "the baseline already has one";
    return "";
  }
  EffectChange change(const DiagnosisModel& baseline) const override {
    if (baseline.kind == DataKind::kStrutLoops) {
      return {{{rig::force_sensor_cutoff_Hz.key_string(), 100.0}},
              {},
              {{rig::force_sensor_cutoff_Hz.key_string(), 1.0, 1e4}},
              {{{rig::force_sensor_cutoff_Hz.key_string(), 20.0}}}};
    }
    // Vehicle spectra: one low-pass on both accelerometers (they share the acquisition's
    // anti-alias filter), its corner fitted; the order is not a parameter, so both are tried
    // (first order from 100 Hz, two stages from 30 Hz) and the lower training cost kept. A
    // second-order corner below the band's top bends the spectrum ~4·dB per (f/f_c)², which no
    // mass, stiffness or damping does to both channels alike.
    return {{{rows::acc_sensor_cutoff_Hz.key_string(), 100.0}, {"acc_sensor_order", 1.0}},
            {},
            {{rows::acc_sensor_cutoff_Hz.key_string(), 1.0, 1e4}},
            {{{rows::acc_sensor_cutoff_Hz.key_string(), 30.0}, {"acc_sensor_order", 2.0}}}};
  }
};

}  // namespace

std::unique_ptr<Effect> make_sensor_band_limit() { return std::make_unique<SensorBandLimit>(); }

}  // namespace ridefit::fitting::diagnose
