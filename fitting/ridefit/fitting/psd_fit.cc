#include "ridefit/fitting/psd_fit.h"

#include <ceres/ceres.h>
#include <fmt/core.h>

#include <Eigen/Core>
#include <algorithm>
#include <boost/math/special_functions/digamma.hpp>
#include <boost/math/special_functions/trigamma.hpp>
#include <cmath>
#include <complex>
#include <memory>
#include <set>
#include <tuple>
#include <unsupported/Eigen/FFT>

#include "ridefit/common/errors.h"
#include "ridefit/fitting/integration_resolution.h"
#include "ridefit/io/command_column.h"
#include "ridefit/io/csv_table.h"
#include "ridefit/io/measurement_file.h"
#include "ridefit/model/quarter_car_parameter_table.h"
#include "ridefit/road/excitation_file.h"
#include "ridefit/road/measured_road.h"
#include "ridefit/signal/correlation_time.h"
#include "ridefit/signal/equivalent_dof.h"
#include "ridefit/signal/hann_window.h"
#include "ridefit/signal/noise_floor.h"
#include "ridefit/signal/signal_presence.h"
#include "ridefit/signal/uniform_sample_rate.h"
#include "ridefit/simulate/quarter_car_sensitivity.h"

namespace ridefit::fitting {
namespace {

constexpr int kMaxFree = static_cast<int>(PsdFitOptions::kMaxFree);

template <typename T>
T& field(model::QuarterCarParameters<T>& p, std::size_t index) {
  return model::quarter_car_parameter(p, index);
}

std::size_t parameter_index(const std::string& name) {
  if (const auto index = model::quarter_car_parameter_index(name)) return *index;
  std::string list;
  for (const auto& row : model::kQuarterCarParameters) {
    list += (list.empty() ? "" : ", ") + std::string(row.key);
  }
  throw InputError(fmt::format("'{}' is not a quarter-car parameter; one of: {}", name, list));
}

// Welch's PSD (periodic Hann, 50 % overlap, mean removed per segment) of a series and of its
// tangents, at the bins listed: P[k] and dP[k]/dθ_j = c·mean(2·Re(X̄·dX_j))/(fs·Σw²).
struct WelchBins {
  std::vector<std::size_t> bins;
  std::size_t length = 0;
  std::vector<double> window;
  double sample_rate_Hz = 0.0;

  double frequency_Hz(std::size_t b) const {
    return static_cast<double>(bins[b]) * sample_rate_Hz / static_cast<double>(length);
  }

  void evaluate(const std::vector<double>& x, const std::vector<std::vector<double>>& tangents,
                std::vector<double>& psd, std::vector<std::vector<double>>& dpsd) const {
    Eigen::FFT<double> fft;
    const std::size_t hop = length / 2;
    const std::size_t segments = (x.size() - length) / hop + 1;
    double window_power = 0.0;
    for (double w : window) window_power += w * w;
    psd.assign(bins.size(), 0.0);
    dpsd.assign(tangents.size(), std::vector<double>(bins.size(), 0.0));
    std::vector<double> segment(length);
    std::vector<std::complex<double>> spectrum, tangent_spectrum;
    auto transform = [&](const std::vector<double>& series, std::size_t start,
                         std::vector<std::complex<double>>& out) {
      double mean = 0.0;
      for (std::size_t i = 0; i < length; ++i) mean += series[start + i];
      mean /= static_cast<double>(length);
      for (std::size_t i = 0; i < length; ++i) segment[i] = (series[start + i] - mean) * window[i];
      fft.fwd(out, segment);
    };
    for (std::size_t s = 0; s < segments; ++s) {
      transform(x, s * hop, spectrum);
      for (std::size_t b = 0; b < bins.size(); ++b) psd[b] += std::norm(spectrum[bins[b]]);
      for (std::size_t j = 0; j < tangents.size(); ++j) {
        transform(tangents[j], s * hop, tangent_spectrum);
        for (std::size_t b = 0; b < bins.size(); ++b) {
          dpsd[j][b] += 2.0 * std::real(std::conj(spectrum[bins[b]]) * tangent_spectrum[bins[b]]);
        }
      }
    }
    for (std::size_t b = 0; b < bins.size(); ++b) {
      const double c = (bins[b] == 0 || 2 * bins[b] == length) ? 1.0 : 2.0;
      const double norm = c / (static_cast<double>(segments) * sample_rate_Hz * window_power);
      psd[b] *= norm;
      for (auto& d : dpsd) d[b] *= norm;
    }
  }
};

// The factor the accelerometer's chain puts on a channel's simulated PSD at `frequency_Hz`.
double chain_power(const model::AccelerationSensors<double>& sensors, bool body,
                   double frequency_Hz) {
  return body ? sensors.body_power_gain(frequency_Hz) : sensors.wheel_power_gain(frequency_Hz);
}

// One bin's residual against the measured log-PSD, with the sensor-noise floor N: the model
// as the sensor shows it, P + N, and the expected log of that noisy estimate. The measured
// estimate's noise part is its own χ² scatter, which the simulation (driven by the same road,
// without the noise) does not share: with q = N/(P + N) the noise's share of the bin, its
// log-estimate lies below ln(P + N) by about b·q·(2 − q) (a second-order expansion of
// E[ln X̂] over Var X̂ ∝ N² + 2·P·N; b = ln(ν/2) − ψ(ν/2) ≈ 1/ν is the whole bias of a pure
// χ²_ν/ν bin). So r = ln(P + N) − b·q·(2 − q) − ln P_meas, and dr/dP = (1 + 2·b·q·(1 − q))/(P + N)
// exactly. N = 0 is the plain ln P − ln P_meas.
struct BinResidual {
  double value = 0.0;
  double slope = 0.0;  // dr/dP
};
BinResidual bin_residual(double psd, double noise_psd, double log_bias, double measured_log) {
  const double shown = psd + noise_psd;
  const double q = noise_psd / shown;
  return {std::log(shown) - log_bias * q * (2.0 - q) - measured_log,
          (1.0 + 2.0 * log_bias * q * (1.0 - q)) / shown};
}

// The Jet's size is the number of free parameters rounded up to 2, 4, 6, 8 or 12: the
// simulation's cost grows with it, and most fits free two to four.
template <int N>
class PsdCost : public ceres::CostFunction {
  using Jet = ceres::Jet<double, N>;

 public:
  PsdCost(const PsdMeasurement& m, const model::QuarterCar& car, std::vector<std::size_t> fields,
          std::vector<double> units, WelchBins welch, std::vector<double> measured_body_log,
          std::vector<double> measured_wheel_log, NoiseFloors noise, double log_bias,
          simulate::AccelerationSolverOptions solver)
      : m_(m),
        car_(car),
        fields_(std::move(fields)),
        units_(std::move(units)),
        welch_(std::move(welch)),
        body_log_(std::move(measured_body_log)),
        wheel_log_(std::move(measured_wheel_log)),
        noise_(noise),
        log_bias_(log_bias),
        solver_(solver) {
    set_num_residuals(static_cast<int>(body_log_.size() + wheel_log_.size()));
    for (std::size_t i = 0; i < fields_.size(); ++i) mutable_parameter_block_sizes()->push_back(1);
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    model::QuarterCarParameters<double> values = car_.parameters();
    model::QuarterCarParameters<Jet> jets = values.cast<Jet>();
    for (std::size_t i = 0; i < fields_.size(); ++i) {
      const double v = parameters[i][0] * units_[i];
      field(values, fields_[i]) = v;
      field(jets, fields_[i]) = Jet(v, static_cast<int>(i));
      field(jets, fields_[i]).v[static_cast<Eigen::Index>(i)] = units_[i];
    }
    const model::QuarterCar car(car_.damper_state(), values, car_.command_input());
    if (!jacobians) return evaluate_values(car, values, residuals);
    const auto series =
        simulate::quarter_car_accelerations<Jet>(car, jets, *m_.road, m_.time_s, solver_);
    if (!series) return false;
    std::size_t row = 0;
    auto channel = [&](const std::vector<Jet>& acc, const std::vector<double>& measured_log,
                       double noise_psd, bool body) {
      if (measured_log.empty()) return true;
      std::vector<double> x(acc.size());
      std::vector<std::vector<double>> tangents(fields_.size(), std::vector<double>(acc.size()));
      for (std::size_t k = 0; k < acc.size(); ++k) {
        x[k] = acc[k].a;
        for (std::size_t j = 0; j < fields_.size(); ++j) {
          tangents[j][k] = acc[k].v[static_cast<Eigen::Index>(j)];
        }
      }
      std::vector<double> psd;
      std::vector<std::vector<double>> dpsd;
      welch_.evaluate(x, tangents, psd, dpsd);
      for (std::size_t b = 0; b < psd.size(); ++b, ++row) {
        // The model as the sensor would show it: its PSD through the accelerometer's chain
        // (c = g²·|H(f)|², acceleration_sensors.h), plus the noise floor. d(c·P) = dc·P + c·dP.
        const double f = welch_.frequency_Hz(b);
        const Jet c = body ? jets.sensors.body_power_gain(f) : jets.sensors.wheel_power_gain(f);
        const double shown = c.a * psd[b];
        if (!(shown + noise_psd > 0.0)) return false;
        const BinResidual r = bin_residual(shown, noise_psd, log_bias_, measured_log[b]);
        residuals[row] = r.value;
        if (jacobians) {
          for (std::size_t j = 0; j < fields_.size(); ++j) {
            const double dc = c.v[static_cast<Eigen::Index>(j)];
            if (jacobians[j]) jacobians[j][row] = (dc * psd[b] + c.a * dpsd[j][b]) * r.slope;
          }
        }
      }
      return true;
    };
    return channel(series->body, body_log_, noise_.body_psd, true) &&
           channel(series->wheel, wheel_log_, noise_.wheel_psd, false);
  }

 private:
  // Residuals only (Ceres' trial steps): the same run in doubles, without tangents.
  bool evaluate_values(const model::QuarterCar& car, const model::QuarterCarParameters<double>& p,
                       double* residuals) const {
    const auto series =
        simulate::quarter_car_accelerations<double>(car, p, *m_.road, m_.time_s, solver_);
    if (!series) return false;
    std::size_t row = 0;
    for (const auto& [acc, measured_log, noise_psd, body] :
         {std::tuple{&series->body, &body_log_, noise_.body_psd, true},
          std::tuple{&series->wheel, &wheel_log_, noise_.wheel_psd, false}}) {
      if (measured_log->empty()) continue;
      std::vector<double> psd;
      std::vector<std::vector<double>> none;
      welch_.evaluate(*acc, {}, psd, none);
      for (std::size_t b = 0; b < psd.size(); ++b, ++row) {
        const double shown = chain_power(p.sensors, body, welch_.frequency_Hz(b)) * psd[b];
        if (!(shown + noise_psd > 0.0)) return false;
        residuals[row] = bin_residual(shown, noise_psd, log_bias_, (*measured_log)[b]).value;
      }
    }
    return true;
  }

  const PsdMeasurement& m_;
  const model::QuarterCar car_;  // a copy: callers may pass a car made for the call
  std::vector<std::size_t> fields_;
  std::vector<double> units_;
  WelchBins welch_;
  std::vector<double> body_log_, wheel_log_;
  NoiseFloors noise_;
  double log_bias_;
  simulate::AccelerationSolverOptions solver_;
};

// ln of Welch's PSD at the bins; for a simulated channel shown as the sensor would (`sensors`
// given), times its chain's factor and with `noise_psd` added (the simulated side's floor).
std::vector<double> log_psd(const WelchBins& welch, const std::vector<double>& x,
                            double noise_psd = 0.0,
                            const model::AccelerationSensors<double>* sensors = nullptr,
                            bool body = true) {
  std::vector<double> psd;
  std::vector<std::vector<double>> none;
  welch.evaluate(x, {}, psd, none);
  for (std::size_t b = 0; b < psd.size(); ++b) {
    const double c = sensors ? chain_power(*sensors, body, welch.frequency_Hz(b)) : 1.0;
    psd[b] = std::log(std::max(c * psd[b] + noise_psd, 1e-300));
  }
  return psd;
}

double floor_of(const std::optional<double>& given, const std::vector<double>& measured,
                double sample_rate_Hz, double band_high_Hz, const char* flag) {
  if (measured.empty()) return 0.0;
  if (given) {
    if (!(*given >= 0.0) || !std::isfinite(*given)) {
      throw InputError(
          fmt::format("{} {}: expected a noise PSD level >= 0 in (m/s^2)^2/Hz", flag, *given));
    }
    return *given;
  }
  return signal::estimate_white_noise_floor(measured, sample_rate_Hz, band_high_Hz);
}

}  // namespace

PsdMeasurement load_psd_measurement(const std::filesystem::path& csv_file,
                                    const std::filesystem::path& excitation_file) {
  const io::CsvTable table = io::read_measurement_table(csv_file);
  PsdMeasurement m;
  m.source = csv_file.string();
  m.time_s = table.time_s();
  m.sample_rate_Hz = signal::uniform_sample_rate_Hz(m.time_s, m.source);
  const auto command = io::read_command_column(table, m.source);
  if (command && !excitation_file.empty()) {
    throw InputError(fmt::format(
        "{} has a {} column but the road comes from the excitation file {}: a controlled "
        "damper's command and its road must share the record's time base; give the road as a "
        "column of the record",
        m.source, command->name, excitation_file.string()));
  }
  if (!excitation_file.empty()) {
    if (table.has("road")) {
      throw InputError(fmt::format(
          "{} has a road column and an excitation file was given too; give one of them", m.source));
    }
    m.road = std::shared_ptr<road::RoadInput>(road::load_excitation(excitation_file));
    if (m.road->duration_s() < m.time_s.back() - 1e-9) {
      throw InputError(fmt::format("{}: the excitation lasts {} s, the measurement {} s",
                                   excitation_file.string(), m.road->duration_s(),
                                   m.time_s.back()));
    }
  } else {
    if (!table.has("road")) {
      throw InputError(fmt::format(
          "{}: no road column; give the road as a column or as an excitation file", m.source));
    }
    const auto& road = table.column("road");
    if (road.unit != "m") {
      throw InputError(
          fmt::format("{}: column road is in {}, expected a length (m, mm)", m.source, road.unit));
    }
    m.road = command ? std::make_shared<road::MeasuredRoad>(m.time_s, road.values, command->values,
                                                            command->unit)
                     : std::make_shared<road::MeasuredRoad>(m.time_s, road.values);
  }
  if (table.has("body_acc")) m.body_acc_m_per_s2 = table.column("body_acc").values;
  if (table.has("wheel_acc")) m.wheel_acc_m_per_s2 = table.column("wheel_acc").values;
  if (m.body_acc_m_per_s2.empty() && m.wheel_acc_m_per_s2.empty()) {
    throw InputError(fmt::format(
        "{}: no body_acc or wheel_acc column; the PSD fit needs at least one", m.source));
  }
  // Zero or constant channels, and a road that does not move, carry nothing to fit: their
  // spectra are round-off (exit 2, not a confident answer).
  std::vector<double> road_m(m.time_s.size());
  for (std::size_t k = 0; k < m.time_s.size(); ++k) road_m[k] = m.road->at(m.time_s[k]).elevation_m;
  signal::require_signal(road_m, excitation_file.empty() ? m.source : excitation_file.string(),
                         "road", "m");
  if (!m.body_acc_m_per_s2.empty()) {
    signal::require_signal(m.body_acc_m_per_s2, m.source, "body_acc", "m/s^2");
  }
  if (!m.wheel_acc_m_per_s2.empty()) {
    signal::require_signal(m.wheel_acc_m_per_s2, m.source, "wheel_acc", "m/s^2");
  }
  return m;
}

namespace {

// Everything a PSD fit fixes before it iterates: the parameters, their bounds and units, the
// Welch bins of the band and the measured log-PSDs.
struct PsdSetup {
  std::vector<std::size_t> fields;
  std::vector<std::pair<double, double>> bounds;
  std::vector<double> units;
  WelchBins welch;
  std::vector<double> body_log, wheel_log;
  NoiseFloors noise;
  double log_bias = 0.0;  // b = ln(ν/2) − ψ(ν/2) of the bins (bin_residual)
  double bin_sd = 1.0;    // √ψ′(ν/2): the standard deviation of a bin's log-estimate
};

// A data sheet's Gaussian prior on a parameter block x = p/unit: s·(x·unit − mean)/sd, in the
// units of the bins' residuals (PsdFitOptions::priors).
struct PriorResidual {
  double unit, mean, weight;  // weight = s/sd
  template <typename T>
  bool operator()(const T* x, T* residual) const {
    residual[0] = T(weight) * (x[0] * T(unit) - T(mean));
    return true;
  }
};

PsdSetup prepare(const PsdMeasurement& m, const model::QuarterCar& car,
                 const PsdFitOptions& options, bool fitting = true) {
  options.validate(fitting);
  std::vector<std::size_t> fields;
  if (fitting) {
    for (const auto& name : options.free) fields.push_back(parameter_index(name));
  }
  WelchBins welch;
  welch.sample_rate_Hz = m.sample_rate_Hz;
  welch.length = static_cast<std::size_t>(std::lround(options.segment_s * m.sample_rate_Hz));
  if (welch.length < 16 || welch.length > m.time_s.size()) {
    throw InputError(
        fmt::format("{}: a {} s segment needs {} samples of the {} recorded; use a shorter segment",
                    m.source, options.segment_s, welch.length, m.time_s.size()));
  }
  welch.window = signal::periodic_hann_window(welch.length);
  for (std::size_t k = 1; 2 * k <= welch.length; ++k) {
    const double f = static_cast<double>(k) * m.sample_rate_Hz / static_cast<double>(welch.length);
    if (f >= options.band_low_Hz && f <= options.band_high_Hz) welch.bins.push_back(k);
  }
  if (welch.bins.size() < fields.size() + 2) {
    throw InputError(fmt::format("band {}–{} Hz holds {} PSD bins; widen it", options.band_low_Hz,
                                 options.band_high_Hz, welch.bins.size()));
  }
  const std::vector<double> body_log =
      m.body_acc_m_per_s2.empty() ? std::vector<double>() : log_psd(welch, m.body_acc_m_per_s2);
  const std::vector<double> wheel_log =
      m.wheel_acc_m_per_s2.empty() ? std::vector<double>() : log_psd(welch, m.wheel_acc_m_per_s2);

  model::QuarterCarParameters<double> start = car.parameters();
  std::vector<std::pair<double, double>> bounds;
  std::vector<double> units;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    double v = field(start, fields[i]);
    std::pair<double, double> b{v / 10.0, v * 10.0};
    if (auto it = options.bounds.find(options.free[i]); it != options.bounds.end()) b = it->second;
    // A start a rounding error outside a bound is on it: a fit that ended on the bound hands on
    // its value rescaled (x·unit), which can land an ulp beyond it.
    const double slack = 1e-12 * std::max(std::abs(b.first), std::abs(b.second));
    if (v > b.second && v - b.second <= slack) v = b.second;
    if (v < b.first && b.first - v <= slack) v = b.first;
    if (!(b.first < b.second) || !(v >= b.first && v <= b.second) || !(v > 0.0)) {
      throw InputError(
          fmt::format("{}: start {} must be > 0 and inside its bounds [{}, {}] (lower below upper)",
                      options.free[i], v, b.first, b.second));
    }
    bounds.push_back(b);
    units.push_back(v);
  }

  const std::size_t segments = (m.time_s.size() - welch.length) / (welch.length / 2) + 1;
  const double nu = signal::welch_degrees_of_freedom(welch.window, welch.length / 2, segments);
  const double log_bias = std::log(0.5 * nu) - boost::math::digamma(0.5 * nu);
  const double bin_sd = std::sqrt(boost::math::trigamma(0.5 * nu));
  return {fields,   bounds, units, welch, body_log, wheel_log, noise_floors(m, options),
          log_bias, bin_sd};
}

simulate::AccelerationSolverOptions solver_options(const PsdFitOptions& options) {
  simulate::AccelerationSolverOptions solver;
  solver.relative_tolerance = options.relative_tolerance;
  solver.frozen_steps = options.frozen_steps;
  return solver;
}

ceres::CostFunction* new_psd_cost(const PsdMeasurement& m, const model::QuarterCar& car,
                                  const PsdSetup& s,
                                  const simulate::AccelerationSolverOptions& solver) {
  const std::size_t n = s.fields.size();
  if (n <= 2) {
    return new PsdCost<2>(m, car, s.fields, s.units, s.welch, s.body_log, s.wheel_log, s.noise,
                          s.log_bias, solver);
  }
  if (n <= 4) {
    return new PsdCost<4>(m, car, s.fields, s.units, s.welch, s.body_log, s.wheel_log, s.noise,
                          s.log_bias, solver);
  }
  if (n <= 6) {
    return new PsdCost<6>(m, car, s.fields, s.units, s.welch, s.body_log, s.wheel_log, s.noise,
                          s.log_bias, solver);
  }
  if (n <= 8) {
    return new PsdCost<8>(m, car, s.fields, s.units, s.welch, s.body_log, s.wheel_log, s.noise,
                          s.log_bias, solver);
  }
  return new PsdCost<kMaxFree>(m, car, s.fields, s.units, s.welch, s.body_log, s.wheel_log, s.noise,
                               s.log_bias, solver);
}

}  // namespace

NoiseFloors noise_floors(const PsdMeasurement& m, const PsdFitOptions& options) {
  return {floor_of(options.body_noise_psd, m.body_acc_m_per_s2, m.sample_rate_Hz,
                   options.band_high_Hz, "body_noise_psd"),
          floor_of(options.wheel_noise_psd, m.wheel_acc_m_per_s2, m.sample_rate_Hz,
                   options.band_high_Hz, "wheel_noise_psd")};
}

std::optional<PsdMismatch> psd_mismatch(const PsdMeasurement& m, const model::QuarterCar& given_car,
                                        const PsdFitOptions& options) {
  // A controlled damper follows the record's command when it has one.
  const model::QuarterCar car = given_car.with_command_from_road(m.road->has_command());
  const PsdSetup setup = prepare(m, car, options, false);
  const auto series = simulate::quarter_car_accelerations<double>(
      car, car.parameters(), *m.road, m.time_s, solver_options(options));
  if (!series) return std::nullopt;
  PsdMismatch mismatch;
  for (const auto& [acc, measured_log, noise_psd, body] :
       {std::tuple{&series->body, &setup.body_log, setup.noise.body_psd, true},
        std::tuple{&series->wheel, &setup.wheel_log, setup.noise.wheel_psd, false}}) {
    if (measured_log->empty()) continue;
    std::vector<double> psd;
    std::vector<std::vector<double>> none;
    setup.welch.evaluate(*acc, {}, psd, none);
    mismatch.channel_residuals.emplace_back();
    for (std::size_t b = 0; b < psd.size(); ++b) {
      const double shown =
          chain_power(car.parameters().sensors, body, setup.welch.frequency_Hz(b)) * psd[b];
      const double r =
          bin_residual(std::max(shown, 1e-300), noise_psd, setup.log_bias, (*measured_log)[b])
              .value;
      mismatch.cost += 0.5 * r * r;
      mismatch.channel_residuals.back().push_back(r);
      ++mismatch.residuals;
    }
  }
  mismatch.body_acc_m_per_s2 = std::move(series->body);
  mismatch.wheel_acc_m_per_s2 = std::move(series->wheel);
  return mismatch;
}

ceres::CostFunction* make_psd_cost(const PsdMeasurement& measurement,
                                   const model::QuarterCar& given_car,
                                   const PsdFitOptions& options) {
  // A controlled damper follows the record's command when it has one.
  const model::QuarterCar car = given_car.with_command_from_road(measurement.road->has_command());
  const PsdSetup setup = prepare(measurement, car, options);
  return new_psd_cost(measurement, car, setup, solver_options(options));
}

PsdFitResult fit_psd(const PsdMeasurement& m, const model::QuarterCar& given_car,
                     const PsdFitOptions& options) {
  // A controlled damper follows the record's command when it has one.
  const model::QuarterCar car = given_car.with_command_from_road(m.road->has_command());
  const PsdSetup setup = prepare(m, car, options);
  const auto& [fields, bounds, units, welch, body_log, wheel_log, noise, log_bias, bin_sd] = setup;
  PsdFitResult best;
  best.final_cost = std::numeric_limits<double>::infinity();
  for (int start_index = 0; start_index < std::max(1, options.starts); ++start_index) {
    std::vector<double> x(fields.size());
    for (std::size_t i = 0; i < fields.size(); ++i) {
      // Start 0 is the model's value; the others spread geometrically inside the bounds.
      const double fraction = (start_index + 0.5) / std::max(1, options.starts);
      const double v =
          start_index == 0
              ? units[i]
              : bounds[i].first * std::pow(bounds[i].second / bounds[i].first, fraction);
      x[i] = v / units[i];
    }
    ceres::Problem problem;
    ceres::CostFunction* cost = new_psd_cost(m, car, setup, solver_options(options));
    std::vector<double*> blocks;
    for (double& v : x) blocks.push_back(&v);
    problem.AddResidualBlock(cost, make_loss_function(options.loss, options.loss_scale), blocks);
    int priors = 0;
    for (std::size_t i = 0; i < fields.size(); ++i) {
      const auto prior = options.priors.find(options.free[i]);
      if (prior == options.priors.end()) continue;
      problem.AddResidualBlock(
          new ceres::AutoDiffCostFunction<PriorResidual, 1, 1>(
              new PriorResidual{units[i], prior->second.mean, bin_sd / prior->second.sd}),
          nullptr, &x[i]);
      ++priors;
    }
    for (std::size_t i = 0; i < fields.size(); ++i) {
      problem.SetParameterLowerBound(&x[i], 0, bounds[i].first / units[i]);
      problem.SetParameterUpperBound(&x[i], 0, bounds[i].second / units[i]);
    }
    ceres::Solver::Options solver;
    solver.linear_solver_type = ceres::DENSE_QR;
    solver.max_num_iterations = options.max_iterations;
    // With bounds, Ceres' trust region otherwise runs a projected line search on every step whose
    // trial points it evaluates with the Jacobian: a whole tangent replay per candidate
    // (psd_fit_bench went from 3.7 to 2.5 s without it). The step is projected onto the bounds all
    // the same.
    solver.max_num_line_search_step_size_iterations = 0;
    solver.logging_type = ceres::SILENT;
    // What the integration resolves (integration_resolution.h): the log-PSD residuals at the
    // iterate at the fit's tolerance and at four times it. Frozen steps are one discrete map.
    simulate::AccelerationSolverOptions coarser = solver_options(options);
    coarser.relative_tolerance = coarser_tolerance(coarser.relative_tolerance);
    const std::unique_ptr<ceres::CostFunction> at_coarser(new_psd_cost(m, car, setup, coarser));
    // The scatter under the same robust loss as the cost it is compared with.
    const std::unique_ptr<ceres::LossFunction> floor_loss(
        make_loss_function(options.loss, options.loss_scale));
    auto measure_floor = [&]() -> double {
      if (options.frozen_steps != nullptr) return 0.0;
      const auto rows = static_cast<std::size_t>(cost->num_residuals());
      std::vector<double> residuals(rows), coarse(rows);
      const std::vector<const double*> at(blocks.begin(), blocks.end());
      if (!cost->Evaluate(at.data(), residuals.data(), nullptr) ||
          !at_coarser->Evaluate(at.data(), coarse.data(), nullptr)) {
        return 0.0;
      }
      return integration_cost_floor(residuals, coarse, floor_loss.get());
    };
    StopAtIntegrationResolution stop(measure_floor,
                                     static_cast<std::size_t>(cost->num_residuals()));
    solver.update_state_every_iteration = true;
    solver.callbacks.push_back(&stop);
    ceres::Solver::Summary summary;
    ceres::Solve(solver, &problem, &summary);
    if (!(summary.final_cost < best.final_cost)) continue;
    PsdFitResult result;
    result.names = options.free;
    result.final_cost = summary.final_cost;
    result.iterations = static_cast<int>(summary.iterations.size()) - 1;
    result.converged = summary.termination_type == ceres::CONVERGENCE || stop.reached();
    result.termination =
        stop.reached() ? integration_resolution_message(stop.floor()) : summary.message;
    const double dof =
        static_cast<double>(cost->num_residuals() + priors) - static_cast<double>(fields.size());
    const double s2 = dof > 0 ? 2.0 * summary.final_cost / dof : 0.0;
    ceres::Covariance::Options covariance_options;
    covariance_options.algorithm_type = ceres::DENSE_SVD;
    ceres::Covariance covariance(covariance_options);
    std::vector<std::pair<const double*, const double*>> pairs;
    for (std::size_t i = 0; i < x.size(); ++i) {
      for (std::size_t j = i; j < x.size(); ++j) pairs.emplace_back(&x[i], &x[j]);
    }
    // Ceres' dense SVD must not see a non-finite Jacobian (it can crash inside Eigen): check the
    // Jacobian at the optimum first, and report no standard errors when it is not finite.
    const bool finite_jacobian = [&] {
      ceres::CRSMatrix jacobian;
      if (!problem.Evaluate(ceres::Problem::EvaluateOptions(), nullptr, nullptr, nullptr,
                            &jacobian)) {
        return false;
      }
      return std::all_of(jacobian.values.begin(), jacobian.values.end(),
                         [](double v) { return std::isfinite(v); });
    }();
    const bool have = dof > 0 && finite_jacobian && covariance.Compute(pairs, &problem);
    const auto k = static_cast<Eigen::Index>(fields.size());
    Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(k, k);
    if (have) {
      for (std::size_t i = 0; i < x.size(); ++i) {
        for (std::size_t j = i; j < x.size(); ++j) {
          double c = 0.0;
          covariance.GetCovarianceBlock(&x[i], &x[j], &c);
          const auto a = static_cast<Eigen::Index>(i), b = static_cast<Eigen::Index>(j);
          cov(a, b) = cov(b, a) = s2 * c * units[i] * units[j];
        }
      }
      result.correlation = cov;
      for (Eigen::Index a = 0; a < k; ++a) {
        for (Eigen::Index b = 0; b < k; ++b) {
          result.correlation(a, b) = cov(a, b) / std::sqrt(cov(a, a) * cov(b, b));
        }
      }
    }
    // Neighbouring bins and a spectrum's misfit are correlated: the errors are widened by √τ of
    // each channel's residuals (the identifiability below judges independent bins).
    if (have) {
      std::vector<double> residuals(static_cast<std::size_t>(cost->num_residuals()));
      const std::vector<const double*> at(blocks.begin(), blocks.end());
      if (cost->Evaluate(at.data(), residuals.data(), nullptr)) {
        // body bins first, then wheel (either may be absent)
        const std::size_t lengths[] = {setup.body_log.size(), setup.wheel_log.size()};
        result.residual_correlation_samples =
            signal::pooled_correlation_time_samples(residuals, lengths);
      }
    }
    const double widen = result.residual_correlation_samples;
    result.fitted = car.parameters();
    std::set<std::size_t> weak;
    for (std::size_t i = 0; i < fields.size(); ++i) {
      const double value = x[i] * units[i];
      result.values.push_back(value);
      field(result.fitted, fields[i]) = value;
      const auto a = static_cast<Eigen::Index>(i);
      if (have) {
        result.standard_errors.push_back(std::sqrt(widen * cov(a, a)));
        // The same rules as the hysteresis fit: SE above half the value, or |ρ| > 0.995.
        if (std::sqrt(cov(a, a)) > 0.5 * std::abs(value)) weak.insert(i);
        for (Eigen::Index b = a + 1; b < k; ++b) {
          if (std::abs(result.correlation(a, b)) > 0.995) {
            weak.insert(i);
            weak.insert(static_cast<std::size_t>(b));
          }
        }
      } else {
        result.standard_errors.push_back(std::nullopt);
        weak.insert(i);  // no covariance: the Jacobian is rank-deficient at the optimum
      }
    }
    for (std::size_t i : weak) result.unidentifiable.push_back(options.free[i]);
    if (!weak.empty()) {
      std::string list;
      for (const auto& name : result.unidentifiable) list += (list.empty() ? "" : ", ") + name;
      result.identifiability_note = fmt::format(
          "the spectra cannot determine {} (a standard error above half the value, a correlation "
          "above 0.995, or a rank-deficient Jacobian): fix {} or widen the band",
          list, weak.size() > 1 ? "some of them" : "it");
    }
    best = std::move(result);
  }
  // The spectra at the optimum, for the figure.
  for (std::size_t b : welch.bins) {
    best.frequency_Hz.push_back(static_cast<double>(b) * m.sample_rate_Hz /
                                static_cast<double>(welch.length));
  }
  const model::QuarterCar fitted_car(car.damper_state(), best.fitted, car.command_input());
  const auto series = simulate::quarter_car_accelerations<double>(
      fitted_car, best.fitted, *m.road, m.time_s, solver_options(options));
  auto exp_of = [](std::vector<double> v) {
    for (double& x : v) x = std::exp(x);
    return v;
  };
  if (series && !body_log.empty()) {
    best.measured_body_psd = exp_of(body_log);
    best.fitted_body_psd =
        exp_of(log_psd(welch, series->body, noise.body_psd, &best.fitted.sensors, true));
  }
  if (series && !wheel_log.empty()) {
    best.measured_wheel_psd = exp_of(wheel_log);
    best.fitted_wheel_psd =
        exp_of(log_psd(welch, series->wheel, noise.wheel_psd, &best.fitted.sensors, false));
  }
  best.noise_floors = noise;
  return best;
}

}  // namespace ridefit::fitting
