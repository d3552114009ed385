#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace ridefit::fuzz {

// What a parser made of one input: read it, or refused it with an InputError (a message for
// the user). Anything else that escapes — another exception, a crash, a sanitizer report, a
// hang — is a finding.
enum class Outcome { kAccepted, kRefused };

// One parser as the fuzzers and the corpus regression test drive it: the input's bytes are
// written to a file (the parsers read files, and relative paths inside a study or an excitation
// resolve next to it, where the shipped datasets are linked) and parsed as the CLI would.
struct Target {
  std::string_view name;  // also the corpus folder: tests/fuzz/corpus/<name>/
  Outcome (*run)(std::span<const std::uint8_t> input);
};

// model_yaml, excitation_yaml, tuning_study_yaml, sweep_study_yaml, csv_with_units, journal,
// opencrg_file, batch_jobs_yaml.
std::span<const Target> targets();

// The target called `name`; std::invalid_argument for another name.
const Target& target(std::string_view name);

}  // namespace ridefit::fuzz
