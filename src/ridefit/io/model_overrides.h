#pragma once

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace ridefit::io {

// Changes to a model file made before it is read, the one form for the quarter and the half car
// (quarter_car_file.h, half_car_file.h): `--set`, a study's `set:` and design values, a hidden
// dataset's spec.
// - `keys`: a key (dotted for the half car: "front.damping_Ns_per_m", "control.law") and its new
//   value as text, as a file would spell it, so that a bad one is reported by the reader with the
//   key's own rule ("is 'abc', expected a number"). Numbers given as doubles are spelled
//   exactly (the shortest text that reads back to the same double).
// - `damper_state`: the quarter car's topology word ("slip", "stick", "stick_slip"; "" = the
//   file's), apart from the numbers because it chooses the model rather than a value in it (the
//   file's own word is still checked). The half car has one per axle, set through `keys`
//   (front.damper_state).
// - `origin`: where the changes came from, for messages: an error one of them causes ends with
//   "(ORIGIN KEY=VALUE)", e.g. "(given on the command line as --set coulomb_force_N=-1)".
struct ModelOverrides {
  ModelOverrides() = default;
  // {{"front.suspension", "strut"}, {"front.damping_Ns_per_m", "1500"}}
  ModelOverrides(std::initializer_list<std::pair<std::string, std::string>> texts);
  // {{KEY, 30.0}}: numbers, spelled exactly
  ModelOverrides(std::initializer_list<std::pair<std::string, double>> numbers);

  std::vector<std::pair<std::string, std::string>> keys;
  std::string damper_state;
  std::string origin = "given as an override";

  ModelOverrides& set(std::string key, std::string text);
  ModelOverrides& set(std::string key, double value);
  bool empty() const { return keys.empty() && damper_state.empty(); }
};

// `message` with "(ORIGIN KEY=VALUE)" added for the first override whose key it names, in quotes
// ('front.damping_Ns_per_m') or, for a dotted key, by its last part; unchanged if none.
std::string with_override_named(const std::string& message, const ModelOverrides& overrides);

}  // namespace ridefit::io
