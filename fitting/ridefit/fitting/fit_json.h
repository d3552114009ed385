#pragma once

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <optional>

namespace ridefit::fitting {

// The JSON pieces every fit's summary shares (fit hysteresis, fit psd, diagnose).

// A correlation matrix as rows of numbers (an empty array when it could not be computed).
nlohmann::json correlation_json(const Eigen::MatrixXd& correlation);

// A value that may be missing (a standard error the data cannot determine): null then.
nlohmann::json number_or_null(const std::optional<double>& value);

}  // namespace ridefit::fitting
