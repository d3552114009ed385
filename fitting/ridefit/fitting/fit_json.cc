#include "ridefit/fitting/fit_json.h"

#include <vector>

namespace ridefit::fitting {

nlohmann::json correlation_json(const Eigen::MatrixXd& correlation) {
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index a = 0; a < correlation.rows(); ++a) {
    std::vector<double> row;
    for (Eigen::Index b = 0; b < correlation.cols(); ++b) row.push_back(correlation(a, b));
    rows.push_back(row);
  }
  return rows;
}

nlohmann::json number_or_null(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json();
}

}  // namespace ridefit::fitting
