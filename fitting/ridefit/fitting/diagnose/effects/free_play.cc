// free_play: slack (backlash) in series with the damper path (model/free_play.h): after each
// reversal the force stays near zero over the slack's width, then rises steeply.
#include <algorithm>
#include <memory>

#include "ridefit/fitting/diagnose/effect.h"
#include "ridefit/model/quarter_car_parameter_table.h"

namespace ridefit::fitting::diagnose {
namespace {

namespace rows = model::quarter_car_rows;

class FreePlay : public Effect {
 public:
  std::string_view id() const override { return "free_play"; }
  std::string_view description() const override {
    return "free play (backlash) in series with the damper: after each reversal the force stays "
           "near zero while the slack is taken up, then rises steeply, so the loop is pinched at "
           "the reversals";
  }
  std::string_view identifiable_from() const override {
    return "loops whose stroke is several times the slack (a stroke inside the slack shows no "
           "force at all)";
  }
  std::string not_applicable(const DiagnosisModel& baseline) const override {
    if (baseline.kind != DataKind::kStrutLoops) {
      return "for strut rig loops: on the road a slack of millimetres hides in the tyre's and "
             "spring's travel";
    }
    if (baseline.strut.free_play_m > 0.0) return "the baseline already has free play";
    return "";
  }
  EffectChange change(const DiagnosisModel&) const override {
    const std::string key = rows::free_play_m.key_string();
    // Millimetres: a worn joint to a loose rack; starts narrow and wide (local minima in b).
    return {{{key, 2e-3}}, std::nullopt, {{key, 1e-5, 0.05}}, {{{key, 6e-3}}, {{key, 0.5e-3}}}};
  }
};

}  // namespace

std::unique_ptr<Effect> make_free_play() { return std::make_unique<FreePlay>(); }

}  // namespace ridefit::fitting::diagnose
