#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace ridefit::simulate {

// x' = A·x + B·u, y = C·x + D·u.
struct LinearStateSpace {
  Eigen::MatrixXd A, B, C, D;
  std::vector<std::string> input_names;
  std::vector<std::string> output_names;
};

}  // namespace ridefit::simulate
