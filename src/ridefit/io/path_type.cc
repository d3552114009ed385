#include "ridefit/io/path_type.h"

#include <fmt/core.h>

#include <system_error>

#include "ridefit/common/errors.h"

namespace ridefit::io {

std::filesystem::file_type path_type(const std::filesystem::path& path) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (error && error != std::errc::no_such_file_or_directory &&
      error != std::errc::not_a_directory) {
    throw InputError(fmt::format("{}: cannot be used: {}", path.string(), error.message()));
  }
  return error ? std::filesystem::file_type::not_found : status.type();
}

}  // namespace ridefit::io
