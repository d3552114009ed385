#pragma once

#include <ceres/loss_function.h>

#include <string>
#include <string_view>

namespace ridefit::fitting {

// A fit's robust loss on its residuals: none (plain least squares), Huber (quadratic near zero,
// linear beyond the scale) or Cauchy (logarithmic beyond it, for heavier outliers).
enum class RobustLoss { kNone, kHuber, kCauchy };

// "none" | "huber" | "cauchy"; InputError listing them for anything else.
RobustLoss parse_robust_loss(std::string_view text);
std::string_view to_string(RobustLoss loss);

// The Ceres loss for `loss` at `scale` (in the residuals' units), or nullptr for kNone. The
// caller hands it to a ceres::Problem, which takes ownership.
ceres::LossFunction* make_loss_function(RobustLoss loss, double scale);

}  // namespace ridefit::fitting
