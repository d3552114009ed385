// top_mount_amplitude_stiffening: the seed's Section 4.2.2 (488 N/mm on the rig, ~707 N/mm at the
// small amplitudes of driving).
#include <memory>

#include "ridefit/fitting/diagnose/effect.h"
#include "ridefit/model/quarter_car_parameter_table.h"

namespace ridefit::fitting::diagnose {
namespace {

namespace rows = model::quarter_car_rows;

class TopMountAmplitudeStiffening : public Effect {
 public:
  std::string_view id() const override { return "top_mount_amplitude_stiffening"; }
  std::string_view description() const override {
    return "a damper-path top mount stiffer at small deflection than on the rig's large "
           "strokes (rubber's amplitude dependence): the wheel mode sits higher on smooth roads";
  }
  std::string not_applicable(const DiagnosisModel& baseline) const override {
    if (baseline.kind == DataKind::kStrutLoops) {
      return "the rig model's top mount is linear; the stiffening shows between the rig's large "
             "strokes and the road's small ones, in vehicle spectra";
    }
    const auto& p = baseline.car.parameters();
    if (p.top_mount_transition_deflection_m > 0.0) {
      return "the baseline's top mount already stiffens at small amplitude";
    }
    if (p.top_mount_stiffness_N_per_m >= 1e9) {
      return "the baseline attaches the damper rigidly: no top mount to stiffen "
             "(see top_mount_compliance)";
    }
    return "";
  }
  EffectChange change(const DiagnosisModel& baseline) const override {
    const double k_large = baseline.car.parameters().top_mount_stiffness_N_per_m;
    // Starts twice and three times the large-amplitude rate: well away from the 1.45× of seed
    // 000's 707 against 488 N/mm (every stiffening record and test here), which the first start
    // at 1.4× all but sat on.
    return {{{rows::top_mount_small_amplitude_stiffness_N_per_m.key_string(), 2.0 * k_large},
             {rows::top_mount_transition_deflection_m.key_string(), 1e-3}},
            std::nullopt,
            {{rows::top_mount_small_amplitude_stiffness_N_per_m.key_string(), 1.001 * k_large,
              5.0 * k_large},
             {rows::top_mount_transition_deflection_m.key_string(), 1e-6, 1e-2}},
            // k_s and δ0 trade off along a curved valley (the stiffness at the amplitude the
            // road excites): start also below and above the typical deflection.
            {{{rows::top_mount_transition_deflection_m.key_string(), 3e-4}},
             {{rows::top_mount_transition_deflection_m.key_string(), 3e-3},
              {rows::top_mount_small_amplitude_stiffness_N_per_m.key_string(), 3.0 * k_large}}}};
  }
};

}  // namespace

std::unique_ptr<Effect> make_top_mount_amplitude_stiffening() {
  return std::make_unique<TopMountAmplitudeStiffening>();
}

}  // namespace ridefit::fitting::diagnose
