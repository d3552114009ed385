#include "ridefit/fitting/diagnose/sparse_selection.h"

#include <fmt/core.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ridefit/common/errors.h"
#include "ridefit/signal/correlation_time.h"

namespace ridefit::fitting::diagnose {
namespace {

// The least-squares fit of `y` on the columns `kept` of `a`, with the coefficients' standard
// errors widened by the residual's correlation time (pooled over the parts' lengths); not ok when
// the columns are not independent.
struct Fit {
  Eigen::VectorXd coefficients;
  Eigen::VectorXd standard_errors;
  bool ok = false;
};

Fit least_squares(const Eigen::MatrixXd& a, const Eigen::VectorXd& y, const std::vector<int>& kept,
                  const std::vector<std::size_t>& lengths) {
  Fit fit;
  const Eigen::MatrixXd columns = a(Eigen::all, kept);
  const Eigen::Index n = columns.rows(), k = columns.cols();
  if (n <= k + 1) return fit;
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(columns);
  if (qr.rank() < k) return fit;
  fit.coefficients = qr.solve(y);
  const Eigen::VectorXd residual = y - columns * fit.coefficients;
  const std::vector<double> r(residual.data(), residual.data() + residual.size());
  const double tau = signal::pooled_correlation_time_samples(r, lengths);
  const double variance = residual.squaredNorm() / static_cast<double>(n - k);
  const Eigen::MatrixXd inverse =
      (columns.transpose() * columns).ldlt().solve(Eigen::MatrixXd::Identity(k, k));
  fit.standard_errors = (variance * tau * inverse.diagonal().array()).max(0.0).sqrt().matrix();
  fit.ok = fit.coefficients.allFinite() && fit.standard_errors.allFinite();
  return fit;
}

}  // namespace

void SparseSelectionOptions::validate() const {
  if (max_terms < 1) {
    throw InputError(fmt::format("shape selection: max_terms {}: expected at least 1", max_terms));
  }
  if (!(min_share > 0.0 && min_share < 1.0)) {
    throw InputError(
        fmt::format("shape selection: min_share {}: expected a share in (0, 1)", min_share));
  }
  if (!(min_z > 0.0) || !std::isfinite(min_z)) {
    throw InputError(
        fmt::format("shape selection: min_z {}: expected a finite value above 0", min_z));
  }
}

SparseSelection select_columns(const SelectionRows& training, const SelectionRows& judging,
                               const SparseSelectionOptions& options, const SelectionRows* all) {
  options.validate();
  SparseSelection selection;
  const Eigen::Index width = training.basis.cols();
  if (training.target.size() < 10 || judging.target.size() < 10 || judging.basis.cols() != width) {
    return selection;
  }
  // Columns on one scale (the training rows' RMS), so the QR and the shares compare like with
  // like; a column that is zero on the training rows cannot enter.
  Eigen::MatrixXd train = training.basis, judge = judging.basis;
  Eigen::VectorXd scale(width);
  std::vector<int> candidates;
  for (Eigen::Index j = 0; j < width; ++j) {
    scale(j) = train.col(j).norm() / std::sqrt(static_cast<double>(train.rows()));
    if (scale(j) > 0.0 && std::isfinite(scale(j))) {
      train.col(j) /= scale(j);
      judge.col(j) /= scale(j);
      candidates.push_back(static_cast<int>(j));
    }
  }
  const double start = judging.target.squaredNorm();
  if (!(start > 0.0) || !std::isfinite(start)) return selection;
  double now = start;
  std::vector<int> kept;
  for (int round = 0; round < options.max_terms; ++round) {
    int best = -1;
    double best_sse = now;
    for (int j : candidates) {
      if (std::find(kept.begin(), kept.end(), j) != kept.end()) continue;
      std::vector<int> trial = kept;
      trial.push_back(j);
      const Fit fit = least_squares(train, training.target, trial, training.lengths);
      if (!fit.ok) continue;
      const Eigen::Index last = fit.coefficients.size() - 1;
      if (!(std::abs(fit.coefficients(last)) >= options.min_z * fit.standard_errors(last))) {
        continue;
      }
      const double sse =
          (judging.target - judge(Eigen::all, trial) * fit.coefficients).squaredNorm();
      if (sse < best_sse) {
        best = j;
        best_sse = sse;
      }
    }
    if (best < 0 || now - best_sse < options.min_share * start) break;
    kept.push_back(best);
    selection.columns.push_back({best, (now - best_sse) / start, 0.0, 0.0});
    now = best_sse;
  }
  selection.judged_share = 1.0 - now / start;
  if (kept.empty()) return selection;

  // The reported coefficients from every row.
  SelectionRows every;
  if (all != nullptr) {
    every = *all;
  } else {
    every.basis.resize(training.basis.rows() + judging.basis.rows(), width);
    every.basis << training.basis, judging.basis;
    every.target.resize(every.basis.rows());
    every.target << training.target, judging.target;
    every.lengths = training.lengths;
    every.lengths.insert(every.lengths.end(), judging.lengths.begin(), judging.lengths.end());
  }
  if (every.basis.cols() != width) {
    throw std::invalid_argument("select_columns: every row's basis has another width");
  }
  for (Eigen::Index j = 0; j < width; ++j) {
    if (scale(j) > 0.0 && std::isfinite(scale(j))) every.basis.col(j) /= scale(j);
  }
  const Fit fit = least_squares(every.basis, every.target, kept, every.lengths);
  for (std::size_t i = 0; i < kept.size(); ++i) {
    const auto e = static_cast<Eigen::Index>(i);
    const double s = scale(kept[i]);
    selection.columns[i].coefficient = fit.ok ? fit.coefficients(e) / s : NAN;
    selection.columns[i].standard_error = fit.ok ? fit.standard_errors(e) / s : NAN;
  }
  return selection;
}

}  // namespace ridefit::fitting::diagnose
