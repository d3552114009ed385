#include "ridefit/fitting/diagnose/loop_disagreement.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "ridefit/common/errors.h"
#include "ridefit/fitting/diagnose/residual_statistics.h"

namespace ridefit::fitting::diagnose {
namespace {

// Regions along `quantity`: quantile bins (half below zero, half above), each judged by its mean
// residual against a standard error that counts the residual's lag-1 correlation (a model error is
// smooth in time, so its samples are far from independent).
void find_regions(const std::string& record, const std::string& name,
                  const std::vector<double>& quantity, const std::vector<double>& residual,
                  double force_rms, double lag1, const LoopDisagreementOptions& options,
                  std::vector<LoopRegion>& regions) {
  const std::size_t n = quantity.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return quantity[a] < quantity[b]; });
  const auto bins = static_cast<std::size_t>(std::max(options.bins, 2));
  const double inflation = std::max((1.0 + lag1) / std::max(1.0 - lag1, 1e-6), 1.0);
  struct Bin {
    double low, high, sum, count;
    int sign;
  };
  std::vector<Bin> judged;
  // Half the bins on each side of zero, so a law that flips with the sign (friction at a
  // reversal) cannot cancel itself in a bin straddling zero.
  const auto negatives = static_cast<std::size_t>(
      std::partition_point(order.begin(), order.end(),
                           [&](std::size_t k) { return quantity[k] < 0.0; }) -
      order.begin());
  std::vector<std::pair<std::size_t, std::size_t>> spans;
  const std::size_t low_bins = negatives == 0 ? 0 : negatives == n ? bins : bins / 2;
  for (std::size_t b = 0; b < low_bins; ++b) {
    spans.emplace_back(b * negatives / low_bins, (b + 1) * negatives / low_bins);
  }
  const std::size_t high_bins = bins - low_bins;
  for (std::size_t b = 0; b < high_bins; ++b) {
    spans.emplace_back(negatives + b * (n - negatives) / high_bins,
                       negatives + (b + 1) * (n - negatives) / high_bins);
  }
  for (const auto& [begin, end] : spans) {
    if (end <= begin + 1) continue;
    double sum = 0.0, squares = 0.0;
    for (std::size_t k = begin; k < end; ++k) sum += residual[order[k]];
    const double count = static_cast<double>(end - begin), mean = sum / count;
    for (std::size_t k = begin; k < end; ++k) {
      squares += (residual[order[k]] - mean) * (residual[order[k]] - mean);
    }
    const double se = std::sqrt(squares / (count - 1.0) / count * inflation);
    const int sign = std::abs(mean) > options.significance_sigmas * se ? (mean > 0 ? 1 : -1) : 0;
    judged.push_back({quantity[order[begin]], quantity[order[end - 1]], sum, count, sign});
  }
  for (std::size_t b = 0; b < judged.size();) {
    if (judged[b].sign == 0) {
      ++b;
      continue;
    }
    std::size_t e = b;
    double sum = 0.0, count = 0.0;
    while (e < judged.size() && judged[e].sign == judged[b].sign) {
      sum += judged[e].sum;
      count += judged[e].count;
      ++e;
    }
    const double mean = sum / count;
    if (std::abs(mean) >= options.min_region_share * force_rms) {
      regions.push_back({record, name, judged[b].low, judged[e - 1].high, mean, mean / force_rms});
    }
    b = e;
  }
}

}  // namespace

std::vector<double> rig_velocity_m_per_s(const HysteresisRecord& r) {
  const std::size_t n = r.time_s.size();
  if (r.velocity_m_per_s.size() == n) return r.velocity_m_per_s;
  std::vector<double> v(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t a = k == 0 ? 0 : k - 1, b = std::min(k + 1, n - 1);
    v[k] = (r.displacement_m[b] - r.displacement_m[a]) / (r.time_s[b] - r.time_s[a]);
  }
  return v;
}

double force_nrmse_percent(const std::vector<HysteresisRecord>& records,
                           const std::vector<std::vector<double>>& simulated_force_N) {
  double residual = 0.0, spread = 0.0;
  for (std::size_t i = 0; i < records.size() && i < simulated_force_N.size(); ++i) {
    const auto& measured = records[i].force_N;
    const auto& simulated = simulated_force_N[i];
    double mean = 0.0;
    for (double f : measured) mean += f / static_cast<double>(measured.size());
    for (std::size_t k = 0; k < measured.size() && k < simulated.size(); ++k) {
      residual += (simulated[k] - measured[k]) * (simulated[k] - measured[k]);
      spread += (measured[k] - mean) * (measured[k] - mean);
    }
  }
  return spread > 0.0 ? 100.0 * std::sqrt(residual / spread) : 0.0;
}

void LoopDisagreementOptions::validate() const {
  if (bins < 2) throw InputError(fmt::format("bins {}: expected at least 2", bins));
  if (!(min_region_share >= 0.0 && min_region_share < 1.0)) {
    throw InputError(
        fmt::format("smallest region share {}: expected a value in [0, 1)", min_region_share));
  }
  if (!(significance_sigmas > 0.0) || !std::isfinite(significance_sigmas)) {
    throw InputError(fmt::format("significance {} standard errors: expected a finite value > 0",
                                 significance_sigmas));
  }
}

LoopDisagreementMap map_loop_disagreement(const std::vector<HysteresisRecord>& records,
                                          const std::vector<std::vector<double>>& simulated_force_N,
                                          const LoopDisagreementOptions& options) {
  options.validate();
  if (records.empty() || records.size() != simulated_force_N.size()) {
    throw InputError(
        fmt::format("the loop map needs one simulated force per record ({} records, "
                    "{} simulated)",
                    records.size(), simulated_force_N.size()));
  }
  LoopDisagreementMap map;
  for (std::size_t i = 0; i < records.size(); ++i) {
    const HysteresisRecord& r = records[i];
    const std::vector<double>& sim = simulated_force_N[i];
    if (sim.size() != r.force_N.size() || r.force_N.size() < 3) {
      throw InputError(fmt::format("{}: {} measured against {} simulated force samples", r.source,
                                   r.force_N.size(), sim.size()));
    }
    std::vector<double> residual(sim.size());
    double mean = 0.0;
    for (std::size_t k = 0; k < sim.size(); ++k) {
      if (!std::isfinite(sim[k])) {
        throw InputError(fmt::format("{}: simulated force sample {} is not finite", r.source, k));
      }
      residual[k] = sim[k] - r.force_N[k];
      mean += r.force_N[k];
    }
    mean /= static_cast<double>(sim.size());
    double squares = 0.0, spread = 0.0, lagged = 0.0;
    for (std::size_t k = 0; k < sim.size(); ++k) {
      squares += residual[k] * residual[k];
      spread += (r.force_N[k] - mean) * (r.force_N[k] - mean);
      if (k > 0) lagged += residual[k] * residual[k - 1];
    }
    const auto n = static_cast<double>(sim.size());
    const double force_rms = std::sqrt(spread / n);
    LoopRecordDisagreement d;
    d.record = r.source;
    d.residual_rms_N = std::sqrt(squares / n);
    d.nrmse_percent = spread > 0.0 ? 100.0 * std::sqrt(squares / spread) : 0.0;
    std::tie(d.residual_max_autocorrelation, d.residual_whiteness_p) = residual_whiteness(residual);
    d.amplitude_dependence = amplitude_dependence(r.force_N, sim);
    map.records.push_back(d);
    if (!(force_rms > 0.0) || !(squares > 0.0)) continue;
    const double lag1 = std::clamp(lagged / squares, -0.99, 0.99);
    find_regions(r.source, "velocity", rig_velocity_m_per_s(r), residual, force_rms, lag1, options,
                 map.regions);
    find_regions(r.source, "displacement", r.displacement_m, residual, force_rms, lag1, options,
                 map.regions);
  }
  map.gap_percent = force_nrmse_percent(records, simulated_force_N);
  return map;
}

}  // namespace ridefit::fitting::diagnose
