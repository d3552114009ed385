#pragma once

#include <ceres/iteration_callback.h>
#include <ceres/loss_function.h>
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <utility>

namespace ridefit::fitting {

// A fit of simulated to measured data cannot tell costs apart below the integrator's own scatter:
// the adaptive run's steps move with the parameters, so its residuals move by about its error
// from one evaluation to the next. Once the fit explains the data to that level, the trust
// region spent a dozen iterations rejecting steps that chase the scatter (on noise-free records:
// every recovery test and benchmark), or accepting and rejecting them at random (on noisy ones).
// This stop ends the fit there instead.
//
// The scatter is measured, not assumed: the residuals r at the current parameters at the fit's
// tolerance and r_c at four times it differ by a few times the fit's integration error e (the
// global error grows about in proportion to the tolerance: 4e − e), δ = |r − r_c|, measured at the
// start values and again wherever the stop would end the fit (the error depends on the
// parameters: a stiffer Dahl element than the truth's makes more of it). The fit stops,
// successfully, when, with δ measured at the current iterate,
//  - its cost is at most ½δ²: its residuals are within a few integration errors, the data
//    explained as well as the integration resolves (noise-free records); or
//  - two steps in a row are rejected whose decreases, as the trust region's model predicted them,
//    are below the cost's scatter ½δ² + |r|·δ/√N (the residuals' own size times the integration
//    error, averaged over N independent residuals): the scatter, not the model, decided the
//    steps (noisy records at their optimum). One such rejection is not enough: partway along a
//    flat valley the trust region may have shrunk to a step the scatter refuses, and the shorter
//    step after it is then accepted and the fit goes on. Where the fit can say what the whole
//    Gauss-Newton step promises (the gradient condition), that must be below the scatter too,
//    and, where it says how many values it fits, below what would move them by a fifth of their
//    standard errors: ½gᵀ(JᵀJ)⁻¹g < ½(0.2)²σ̂², σ̂² = 2·cost/(N − p). The scatter bounds what the
//    integration resolves in the cost; this bounds what the stop may leave of the parameters
//    (a noisy record's cost is flat to within the scatter across several standard errors).
// Far from the optimum the predicted decreases are orders of magnitude above that, so neither
// ends a fit early; Ceres' own tolerances still apply. Needs
// Solver::Options::update_state_every_iteration, so the parameter blocks hold the iterate.
inline double coarser_tolerance(double relative_tolerance) {
  return relative_tolerance * 4.0 < 0.1 ? relative_tolerance * 4.0 : 0.1;
}

// ½δ²: the cost of residuals at the integration's scatter, ½Σρ(δᵢ²) under the fit's robust loss
// ρ (null: none) so that it compares with the cost Ceres reports, which carries the loss: a
// Cauchy or Huber cost is below the plain one wherever residuals pass the loss's scale.
// `residuals` and `coarse_residuals` are the raw ones (no loss applied).
inline double integration_cost_floor(std::span<const double> residuals,
                                     std::span<const double> coarse_residuals,
                                     const ceres::LossFunction* loss = nullptr) {
  double cost = 0.0;
  for (std::size_t i = 0; i < residuals.size() && i < coarse_residuals.size(); ++i) {
    const double d = residuals[i] - coarse_residuals[i];
    double rho[3] = {d * d, 1.0, 0.0};
    if (loss != nullptr) loss->Evaluate(d * d, rho);
    cost += rho[0];
  }
  return 0.5 * cost;
}

class StopAtIntegrationResolution final : public ceres::IterationCallback {
 public:
  // `measure_floor()`: ½δ² at the parameter blocks' current values (0 when a run fails there).
  // `gauss_newton_decrease()` (may be empty): the decrease the full Gauss-Newton step promises
  // from the parameter blocks' current values, ½gᵀ(JᵀJ)⁻¹g (infinity when it cannot be
  // computed). The rejected-step condition ends a fit only when that promise too is below the
  // scatter: a trust region shrunk partway along a flat valley promises little for its own short
  // step while the whole step towards the valley's floor promises more.
  // `free_count` (0: not known): the values fitted, for the standard-error condition.
  StopAtIntegrationResolution(std::function<double()> measure_floor, std::size_t residual_count,
                              std::function<double()> gauss_newton_decrease = {},
                              std::size_t free_count = 0)
      : measure_(std::move(measure_floor)),
        gauss_newton_(std::move(gauss_newton_decrease)),
        count_(static_cast<double>(residual_count > 0 ? residual_count : 1)),
        free_(static_cast<double>(free_count)) {}

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    if (summary.iteration == 0 || summary.step_is_successful) ++iterate_;
    if (iterate_ == 1 && measured_at_ == 0) measure_here();
    if (!wants_to_stop(summary)) {
      refused_in_a_row_ = 0;
      return ceres::SOLVER_CONTINUE;
    }
    if (measured_at_ != iterate_) {
      measure_here();
      if (!wants_to_stop(summary)) {
        refused_in_a_row_ = 0;
        return ceres::SOLVER_CONTINUE;
      }
    }
    if (!summary.step_is_successful && summary.iteration > 0) {
      if (++refused_in_a_row_ < 2) return ceres::SOLVER_CONTINUE;
      if (gauss_newton_ && !(gauss_newton_() < std::min(scatter_, resolved(summary.cost)))) {
        refused_in_a_row_ = 0;
        return ceres::SOLVER_CONTINUE;
      }
    }
    reached_ = true;
    return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
  }

  bool reached() const { return reached_; }
  double floor() const { return floor_; }

 private:
  // The decrease of a step that moves the values by a fifth of their standard errors.
  double resolved(double cost) const {
    if (!(free_ > 0.0) || !(count_ > free_)) return std::numeric_limits<double>::infinity();
    constexpr double kFractionOfStandardError = 0.2;
    const double variance = 2.0 * std::abs(cost) / (count_ - free_);
    return 0.5 * kFractionOfStandardError * kFractionOfStandardError * variance;
  }

  void measure_here() {
    floor_ = measure_();
    measured_at_ = iterate_;
  }

  bool wants_to_stop(const ceres::IterationSummary& summary) {
    if (!(floor_ > 0.0)) return false;
    const bool accepted = summary.iteration == 0 || summary.step_is_successful;
    if (accepted && summary.cost <= floor_) return true;
    // A trial point the model could not be solved at (Ceres marks it invalid, its cost the
    // largest double) says nothing about the scatter.
    if (summary.iteration == 0 || !summary.step_is_valid || summary.relative_decrease == 0.0 ||
        !(std::abs(summary.cost) < 1e300)) {
      return false;
    }
    // Only a rejected step: one the model promised little for and the scatter then refused.
    // Small accepted steps are progress along a flat valley (a damper knee traded against the
    // damping below it), which the fit must be allowed to follow.
    if (summary.step_is_successful) return false;
    const double predicted = std::abs(summary.cost_change / summary.relative_decrease);
    scatter_ = floor_ + std::sqrt(2.0 * std::abs(summary.cost)) * std::sqrt(2.0 * floor_ / count_);
    return std::isfinite(predicted) && predicted < scatter_;
  }

  std::function<double()> measure_;
  std::function<double()> gauss_newton_;
  double count_;
  double free_;           // values fitted (0: not known)
  double scatter_ = 0.0;  // the cost's scatter at the last rejected step
  double floor_ = 0.0;
  long iterate_ = 0;          // accepted iterates so far (the start is the first)
  long measured_at_ = 0;      // the iterate floor_ was measured at
  int refused_in_a_row_ = 0;  // consecutive rejections the scatter decided
  bool reached_ = false;
};

// The termination text a fit reports when the stop ended it.
inline std::string integration_resolution_message(double cost_floor) {
  return fmt::format(
      "Converged to the integrator's resolution (cost scatter {:.3g} from the integration "
      "error; lower the relative tolerance to resolve further)",
      cost_floor);
}

}  // namespace ridefit::fitting
