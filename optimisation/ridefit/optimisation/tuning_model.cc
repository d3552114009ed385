#include "ridefit/optimisation/tuning_model.h"

#include <fmt/core.h>

#include "ridefit/common/errors.h"
#include "ridefit/model/half_car_parameter_table.h"
#include "ridefit/model/quarter_car_parameter_table.h"

namespace ridefit::optimisation {
namespace {

bool is_stick_slip_strut(const model::AxleTopology& axle) {
  return axle.suspension == model::AxleSuspension::kStrut &&
         axle.damper_state == model::DamperState::kStickSlip;
}

// The friction, load-case and design values in the order build_tuning_model applies them.
std::vector<ModelValue> study_values(const TuningStudy& study, const LoadCase& load_case,
                                     std::span<const double> design_values) {
  std::vector<ModelValue> values = study.friction_values;
  values.insert(values.end(), load_case.model_values.begin(), load_case.model_values.end());
  for (std::size_t v = 0; v < study.design.size() && v < design_values.size(); ++v) {
    for (const auto& key : study.design[v].keys) values.emplace_back(key, design_values[v]);
  }
  return values;
}

[[noreturn]] void not_a_key(const std::string& origin, const std::string& key) {
  throw InputError(fmt::format("{}: '{}' is not a number of the model", origin, key));
}

}  // namespace

std::vector<std::pair<std::string, std::string>> tuned_values(
    const TuningStudy& study, std::span<const double> design_values) {
  std::vector<std::pair<std::string, std::string>> values = study.model_settings;
  for (const auto& [key, value] : study.friction_values) {
    values.emplace_back(key, fmt::format("{}", value));
  }
  for (std::size_t v = 0; v < study.design.size(); ++v) {
    for (const auto& key : study.design[v].keys) {
      values.emplace_back(key, fmt::format("{}", design_values[v]));
    }
  }
  return values;
}

TuningModel build_tuning_model(const TuningStudy& study, FrictionVariant variant,
                               const LoadCase& load_case, std::span<const double> design_values,
                               const std::string& origin) {
  const std::vector<ModelValue> values = study_values(study, load_case, design_values);
  TuningModel model;
  // Errors read "ORIGIN: the file's message (given as KEY=VALUE)": here the overrides came from
  // the study.
  io::ModelOverrides overrides;
  overrides.origin = "given as";
  if (study.kind == ModelKind::kQuarterCar) {
    for (const auto& [key, text] : study.model_settings) {
      if (key == "damper_state") {
        overrides.damper_state = text;
      } else {
        overrides.set(key, text);
      }
    }
    for (const auto& [key, value] : values) overrides.set(key, value);
    try {
      auto file = io::load_quarter_car(study.model_file, overrides);
      if (variant == FrictionVariant::kBlind &&
          file.damper_state == model::DamperState::kStickSlip) {
        overrides.damper_state = "slip";
        file = io::load_quarter_car(study.model_file, overrides);
      }
      model.quarter = std::move(file);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: {}", origin, e.what()));
    }
    return model;
  }
  overrides.keys = study.model_settings;
  for (const auto& [key, value] : values) overrides.set(key, value);
  try {
    auto file = io::load_half_car(study.model_file, overrides);
    if (variant == FrictionVariant::kBlind) {
      bool changed = false;
      if (is_stick_slip_strut(file.topology.front)) {
        overrides.set("front.damper_state", "slip");
        changed = true;
      }
      if (is_stick_slip_strut(file.topology.rear)) {
        overrides.set("rear.damper_state", "slip");
        changed = true;
      }
      if (changed) file = io::load_half_car(study.model_file, overrides);
    }
    model.half = std::move(file);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", origin, e.what()));
  }
  return model;
}

TuningModel load_base_model(const TuningStudy& study, const std::string& origin) {
  TuningStudy settings_only = study;
  settings_only.friction_values.clear();
  settings_only.design.clear();
  return build_tuning_model(settings_only, FrictionVariant::kStudy, LoadCase{}, {}, origin);
}

TuningModel edit_tuning_model(const TuningModel& base, const TuningStudy& study,
                              FrictionVariant variant, const LoadCase& load_case,
                              std::span<const double> design_values, const std::string& origin) {
  TuningModel model = base;
  const std::vector<ModelValue> values = study_values(study, load_case, design_values);
  std::optional<model::ParameterError> error;
  if (model.quarter) {
    auto& p = model.quarter->parameters;
    for (const auto& [key, value] : values) {
      const auto index = model::quarter_car_parameter_index(key);
      if (!index) not_a_key(origin, key);
      model::set_quarter_car_parameter(p, *index, value);
    }
    if (variant == FrictionVariant::kBlind &&
        model.quarter->damper_state == model::DamperState::kStickSlip) {
      model.quarter->damper_state = model::DamperState::kSlip;
    }
    error = model::validate(p);
  } else {
    auto& p = model.half->parameters;
    auto& topology = model.half->topology;
    for (const auto& [key, value] : values) {
      const auto field = model::half_car_field(p, topology.control, key);
      if (!field) not_a_key(origin, key);
      *field->value = value;
    }
    if (variant == FrictionVariant::kBlind) {
      for (auto* axle : {&topology.front, &topology.rear}) {
        if (is_stick_slip_strut(*axle)) axle->damper_state = model::DamperState::kSlip;
      }
    }
    error = model::validate(p, topology);
  }
  if (error) throw InputError(fmt::format("{}: {}", origin, error->text()));
  return model;
}

bool has_friction(const TuningModel& model) {
  if (model.quarter) {
    return model.quarter->damper_state == model::DamperState::kStickSlip &&
           model.quarter->parameters.coulomb_force_N > 0.0;
  }
  const auto& t = model.half->topology;
  const auto& p = model.half->parameters;
  return (is_stick_slip_strut(t.front) && p.front.coulomb_force_N > 0.0) ||
         (is_stick_slip_strut(t.rear) && p.rear.coulomb_force_N > 0.0);
}

}  // namespace ridefit::optimisation
