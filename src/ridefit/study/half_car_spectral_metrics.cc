#include "ridefit/study/half_car_spectral_metrics.h"

#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

#include "ridefit/comfort/frequency_weighting.h"
#include "ridefit/simulate/frequency_response.h"

namespace ridefit::study {

using simulate::HalfCarLinearOutput;

HalfCarSpectra half_car_spectra(const model::HalfCar& car, const road::RoadSpectrum& road,
                                std::size_t points) {
  if (points < 2) throw std::invalid_argument("half_car_spectra: needs at least 2 frequencies");
  const simulate::FrequencyResponse response(simulate::half_car_state_space(car));
  const double speed = road.speed_m_per_s;
  const double tau = car.parameters().wheelbase_m() / speed;
  const double f_low = road.band.low_cycles_per_m * speed;
  const double f_high = road.band.high_cycles_per_m * speed;
  HalfCarSpectra spectra;
  spectra.frequency_Hz.resize(points);
  for (auto& psd : spectra.psd) psd.resize(points);
  Eigen::VectorXcd inputs = Eigen::VectorXcd::Zero(simulate::kRearRoadRate + 1);
  const double ratio = std::log(f_high / f_low) / static_cast<double>(points - 1);
  for (std::size_t k = 0; k < points; ++k) {
    const double f = f_low * std::exp(ratio * static_cast<double>(k));
    spectra.frequency_Hz[k] = f;
    const double road_psd = road.spectrum.psd_m3(f / speed) / speed;  // m²/Hz
    const std::complex<double> jw(0.0, 2.0 * std::numbers::pi * f);
    const std::complex<double> delay = std::exp(-jw * tau);
    // The road under both wheels: z_f = z, ż_f = jω·z, the rear the same a wheelbase later.
    inputs(simulate::kFrontRoad) = 1.0;
    inputs(simulate::kFrontRoadRate) = jw;
    inputs(simulate::kRearRoad) = delay;
    inputs(simulate::kRearRoadRate) = delay * jw;
    const Eigen::VectorXcd total = response.at(f, inputs);
    for (int y = 0; y < simulate::kHalfCarLinearOutputs; ++y) {
      spectra.psd[static_cast<std::size_t>(y)][k] = std::norm(total(y)) * road_psd;
    }
  }
  return spectra;
}

HalfCarMetrics half_car_spectral_metrics(const model::HalfCar& car, const road::RoadSpectrum& road,
                                         std::size_t points) {
  return half_car_spectral_metrics(half_car_spectra(car, road, points), car.parameters());
}

HalfCarMetrics half_car_spectral_metrics(const HalfCarSpectra& spectra,
                                         const model::HalfCarParameters<double>& parameters) {
  const auto& f = spectra.frequency_Hz;
  // ∫ S df = ∫ S·f d(ln f), trapezoid on the log grid.
  // |W(f)|² on the grid, once per weighting (not once per output and trapezoid end).
  auto squared = [&](comfort::Weighting weighting) {
    std::vector<double> w2(f.size());
    for (std::size_t k = 0; k < f.size(); ++k) {
      const double w = comfort::weighting_magnitude(weighting, f[k]);
      w2[k] = w * w;
    }
    return w2;
  };
  const std::vector<double> wk = squared(comfort::Weighting::kWk);
  const std::vector<double> we = squared(comfort::Weighting::kWe);
  auto integral = [&](HalfCarLinearOutput y, const std::vector<double>* weighting) {
    const auto& psd = spectra.psd[static_cast<std::size_t>(y)];
    double sum = 0.0;
    auto integrand = [&](std::size_t k) {
      return (weighting ? (*weighting)[k] : 1.0) * psd[k] * f[k];
    };
    for (std::size_t k = 0; k + 1 < f.size(); ++k) {
      sum += 0.5 * (integrand(k) + integrand(k + 1)) * std::log(f[k + 1] / f[k]);
    }
    return std::sqrt(sum);
  };
  HalfCarMetrics m;
  m.seat_acc_wk_rms_m_per_s2 = integral(simulate::kSeatAcc, &wk);
  m.lower_body_acc_wk_rms_m_per_s2 = integral(simulate::kLowerBodyAcc, &wk);
  m.upper_body_acc_wk_rms_m_per_s2 = integral(simulate::kUpperBodyAcc, &wk);
  m.pitch_acc_we_rms_rad_per_s2 = integral(simulate::kPitchAcc, &we);
  m.seat_acc_rms_m_per_s2 = integral(simulate::kSeatAcc, nullptr);
  m.lower_body_acc_rms_m_per_s2 = integral(simulate::kLowerBodyAcc, nullptr);
  m.upper_body_acc_rms_m_per_s2 = integral(simulate::kUpperBodyAcc, nullptr);
  m.body_acc_rms_m_per_s2 = integral(simulate::kBodyAcc, nullptr);
  m.pitch_acc_rms_rad_per_s2 = integral(simulate::kPitchAcc, nullptr);
  m.front_travel_rms_m = integral(simulate::kFrontTravel, nullptr);
  m.rear_travel_rms_m = integral(simulate::kRearTravel, nullptr);
  m.front_tyre_force_rms_N = integral(simulate::kFrontTyreForce, nullptr);
  m.rear_tyre_force_rms_N = integral(simulate::kRearTyreForce, nullptr);
  const auto [front_load, rear_load] = static_wheel_loads_N(parameters);
  m.front_dynamic_load_ratio = m.front_tyre_force_rms_N / front_load;
  m.rear_dynamic_load_ratio = m.rear_tyre_force_rms_N / rear_load;
  return m;
}

}  // namespace ridefit::study
