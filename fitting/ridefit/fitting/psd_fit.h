#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <ceres/cost_function.h>

#include <Eigen/Core>

#include "ridefit/model/quarter_car.h"
#include "ridefit/road/road_input.h"
#include "ridefit/simulate/esdirk_integrator.h"

#include "ridefit/fitting/psd_fit_options.h"

namespace ridefit::fitting {

// A vehicle measurement for the PSD fit: the road under the wheel and the measured body and/or
// wheel acceleration, on one uniform time base.
struct PsdMeasurement {
  std::string source;
  std::vector<double> time_s;
  double sample_rate_Hz = 0.0;
  std::shared_ptr<road::RoadInput> road;
  std::vector<double> body_acc_m_per_s2;   // empty when the file has no body_acc
  std::vector<double> wheel_acc_m_per_s2;  // empty when the file has no wheel_acc
};

// Reads a CSV with `time` and at least one of `body_acc`, `wheel_acc` (any supported units), and
// the road either as a `road` column or, when `excitation_file` is given, from that excitation
// (a known rig or road input). A `current` or `voltage` column is a controlled damper's command:
// the road then carries it (RoadInput::has_command) and the fits' cars follow it. InputError
// naming the file and what is missing.
PsdMeasurement load_psd_measurement(const std::filesystem::path& csv_file,
                                    const std::filesystem::path& excitation_file = {});

// The noise floors a fit or a comparison on `measurement` uses [(m/s²)²/Hz]: the options' values
// where given, else estimated from the measured channel above options.band_high_Hz; 0 for a
// channel the record does not have.
struct NoiseFloors {
  double body_psd = 0.0;
  double wheel_psd = 0.0;
};
NoiseFloors noise_floors(const PsdMeasurement& measurement, const PsdFitOptions& options);

struct PsdFitResult {
  std::vector<std::string> names;
  std::vector<double> values;
  std::vector<std::optional<double>> standard_errors;
  Eigen::MatrixXd correlation;  // of the free parameters; empty when not computable
  std::vector<std::string> unidentifiable;
  std::string identifiability_note;
  double final_cost = 0.0;
  // Bins per independent residual at the end (signal::correlation_time_samples, each channel's
  // own pooled): the standard errors are widened by its square root.
  double residual_correlation_samples = 1.0;
  int iterations = 0;
  bool converged = false;
  std::string termination;
  std::vector<double> frequency_Hz;                          // the band's bins
  std::vector<double> measured_body_psd, fitted_body_psd;    // empty without body_acc
  std::vector<double> measured_wheel_psd, fitted_wheel_psd;  // empty without wheel_acc
  // The fitted PSDs include the noise floors (P_sim + N: what was compared with the
  // measurement); the floors themselves [(m/s²)²/Hz].
  NoiseFloors noise_floors;
  model::QuarterCarParameters<double> fitted;
};

// Fits the free parameters of the stick/slip (or the file's) quarter car so that its simulated
// body and wheel acceleration PSDs match the measured ones over the band: residuals are the
// differences of the natural logs of the PSDs bin by bin, ln(c·P_sim + N) − ln(P_meas) with c the
// accelerometer chain's g²·|H(f)|² (the car's sensors, model/acceleration_sensors.h: 1 for an
// ideal sensor; its gains and cutoff may be freed, d(c·P) = dc·P + c·dP) and N the
// channel's sensor-noise floor (noise_floors; d ln(P + N) = dP/(P + N)), less the small expected
// log-bias of the noise's own χ² scatter in bins it dominates (b·q·(2 − q), q = N/(P + N),
// b ≈ 1/ν; psd_fit.cc bin_residual) (Welch with the same settings on both sides, so every bin has
// the same χ² confidence and the same weight). The
// simulation runs the measured road through quarter_car_accelerations (adaptive ESDIRK; with Jets,
// the tangents of its frozen step sequence), and the PSD's derivatives follow from the FFT's
// linearity (dP = 2·Re(X̄·dX) per segment), so the Jacobian is exact. Standard errors from the
// Jacobian at the optimum, scaled by the residual variance and the bins' correlation time (the
// errors widened by √τ). The cost function fit_psd hands to
// Ceres (log-PSD residuals of the band, one parameter block of size 1 per free parameter in units
// of its start value, so 1.0 is the model's value), exposed for the gradient check. The caller owns
// it; `measurement` and `car` must outlive it.
ceres::CostFunction* make_psd_cost(const PsdMeasurement& measurement, const model::QuarterCar& car,
                                   const PsdFitOptions& options);

// How far `car` is from `measurement` on the fit's own terms (band, segments, tolerance; `free` is
// ignored): ½·Σ r² over the log-PSD residuals of both channels, their count, and the simulated
// accelerations on the measurement's time base. None when the simulation fails (the integrator
// gives up). Scores a fitted model on data the fit did not see.
struct PsdMismatch {
  double cost = 0.0;
  std::size_t residuals = 0;
  std::vector<double> body_acc_m_per_s2, wheel_acc_m_per_s2;
  // The residuals per channel (body, then wheel when measured), bin by bin.
  std::vector<std::vector<double>> channel_residuals;
};
std::optional<PsdMismatch> psd_mismatch(const PsdMeasurement& measurement,
                                        const model::QuarterCar& car, const PsdFitOptions& options);

PsdFitResult fit_psd(const PsdMeasurement& measurement, const model::QuarterCar& car,
                     const PsdFitOptions& options);

}  // namespace ridefit::fitting
