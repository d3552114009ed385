#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "ridefit/io/half_car_file.h"
#include "ridefit/io/quarter_car_file.h"
#include "ridefit/optimisation/tuning_study.h"

namespace ridefit::optimisation {

// Which friction the model carries. kStudy: the model's or the study's friction; kBlind: every
// stick/slip strut becomes a slip strut (top mount in series with the damper, no Dahl element):
// the model an engineer tunes with when friction is ignored.
enum class FrictionVariant { kStudy, kBlind };

// A quarter car or a half car, built for one evaluation.
struct TuningModel {
  std::optional<io::QuarterCarFile> quarter;
  std::optional<io::HalfCarFile> half;
};

// The study's model with, in this order, the study's friction values, the load case's values
// and the design values (one per design variable, on each of its keys). InputError when the
// model rejects a value; `origin` says where the values came from in the message.
TuningModel build_tuning_model(const TuningStudy& study, FrictionVariant variant,
                               const LoadCase& load_case, std::span<const double> design_values,
                               const std::string& origin);

// The study's model with its `set:` settings (topology words and values), read from the model
// file once; the evaluations edit copies of it in memory (edit_tuning_model).
TuningModel load_base_model(const TuningStudy& study, const std::string& origin);

// build_tuning_model's model without a file: `base` (load_base_model's) with the same values
// set through the parameter tables (model/*_parameter_table.h) and checked by their validate().
// The study loader has built every case and every corner of the design box from the file, so
// within the bounds this is the same model; InputError naming `origin` and the key otherwise.
TuningModel edit_tuning_model(const TuningModel& base, const TuningStudy& study,
                              FrictionVariant variant, const LoadCase& load_case,
                              std::span<const double> design_values, const std::string& origin);

// Every key an optimised model file changes, as text: the study's `set:` values, its friction
// values, then the design values (numbers with 17 significant digits).
std::vector<std::pair<std::string, std::string>> tuned_values(
    const TuningStudy& study, std::span<const double> design_values);

// True when some damper of the model is stick/slip with a Coulomb force above zero.
bool has_friction(const TuningModel& model);

}  // namespace ridefit::optimisation
