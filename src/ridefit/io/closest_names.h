#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace ridefit::io {

// Up to `count` of `candidates` closest to `name` (edit distance, ties in the candidates'
// order), for "unknown ...; did you mean ..." messages. Candidates further than half of the
// name's length are left out.
std::vector<std::string> closest_names(const std::string& name,
                                       const std::vector<std::string>& candidates,
                                       std::size_t count = 3);

// closest_names as text: "; closest: a, b, c", or "" when none is close.
std::string closest_names_text(const std::string& name, const std::vector<std::string>& candidates,
                               std::size_t count = 3);

// The dotted keys of a YAML file's numbers (e.g. front.damping_Ns_per_m), candidates for
// closest_names when a key of the file is misspelt. An unreadable file gives none.
std::vector<std::string> yaml_number_keys(const std::filesystem::path& yaml_file);

}  // namespace ridefit::io
