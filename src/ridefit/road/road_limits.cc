#include "ridefit/road/road_limits.h"

#include <fmt/core.h>

#include <system_error>

#include "ridefit/common/errors.h"

namespace ridefit::road {

void check_speed_m_per_s(double speed_m_per_s, const std::string& key) {
  if (speed_m_per_s > 0.0 && speed_m_per_s <= kMaxSpeed_m_per_s) return;  // false for NaN
  const double km_per_h = speed_m_per_s * 3.6;
  const std::string given = key.ends_with("km_per_h")
                                ? fmt::format("{:g} km/h ({:g} m/s)", km_per_h, speed_m_per_s)
                                : fmt::format("{:g} m/s ({:g} km/h)", speed_m_per_s, km_per_h);
  throw InputError(fmt::format(
      "key '{}' is {}, expected a speed > 0 and at most {:g} m/s ({:g} km/h, faster than any "
      "road vehicle)",
      key, given, kMaxSpeed_m_per_s, kMaxSpeed_m_per_s * 3.6));
}

void check_data_file(const std::filesystem::path& path, const std::string& expected) {
  std::error_code error;  // e.g. no permission: left to the reader's "cannot open"
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (std::filesystem::is_directory(status)) {
    throw InputError(fmt::format("{}: is a directory; expected {}", path.string(), expected));
  }
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
    throw InputError(fmt::format("{}: is not a regular file (a device or a pipe?); expected {}",
                                 path.string(), expected));
  }
}

}  // namespace ridefit::road
