#include "ridefit/simulate/esdirk_integrator.h"

#include <fmt/core.h>

#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

#include "ridefit/common/errors.h"

namespace ridefit::simulate {
namespace {

using Tableau = EsdirkTableau;
constexpr int kS = Tableau::kStages;
constexpr double kGamma = Tableau::kGamma;

// Newton stops when its estimated remaining error is this share of the error tolerance.
constexpr double kNewtonShare = 0.05;
constexpr double kNewtonShareRecorded = 1e-5;
constexpr int kMaxNewtonIterations = 7;
constexpr int kJacobianAge = 50;         // steps a Jacobian may serve before it is refreshed
constexpr long kMinStepsPerOutput = 40;  // the step limit's floor per output interval
// A root in the first share of a step is left to the error control: a kink that close to the
// step's start costs little accuracy, and shortening to it would only add a tiny step.
constexpr double kEventMinShare = 0.05;
// A located or predicted kink ends the step this share of it past the root, so the next step
// starts on the new branch (its Jacobian then has the right slopes) and no stage sits on the
// kink itself, where the computed map would not be differentiable in the parameters.
constexpr double kEventOvershoot = 2e-2;

// N: the state size at compile time (the quarter car's 4–6 states, the strut's 2), or
// Eigen::Dynamic up to 24 (the half car): fixed sizes let Eigen unroll the small linear algebra.
template <int N>
class EsdirkSolver {
 public:
  static constexpr int kMax = N == Eigen::Dynamic ? 24 : N;
  using Vector = Eigen::Matrix<double, N, 1, 0, kMax, 1>;
  using Matrix = Eigen::Matrix<double, N, N, 0, kMax, kMax>;
  using Switching =
      Eigen::Matrix<double, Eigen::Dynamic, 1, 0, OdeSystem::kMaxSwitchingFunctions, 1>;

  EsdirkSolver(const OdeSystem& system, const IntegratorOptions& options)
      : system_(system), options_(options), n_(system.size()), lu_(n_), g_inverse_(n_, n_) {
    rtol_ = options.relative_tolerance;
    atol_.resize(n_);
    for (int i = 0; i < n_; ++i) atol_[i] = rtol_ * system.typical_magnitude(i);
    J_.resize(n_, n_);
    g_count_ = std::min(system.switching_count(), OdeSystem::kMaxSwitchingFunctions);
  }

  void run(const std::vector<double>& times, Trajectory& trajectory, EsdirkStepHistory* history,
           const EsdirkStepHistory* frozen) {
    auto& stats = trajectory.statistics;
    double t = times.front();
    const double t_end = times.back();
    Vector y = Eigen::Map<const Vector>(trajectory.states.data(), n_);
    Vector k[kS];
    for (auto& ki : k) ki.resize(n_);
    if (!rhs(t, y, k[0], stats)) {
      throw RunError(fmt::format("ESDIRK: the right-hand side is not finite at t = {:.6g} s", t));
    }
    double max_step = options_.max_step_s;
    if (system_.max_step_s() > 0.0 && (max_step <= 0.0 || system_.max_step_s() < max_step)) {
      max_step = system_.max_step_s();
    }
    if (max_step <= 0.0) max_step = t_end - t;
    const double span = t_end - t;
    // The limit per second, but never below kMinStepsPerOutput per output interval: a record
    // sampled at 1 kHz with content up to 50 Hz needs 15-20 steps per sample at rtol 1e-6 (the
    // NEES MR random test: 217 000 steps in 12.3 s, 0.16 s of work), which a limit per second
    // alone would refuse.
    const long max_steps =
        std::max({1000L, static_cast<long>(std::ceil(options_.max_steps_per_s * span)),
                  kMinStepsPerOutput * static_cast<long>(times.size() > 1 ? times.size() - 1 : 1)});
    // Hairer's first guess from the state's and the rate's size; the controller does the rest.
    Vector w = weights(y, y);
    const double d0 = norm(y, w), d1 = norm(k[0], w);
    double h = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
    h = std::min({h, max_step, span});
    const double h_min = 1e-12 * std::max(1.0, std::abs(t_end));

    Switching g_start(g_count_), g_end(g_count_);
    if (g_count_ > 0) system_.switching(t, y.data(), g_start.data());

    std::size_t next_output = 1;
    double error_previous = 1e-4;  // the PI controller's memory
    bool rejected_last = false;
    Vector y_new(n_), z(n_), base(n_), error(n_), residual(n_), dz(n_);
    // A recorded run's stages are the points its tangents are taken at (esdirk_tangents.h):
    // converged further, so that the tangent is that of the stage's solution.
    const double newton_share = history != nullptr ? kNewtonShareRecorded : kNewtonShare;
    // The last accepted step's start, for predictions (read only once h_previous > 0).
    Vector y_previous = Vector::Zero(n_), f_previous = Vector::Zero(n_);
    double h_previous = 0.0;
    long accepted = 0;

    while (t < t_end) {
      if (accepted + stats.error_test_failures + stats.nonlinear_convergence_failures > max_steps) {
        throw RunError(fmt::format(
            "ESDIRK failed at t = {:.6g} s: too many steps ({}): the solution varies faster "
            "than the tolerance can follow",
            t, max_steps));
      }
      h = std::min(h, max_step);
      bool last = false;
      if (t + h >= t_end - 1e-12 * std::abs(t_end)) {
        h = t_end - t;
        last = true;
      }
      // An input's kink at the next output time: end the step there (no sliver left behind).
      bool lands = false;
      if (options_.steps_end_on_outputs && frozen == nullptr && !last &&
          next_output + 1 < times.size()) {
        const double gap = times[next_output] - t;
        if (h >= gap) {
          h = gap;
          lands = true;
        } else if (h > 0.7 * gap) {
          h = 0.5 * gap;
        }
      }
      if (frozen != nullptr) {  // the given steps, Newton converged fully, no error control
        if (static_cast<std::size_t>(accepted) >= frozen->step_count()) {
          throw RunError("ESDIRK: the frozen step sequence ends before the last output time");
        }
        h = frozen->length_s[static_cast<std::size_t>(accepted)];
        last = static_cast<std::size_t>(accepted) + 1 == frozen->step_count();
        refresh_jacobian(t, y, stats);
        factor(h);
      }
      bool event_shortened = false;
      int refreshes = 0;  // Jacobians taken anew for this step after Newton failed
      // A kink ahead, predicted on the last step's interpolant continued: a step across one
      // rarely converges (Newton cycles between the two slopes), so end this one there.
      if (g_count_ > 0 && h_previous > 0.0 && frozen == nullptr) {
        const double share =
            predicted_root(t, h, h_previous, y_previous, y, f_previous, k[0], g_start);
        if (share >= kEventMinShare && share * (1.0 + kEventOvershoot) < 1.0) {
          h *= share * (1.0 + kEventOvershoot);
          last = false;
          lands = false;
        }
      }
      // Attempt steps from t until one is accepted.
      for (;;) {
        if (h < h_min) {
          throw RunError(fmt::format(
              "ESDIRK failed at t = {:.6g} s: the step fell below {:.3g} s ({})", t, h_min,
              stats.nonlinear_convergence_failures > 0
                  ? "Newton does not converge: check the model for extreme parameter values"
                  : "the error test keeps failing"));
        }
        if (jacobian_age_ >= kJacobianAge || !have_jacobian_) refresh_jacobian(t, y, stats);
        if (!lu_valid_ || std::abs(h / h_lu_ - 1.0) > 0.2) factor(h);
        // Stages 2..s: Z_i = y + h·Σ_{j<i} a_ij k_j + γh·f(t + c_i h, Z_i).
        bool converged = true;
        double worst_rate = 0.0;
        for (int i = 1; i < kS && converged; ++i) {
          base = y;
          for (int j = 0; j < i; ++j) base += (h * Tableau::a[i][j]) * k[j];
          // Predictor: the previous stage continued with its slope.
          z = i == 1 ? Vector(y + (Tableau::c[1] * h) * k[0])
                     : Vector(base + (kGamma * h) * k[i - 1]);
          const double t_stage = t + Tableau::c[i] * h;
          // The first iterate counts as converged only when its update is already that small: a
          // rate remembered from the last step misjudged stiff stretches where J moves fast (the
          // Dahl exponent's |s|^(d−1) near s = 0), and the run drifted by tens of newtons.
          double eta = 1.0;
          double previous_norm = 0.0;
          converged = false;
          // A recorded run's stage that reached the ordinary accuracy (kNewtonShare) and then
          // stalls short of the recorded one (a free play's dead zone, a Baumgarte pull: J moves
          // within the step) is polished by full Newton below, where the system asks for it and
          // the stage lies on the step's side of every kink: failing it shrank the step until
          // the run gave up (a 25 mm MR test at 230 000 steps), and keeping it unpolished left
          // the tangents off by up to 1 % (the tangent is that of the stage's solution). On
          // other systems (a Stribeck strut) polished stages made the tangents worse than
          // shrinking the step: there a stall marks a step too long for its nonlinearity.
          bool ordinary_accuracy = false;
          for (int it = 0; it < (frozen == nullptr ? kMaxNewtonIterations : 50); ++it) {
            if (frozen != nullptr && it > 0) {  // full Newton: J at the iterate
              refresh_jacobian(t_stage, z, stats);
              factor(h);
            }
            if (!rhs(t_stage, z, residual, stats)) break;
            residual = z - base - (kGamma * h) * residual;
            // The stage equation's own residual must be within the tolerance too: with a stale
            // G (the Dahl element's Jacobian changes by orders of magnitude between sticking and
            // sliding) G⁻¹·r can be tiny while r is not, and the run accepted stages off by
            // newtons.
            const double residual_norm = norm(residual, w);
            dz = solve(residual);
            z -= dz;
            const double dz_norm = norm(dz, w);
            if (!std::isfinite(dz_norm)) break;
            if (it > 0) {
              const double rate = dz_norm / previous_norm;
              worst_rate = std::max(worst_rate, rate);
              if (rate >= 0.9 && frozen == nullptr) break;
              eta = rate / (1.0 - rate);
            }
            if (!ordinary_accuracy && eta * dz_norm <= kNewtonShare && residual_norm <= 1.0) {
              ordinary_accuracy = true;
              z_ordinary_ = z;
            }
            // Frozen steps: converged to round-off (1e-9 of the tolerance, or the iteration
            // stalls below 1e-5 of it).
            const bool frozen_done =
                frozen != nullptr &&
                (dz_norm < 1e-9 || (it > 2 && dz_norm < 1e-5 && dz_norm >= 0.5 * previous_norm));
            if ((frozen == nullptr && eta * dz_norm <= newton_share && residual_norm <= 1.0) ||
                frozen_done || dz_norm == 0.0) {
              converged = true;
              break;
            }
            previous_norm = dz_norm;
          }
          if (!converged && history != nullptr && frozen == nullptr && ordinary_accuracy &&
              system_.polishes_recorded_stages() &&
              !straddles_kink(t_stage, z_ordinary_, g_start)) {
            z = z_ordinary_;
            converged = polish_stage(t_stage, h, base, z, w, stats);
          }
          if (converged) {
            k[i] = (z - base) / (kGamma * h);
            if (i == kS - 1) y_new = z;
            if (history != nullptr) stage_buffer_[i - 1] = z;
          }
        }
        if (!converged) {
          ++stats.nonlinear_convergence_failures;
          if (frozen != nullptr) {
            throw RunError(
                fmt::format("ESDIRK: Newton failed on a frozen step at t = {:.6g} s", t));
          }
          // A stale Jacobian, or one from the other side of a kink (the Dahl law's slope in v
          // jumps at a reversal): take it anew where Newton went, and try the step again.
          if (refreshes < 2) {
            ++refreshes;
            refresh_jacobian(t, z.allFinite() ? z : y, stats);
            factor(h);
          } else {
            refreshes = 0;
            h *= 0.25;
            last = false;
            lands = false;
          }
          continue;
        }
        // Events: end the step on the first kink inside it.
        if (g_count_ > 0 && frozen == nullptr) {
          system_.switching(t + h, y_new.data(), g_end.data());
          if (!event_shortened) {
            const double share = first_root(t, h, g_start, g_end, [&](double m) {
              return hermite(m, h, y, y_new, k[0], k[kS - 1]);
            });
            if (share >= kEventMinShare && share * (1.0 + kEventOvershoot) < 1.0) {
              h *= share * (1.0 + kEventOvershoot);
              last = false;
              lands = false;
              event_shortened = true;
              ++stats.events;
              continue;
            }
          }
        }
        // The embedded error, filtered through G for the stiff components.
        error.setZero();
        for (int j = 0; j < kS; ++j)
          error += (h * (Tableau::a[kS - 1][j] - Tableau::b_embedded[j])) * k[j];
        error = solve(error);
        w = weights(y, y_new);
        const double error_norm = std::max(norm(error, w), 1e-10);
        if (frozen == nullptr && (!std::isfinite(error_norm) || error_norm > 1.0)) {
          ++stats.error_test_failures;
          const double shrink = std::isfinite(error_norm)
                                    ? std::max(0.2, 0.9 * std::pow(error_norm, -1.0 / 3.0))
                                    : 0.2;
          h *= shrink;
          last = false;
          lands = false;
          event_shortened = false;
          rejected_last = true;
          continue;
        }
        // Accepted.
        if (history != nullptr) {
          history->start_s.push_back(t);
          history->length_s.push_back(h);
          for (int i = 0; i < kS - 1; ++i) {
            history->stages.insert(history->stages.end(), stage_buffer_[i].data(),
                                   stage_buffer_[i].data() + n_);
          }
        }
        const double t_new = last ? t_end : lands ? times[next_output] : t + h;
        while (next_output < times.size() && times[next_output] <= t_new) {
          const double theta = (times[next_output] - t) / h;
          double* out = trajectory.states.data() + next_output * static_cast<std::size_t>(n_);
          Eigen::Map<Vector>(out, n_) = hermite(theta, h, y, y_new, k[0], k[kS - 1]);
          if (options_.progress) options_.progress(times[next_output]);
          ++next_output;
        }
        ++accepted;
        ++jacobian_age_;
        if (worst_rate > 0.5) have_jacobian_ = false;  // slow Newton: refresh next step
        y_previous = y;
        f_previous = k[0];
        h_previous = t_new - t;
        t = t_new;
        y = y_new;
        k[0] = k[kS - 1];  // stiffly accurate: f at the step's end is its last stage's slope
        if (g_count_ > 0) g_start = g_end;
        double grow = 0.9 * std::pow(error_norm, -0.7 / 3.0) * std::pow(error_previous, 0.4 / 3.0);
        grow = std::clamp(grow, 0.2, 5.0);
        if (rejected_last) grow = std::min(grow, 1.0);
        error_previous = error_norm;
        rejected_last = false;
        h *= grow;
        break;
      }
    }
    stats.steps = accepted;
  }

 private:
  // Full Newton (the Jacobian at every iterate) on the stage equation z − base − γh·f(t, z) = 0
  // from z, to round-off as a frozen step's replay converges (1e-9 of the tolerance, or stalled
  // below 1e-5 of it); false when it gets neither in 20 iterations. Leaves the fresh Jacobian
  // factored.
  bool polish_stage(double t, double h, const Vector& base, Vector& z, const Vector& w,
                    SolverStatistics& stats) {
    Vector f(n_), dz(n_);
    double previous_norm = 0.0;
    for (int it = 0; it < 20; ++it) {
      refresh_jacobian(t, z, stats);
      factor(h);
      if (!rhs(t, z, f, stats)) return false;
      f = z - base - (kGamma * h) * f;
      dz = solve(f);
      z -= dz;
      const double dz_norm = norm(dz, w);
      if (!std::isfinite(dz_norm)) return false;
      if (dz_norm < 1e-9 || (it > 2 && dz_norm < 1e-5 && dz_norm >= 0.5 * previous_norm)) {
        return true;
      }
      previous_norm = dz_norm;
    }
    return false;
  }

  // Whether a switching function has another sign at (t, z) than in `g_start`.
  bool straddles_kink(double t, const Vector& z, const Switching& g_start) const {
    if (g_count_ == 0) return false;
    Switching g(g_count_);
    system_.switching(t, z.data(), g.data());
    for (int j = 0; j < g_count_; ++j) {
      if ((g[j] < 0.0) != (g_start[j] < 0.0)) return true;
    }
    return false;
  }

  bool rhs(double t, const Vector& y, Vector& f, SolverStatistics& stats) const {
    ++stats.rhs_evaluations;
    f.resize(n_);
    return system_.derivatives(t, y.data(), f.data());
  }

  template <typename State>
  void refresh_jacobian(double t, const State& y, SolverStatistics& stats) {
    ++stats.jacobian_evaluations;
    if (!system_.jacobian(t, y.data(), J_.data())) {
      throw RunError(fmt::format("ESDIRK: the Jacobian is not finite at t = {:.6g} s", t));
    }
    have_jacobian_ = true;
    jacobian_age_ = 0;
    lu_valid_ = false;
  }

  void factor(double h) {
    lu_.compute(Matrix::Identity(n_, n_) - (kGamma * h) * J_);
    if constexpr (N != Eigen::Dynamic) g_inverse_ = lu_.inverse();
    h_lu_ = h;
    lu_valid_ = true;
  }

  // G⁻¹·v: an explicit inverse for the small fixed sizes (a matrix-vector product per Newton
  // iteration is cheaper than two triangular solves), the LU otherwise.
  Vector solve(const Vector& v) const {
    if constexpr (N != Eigen::Dynamic) {
      return g_inverse_ * v;
    } else {
      return lu_.solve(v);
    }
  }

  Vector weights(const Vector& a, const Vector& b) const {
    Vector w(n_);
    for (int i = 0; i < n_; ++i) {
      w[i] = 1.0 / (rtol_ * std::max(std::abs(a[i]), std::abs(b[i])) + atol_[i]);
    }
    return w;
  }

  double norm(const Vector& v, const Vector& w) const {
    return std::sqrt((v.cwiseProduct(w)).squaredNorm() / n_);
  }

  Vector hermite(double theta, double h, const Vector& y0, const Vector& y1, const Vector& f0,
                 const Vector& f1) const {
    const double t2 = theta * theta, t3 = t2 * theta;
    return (2 * t3 - 3 * t2 + 1) * y0 + ((t3 - 2 * t2 + theta) * h) * f0 + (-2 * t3 + 3 * t2) * y1 +
           ((t3 - t2) * h) * f1;
  }

  // The share of a step of length h from t at which the first switching function changes sign,
  // predicted on the last step's interpolant (from t − h_previous) continued; 1 for none.
  double predicted_root(double t, double h, double h_previous, const Vector& y_previous,
                        const Vector& y, const Vector& f_previous, const Vector& f,
                        const Switching& g0) const {
    const double reach = h / h_previous;
    auto state_at = [&](double share) {
      return hermite(1.0 + share * reach, h_previous, y_previous, y, f_previous, f);
    };
    Switching g1(g_count_);
    const Vector y1 = state_at(1.0);
    system_.switching(t + h, y1.data(), g1.data());
    return first_root(t, h, g0, g1, state_at);
  }

  // The share of the step at which the first switching function changes sign (1 when none
  // does), by the Illinois method on the states `state_at(share)`.
  template <typename StateAt>
  double first_root(double t, double h, const Switching& g0, const Switching& g1,
                    StateAt&& state_at) const {
    double first = 1.0;
    Switching g(g_count_);
    for (int j = 0; j < g_count_; ++j) {
      if ((g0[j] < 0.0) == (g1[j] < 0.0)) continue;
      double a = 0.0, b = 1.0, ga = g0[j], gb = g1[j];
      int side = 0;
      for (int it = 0; it < 40 && b - a > 1e-7; ++it) {
        double m = (a * gb - b * ga) / (gb - ga);
        if (!(m > a && m < b)) m = 0.5 * (a + b);
        const Vector ym = state_at(m);
        system_.switching(t + m * h, ym.data(), g.data());
        const double gm = g[j];
        if ((gm < 0.0) == (ga < 0.0)) {
          a = m;
          ga = gm;
          if (side == -1) gb *= 0.5;
          side = -1;
        } else {
          b = m;
          gb = gm;
          if (side == 1) ga *= 0.5;
          side = 1;
        }
      }
      // End just past the root, so the next step starts on the new branch.
      first = std::min(first, b);
    }
    return first;
  }

  const OdeSystem& system_;
  const IntegratorOptions& options_;
  int n_;
  double rtol_ = 1e-6;
  Vector atol_;
  Matrix J_;
  Eigen::PartialPivLU<Matrix> lu_;
  Matrix g_inverse_;
  double h_lu_ = 0.0;
  bool lu_valid_ = false;
  bool have_jacobian_ = false;
  int jacobian_age_ = 0;
  int g_count_ = 0;
  Vector stage_buffer_[kS - 1];
  Vector z_ordinary_;  // a recorded stage at the ordinary accuracy, to polish (polish_stage)
};

template <int N>
void run_with(const OdeSystem& system, const std::vector<double>& times,
              const IntegratorOptions& options, Trajectory& trajectory, EsdirkStepHistory* history,
              const EsdirkStepHistory* frozen) {
  EsdirkSolver<N> solver(system, options);
  solver.run(times, trajectory, history, frozen);
}

// Runs the solver of the first size in Sizes that equals n; false when none does.
template <int... Sizes>
bool run_fixed(int n, const OdeSystem& system, const std::vector<double>& times,
               const IntegratorOptions& options, Trajectory& trajectory, EsdirkStepHistory* history,
               const EsdirkStepHistory* frozen) {
  return ((n == Sizes &&
           (run_with<Sizes>(system, times, options, trajectory, history, frozen), true)) ||
          ...);
}

Trajectory run_esdirk(const OdeSystem& system, const std::vector<double>& x0,
                      const std::vector<double>& output_times_s, const IntegratorOptions& options,
                      EsdirkStepHistory* history, const EsdirkStepHistory* frozen) {
  if (!(options.relative_tolerance > 0.0 && options.relative_tolerance <= 0.1)) {
    throw InputError(fmt::format("relative tolerance {}: expected a value in (0, 0.1]",
                                 options.relative_tolerance));
  }
  Trajectory trajectory = start_trajectory(system, x0, output_times_s, Method::kEsdirk);
  const int n = trajectory.state_size;
  if (n > 24) throw InputError(fmt::format("ESDIRK: {} states, at most 24 supported", n));
  if (history != nullptr) {
    *history = EsdirkStepHistory();
    history->state_size = n;
  }
  if (output_times_s.size() == 1) return trajectory;
  // Fixed sizes for the strut (2, 3 with a lagged command), the quarter car (4–6) and the half
  // car (14–18).
  const bool fixed = run_fixed<2, 3, 4, 5, 6, 14, 15, 16, 17, 18>(
      n, system, output_times_s, options, trajectory, history, frozen);
  if (!fixed) {
    run_with<Eigen::Dynamic>(system, output_times_s, options, trajectory, history, frozen);
  }
  return trajectory;
}

}  // namespace

Trajectory integrate_esdirk(const OdeSystem& system, const std::vector<double>& x0,
                            const std::vector<double>& output_times_s,
                            const IntegratorOptions& options, EsdirkStepHistory* history) {
  return run_esdirk(system, x0, output_times_s, options, history, nullptr);
}

Trajectory integrate_esdirk_on_steps(const OdeSystem& system, const std::vector<double>& x0,
                                     const std::vector<double>& output_times_s,
                                     const IntegratorOptions& options,
                                     const EsdirkStepHistory& steps) {
  return run_esdirk(system, x0, output_times_s, options, nullptr, &steps);
}

}  // namespace ridefit::simulate
