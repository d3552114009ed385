#include "ridefit/road/international_roughness_index.h"

#include <fmt/core.h>

#include <Eigen/Dense>
#include <unsupported/Eigen/MatrixFunctions>

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "ridefit/common/errors.h"

namespace ridefit::road {
namespace {

constexpr double kInitialSlopeLength_m = 11.0;

// The continuous system in the slope domain: states (z_s', z_s'', z_u', z_u'') (the slope
// profile drives the car, so each state is the elevation form's derivative), input the
// profile slope; returns the exact step for a slope held over dt: x+ = Φx + Γs.
struct Transition {
  Eigen::Matrix4d phi;
  Eigen::Vector4d gamma;
};

Transition transition(const GoldenQuarterCar& car, double dt) {
  const double k1 = car.tyre_stiffness;
  const double k2 = car.suspension_stiffness;
  const double c = car.damping;
  const double mu = car.unsprung_mass_ratio;
  Eigen::Matrix<double, 5, 5> augmented = Eigen::Matrix<double, 5, 5>::Zero();
  augmented.block<4, 4>(0, 0) << 0.0, 1.0, 0.0, 0.0,  //
      -k2, -c, k2, c,                                 //
      0.0, 0.0, 0.0, 1.0,                             //
      k2 / mu, c / mu, -(k1 + k2) / mu, -c / mu;
  augmented(3, 4) = k1 / mu;
  const Eigen::Matrix<double, 5, 5> step = (augmented * dt).exp();
  return {step.block<4, 4>(0, 0), step.block<4, 1>(0, 4)};
}

// The spacing to simulate: the input's own if uniform and dividing the base, else the largest
// divisor 0.25/m of the base not above the median spacing.
struct SimulationGrid {
  double spacing_m = 0.0;
  bool resample = true;
};

SimulationGrid simulation_grid(const RoadProfile& profile, double base_m) {
  const double spacing = nominal_spacing_m(profile);
  const double ratio = base_m / spacing;
  const double nearest = std::round(ratio);
  if (nearest >= 1.0 && std::abs(ratio - nearest) <= 1e-6 * ratio && is_uniform(profile, spacing)) {
    return {spacing, false};
  }
  return {base_m / std::max(1.0, std::ceil(ratio - 1e-6)), true};
}

}  // namespace

InternationalRoughnessIndex international_roughness_index(const RoadProfile& profile,
                                                          const IriOptions& options) {
  check_road_profile(profile, 2);
  if (!std::isfinite(options.segment_length_m) || !(options.segment_length_m > 0.0)) {
    throw InputError(fmt::format("IRI: segment length {} m is invalid; expected > 0 m",
                                 options.segment_length_m));
  }
  if (!std::isfinite(options.moving_average_m) || !(options.moving_average_m > 0.0)) {
    throw InputError(fmt::format("IRI: moving-average length {} m is invalid; expected > 0 m",
                                 options.moving_average_m));
  }
  const double length = profile_length_m(profile);
  const double needed = std::max(options.segment_length_m, kInitialSlopeLength_m);
  if (length < needed - 1e-9) {
    throw InputError(fmt::format(
        "IRI: the profile is {} m long, shorter than {} m (one segment of {} m, and the 11 m "
        "the standard's initial slope needs)",
        length, needed, options.segment_length_m));
  }

  const SimulationGrid plan = simulation_grid(profile, options.moving_average_m);
  const double dx = plan.spacing_m;
  const RoadProfile grid = plan.resample ? uniform(profile, dx) : profile;
  const std::vector<double>& y = grid.elevation_m;
  const auto base =
      static_cast<std::size_t>(std::max(1.0, std::round(options.moving_average_m / dx)));
  if (y.size() <= base + 1) {
    throw InputError(
        fmt::format("IRI: the profile has too few samples ({}) at {} m spacing", y.size(), dx));
  }
  const std::size_t slopes = y.size() - base;
  const double base_length = static_cast<double>(base) * dx;

  const GoldenQuarterCar car;
  const Transition step = transition(car, dx / car.speed_m_per_s);
  const double x0 = grid.distance_m.front();
  const double initial_slope =
      (elevation_at(grid, x0 + kInitialSlopeLength_m) - y.front()) / kInitialSlopeLength_m;
  Eigen::Vector4d state(initial_slope, 0.0, initial_slope, 0.0);

  // Slope i is held over [x_i, x_{i+1}]; its |z_s' − z_u'| at the step's end belongs to the
  // segment holding the step's midpoint.
  const double segment = options.segment_length_m;
  const auto full_segments = static_cast<std::size_t>(std::floor(length / segment + 1e-9));
  const double remainder = length - static_cast<double>(full_segments) * segment;
  const bool keep_partial = remainder >= 0.5 * segment;
  const std::size_t segment_count = full_segments + (keep_partial ? 1 : 0);
  std::vector<double> sums(segment_count, 0.0);
  std::vector<std::size_t> counts(segment_count, 0);
  double total = 0.0;
  for (std::size_t i = 0; i < slopes; ++i) {
    const double s = (y[i + base] - y[i]) / base_length;
    state = step.phi * state + step.gamma * s;
    const double rate = std::abs(state(0) - state(2));
    total += rate;
    const double middle = (static_cast<double>(i) + 0.5) * dx;
    auto index = static_cast<std::size_t>(middle / segment);
    if (index >= segment_count) index = segment_count - 1;  // a short tail joins the last
    sums[index] += rate;
    ++counts[index];
  }

  InternationalRoughnessIndex result;
  result.spacing_m = dx;
  result.iri_m_per_km = 1000.0 * total / static_cast<double>(slopes);
  for (std::size_t k = 0; k < segment_count; ++k) {
    IriSegment out;
    out.start_m = static_cast<double>(k) * segment;
    out.end_m = k + 1 == segment_count ? length : out.start_m + segment;
    out.iri_m_per_km = counts[k] > 0 ? 1000.0 * sums[k] / static_cast<double>(counts[k]) : 0.0;
    result.segments.push_back(out);
  }
  return result;
}

}  // namespace ridefit::road
