#include "ridefit/io/value_range.h"

#include <fmt/core.h>

#include <cmath>

#include "ridefit/common/errors.h"

namespace ridefit::io {
namespace {

constexpr long kMaxCount = 10000;

}  // namespace

std::vector<double> read_value_range(const YamlMap& range) {
  const double from = range.number("from");
  const double to = range.number("to");
  const long count = range.integer("count");
  if (count < 1 || count > kMaxCount) {
    throw InputError(
        fmt::format("{} is {}, expected 1 … {}", range.locate("count"), count, kMaxCount));
  }
  const std::string spacing =
      range.has("spacing") ? range.choice("spacing", {"linear", "log"}) : "linear";
  if (spacing == "log" && !(from > 0.0 && to > 0.0)) {
    throw InputError(fmt::format("{}: log spacing needs from > 0 and to > 0 (got {} and {})",
                                 range.locate("spacing"), from, to));
  }
  range.finish();
  std::vector<double> values;
  for (long i = 0; i < count; ++i) {
    const double s = count == 1 ? 0.0 : static_cast<double>(i) / static_cast<double>(count - 1);
    values.push_back(spacing == "log" ? from * std::pow(to / from, s) : from + s * (to - from));
  }
  values.back() = count == 1 ? from : to;  // exact ends
  return values;
}

}  // namespace ridefit::io
