#pragma once

#include <string>

namespace ridefit::common {

// An option of an in-memory settings struct that breaks its rule: the option's key as a file
// spells it ("starts") and what is wrong ("is 0, expected 1 … 1000"). validate() functions return
// it rather than throw, so that a file reader can prefix the key's file and line and a library
// caller the section: one rule, one wording, wherever the value came from.
struct SettingError {
  std::string key;
  std::string message;
};

}  // namespace ridefit::common
