#pragma once

#include <Eigen/Core>
#include <Eigen/LU>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <unsupported/Eigen/AutoDiff>
#include <vector>

#include "ridefit/model/quarter_car.h"
#include "ridefit/road/road_input.h"
#include "ridefit/simulate/autodiff_parameters.h"

namespace ridefit::simulate {

// The quarter car's body and wheel acceleration at fixed output times, templated on the scalar
// so that Ceres' Jets carry their derivatives with respect to the model's parameters (the PSD
// fit). The stick/slip model is stiff (Dahl's σ0 beside the damper), so it is integrated with
// Alexander's two-stage, L-stable, second-order SDIRK (γ = 1 − 1/√2) at `steps_per_sample`
// steps per output interval: stiff components are damped as they physically are, the body and
// wheel modes keep their frequency to O((ωh)²). Both stages share G = I − γ·h·∂f/∂y, formed
// once per step (the Jacobian by forward-mode autodiff at the step's start) and used for a
// simplified Newton in doubles; each stage then takes one Newton step in T from its converged
// value, which carries the implicit-function derivative of the discrete scheme (as in
// strut_test_response.h). Starts at rest at static equilibrium.
//
// Returns no value when a stage's Newton iteration does not converge.
template <typename T>
struct AccelerationSeries {
  std::vector<T> body;   // body acceleration [m/s²] at each output time
  std::vector<T> wheel;  // wheel acceleration
};

template <typename T>
std::optional<AccelerationSeries<T>> quarter_car_accelerations(
    const model::QuarterCar& car, const model::QuarterCarParameters<T>& parameters,
    const model::QuarterCarParameters<double>& values, const road::RoadInput& road,
    std::span<const double> output_times_s, int steps_per_sample = 2) {
  using Gradient = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, model::QuarterCar::kMaxStates, 1>;
  using AutoDiff = Eigen::AutoDiffScalar<Gradient>;
  // Stack-allocated up to the model's 6 states: the inner loop must not touch the heap.
  using Vector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, model::QuarterCar::kMaxStates, 1>;
  using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0,
                               model::QuarterCar::kMaxStates, model::QuarterCar::kMaxStates>;
  const int n = car.state_size();
  const double gamma = 1.0 - std::sqrt(0.5);
  const model::QuarterCarParameters<AutoDiff> ad_values = autodiff_parameters<AutoDiff>(values, n);
  Vector y = Vector::Zero(n);
  std::vector<T> yt(static_cast<std::size_t>(n), T(0.0));
  AccelerationSeries<T> out;
  // Newton iterations and the Jacobian ask for the road at the same stage time again and again.
  double cached_time = std::numeric_limits<double>::quiet_NaN();
  road::RoadSample cached_road;
  auto road_at = [&](double t) {
    if (t != cached_time) {
      cached_road = road.at(t);
      cached_time = t;
    }
    return cached_road;
  };
  auto record = [&](double t) {
    std::vector<T> ydot(static_cast<std::size_t>(n));
    car.derivatives(yt.data(), road_at(t), parameters, ydot.data());
    out.body.push_back(ydot[2]);
    out.wheel.push_back(ydot[3]);
  };
  auto f_double = [&](double t, const Vector& state, Vector& rate) {
    rate.resize(n);
    car.derivatives(state.data(), road_at(t), values, rate.data());
  };
  auto jacobian = [&](double t, const Vector& state) {
    AutoDiff xa[model::QuarterCar::kMaxStates];
    AutoDiff fa[model::QuarterCar::kMaxStates];
    for (int i = 0; i < n; ++i) xa[i] = AutoDiff(state[i], n, i);
    car.derivatives(xa, road_at(t), ad_values, fa);
    Matrix j(n, n);
    for (int r = 0; r < n; ++r) {
      for (int c = 0; c < n; ++c) {
        j(r, c) = fa[r].derivatives().size() == n ? fa[r].derivatives()[c] : 0.0;
      }
    }
    return j;
  };
  const Vector scale = [&] {
    Vector s(n);
    for (int i = 0; i < n; ++i) s[i] = i < 2 ? 1e-6 : i < 4 ? 1e-5 : i == 4 ? 1e-7 : 1e-3;
    return s;
  }();
  // One SDIRK step from t0 over h; where Newton fails (a branch switch of the Dahl element
  // inside a step) the step is split in two, down to h/64.
  std::function<bool(double, double, int)> advance = [&](double t0, double h, int depth) -> bool {
    const auto attempt = [&]() -> bool {
      const Eigen::PartialPivLU<Matrix> lu(Matrix::Identity(n, n) - gamma * h * jacobian(t0, y));
      // Stage i solves Y = base + γh·f(t_i, Y); base_T is its Jet counterpart.
      auto solve_stage = [&](double t_stage, const Vector& base, const std::vector<T>& base_t,
                             Vector& stage, std::vector<T>& stage_t) {
        stage = base;
        Vector rate;
        bool converged = false;
        // Simplified Newton on the step's G; where the Dahl element switches branch G goes
        // stale, so after a few slow iterations it is re-formed at the current iterate.
        Eigen::PartialPivLU<Matrix> local = lu;
        for (int it = 0; it < 40; ++it) {
          if (it > 0 && it % 6 == 0) {
            local.compute(Matrix::Identity(n, n) - gamma * h * jacobian(t_stage, stage));
          }
          f_double(t_stage, stage, rate);
          const Vector residual = stage - base - gamma * h * rate;
          const Vector step = local.solve(residual);
          if (!step.allFinite()) return false;
          stage -= step;
          if ((step.array().abs() / (stage.array().abs() + scale.array())).maxCoeff() < 1e-9) {
            converged = true;
            break;
          }
        }
        if (!converged) return false;
        // One exact Newton step in T: G at the converged stage, residual in T.
        const Eigen::PartialPivLU<Matrix> exact(Matrix::Identity(n, n) -
                                                gamma * h * jacobian(t_stage, stage));
        const Matrix g_inverse = exact.inverse();
        std::vector<T> y_stage(static_cast<std::size_t>(n)), rate_t(static_cast<std::size_t>(n));
        for (int i = 0; i < n; ++i) y_stage[static_cast<std::size_t>(i)] = T(stage[i]);
        car.derivatives(y_stage.data(), road_at(t_stage), parameters, rate_t.data());
        std::vector<T> residual_t(static_cast<std::size_t>(n));
        for (int i = 0; i < n; ++i) {
          const auto u = static_cast<std::size_t>(i);
          residual_t[u] = y_stage[u] - base_t[u] - T(gamma * h) * rate_t[u];
        }
        stage_t.assign(static_cast<std::size_t>(n), T(0.0));
        for (int i = 0; i < n; ++i) {
          T correction(0.0);
          for (int j = 0; j < n; ++j) {
            correction += T(g_inverse(i, j)) * residual_t[static_cast<std::size_t>(j)];
          }
          stage_t[static_cast<std::size_t>(i)] = y_stage[static_cast<std::size_t>(i)] - correction;
        }
        return true;
      };
      Vector y1, y2;
      std::vector<T> y1_t, y2_t;
      if (!solve_stage(t0 + gamma * h, y, yt, y1, y1_t)) return false;
      // f(Y1) from the stage equation, exactly as the scheme defines it: (Y1 − y_n)/(γh).
      std::vector<T> k1_t(static_cast<std::size_t>(n));
      Vector k1(n);
      for (int i = 0; i < n; ++i) {
        const auto u = static_cast<std::size_t>(i);
        k1[i] = (y1[i] - y[i]) / (gamma * h);
        k1_t[u] = (y1_t[u] - yt[u]) / T(gamma * h);
      }
      Vector base2 = y + (1.0 - gamma) * h * k1;
      std::vector<T> base2_t(static_cast<std::size_t>(n));
      for (int i = 0; i < n; ++i) {
        const auto u = static_cast<std::size_t>(i);
        base2_t[u] = yt[u] + T((1.0 - gamma) * h) * k1_t[u];
      }
      if (!solve_stage(t0 + h, base2, base2_t, y2, y2_t)) return false;
      y = y2;
      yt = y2_t;
      return true;
    };
    const Vector y_saved = y;
    const std::vector<T> yt_saved = yt;
    if (attempt()) return true;
    y = y_saved;
    yt = yt_saved;
    if (depth >= 6) return false;
    return advance(t0, h / 2, depth + 1) && advance(t0 + h / 2, h / 2, depth + 1);
  };
  if (output_times_s.empty()) return out;
  record(output_times_s[0]);
  for (std::size_t k = 1; k < output_times_s.size(); ++k) {
    const double h_sample = (output_times_s[k] - output_times_s[k - 1]) / steps_per_sample;
    for (int s = 0; s < steps_per_sample; ++s) {
      if (!advance(output_times_s[k - 1] + s * h_sample, h_sample, 0)) return std::nullopt;
    }
    record(output_times_s[k]);
  }
  return out;
}

}  // namespace ridefit::simulate
