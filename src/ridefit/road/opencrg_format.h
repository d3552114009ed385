#pragma once

#include <cstddef>

#include "ridefit/road/opencrg_file.h"

namespace ridefit::road {

// The data formats' layout, shared by the OpenCRG reader and writer: ASCII values of fixed width
// (LRFI 10 characters, LDFI 20), binary big-endian IEEE reals (KRBI 4 bytes, KDBI 8), both in
// records of 80 characters or bytes.
inline constexpr std::size_t kCrgRecordBytes = 80;
// Elevations beyond this are no road (as for the profile road).
inline constexpr double kCrgMaxElevation_m = 1e4;

inline const char* format_name(CrgFormat format) {
  switch (format) {
    case CrgFormat::kLrfi:
      return "LRFI";
    case CrgFormat::kLdfi:
      return "LDFI";
    case CrgFormat::kKrbi:
      return "KRBI";
    case CrgFormat::kKdbi:
      return "KDBI";
  }
  return "?";
}

inline bool is_binary(CrgFormat format) {
  return format == CrgFormat::kKrbi || format == CrgFormat::kKdbi;
}
inline std::size_t value_width(CrgFormat format) {  // characters or bytes per value
  switch (format) {
    case CrgFormat::kLrfi:
      return 10;
    case CrgFormat::kLdfi:
      return 20;
    case CrgFormat::kKrbi:
      return 4;
    case CrgFormat::kKdbi:
      return 8;
  }
  return 10;
}
inline std::size_t values_per_record(CrgFormat format) {
  return kCrgRecordBytes / value_width(format);
}

}  // namespace ridefit::road
