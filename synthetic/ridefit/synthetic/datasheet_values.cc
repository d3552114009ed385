#include "ridefit/synthetic/datasheet_values.h"

#include <cmath>
#include <random>

#include "ridefit/fitting/diagnose/diagnosis_options.h"
#include "ridefit/model/quarter_car_parameter_table.h"

namespace ridefit::synthetic {

const std::map<std::string, double>& datasheet_error_widths() {
  // The diagnosis's priors and the errors drawn here are one set: a sheet off by up to one
  // standard deviation of what the diagnosis assumes.
  static const std::map<std::string, double> widths = fitting::diagnose::datasheet_tolerances();
  return widths;
}

std::vector<std::pair<std::string, double>> datasheet_values(const model::QuarterCar& car,
                                                             std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const model::QuarterCarParameters<double>& p = car.parameters();
  auto value = [&](const std::string& name) {
    return model::quarter_car_parameter(p, *model::quarter_car_parameter_index(name));
  };
  std::vector<std::pair<std::string, double>> values;
  for (const auto& [name, width] : datasheet_error_widths()) {
    const double draw = unit(rng);  // drawn for every key, so one key's switch moves no other
    // A rigid mount (1e9 N/m and above) is the model's topology, not a value a sheet gets wrong.
    const bool rigid = name == model::quarter_car_rows::top_mount_stiffness_N_per_m.key_string() &&
                       value(name) >= 1e9;
    values.emplace_back(name, rigid ? value(name) : value(name) * (1.0 + width * draw));
  }
  const std::string sigma0 = model::quarter_car_rows::dahl_sigma0_N_per_m.key_string();
  values.emplace_back(sigma0, value(sigma0) * std::pow(2.0, unit(rng)));
  return values;
}

}  // namespace ridefit::synthetic
