// sensor_delay: the force channel lags the displacement channel by a constant time.
#include <memory>

#include "ridefit/fitting/diagnose/effect.h"
#include "ridefit/model/strut_test_parameter_table.h"

namespace ridefit::fitting::diagnose {
namespace {

namespace rig = model::strut_rig_rows;

class SensorDelay : public Effect {
 public:
  std::string_view id() const override { return "sensor_delay"; }
  std::string_view description() const override {
    return "a time delay between the channels (acquisition skew, an anti-alias filter's group "
           "delay): the measured force is the force of a moment earlier, which tilts loops like "
           "extra damping";
  }
  bool measurement_chain() const override { return true; }
  std::string not_applicable(const DiagnosisModel& baseline) const override {
    if (baseline.kind != DataKind::kStrutLoops) {
      return "a pure delay leaves an auto-spectrum unchanged (|e^(-i·2πf·τ)| = 1 at every "
             "frequency), and the spectral diagnosis compares auto-spectra only: a delay between "
             "road and accelerations needs a comparison in time or the cross-spectra with the "
             "road";
    }
    if (baseline.strut.force_delay_s > 0.0) return "the baseline already has a delay";
    return "";
  }
  EffectChange change(const DiagnosisModel&) const override {
    return {{{rig::force_delay_s.key_string(), 0.001}},
            {},
            {{rig::force_delay_s.key_string(), 0.0, 0.05}},
            {{{rig::force_delay_s.key_string(), 0.01}}}};
  }
};

}  // namespace

std::unique_ptr<Effect> make_sensor_delay() { return std::make_unique<SensorDelay>(); }

}  // namespace ridefit::fitting::diagnose
