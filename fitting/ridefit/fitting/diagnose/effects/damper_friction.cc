// damper_friction: Dahl friction in the damper path (seed 000, Section 3.1), on the road or on
// the rig.
#include <memory>
#include <utility>
#include <vector>

#include "ridefit/fitting/diagnose/effect.h"
#include "ridefit/model/quarter_car_parameter_table.h"

namespace ridefit::fitting::diagnose {
namespace {

namespace rows = model::quarter_car_rows;

class DamperFriction : public Effect {
 public:
  std::string_view id() const override { return "damper_friction"; }
  std::string_view description() const override {
    return "Dahl friction beside the damper (seal and guide friction): the strut sticks at "
           "small amplitude, the body mode moves up and the damping seen at low amplitude grows";
  }
  std::string not_applicable(const DiagnosisModel& baseline) const override {
    if (baseline.kind == DataKind::kStrutLoops) {
      return baseline.strut.coulomb_force_N > 0.0 ? "the baseline already has Dahl friction" : "";
    }
    const auto& car = baseline.car;
    if (car.damper_state() == model::DamperState::kStick) {
      return "the baseline's damper is locked (stick): friction beside it cannot act";
    }
    if (car.damper_state() == model::DamperState::kStickSlip &&
        car.parameters().coulomb_force_N > 0.0) {
      return "the baseline already has Dahl friction";
    }
    return "";
  }
  EffectChange change(const DiagnosisModel& baseline) const override {
    // σ0 far above the top mount (the pre-sliding branch is then set by the top mount, which is
    // why σ0 is not fitted from spectra) unless the model already names one.
    const double named = baseline.kind == DataKind::kStrutLoops
                             ? baseline.strut.dahl_sigma0_N_per_m
                             : baseline.car.parameters().dahl_sigma0_N_per_m;
    const double sigma0 = named > 1e3 ? named : 5e6;
    std::vector<FreeParameter> free{{rows::coulomb_force_N.key_string(), 1.0, 1000.0}};
    // A rig loop shows the pre-sliding rise after each reversal, so σ0 is fitted there (a named
    // one is a guess, and held it would leave its error to other effects); the records' own
    // estimate (strut_start.h) is the fit's second start.
    if (baseline.kind == DataKind::kStrutLoops) {
      free.push_back({rows::dahl_sigma0_N_per_m.key_string(), 1e4, 1e10});
    }
    return {{{rows::dahl_sigma0_N_per_m.key_string(), sigma0},
             {rows::coulomb_force_N.key_string(), 30.0},
             {rows::dahl_exponent.key_string(), 1.0}},
            model::DamperState::kStickSlip,
            std::move(free),
            {}};
  }
};

}  // namespace

std::unique_ptr<Effect> make_damper_friction() { return std::make_unique<DamperFriction>(); }

}  // namespace ridefit::fitting::diagnose
