// tyre_damping: the tyre's own damping in parallel with its stiffness.
#include <memory>

#include "ridefit/fitting/diagnose/effect.h"
#include "ridefit/model/quarter_car_parameter_table.h"

namespace ridefit::fitting::diagnose {
namespace {

namespace rows = model::quarter_car_rows;

class TyreDamping : public Effect {
 public:
  std::string_view id() const override { return "tyre_damping"; }
  std::string_view description() const override {
    return "damping in the tyre (rubber hysteresis in the carcass): lowers and widens the "
           "wheel-hop peak and passes more road input above it";
  }
  std::string not_applicable(const DiagnosisModel& baseline) const override {
    if (baseline.kind == DataKind::kStrutLoops) {
      return "strut rig loops have no tyre";
    }
    if (baseline.car.parameters().tyre_damping_Ns_per_m > 0.0) {
      return "the baseline already has tyre damping (free it to refit it)";
    }
    return "";
  }
  EffectChange change(const DiagnosisModel&) const override {
    return {{{rows::tyre_damping_Ns_per_m.key_string(), 100.0}},
            std::nullopt,
            {{rows::tyre_damping_Ns_per_m.key_string(), 1.0, 5000.0}},
            {}};
  }
};

}  // namespace

std::unique_ptr<Effect> make_tyre_damping() { return std::make_unique<TyreDamping>(); }

}  // namespace ridefit::fitting::diagnose
