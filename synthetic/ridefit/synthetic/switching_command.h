#pragma once

#include <random>
#include <vector>

namespace ridefit::synthetic {

// A controlled damper's command (an MR damper's coil current, say) that switches at random
// between random levels in [0, top], each held 0.15–0.5 s, over [0, duration_s]. The edges are
// smooth (tanh, 2 ms) so that the reference integrator, which reads the command at every instant,
// sees a smooth input. Levels and switching times are drawn from `rng`: the first level, then
// per switch a hold time and the next level.
class SwitchingCommand {
 public:
  SwitchingCommand(double duration_s, double top, std::mt19937_64& rng);

  double operator()(double time_s) const;

  const std::vector<double>& switch_times_s() const { return switch_s_; }
  const std::vector<double>& levels() const { return level_; }

 private:
  std::vector<double> switch_s_;
  std::vector<double> level_;  // one more than switch_s_
};

}  // namespace ridefit::synthetic
