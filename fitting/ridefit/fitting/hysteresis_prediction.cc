#include "ridefit/fitting/hysteresis_prediction.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "ridefit/common/errors.h"
#include "ridefit/signal/excitation_band.h"

namespace ridefit::fitting {

double nrmse_percent(const std::vector<double>& measured_N, const std::vector<double>& model_N,
                     std::size_t first) {
  const std::size_t n = std::min(measured_N.size(), model_N.size());
  if (first >= n) return 0.0;
  double mean = 0.0;
  for (std::size_t k = first; k < n; ++k) mean += measured_N[k];
  mean /= static_cast<double>(n - first);
  double residual = 0.0, spread = 0.0;
  for (std::size_t k = first; k < n; ++k) {
    residual += (model_N[k] - measured_N[k]) * (model_N[k] - measured_N[k]);
    spread += (measured_N[k] - mean) * (measured_N[k] - mean);
  }
  return spread > 0.0 ? 100.0 * std::sqrt(residual / spread) : 0.0;
}

std::optional<std::vector<double>> run_fitted_strut(
    const HysteresisRecord& record, const model::StrutTestParameters<double>& strut,
    const simulate::StrutTestSolverOptions& solver) {
  auto force =
      simulate::strut_test_force<double>(record.time_s, record.displacement_m, strut, strut, solver,
                                         record.command, record.velocity_m_per_s);
  if (force || solver.frozen_steps != nullptr) return force;
  simulate::StrutTestSolverOptions patient = solver;
  patient.max_steps_per_s *= 20.0;
  return simulate::strut_test_force<double>(record.time_s, record.displacement_m, strut, strut,
                                            patient, record.command, record.velocity_m_per_s);
}

std::vector<RecordPrediction> predict_records(const std::vector<HysteresisRecord>& records,
                                              const model::StrutTestParameters<double>& strut,
                                              const simulate::StrutTestSolverOptions& solver,
                                              double score_from_s) {
  std::vector<RecordPrediction> out;
  for (const auto& r : records) {
    const auto force = run_fitted_strut(r, strut, solver);
    if (!force) {
      throw RunError(fmt::format(
          "{}: the fitted strut cannot be solved on this record (the integrator failed)",
          r.source));
    }
    RecordPrediction p;
    p.source = r.source;
    p.force_N = *force;
    p.score_from_s = score_from_s;
    const auto first = static_cast<std::size_t>(
        std::lower_bound(r.time_s.begin(), r.time_s.end(), score_from_s) - r.time_s.begin());
    p.scored = r.time_s.size() - first;
    double squares = 0.0;
    for (std::size_t k = first; k < r.force_N.size(); ++k) {
      squares += (p.force_N[k] - r.force_N[k]) * (p.force_N[k] - r.force_N[k]);
    }
    p.residual_rms_N = p.scored > 0 ? std::sqrt(squares / static_cast<double>(p.scored)) : 0.0;
    p.nrmse_percent = nrmse_percent(r.force_N, p.force_N, first);
    p.in_band_nrmse_percent = p.nrmse_percent;
    const std::size_t n = r.time_s.size();
    if (p.scored >= 128 && r.time_s[n - 1] > r.time_s[first]) {
      const simulate::RigDisplacement x(r.time_s, r.displacement_m, solver.interpolation,
                                        r.velocity_m_per_s);
      std::vector<double> velocity, residual;
      for (std::size_t k = first; k < n; ++k) {
        velocity.push_back(x.rate_at(r.time_s[k]));
        residual.push_back(p.force_N[k] - r.force_N[k]);
      }
      // (uneven steps, as printed time stamps give, are taken at their mean rate)
      const double rate_Hz =
          static_cast<double>(p.scored - 1) / (r.time_s[n - 1] - r.time_s[first]);
      const signal::ExcitationBand band = signal::excitation_band(velocity, residual, rate_Hz);
      // Only for a random motion: under a sine or triangle the force's harmonics above the
      // motion's band are the damper's own nonlinearity, which a model must follow, not noise.
      if (band.repeat_correlation < 0.5) {
        p.excitation_band_Hz = band.band_Hz;
        p.in_band_nrmse_percent = p.nrmse_percent * std::sqrt(band.residual_in_band_share);
      }
    }
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace ridefit::fitting
