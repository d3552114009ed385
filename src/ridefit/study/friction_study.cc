#include "ridefit/study/friction_study.h"

#include <algorithm>
#include <cmath>

#include "ridefit/comfort/vibration_metrics.h"
#include "ridefit/comfort/weighting_filter.h"
#include "ridefit/common/parallel_for.h"
#include "ridefit/signal/band_power.h"
#include "ridefit/signal/spectrum_peak.h"
#include "ridefit/signal/statistics.h"
#include "ridefit/signal/welch_psd.h"

namespace ridefit::study {
namespace {

FrictionCase run_case(const model::QuarterCarParameters<double>& base, double coulomb_force_N,
                      const road::RoadInput& road, const FrictionStudyOptions& options,
                      std::vector<double>& frequency_Hz) {
  model::QuarterCarParameters<double> parameters = base;
  parameters.coulomb_force_N = coulomb_force_N;
  const model::QuarterCar car(model::DamperState::kStickSlip, parameters);
  const auto response = simulate::simulate(car, road, options.simulation);

  const double fs = options.simulation.output_rate_Hz;
  signal::WelchOptions welch;
  // A run shorter than one segment gets a single segment over the whole run.
  welch.segment_length_samples = std::min(
      static_cast<std::size_t>(std::lround(options.psd_segment_s * fs)), response.time_s.size());
  const auto body = signal::welch_psd(response.body_acc_m_per_s2, fs, welch);
  const auto wheel = signal::welch_psd(response.wheel_acc_m_per_s2, fs, welch);

  FrictionCase result;
  result.coulomb_force_N = coulomb_force_N;
  result.body_peak_Hz =
      signal::find_peak(body, options.body_band_low_Hz, options.body_band_high_Hz).frequency_Hz;
  result.wheel_peak_Hz =
      signal::find_peak(wheel, options.wheel_band_low_Hz, options.wheel_band_high_Hz).frequency_Hz;
  result.body_acc_rms_m_per_s2 = signal::rms(response.body_acc_m_per_s2);
  result.wheel_acc_rms_m_per_s2 = signal::rms(response.wheel_acc_m_per_s2);
  if (fs >= comfort::minimum_sample_rate_Hz(comfort::Weighting::kWk)) {
    const comfort::VibrationMetrics body_wk = comfort::vibration_metrics(
        comfort::apply_weighting(comfort::Weighting::kWk, response.body_acc_m_per_s2, fs), fs);
    result.body_acc_wk_rms_m_per_s2 = body_wk.weighted_rms_m_per_s2;
    result.body_acc_wk_vdv_m_per_s1_75 = body_wk.vdv_m_per_s1_75;
  }
  result.body_slip_band_rms_m_per_s2 =
      signal::band_rms(body, options.slip_band_low_Hz, options.slip_band_high_Hz);
  result.body_stick_band_rms_m_per_s2 =
      signal::band_rms(body, options.stick_band_low_Hz, options.stick_band_high_Hz);
  double stuck = 0.0;
  for (double s : response.stuck) stuck += s;
  result.stuck_share = stuck / static_cast<double>(response.stuck.size());
  result.body_psd = body.psd;
  result.wheel_psd = wheel.psd;
  result.statistics = response.statistics;
  frequency_Hz = body.frequency_Hz;
  return result;
}

}  // namespace

FrictionStudyResult run_friction_study(const model::QuarterCarParameters<double>& parameters,
                                       const road::RoadInput& road,
                                       const FrictionStudyOptions& options,
                                       const std::function<void(const FrictionCase&)>& progress) {
  const std::size_t count = options.coulomb_forces_N.size();
  FrictionStudyResult result;
  result.cases.resize(count);
  std::vector<std::vector<double>> frequencies(count);
  common::parallel_for(
      count, options.threads,
      [&](std::size_t i) {
        result.cases[i] =
            run_case(parameters, options.coulomb_forces_N[i], road, options, frequencies[i]);
      },
      [&](std::size_t i) {
        if (progress) progress(result.cases[i]);
      });
  if (count > 0) result.frequency_Hz = frequencies.front();
  return result;
}

}  // namespace ridefit::study
