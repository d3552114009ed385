#pragma once

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

}  // namespace ridefit::io
