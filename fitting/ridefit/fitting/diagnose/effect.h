#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ridefit/model/quarter_car.h"
#include "ridefit/model/strut_test.h"

namespace ridefit::fitting::diagnose {

// What the measurement is: vehicle accelerations over a road, compared as spectra, or strut
// rig tests (imposed displacement, measured force), compared as loops in time.
enum class DataKind { kVehicleSpectra, kStrutLoops };

// A model under diagnosis, with the data it is compared against in mind: a quarter car for
// vehicle spectra, the strut on its rig (fitting/strut_parameters.h names) for loops.
struct DiagnosisModel {
  model::QuarterCar car{model::DamperState::kSlip, model::QuarterCarParameters<double>{}};
  DataKind kind = DataKind::kVehicleSpectra;
  model::StrutTestParameters<double> strut{};
  // The baseline's parameters every fit frees (set by the diagnosis; an effect whose parameter
  // one of them already carries leaves that one out).
  std::vector<std::string> free{};
  // The records carry a damper command (a current or voltage column): set by the diagnosis.
  bool has_command = false;
  // The RMS speed of the damper's stroke in the training records [m/s] (the rig's, or the
  // baseline's travel rate over the road), set by the diagnosis: where a velocity law's knee
  // starts, read off the data rather than assumed. 0 when unknown.
  double damper_speed_rms_m_per_s = 0.0;
};

// A parameter a fit frees, with the bounds that keep it physical.
struct FreeParameter {
  std::string name;  // a quarter-car key (model/quarter_car_parameter_names.h) or, for loops, a
                     // strut-test one (fitting/strut_parameters.h)
  double lower = 0.0;
  double upper = 0.0;
};

// What adding an effect does to a model: keys set to the values its fit starts from (the
// switch `tyre_lift_off` as 1), an optional change of topology, and its parameters to fit.
struct EffectChange {
  std::map<std::string, double> set;
  std::optional<model::DamperState> damper_state;
  std::vector<FreeParameter> free;
  // Further starts for effects whose fit has local minima: each replaces some of `set`'s values;
  // the fit from every start is run and the lowest training cost kept.
  std::vector<std::map<std::string, double>> other_starts;
};

// One physical effect a model may be missing. The id is what reports and JSON show.
class Effect {
 public:
  virtual ~Effect() = default;
  virtual std::string_view id() const = 0;
  // One sentence: what it is physically and what it does to the response.
  virtual std::string_view description() const = 0;
  // Why the effect cannot be added to `baseline` (it is already there, or data of the baseline's
  // kind cannot show it), or "" when it can.
  virtual std::string not_applicable(const DiagnosisModel& baseline) const = 0;
  // The change that adds it, with a start inside its bounds. Called only when applicable.
  virtual EffectChange change(const DiagnosisModel& baseline) const = 0;
  // True for effects of the measurement chain (a sensor's gain, delay or band limit) rather than
  // of the car or strut: the report keeps "the model misses physics" apart from "the measurement
  // chain differs".
  virtual bool measurement_chain() const { return false; }
  // What records would show the effect, for when its parameters cannot be identified from the
  // records at hand (e.g. "sliding velocities around v_s"); "" when there is nothing to add.
  virtual std::string_view identifiable_from() const { return ""; }
};

// Every effect, sorted by id. Each lives in diagnose/effects/<id>.cc and defines
// `std::unique_ptr<Effect> make_<id>()`; CMake generates the list from that folder, so adding an
// effect is one new file.
const std::vector<std::unique_ptr<Effect>>& effect_library();

// The effect with this id; InputError listing the ids for an unknown one.
const Effect& find_effect(std::string_view id);

// `model` with `change` applied (keys set, topology changed).
DiagnosisModel apply(const DiagnosisModel& model, const EffectChange& change);

// A strut's value of a key of fitting/strut_parameters.h.
double parameter_value(const model::StrutTestParameters<double>& strut, std::string_view name);

// A quarter car's value of a key of model/quarter_car_parameter_names.h, or of the switches
// tyre_lift_off (0 or 1) and acc_sensor_order (1 or 2).
double parameter_value(const model::QuarterCar& car, std::string_view name);

}  // namespace ridefit::fitting::diagnose
