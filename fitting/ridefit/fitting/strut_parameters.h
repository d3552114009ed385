#pragma once

#include <array>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "ridefit/model/quarter_car.h"
#include "ridefit/model/quarter_car_parameter_table.h"
#include "ridefit/model/strut_test.h"
#include "ridefit/model/strut_test_parameter_table.h"

namespace ridefit::fitting {

// The parameters of a strut test: a row of the model's parameter tables (key, unit, what it
// means; model/quarter_car_parameter_table.h for the damper path, model/
// strut_test_parameter_table.h for the rig-only ones) with the bounds a fit uses unless told
// otherwise: wide enough for any passenger-car strut, tight enough to keep the solver out of
// nonsense (a negative stiffness, a friction exponent of 100).
struct StrutParameterInfo {
  const model::ParameterInfo* row;
  double lower;
  double upper;
  bool in_model_file;  // a quarter-car model key (the rig-only ones are not)

  std::string_view name() const { return row->key; }
};

// The Stribeck pair acts only when stribeck_velocity_m_per_s > 0 (its default 0 is off and below
// its bound, so fitting it needs a --start or a model file that has it); static_friction_force_N
// is read only then.
// The controlled damper's slopes act only with a command column; its lag τ only when > 0 (0 is
// below its bound: fitting it needs a start). The load cell's chain (gain, delay, cutoff) is
// rig-only; a cutoff of 0 is off and below its bound likewise.
// Free play's 0 is off and below its bound likewise. A gas spring's rate is not negative (force
// tension positive: the push-out grows as the rod goes in); fits of the UTFSM MR files that
// allowed it traded a negative rate against the offset (the 2 mm file: −16.7 kN/m, offset
// −462 N, 19 % NRMSE; held ≥ 0: 2.2 kN/m, 106 N, 12 %).
inline constexpr std::array<StrutParameterInfo, 27> kStrutParameters{{
    {&model::quarter_car_rows::dahl_sigma0_N_per_m, 1e3, 1e10, true},
    {&model::quarter_car_rows::coulomb_force_N, 0.0, 1e4, true},
    {&model::quarter_car_rows::dahl_exponent, 0.2, 5.0, true},
    {&model::quarter_car_rows::top_mount_stiffness_N_per_m, 1e3, 1e10, true},
    {&model::quarter_car_rows::damping_Ns_per_m, 1.0, 1e6, true},
    {&model::strut_rig_rows::gas_force_N, -1e4, 1e4, false},
    {&model::strut_rig_rows::gas_stiffness_N_per_m, 0.0, 1e6, false},
    {&model::strut_rig_rows::force_offset_N, -1e4, 1e4, false},
    {&model::quarter_car_rows::static_friction_force_N, 0.0, 1e4, true},
    {&model::quarter_car_rows::stribeck_velocity_m_per_s, 1e-5, 10.0, true},
    {&model::quarter_car_rows::damping_per_command_Ns_per_m, -1e5, 1e6, true},
    {&model::quarter_car_rows::coulomb_force_per_command_N, -1e4, 1e4, true},
    {&model::quarter_car_rows::command_lag_s, 1e-4, 1.0, true},
    {&model::strut_rig_rows::force_gain, 0.5, 2.0, false},
    {&model::strut_rig_rows::force_delay_s, 0.0, 0.1, false},
    {&model::strut_rig_rows::force_sensor_cutoff_Hz, 1.0, 1e5, false},
    {&model::quarter_car_rows::friction_compression_to_rebound_ratio, 0.2, 5.0, true},
    {&model::quarter_car_rows::free_play_m, 1e-5, 0.1, true},
    // The rest of the quarter car's damper path (a knee of 0 is off and below its bound).
    {&model::quarter_car_rows::compression_to_rebound_ratio, 0.1, 10.0, true},
    {&model::quarter_car_rows::damper_knee_velocity_m_per_s, 1e-4, 5.0, true},
    {&model::quarter_car_rows::damping_above_knee_Ns_per_m, 1.0, 1e6, true},
    {&model::quarter_car_rows::top_mount_small_amplitude_stiffness_N_per_m, 1e3, 1e10, true},
    {&model::quarter_car_rows::top_mount_transition_deflection_m, 1e-7, 0.1, true},
    {&model::quarter_car_rows::command_exponent, 0.2, 3.0, true},
    {&model::strut_rig_rows::moving_mass_kg, 0.0, 1e5, false},
    // A free play's damping acts only with free play (its 0, a dry play, is inside the box).
    {&model::quarter_car_rows::free_play_damping_Ns_per_m, 0.0, 1e7, true},
    // The knee's power: a shear-thinning MR fluid fits 0.2–0.5 (acts only with the knee).
    {&model::quarter_car_rows::damping_above_knee_exponent, 0.05, 3.0, true},
}};

// The strut of a quarter-car model as the rig sees it: its damper path's parameters, with no gas
// force and no load-cell offset (rig-only, zero until fitted).
model::StrutTestParameters<double> strut_on_rig(const model::QuarterCarParameters<double>& q);
// The same for a model with its topology: a slip model has no Dahl element, so none on the rig
// either (its coulomb_force_N, if any, is unused on the road too).
model::StrutTestParameters<double> strut_on_rig(const model::QuarterCar& car);

// Index into kStrutParameters; InputError naming the accepted names for an unknown one.
std::size_t strut_parameter_index(std::string_view name);

// `p` with the parameters named in `values` (kStrutParameters names) set to theirs; InputError
// "NAME: ..." for a name that is not a strut-test parameter.
model::StrutTestParameters<double> with_strut_values(model::StrutTestParameters<double> p,
                                                     const std::map<std::string, double>& values);

// What a fitted model file writes: the free parameters, then the other start values the fit
// ran with (a --start of a parameter that is not fitted, e.g. a rigid mount for a damper on a
// press): without them the file would not reproduce the fit.
std::vector<std::string> written_parameters(const std::vector<std::string>& free,
                                            const std::map<std::string, double>& starts);

// The model-file keys among `names` (kStrutParameters names, in that order) with their values in
// `p`: what a fitted model file holds. The rig-only parameters (gas force, load-cell offset and
// chain) are no model keys and are left out.
std::vector<std::pair<std::string, double>> model_file_values(
    const model::StrutTestParameters<double>& p, const std::vector<std::string>& names);

// The field of `p` for kStrutParameters[index]: the strut's own (model::strut_field) for a row of
// the damper path, else one of the rig's.
template <typename T>
T& strut_parameter(model::StrutTestParameters<T>& p, std::size_t index) {
  const model::ParameterInfo& row = *kStrutParameters[index].row;
  if (const auto i = model::strut_row(row)) return model::strut_field(p.strut(), *i);
  T* const rig[] = {&p.gas_force_N,   &p.gas_stiffness_N_per_m,  &p.force_offset_N, &p.force_gain,
                    &p.force_delay_s, &p.force_sensor_cutoff_Hz, &p.moving_mass_kg};
  static_assert(std::size(rig) == model::kStrutRigParameters.size());
  return *rig[&row - model::kStrutRigParameters.data()];
}

// Read-only: the same field of a const strut (the switch above written once).
template <typename T>
const T& strut_parameter(const model::StrutTestParameters<T>& p, std::size_t index) {
  return strut_parameter(const_cast<model::StrutTestParameters<T>&>(p), index);
}

}  // namespace ridefit::fitting
