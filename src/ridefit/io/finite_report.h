#pragma once

#include <filesystem>
#include <string>

namespace ridefit::io {

// RunError when a report's text shows a value that is not a number (nan, inf, as a word of its
// own): a report never presents one as a result. `path` names the report in the message. Run on
// the text in memory, before any file of the run is written.
void require_finite_report(const std::string& text, const std::filesystem::path& path);

}  // namespace ridefit::io
