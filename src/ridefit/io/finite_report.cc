#include "ridefit/io/finite_report.h"

#include <fmt/core.h>

#include <algorithm>
#include <regex>

#include "ridefit/common/errors.h"

namespace ridefit::io {

void require_finite_report(const std::string& text, const std::filesystem::path& path) {
  // Not inside a word, a path or a file name (e.g. "inflection", "datasets/inf.csv").
  static const std::regex non_finite(R"((^|[^A-Za-z_/.])[-+]?(nan|inf)([^A-Za-z_/.]|$))",
                                     std::regex::icase);
  std::smatch match;
  if (std::regex_search(text, match, non_finite)) {
    const auto at = static_cast<std::size_t>(match.position(0));
    const std::size_t line_start =
        text.rfind('\n', at) == std::string::npos ? 0 : text.rfind('\n', at) + 1;
    const std::size_t line_end = std::min(text.find('\n', at), text.size());
    throw RunError(fmt::format(
        "{} would show a value that is not a number, in: {}; nothing was written (the data may "
        "be degenerate: check the records)",
        path.string(), text.substr(line_start, line_end - line_start)));
  }
}

}  // namespace ridefit::io
