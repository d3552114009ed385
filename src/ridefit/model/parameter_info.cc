#include "ridefit/model/parameter_info.h"

#include <fmt/core.h>

namespace ridefit::model {

std::string expected_range(const ParameterInfo& info) {
  // The wording of io::YamlMap's positive_up_to, non_negative_up_to and number_in.
  if (info.lower == 0.0 && info.lower_open) {
    return fmt::format("a value > 0 and <= {:g}", info.upper);
  }
  if (info.lower == 0.0) return fmt::format("a value in [0, {:g}]", info.upper);
  return fmt::format("a value in [{}, {}]", info.lower, info.upper);
}

std::optional<ParameterError> check_range(const ParameterInfo& info, double value,
                                          std::string_view key) {
  if (info.contains(value)) return std::nullopt;
  return ParameterError{std::string(key.empty() ? info.key : key),
                        fmt::format("is {}, expected {}{}", value, expected_range(info),
                                    info.zero_is_off ? " (or 0: off)" : "")};
}

}  // namespace ridefit::model
