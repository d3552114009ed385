// command_dependence: a controlled (semi-active) damper whose damping and friction level follow
// the command (coil current or valve voltage) after a lag (model/strut_test.h).
#include <memory>

#include "ridefit/fitting/diagnose/effect.h"
#include "ridefit/model/quarter_car_parameter_table.h"

namespace ridefit::fitting::diagnose {
namespace {

namespace rows = model::quarter_car_rows;

class CommandDependence : public Effect {
 public:
  std::string_view id() const override { return "command_dependence"; }
  std::string_view description() const override {
    return "a controlled damper: damping and friction rise with the command (coil current or "
           "valve voltage) after the fluid's response time, c(ū) = c + c_b·ū, Fc(ū) = Fc + "
           "Fc_b·ū, ū' = (u − ū)/τ";
  }
  std::string not_applicable(const DiagnosisModel& baseline) const override {
    if (!baseline.has_command) {
      return "the records have no command column (current[A] or voltage[V])";
    }
    const bool commanded = baseline.kind == DataKind::kStrutLoops
                               ? baseline.strut.commanded()
                               : baseline.car.parameters().commanded();
    if (commanded) return "the baseline already follows the command";
    return "";
  }
  EffectChange change(const DiagnosisModel& baseline) const override {
    if (baseline.kind == DataKind::kVehicleSpectra) return vehicle_change(baseline);
    // Slopes start at a small share of the passive levels per unit command; friction needs a
    // Dahl element, which the change adds when the baseline has none (σ0 from the baseline or
    // far above the top mount).
    const auto& s = baseline.strut;
    const double sigma0 = s.dahl_sigma0_N_per_m > 1e3 ? s.dahl_sigma0_N_per_m : 5e6;
    EffectChange change{
        {{rows::damping_per_command_Ns_per_m.key_string(), 0.3 * s.damping_Ns_per_m},
         {rows::coulomb_force_per_command_N.key_string(), 20.0},
         {rows::command_lag_s.key_string(), 0.01},
         {rows::dahl_sigma0_N_per_m.key_string(), sigma0},
         {rows::dahl_exponent.key_string(), s.coulomb_force_N > 0.0 ? s.dahl_exponent : 1.0}},
        {},
        {{rows::damping_per_command_Ns_per_m.key_string(), -1e5, 1e6},
         {rows::coulomb_force_per_command_N.key_string(), -1e4, 1e4},
         {rows::command_lag_s.key_string(), 1e-4, 0.5}},
        {{{rows::command_lag_s.key_string(), 0.002}}, {{rows::command_lag_s.key_string(), 0.05}}}};
    return change;
  }

 private:
  // On vehicle spectra the damping's slope is what the accelerations show; the friction level's
  // slope only where the baseline's damper has Dahl friction (stick/slip with Fc > 0). The lag
  // stays fixed at a typical fluid response (10 ms): at road frequencies below 25 Hz it shifts
  // the damping's timing by less than 2 % of a period, which the spectra cannot resolve, and a
  // free lag would wander along a flat cost.
  static EffectChange vehicle_change(const DiagnosisModel& baseline) {
    const auto& p = baseline.car.parameters();
    EffectChange change{
        {{rows::damping_per_command_Ns_per_m.key_string(), 0.3 * p.damping_Ns_per_m},
         {rows::command_lag_s.key_string(), 0.01}},
        {},
        {{rows::damping_per_command_Ns_per_m.key_string(), -1e5, 1e6}},
        {{{rows::damping_per_command_Ns_per_m.key_string(), 1.0 * p.damping_Ns_per_m}}}};
    if (baseline.car.damper_state() == model::DamperState::kStickSlip && p.coulomb_force_N > 0.0) {
      change.set[rows::coulomb_force_per_command_N.key_string()] = 0.0;
      change.free.push_back({rows::coulomb_force_per_command_N.key_string(), -1e4, 1e4});
    }
    return change;
  }
};

}  // namespace

std::unique_ptr<Effect> make_command_dependence() { return std::make_unique<CommandDependence>(); }

}  // namespace ridefit::fitting::diagnose
