#include "ridefit/study/quarter_car_spectral_metrics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "ridefit/comfort/frequency_weighting.h"
#include "ridefit/comfort/tyre_load_metrics.h"
#include "ridefit/signal/expected_peak.h"
#include "ridefit/simulate/frequency_response.h"
#include "ridefit/simulate/quarter_car_state_space.h"

namespace ridefit::study {

QuarterCarMetrics quarter_car_spectral_metrics(const model::QuarterCar& car,
                                               const road::RoadSpectrum& road, std::size_t points,
                                               double settle_s) {
  if (points < 2) throw std::invalid_argument("quarter_car_spectral_metrics: needs 2 frequencies");
  const simulate::FrequencyResponse response(simulate::quarter_car_state_space(car));
  const double speed = road.speed_m_per_s;
  const double f_low = road.band.low_cycles_per_m * speed;
  const double f_high = road.band.high_cycles_per_m * speed;
  const double ratio = std::log(f_high / f_low) / static_cast<double>(points - 1);
  std::vector<double> f(points), wk2(points);
  std::array<std::vector<double>, simulate::kQuarterCarLinearOutputs> psd;
  for (auto& p : psd) p.resize(points);
  for (std::size_t k = 0; k < points; ++k) {
    f[k] = f_low * std::exp(ratio * static_cast<double>(k));
    const double road_psd = road.spectrum.psd_m3(f[k] / speed) / speed;  // m²/Hz
    const std::complex<double> jw(0.0, 2.0 * std::numbers::pi * f[k]);
    const Eigen::MatrixXcd h = response.at(f[k]);
    for (int y = 0; y < simulate::kQuarterCarLinearOutputs; ++y) {
      psd[static_cast<std::size_t>(y)][k] = std::norm(h(y, 0) + jw * h(y, 1)) * road_psd;
    }
    const double w = comfort::weighting_magnitude(comfort::Weighting::kWk, f[k]);
    wk2[k] = w * w;
  }
  auto rms = [&](simulate::QuarterCarLinearOutput y) {
    return std::sqrt(signal::spectral_moment(f, psd[static_cast<std::size_t>(y)], 0));
  };
  std::vector<double> weighted(points);
  for (std::size_t k = 0; k < points; ++k) weighted[k] = wk2[k] * psd[simulate::kQuarterBodyAcc][k];
  QuarterCarMetrics m;
  m.body_acc_wk_rms_m_per_s2 = std::sqrt(signal::spectral_moment(f, weighted, 0));
  m.body_acc_rms_m_per_s2 = rms(simulate::kQuarterBodyAcc);
  m.wheel_acc_rms_m_per_s2 = rms(simulate::kQuarterWheelAcc);
  m.travel_rms_m = rms(simulate::kQuarterTravel);
  const auto& travel = psd[simulate::kQuarterTravel];
  m.travel_peak_m = signal::expected_gaussian_peak(signal::spectral_moment(f, travel, 0),
                                                   signal::spectral_moment(f, travel, 2),
                                                   std::max(road.duration_s - settle_s, 1.0));
  m.tyre_force_rms_N = rms(simulate::kQuarterTyreForce);
  m.dynamic_load_ratio = m.tyre_force_rms_N / comfort::static_tyre_load_N(car.parameters());
  m.stuck_share = 0.0;
  return m;
}

}  // namespace ridefit::study
