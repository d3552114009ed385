#include "ridefit/fitting/strut_parameters.h"

#include <fmt/core.h>

#include "ridefit/io/input_error.h"

namespace ridefit::fitting {

std::size_t strut_parameter_index(std::string_view name) {
  std::string names;
  for (std::size_t i = 0; i < kStrutParameters.size(); ++i) {
    if (kStrutParameters[i].name == name) return i;
    names += (names.empty() ? "" : ", ") + std::string(kStrutParameters[i].name);
  }
  throw InputError(
      fmt::format("'{}' is not a strut-test parameter; the parameters are: {}", name, names));
}

}  // namespace ridefit::fitting
