#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace ridefit::model {

// One row of a model's parameter table: the YAML key (design.md's name, unit in the name), the
// unit as printed, the plausibility range and what the parameter means. The range is far beyond
// any road vehicle and close enough to catch a unit slip (N/mm typed as N/m is 1e3 off; 1e300 is
// a typo) before it becomes a NaN in the solver. A row is the single place a parameter's name,
// unit and limits are written: the file readers, --set, the sweeps, the optimiser, the fits and
// the diagnosis all read them from here.
struct ParameterInfo {
  std::string_view key;
  std::string_view unit;
  double lower;
  double upper;
  bool lower_open;   // (lower, upper] rather than [lower, upper]
  bool zero_is_off;  // an optional effect: 0 switches it off and is always accepted
  std::string_view meaning;

  // The key as a std::string, for the maps and lists of keys.
  std::string key_string() const { return std::string(key); }

  bool contains(double value) const {
    if (zero_is_off && value == 0.0) return true;
    return (lower_open ? value > lower : value >= lower) && value <= upper;
  }
};

// "a value > 0 and <= 1e+10", "a value in [0, 1e+07]", "a value in [0.1, 10]": the range as the
// file readers word it.
std::string expected_range(const ParameterInfo& info);

// A parameter of an in-memory model that breaks its row or a rule between parameters: the key
// (dotted for the half car, "front.damping_Ns_per_m") and what is wrong, as "is 0, expected a
// value > 0 and <= 1e+07", so that a caller prefixes where the value came from.
struct ParameterError {
  std::string key;
  std::string message;

  std::string text() const { return "'" + key + "' " + message; }
};

// The error for `value` outside `info`'s range, or none. `key` overrides info.key (a dotted key).
std::optional<ParameterError> check_range(const ParameterInfo& info, double value,
                                          std::string_view key = {});

}  // namespace ridefit::model
