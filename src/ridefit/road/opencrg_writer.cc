#include "ridefit/road/opencrg_file.h"

#include <fmt/core.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/io/atomic_file.h"
#include "ridefit/road/opencrg_format.h"

namespace ridefit::road {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// LRFI: fixed point (7 decimals) where that keeps more digits than E notation; LDFI: E.
std::string ascii_value(double value, CrgFormat format) {
  if (std::isnan(value))
    return format == CrgFormat::kLrfi ? fmt::format("{:>10}", "*missing*")
                                      : fmt::format("{:>20}", "*missing*");
  const double magnitude = std::abs(value);
  if (magnitude < 1e-99) value = 0.0;  // a two-digit exponent keeps the width
  if (format == CrgFormat::kLrfi) {
    if (value == 0.0 || (magnitude >= 1e-3 && magnitude < 9.9999999)) {
      return fmt::format("{:10.7f}", value);
    }
    return fmt::format("{:10.3E}", value);
  }
  return fmt::format("{:20.13E}", value);
}

void append_binary(std::string& out, double value, CrgFormat format) {
  if (format == CrgFormat::kKrbi) {
    const std::uint32_t bits =
        std::isnan(value) ? 0x7FC00000u : std::bit_cast<std::uint32_t>(static_cast<float>(value));
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<char>(bits >> shift));
  } else {
    const std::uint64_t bits =
        std::isnan(value) ? 0x7FF8000000000000ull : std::bit_cast<std::uint64_t>(value);
    for (int shift = 56; shift >= 0; shift -= 8) out.push_back(static_cast<char>(bits >> shift));
  }
}

}  // namespace

void write_opencrg(const CrgGrid& grid, const std::filesystem::path& path, CrgFormat format) {
  const std::size_t n = grid.columns();
  const std::size_t rows = grid.rows();
  if (n == 0 || rows < 2 || grid.z_m.size() != rows * n || !(grid.u_increment_m > 0.0) ||
      (!grid.slope.empty() && grid.slope.size() != rows) ||
      (!grid.banking.empty() && grid.banking.size() != rows)) {
    throw InputError(
        fmt::format("{}: cannot write an inconsistent OpenCRG grid ({} long sections, "
                    "{} elevations, {} slopes, {} bankings, u increment {:g})",
                    path.string(), n, grid.z_m.size(), grid.slope.size(), grid.banking.size(),
                    grid.u_increment_m));
  }
  for (double z : grid.z_m) {
    if (!std::isnan(z) && !(std::abs(z) <= kCrgMaxElevation_m)) {
      throw InputError(fmt::format("{}: cannot write elevation {:g} m (beyond +-{:g} m)",
                                   path.string(), z, kCrgMaxElevation_m));
    }
  }
  std::string out = "$CT\n";
  std::istringstream comment(grid.comment.empty() ? "written by ridefit" : grid.comment);
  for (std::string line; std::getline(comment, line);) {
    out += (line.starts_with("$") || line.starts_with("*") ? " " : "") + line + "\n";
  }
  out += "$ROAD_CRG\n";
  out += fmt::format("REFERENCE_LINE_START_U   = {}\n", grid.u_start_m);
  out += fmt::format("REFERENCE_LINE_END_U     = {}\n",
                     grid.u_start_m + static_cast<double>(rows - 1) * grid.u_increment_m);
  out += fmt::format("REFERENCE_LINE_INCREMENT = {}\n", grid.u_increment_m);
  out += fmt::format("LONG_SECTION_V_RIGHT     = {}\n", grid.v_m.front());
  out += fmt::format("LONG_SECTION_V_LEFT      = {}\n", grid.v_m.back());
  out += "$KD_DEFINITION\n";
  out += fmt::format("#:{}\n", format_name(format));
  out += fmt::format("U:reference line u,m,{},{}\n", grid.u_start_m, grid.u_increment_m);
  if (!grid.slope.empty()) out += "D:reference line slope,m/m\n";
  if (!grid.banking.empty()) out += "D:reference line banking,m/m\n";
  for (double v : grid.v_m) out += fmt::format("D:long section at v = {},m\n", v);
  out += "$\n";
  out += std::string(kCrgRecordBytes, '$') + "\n";

  const std::size_t per_record = values_per_record(format);
  std::vector<double> row;
  std::size_t written = 0;  // binary: values in the current data block
  for (std::size_t r = 0; r < rows; ++r) {
    row.clear();
    if (!grid.slope.empty()) row.push_back(grid.slope[r]);
    if (!grid.banking.empty()) row.push_back(grid.banking[r]);
    row.insert(row.end(), grid.z_m.begin() + static_cast<long>(r * n),
               grid.z_m.begin() + static_cast<long>((r + 1) * n));
    if (is_binary(format)) {
      for (double value : row) append_binary(out, value, format);
      written += row.size();
    } else {
      for (std::size_t k = 0; k < row.size(); ++k) {
        out += ascii_value(row[k], format);
        if ((k + 1) % per_record == 0 || k + 1 == row.size()) out += "\n";
      }
    }
  }
  if (is_binary(format)) {
    for (; written % per_record != 0; ++written) append_binary(out, kNaN, format);
  }

  io::write_atomically(path, [&](std::ostream& file) {
    file.write(out.data(), static_cast<std::streamsize>(out.size()));
  });
}

}  // namespace ridefit::road
