#include "ridefit/synthetic/switching_command.h"

#include <cmath>

namespace ridefit::synthetic {

namespace {
constexpr double kEdge_s = 0.002;
}  // namespace

SwitchingCommand::SwitchingCommand(double duration_s, double top, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> hold(0.15, 0.5), value(0.0, top);
  level_.push_back(value(rng));
  for (double t = hold(rng); t < duration_s; t += hold(rng)) {
    switch_s_.push_back(t);
    level_.push_back(value(rng));
  }
}

double SwitchingCommand::operator()(double time_s) const {
  double u = level_[0];
  for (std::size_t i = 0; i < switch_s_.size(); ++i) {
    u += 0.5 * (level_[i + 1] - level_[i]) * (1.0 + std::tanh((time_s - switch_s_[i]) / kEdge_s));
  }
  return u;
}

}  // namespace ridefit::synthetic
