#include "ridefit/fitting/friction_compression.h"

#include <fmt/core.h>

#include <Eigen/Dense>
#include <cmath>

#include "ridefit/common/errors.h"
#include "ridefit/fitting/hysteresis_fit.h"
#include "ridefit/model/quarter_car_parameter_table.h"

namespace ridefit::fitting {

FrictionCompressionLine fit_friction_compression(std::span<const double> compression_m,
                                                 std::span<const double> coulomb_force_N,
                                                 std::span<const double> standard_error_N) {
  const std::size_t n = compression_m.size();
  if (n < 2 || coulomb_force_N.size() != n ||
      (!standard_error_N.empty() && standard_error_N.size() != n)) {
    throw InputError(fmt::format(
        "friction against compression: {} compressions for {} friction values; give one "
        "compression per file, at least two",
        n, coulomb_force_N.size()));
  }
  Eigen::MatrixXd x(static_cast<Eigen::Index>(n), 2);
  Eigen::VectorXd y(static_cast<Eigen::Index>(n)), w(static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    if (!std::isfinite(compression_m[i]) || !std::isfinite(coulomb_force_N[i])) {
      throw InputError("friction against compression: a value is not finite");
    }
    double weight = 1.0;
    if (!standard_error_N.empty()) {
      if (!(standard_error_N[i] > 0.0)) {
        throw InputError(
            fmt::format("friction against compression: standard error {} of point {} must be > 0",
                        standard_error_N[i], i + 1));
      }
      weight = 1.0 / (standard_error_N[i] * standard_error_N[i]);
    }
    x(k, 0) = 1.0;
    x(k, 1) = compression_m[i];
    y(k) = coulomb_force_N[i];
    w(k) = weight;
  }
  if (!(x.col(1).maxCoeff() > x.col(1).minCoeff())) {
    throw InputError(
        "friction against compression: every file has the same compression; a slope needs two "
        "or more");
  }
  const Eigen::Matrix2d normal = x.transpose() * w.asDiagonal() * x;
  const Eigen::Vector2d beta = normal.ldlt().solve(x.transpose() * w.asDiagonal() * y);
  FrictionCompressionLine line;
  line.intercept_N = beta(0);
  line.slope_N_per_m = beta(1);
  if (n >= 3) {
    const Eigen::VectorXd residual = y - x * beta;
    const double chi2 = residual.dot(w.asDiagonal() * residual) / static_cast<double>(n - 2);
    const Eigen::Matrix2d covariance = chi2 * normal.inverse();
    line.intercept_se_N = std::sqrt(covariance(0, 0));
    line.slope_se_N_per_m = std::sqrt(covariance(1, 1));
  }
  return line;
}

FrictionCompressionLine fit_friction_compression(const HysteresisFitResult& fit,
                                                 std::span<const double> compression_m) {
  std::vector<double> friction_N, standard_error_N;
  for (const auto& p : fit.parameters) {
    if (p.name != model::quarter_car_rows::coulomb_force_N.key || p.file.empty()) continue;
    friction_N.push_back(p.value);
    if (p.standard_error) standard_error_N.push_back(*p.standard_error);
  }
  // Weighted only when every value has its error; one missing would misalign the weights.
  if (standard_error_N.size() != friction_N.size()) standard_error_N.clear();
  return fit_friction_compression(compression_m, friction_N, standard_error_N);
}

}  // namespace ridefit::fitting
