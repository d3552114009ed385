// gas_force: the gas spring of a twin-tube or mono-tube strut, seen on the rig (seed 000,
// Section 2.2's F_g0 + k_g·x).
#include <algorithm>
#include <memory>

#include "ridefit/fitting/diagnose/effect.h"
#include "ridefit/model/strut_test_parameter_table.h"

namespace ridefit::fitting::diagnose {
namespace {

namespace rig = model::strut_rig_rows;

class GasForce : public Effect {
 public:
  std::string_view id() const override { return "gas_force"; }
  std::string_view description() const override {
    return "the damper's gas spring: a preload pushing the rod out plus a rate, so the loop is "
           "shifted and tilted (force rising with compression) where the model's is level";
  }
  std::string not_applicable(const DiagnosisModel& baseline) const override {
    if (baseline.kind != DataKind::kStrutLoops) {
      return "for strut rig loops: on the car the gas preload only moves the static ride height "
             "and its rate adds to the spring's, which the spectra cannot tell apart";
    }
    if (baseline.strut.gas_force_N != 0.0 || baseline.strut.gas_stiffness_N_per_m != 0.0) {
      return "the baseline already has a gas force";
    }
    return "";
  }
  EffectChange change(const DiagnosisModel& baseline) const override {
    // A small rate to start from (a gas spring is never exactly zero; the fit sets its size).
    EffectChange change{
        {{rig::gas_force_N.key_string(), 0.0}, {rig::gas_stiffness_N_per_m.key_string(), 1000.0}},
        std::nullopt,
        {{rig::gas_stiffness_N_per_m.key_string(), -1e5, 1e5}},
        {}};
    // A preload is a constant force, the same to the rig as the load cell's offset: when the
    // baseline fits that offset, it carries the preload too (and the report's offset is the sum).
    if (std::find(baseline.free.begin(), baseline.free.end(), rig::force_offset_N.key) ==
        baseline.free.end()) {
      change.free.push_back({rig::gas_force_N.key_string(), -5e3, 5e3});
    }
    return change;
  }
};

}  // namespace

std::unique_ptr<Effect> make_gas_force() { return std::make_unique<GasForce>(); }

}  // namespace ridefit::fitting::diagnose
