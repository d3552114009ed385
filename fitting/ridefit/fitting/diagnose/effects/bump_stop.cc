// bump_stop: progressive contact beyond a compression clearance.
#include <memory>

#include "ridefit/fitting/diagnose/effect.h"
#include "ridefit/model/quarter_car_parameter_table.h"

namespace ridefit::fitting::diagnose {
namespace {

namespace rows = model::quarter_car_rows;

class BumpStop : public Effect {
 public:
  std::string_view id() const override { return "bump_stop"; }
  std::string_view description() const override {
    return "a progressive bump stop beyond a compression clearance: hard hits on large inputs "
           "put body energy far above the body mode";
  }
  std::string not_applicable(const DiagnosisModel& baseline) const override {
    if (baseline.kind == DataKind::kStrutLoops) {
      return "the rig tests stay inside the strut's free travel and the rig model has no bump stop";
    }
    if (baseline.car.parameters().bump_stop_stiffness_N_per_m > 0.0) {
      return "the baseline already has a bump stop";
    }
    return "";
  }
  EffectChange change(const DiagnosisModel& baseline) const override {
    // Start soft (the spring's own rate) and at a typical clearance, so the first evaluations
    // change the model gently.
    const double k = baseline.car.parameters().spring_stiffness_N_per_m;
    return {{{rows::bump_stop_stiffness_N_per_m.key_string(), k},
             {rows::bump_stop_clearance_m.key_string(), 0.02}},
            std::nullopt,
            {{rows::bump_stop_stiffness_N_per_m.key_string(), 0.1 * k, 1000.0 * k},
             {rows::bump_stop_clearance_m.key_string(), 0.001, 0.2}},
            {}};
  }
};

}  // namespace

std::unique_ptr<Effect> make_bump_stop() { return std::make_unique<BumpStop>(); }

}  // namespace ridefit::fitting::diagnose
