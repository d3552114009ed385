// tyre_lift_off: unilateral tyre contact.
#include <memory>

#include "ridefit/fitting/diagnose/effect.h"

namespace ridefit::fitting::diagnose {
namespace {

class TyreLiftOff : public Effect {
 public:
  std::string_view id() const override { return "tyre_lift_off"; }
  std::string_view description() const override {
    return "a tyre that can leave the road (it pushes but never pulls): on rough roads the "
           "wheel flies and lands, putting energy above the wheel mode; no parameter to fit";
  }
  std::string not_applicable(const DiagnosisModel& baseline) const override {
    if (baseline.kind == DataKind::kStrutLoops) {
      return "strut rig loops have no tyre";
    }
    if (baseline.car.parameters().tyre_lift_off) return "the baseline's tyre already lifts off";
    return "";
  }
  EffectChange change(const DiagnosisModel&) const override {
    return {{{"tyre_lift_off", 1.0}}, std::nullopt, {}, {}};
  }
};

}  // namespace

std::unique_ptr<Effect> make_tyre_lift_off() { return std::make_unique<TyreLiftOff>(); }

}  // namespace ridefit::fitting::diagnose
