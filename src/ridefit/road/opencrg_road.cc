#include "ridefit/road/opencrg_road.h"

#include <fmt/core.h>

#include <cmath>
#include <string>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/road/profile_road.h"

namespace ridefit::road {

SpatialProfileRoad make_opencrg_road(const CrgGrid& grid, const OpenCrgRoadParameters& parameters,
                                     const std::string& source) {
  const double v = parameters.lateral_offset_m;
  if (grid.v_m.empty() || !(v >= grid.v_m.front() && v <= grid.v_m.back())) {
    throw InputError(
        fmt::format("key 'lateral_offset_m' is {:g} m, outside the long sections of {}: expected "
                    "{:g} <= lateral_offset_m <= {:g} m (LONG_SECTION_V_RIGHT to _LEFT)",
                    v, source, grid.v_m.empty() ? std::nan("") : grid.v_m.front(),
                    grid.v_m.empty() ? std::nan("") : grid.v_m.back()));
  }
  const std::vector<double> elevation = crg_track(grid, v, source);
  std::vector<double> u(grid.rows());
  for (std::size_t r = 0; r < u.size(); ++r) u[r] = grid.u(r);
  ProfileRoadParameters p;
  p.speed_m_per_s = parameters.speed_m_per_s;
  p.offset_m = parameters.offset_m;
  try {
    return make_profile_road(u, elevation, p);
  } catch (const InputError& e) {
    const std::string message = e.what();
    if (message.starts_with("key")) throw;  // about a YAML key, not the file
    throw InputError(fmt::format("{}: {}", source, message));
  }
}

SpatialProfileRoad load_opencrg_road(const std::filesystem::path& crg_file,
                                     const OpenCrgRoadParameters& parameters) {
  return make_opencrg_road(read_opencrg(crg_file), parameters, crg_file.string());
}

}  // namespace ridefit::road
