// damper_asymmetry: rebound and compression damping differ.
#include <memory>

#include "ridefit/fitting/diagnose/effect.h"
#include "ridefit/model/quarter_car_parameter_table.h"

namespace ridefit::fitting::diagnose {
namespace {

namespace rows = model::quarter_car_rows;

class DamperAsymmetry : public Effect {
 public:
  std::string_view id() const override { return "damper_asymmetry"; }
  std::string_view description() const override {
    return "a damper softer in compression than in rebound (valving): the body rides down on "
           "rough roads and the response gains even harmonics";
  }
  std::string not_applicable(const DiagnosisModel& baseline) const override {
    // On the rig the damper path is the car's (StrutParameters::damper_path): its valving acts
    // there.
    if (baseline.kind == DataKind::kStrutLoops) {
      return baseline.strut.compression_to_rebound_ratio != 1.0
                 ? "the baseline's damper is already asymmetric"
                 : "";
    }
    if (baseline.car.damper_state() == model::DamperState::kStick) {
      return "the baseline's damper is locked (stick): its valving cannot act";
    }
    if (baseline.car.parameters().compression_to_rebound_ratio != 1.0) {
      return "the baseline's damper is already asymmetric";
    }
    return "";
  }
  EffectChange change(const DiagnosisModel&) const override {
    return {{{rows::compression_to_rebound_ratio.key_string(), 0.7}},
            std::nullopt,
            {{rows::compression_to_rebound_ratio.key_string(), 0.1, 3.0}},
            {}};
  }
};

}  // namespace

std::unique_ptr<Effect> make_damper_asymmetry() { return std::make_unique<DamperAsymmetry>(); }

}  // namespace ridefit::fitting::diagnose
