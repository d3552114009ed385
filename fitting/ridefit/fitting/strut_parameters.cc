#include "ridefit/fitting/strut_parameters.h"

#include <algorithm>

#include <fmt/core.h>

#include "ridefit/common/errors.h"

namespace ridefit::fitting {

std::size_t strut_parameter_index(std::string_view name) {
  std::string names;
  for (std::size_t i = 0; i < kStrutParameters.size(); ++i) {
    if (kStrutParameters[i].name() == name) return i;
    names += (names.empty() ? "" : ", ") + std::string(kStrutParameters[i].name());
  }
  throw InputError(
      fmt::format("'{}' is not a strut-test parameter; the parameters are: {}", name, names));
}

model::StrutTestParameters<double> with_strut_values(model::StrutTestParameters<double> p,
                                                     const std::map<std::string, double>& values) {
  for (const auto& [name, value] : values) {
    try {
      strut_parameter(p, strut_parameter_index(name)) = value;
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: {}", name, e.what()));
    }
  }
  return p;
}

std::vector<std::string> written_parameters(const std::vector<std::string>& free,
                                            const std::map<std::string, double>& starts) {
  std::vector<std::string> names = free;
  for (const auto& [name, value] : starts) {
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  return names;
}

std::vector<std::pair<std::string, double>> model_file_values(
    const model::StrutTestParameters<double>& p, const std::vector<std::string>& names) {
  std::vector<std::pair<std::string, double>> values;
  for (const auto& name : names) {
    const std::size_t index = strut_parameter_index(name);
    if (kStrutParameters[index].in_model_file) values.emplace_back(name, strut_parameter(p, index));
  }
  return values;
}

model::StrutTestParameters<double> strut_on_rig(const model::QuarterCarParameters<double>& q) {
  return model::StrutTestParameters<double>::on_rig(q.strut());
}

model::StrutTestParameters<double> strut_on_rig(const model::QuarterCar& car) {
  model::StrutTestParameters<double> strut = strut_on_rig(car.parameters());
  if (car.damper_state() == model::DamperState::kSlip) strut.coulomb_force_N = 0.0;
  return strut;
}

}  // namespace ridefit::fitting
