#include "ridefit/fitting/robust_loss.h"

#include <fmt/core.h>

#include "ridefit/common/errors.h"

namespace ridefit::fitting {

RobustLoss parse_robust_loss(std::string_view text) {
  if (text == "none") return RobustLoss::kNone;
  if (text == "huber") return RobustLoss::kHuber;
  if (text == "cauchy") return RobustLoss::kCauchy;
  throw InputError(fmt::format("loss '{}': expected one of none, huber, cauchy", text));
}

std::string_view to_string(RobustLoss loss) {
  switch (loss) {
    case RobustLoss::kHuber:
      return "huber";
    case RobustLoss::kCauchy:
      return "cauchy";
    case RobustLoss::kNone:
      break;
  }
  return "none";
}

ceres::LossFunction* make_loss_function(RobustLoss loss, double scale) {
  switch (loss) {
    case RobustLoss::kHuber:
      return new ceres::HuberLoss(scale);
    case RobustLoss::kCauchy:
      return new ceres::CauchyLoss(scale);
    case RobustLoss::kNone:
      break;
  }
  return nullptr;
}

}  // namespace ridefit::fitting
