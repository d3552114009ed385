// top_mount_compliance: the damper path's top mount in series with the damper.
#include <memory>

#include "ridefit/fitting/diagnose/effect.h"
#include "ridefit/model/quarter_car_parameter_table.h"

namespace ridefit::fitting::diagnose {
namespace {

namespace rows = model::quarter_car_rows;

// A damper-path top mount at or above this stiffness counts as a rigid attachment: its own
// mode would lie far above any road input (above 700 Hz against a 50 kg wheel).
constexpr double kRigid_N_per_m = 1e9;

class TopMountCompliance : public Effect {
 public:
  std::string_view id() const override { return "top_mount_compliance"; }
  std::string_view description() const override {
    return "a compliant top mount in series with the damper (rubber bushing): the damper is "
           "bypassed at high frequency, so the wheel mode rises and loses damping";
  }
  std::string not_applicable(const DiagnosisModel& baseline) const override {
    const double k = baseline.kind == DataKind::kStrutLoops
                         ? baseline.strut.top_mount_stiffness_N_per_m
                         : baseline.car.parameters().top_mount_stiffness_N_per_m;
    if (k < kRigid_N_per_m) {
      return "the baseline already has a compliant damper-path top mount "
             "(top_mount_stiffness_N_per_m below 1e9)";
    }
    return "";
  }
  EffectChange change(const DiagnosisModel&) const override {
    return {{{rows::top_mount_stiffness_N_per_m.key_string(), 1e6}},
            std::nullopt,
            {{rows::top_mount_stiffness_N_per_m.key_string(), 5e4, 1e8}},
            {}};
  }
};

}  // namespace

std::unique_ptr<Effect> make_top_mount_compliance() {
  return std::make_unique<TopMountCompliance>();
}

}  // namespace ridefit::fitting::diagnose
