#include "ridefit/fitting/strut_start.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "ridefit/common/errors.h"
#include "ridefit/fitting/strut_parameters.h"

namespace ridefit::fitting {
namespace {

// The levels are read off the sliding rows only: after a reversal the friction element takes
// 2·Fc/σ0 of travel (and the top mount F/k) to turn, while |v| rises, so rows near reversals
// make the friction look viscous (a 1 A MR test read 6.7× the damping per command at a 0.2
// share). At 0.7 of the RMS speed a sine's rows are at least half its amplitude past a reversal.
constexpr double kSlidingSpeedShare = 0.7;

}  // namespace

std::map<std::string, double> estimate_strut_start(const std::vector<HysteresisRecord>& records) {
  const bool commanded =
      !records.empty() && std::all_of(records.begin(), records.end(),
                                      [](const HysteresisRecord& r) { return !r.command.empty(); });
  struct Row {
    double x, v, u, f;
  };
  std::vector<Row> rows;
  for (const auto& r : records) {
    const std::size_t n = r.time_s.size();
    if (n < 3) continue;
    std::vector<Row> own;
    double v_squares = 0.0;
    for (std::size_t k = 1; k + 1 < n; ++k) {
      const double v =
          (r.displacement_m[k + 1] - r.displacement_m[k - 1]) / (r.time_s[k + 1] - r.time_s[k - 1]);
      own.push_back({r.displacement_m[k], v, commanded ? r.command[k] : 0.0, r.force_N[k]});
      v_squares += v * v;
    }
    const double v_rms = std::sqrt(v_squares / static_cast<double>(own.size()));
    for (const auto& row : own) {
      if (std::abs(row.v) > kSlidingSpeedShare * v_rms) rows.push_back(row);
    }
  }
  std::map<std::string, double> estimate;
  if (rows.size() < 10) return estimate;
  // Is |v| nearly constant (a triangle, or a sine's sliding rows, which spread by about 0.15 of
  // their mean speed)? Then the slope cannot be told from the level: at a 0.1 spread a five-
  // current sine file read 67 N·s/m and 10 500 N·s/m per ampere for 1500 and 2500.
  double mean_speed = 0.0, speed_squares = 0.0;
  for (const auto& row : rows) mean_speed += std::abs(row.v) / static_cast<double>(rows.size());
  for (const auto& row : rows) {
    speed_squares += (std::abs(row.v) - mean_speed) * (std::abs(row.v) - mean_speed);
  }
  const bool slope_seen =
      std::sqrt(speed_squares / static_cast<double>(rows.size())) > 0.2 * mean_speed;
  // Columns: 1, x, sgn v, [v], [u·sgn v, [u·v]].
  namespace qc = model::quarter_car_rows;
  namespace rig = model::strut_rig_rows;
  std::vector<std::string> names = {rig::force_offset_N.key_string(),
                                    rig::gas_stiffness_N_per_m.key_string(),
                                    qc::coulomb_force_N.key_string()};
  if (slope_seen) names.push_back(qc::damping_Ns_per_m.key_string());
  if (commanded) {
    names.push_back(qc::coulomb_force_per_command_N.key_string());
    if (slope_seen) names.push_back(qc::damping_per_command_Ns_per_m.key_string());
  }
  // The least squares at command exponent p (the command law's levels affine in sgn(u)·|u|^p):
  // the residual's norm and the scaled solution.
  struct Solved {
    double residual = 0.0;
    Eigen::VectorXd solution, norms;
    bool full_rank = false;
  };
  auto solve_at = [&](double p) {
    Eigen::MatrixXd a(static_cast<Eigen::Index>(rows.size()),
                      static_cast<Eigen::Index>(names.size()));
    Eigen::VectorXd b(static_cast<Eigen::Index>(rows.size()));
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const auto& row = rows[i];
      const double sign = row.v < 0.0 ? -1.0 : 1.0;
      const double shaped = p == 1.0 ? row.u : std::copysign(std::pow(std::abs(row.u), p), row.u);
      const auto r = static_cast<Eigen::Index>(i);
      Eigen::Index c = 0;
      a(r, c++) = 1.0;
      a(r, c++) = row.x;
      a(r, c++) = sign;
      if (slope_seen) a(r, c++) = row.v;
      if (commanded) {
        a(r, c++) = shaped * sign;
        if (slope_seen) a(r, c++) = shaped * row.v;
      }
      b(r) = row.f;
    }
    // Columns scaled to unit norm so the rank decision is about shape, not units.
    Solved out;
    out.norms = a.colwise().norm();
    for (Eigen::Index c = 0; c < a.cols(); ++c) {
      if (out.norms(c) > 0.0) a.col(c) /= out.norms(c);
    }
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
    qr.setThreshold(1e-8);
    out.full_rank = qr.rank() == a.cols();
    if (!out.full_rank) return out;
    out.solution = qr.solve(b);
    out.residual = (a * out.solution - b).norm();
    return out;
  };
  Solved solved = solve_at(1.0);
  if (!solved.full_rank) return estimate;
  // The command's shape: an MR damper's yield force grows more than linearly at small currents
  // and saturates at large ones, so p is read off the levels too (a grid from 0.2 to 3; a fit
  // started at p = 0.6 on a five-current file whose levels go as I^1.25 stayed below 1, 31 % on
  // the 0 A test). Only where the command takes more than two values: two levels fix any p.
  double exponent = 1.0;
  if (commanded) {
    std::vector<double> levels;
    for (const auto& row : rows) levels.push_back(row.u);
    std::sort(levels.begin(), levels.end());
    const auto distinct = std::unique(levels.begin(), levels.end(), [](double l, double r) {
      return std::abs(l - r) < 1e-9 * std::max(1.0, std::abs(r));
    });
    if (distinct - levels.begin() > 2) {
      for (int i = 4; i <= 60; ++i) {
        const double p = 0.05 * i;
        if (p == 1.0) continue;
        Solved trial = solve_at(p);
        if (trial.full_rank && trial.residual < solved.residual) {
          solved = std::move(trial);
          exponent = p;
        }
      }
      estimate[qc::command_exponent.key_string()] = exponent;
    }
  }
  for (std::size_t i = 0; i < names.size(); ++i) {
    const auto c = static_cast<Eigen::Index>(i);
    const double value = solved.norms(c) > 0.0 ? solved.solution(c) / solved.norms(c) : 0.0;
    if (!std::isfinite(value)) continue;
    if ((names[i] == qc::coulomb_force_N.key || names[i] == qc::damping_Ns_per_m.key) &&
        !(value > 0.0)) {
      continue;
    }
    estimate[names[i]] = value;
  }
  const auto friction = estimate.find(qc::coulomb_force_N.key_string());
  if (friction != estimate.end()) {
    if (const auto sigma0 = estimate_pre_sliding_stiffness(records, friction->second)) {
      estimate[qc::dahl_sigma0_N_per_m.key_string()] = *sigma0;
    }
  }
  return estimate;
}

std::optional<double> estimate_pre_sliding_stiffness(const std::vector<HysteresisRecord>& records,
                                                     double friction_N) {
  if (!(friction_N > 0.0)) return std::nullopt;
  std::vector<double> slopes;
  for (const auto& r : records) {
    const auto& x = r.displacement_m;
    const auto& f = r.force_N;
    const std::size_t n = x.size();
    const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
    // A reversal: x turns by more than 2 % of the stroke (quantisation at a turning point does
    // not count). From it, the secant to where the force has moved by Fc.
    const double turn = 0.02 * (*hi - *lo);
    std::size_t extreme = 0;
    int direction = 0;
    for (std::size_t k = 1; k < n; ++k) {
      const double d = x[k] - x[extreme];
      if (direction >= 0 && x[k] > x[extreme]) {
        extreme = k;
        direction = 1;
        continue;
      }
      if (direction <= 0 && x[k] < x[extreme]) {
        extreme = k;
        direction = -1;
        continue;
      }
      if (std::abs(d) < turn || direction == 0) continue;
      // x has turned at `extreme`: follow the force from there.
      for (std::size_t j = extreme + 1; j < n; ++j) {
        const double dx = std::abs(x[j] - x[extreme]);
        if (std::abs(f[j] - f[extreme]) >= friction_N) {
          // Dahl from a reversal (d = 1): ΔF = 2Fc(1 − exp(−σ0·Δx/(2Fc))), ΔF = Fc at
          // Δx = 2·ln 2·Fc/σ0, so σ0 = 2·ln 2 × the secant there.
          if (dx > 0.0) slopes.push_back(2.0 * std::log(2.0) * friction_N / dx);
          break;
        }
        if (dx > 4.0 * turn) break;  // no clear pre-sliding branch
      }
      direction = -direction;
      extreme = k;
    }
  }
  if (slopes.size() < 2) return std::nullopt;
  std::nth_element(slopes.begin(), slopes.begin() + static_cast<std::ptrdiff_t>(slopes.size() / 2),
                   slopes.end());
  return slopes[slopes.size() / 2];
}

model::StrutTestParameters<double> with_estimates(model::StrutTestParameters<double> base,
                                                  const std::map<std::string, double>& estimate,
                                                  const std::vector<std::string>& free) {
  for (const auto& name : free) {
    const auto found = estimate.find(name);
    if (found == estimate.end()) continue;
    strut_parameter(base, strut_parameter_index(name)) = found->second;
  }
  return base;
}

namespace {

// Iterations each start gets before the best goes on alone.
constexpr int kRaceIterations = 4;

}  // namespace

HysteresisFitResult fit_hysteresis_from_starts(
    const std::vector<HysteresisRecord>& records,
    const std::vector<model::StrutTestParameters<double>>& starts,
    const HysteresisFitOptions& given_options, const std::vector<std::string>& start_labels,
    std::string* chosen) {
  HysteresisFitOptions options = given_options;
  if (options.force_scale_N == 0.0) options.force_scale_N = largest_force_N(records);
  const auto bounds = options.resolved_bounds();
  std::vector<std::size_t> free;
  for (const auto& name : options.free) free.push_back(strut_parameter_index(name));
  std::vector<std::vector<double>> seen;
  // Each start's first result (a few iterations when racing), with its label.
  std::vector<std::pair<HysteresisFitResult, std::string>> tried;
  std::string failure;
  // With several starts and shared parameters, every start gets a few iterations first and only
  // the lowest cost is fitted on to convergence: the starts differ in where they begin, not in
  // the basin a few Gauss-Newton steps have found, and full fits from each cost twice as much.
  const bool race =
      starts.size() > 1 && options.per_file.empty() && options.max_iterations > kRaceIterations;
  HysteresisFitOptions first_steps = options;
  if (race) first_steps.max_iterations = kRaceIterations;
  auto clamp_free = [&](model::StrutTestParameters<double>& start) {
    for (std::size_t index : free) {
      double& value = strut_parameter(start, index);
      value = std::clamp(value, bounds[index].first, bounds[index].second);
    }
  };
  for (std::size_t s = 0; s < starts.size(); ++s) {
    model::StrutTestParameters<double> start = starts[s];
    // The first start is the caller's own and keeps its checks (an out-of-bounds start is an
    // InputError there); the others are clamped inside.
    if (s > 0) clamp_free(start);
    std::vector<double> key;
    for (std::size_t index : free) key.push_back(strut_parameter(start, index));
    if (std::find(seen.begin(), seen.end(), key) != seen.end()) continue;
    seen.push_back(key);
    try {
      tried.emplace_back(fit_hysteresis(records, start, race ? first_steps : options),
                         s < start_labels.size() ? start_labels[s] : "");
    } catch (const RunError& e) {
      failure = e.what();
    }
  }
  if (tried.empty()) throw RunError(failure.empty() ? "fit: no start to fit from" : failure);
  std::stable_sort(tried.begin(), tried.end(), [](const auto& a, const auto& b) {
    return a.first.final_cost < b.first.final_cost;
  });
  // The best start fitted on to convergence; when it ends on a bound (a collapse, or a mechanism
  // traded for another), the next ones too, before the collapse is reported: the fit kept is the
  // lowest cost, off the bounds where two costs are about the same.
  std::optional<HysteresisFitResult> kept;
  for (auto& [first, label] : tried) {
    HysteresisFitResult fit = std::move(first);
    if (race && !fit.converged && !fit.fitted.empty()) {
      const int first_iterations = fit.iterations;
      // Bounds derived from the data (a Stribeck level above Fc) move with the values, so the
      // iterate may sit a rounding error outside them.
      model::StrutTestParameters<double> from = fit.fitted.front();
      clamp_free(from);
      try {
        fit = fit_hysteresis(records, from, options);
      } catch (const RunError& e) {
        failure = e.what();
        continue;
      }
      fit.iterations += first_iterations;
    }
    // Off the bounds wins only among fits about as good (within 2 % in cost): a parameter on its
    // bound that the data do not need (a free play of zero) is no collapse, and a start that
    // ended 25 times worse off the bounds (the UTFSM 2 mm file: 74 % against 12 % NRMSE) is no
    // better fit.
    const auto about_as_good = [](double a, double b) { return a <= 1.02 * b && b <= 1.02 * a; };
    const bool better = !kept || (kept->on_bounds.empty() != fit.on_bounds.empty() &&
                                          about_as_good(fit.final_cost, kept->final_cost)
                                      ? fit.on_bounds.empty()
                                      : fit.final_cost < kept->final_cost);
    if (better) {
      kept = std::move(fit);
      if (chosen != nullptr) *chosen = label;
    }
    if (kept->on_bounds.empty()) break;
  }
  if (!kept) throw RunError(failure);
  return *kept;
}

HysteresisFitResult fit_hysteresis_from_file_and_records(
    const std::vector<HysteresisRecord>& records, const model::StrutTestParameters<double>& start,
    const HysteresisFitOptions& options, std::string* chosen) {
  const auto estimated = with_estimates(start, estimate_strut_start(records), options.free);
  return fit_hysteresis_from_starts(records, {start, estimated}, options,
                                    {"the model file", "levels read off the records"}, chosen);
}

}  // namespace ridefit::fitting
