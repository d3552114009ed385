#include "ridefit/road/opencrg_file.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "ridefit/common/errors.h"

namespace ridefit::road {

std::vector<double> crg_track(const CrgGrid& grid, double v_m, const std::string& source) {
  const std::vector<double>& v = grid.v_m;
  if (v.empty() || !(v_m >= v.front() && v_m <= v.back())) {
    throw InputError(fmt::format(
        "{}: lateral position v = {:g} m is outside the long sections, "
        "v from {:g} to {:g} m",
        source, v_m, v.empty() ? std::nan("") : v.front(), v.empty() ? std::nan("") : v.back()));
  }
  std::size_t j = 0;
  while (j + 1 < v.size() && v[j + 1] <= v_m) ++j;
  const std::size_t k = std::min(j + 1, v.size() - 1);
  const double w = k == j ? 0.0 : (v_m - v[j]) / (v[k] - v[j]);
  const std::size_t rows = grid.rows();

  const auto filled = [&](std::size_t column) {
    std::vector<double> z(rows);
    for (std::size_t r = 0; r < rows; ++r) z[r] = grid.z(r, column);
    std::size_t previous = rows;  // the last valid row so far (rows: none)
    for (std::size_t r = 0; r < rows; ++r) {
      if (std::isnan(z[r])) continue;
      if (previous == rows) {
        std::fill(z.begin(), z.begin() + static_cast<long>(r), z[r]);  // hold the first
      } else {
        for (std::size_t m = previous + 1; m < r; ++m) {
          const double a = static_cast<double>(m - previous) / static_cast<double>(r - previous);
          z[m] = (1.0 - a) * z[previous] + a * z[r];
        }
      }
      previous = r;
    }
    if (previous == rows) {
      throw InputError(
          fmt::format("{}: long section {} (v = {:g} m) has no valid elevation: all "
                      "{} values from u = {:g} to {:g} m are missing",
                      source, column + 1, v[column], rows, grid.u(0), grid.u(rows - 1)));
    }
    std::fill(z.begin() + static_cast<long>(previous) + 1, z.end(), z[previous]);  // hold the last
    return z;
  };

  std::vector<double> track = filled(w < 1.0 ? j : k);
  if (w > 0.0 && w < 1.0) {
    const std::vector<double> right = filled(k);
    for (std::size_t r = 0; r < rows; ++r) track[r] = (1.0 - w) * track[r] + w * right[r];
  }
  return track;
}

}  // namespace ridefit::road
