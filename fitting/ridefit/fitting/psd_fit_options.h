#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ridefit/fitting/robust_loss.h"
#include "ridefit/simulate/esdirk_integrator.h"

namespace ridefit::fitting {

// What a PSD fit frees and how it compares spectra (Ceres' Solver::Options style: plain fields
// with defaults, checked as a whole by validate()).
struct PsdFitOptions {
  std::vector<std::string> free;                            // quarter-car keys, at most 12
  std::map<std::string, std::pair<double, double>> bounds;  // default: a decade each way
  double band_low_Hz = 0.5;
  double band_high_Hz = 30.0;
  double segment_s = 10.0;  // Welch, Hann, 50 % overlap, the same on both sides
  // The simulation's relative tolerance (simulate::AccelerationSolverOptions): 1e-4 keeps the
  // accelerations' RMS within 0.02 % of CVODE at 1e-10, far inside a Welch bin's scatter.
  double relative_tolerance = 1e-4;
  // Tests only: run every evaluation on these steps (simulate::quarter_car_steps at the point
  // checked), so central differences see the same discrete map the Jacobian belongs to.
  const simulate::EsdirkStepHistory* frozen_steps = nullptr;
  int max_iterations = 50;
  int starts = 1;  // multi-start: also start at these many spread points within the bounds
  RobustLoss loss = RobustLoss::kNone;  // on the log-PSD residuals
  double loss_scale = 0.5;              // in natural-log units: a factor e^0.5 = 1.65 in PSD
  // The white sensor-noise floor of each channel, the one-sided PSD level N [(m/s²)²/Hz] the
  // accelerometer adds: the fit compares ln(P_sim + N) with ln(P_meas), so bins where the noise
  // dominates the measurement no longer pull the parameters. Empty = estimated from each
  // measured record (signal/noise_floor.h: the constant of a power law plus a constant fitted
  // to the measured PSD above the band); 0 = no floor (the plain log-PSD residual).
  std::optional<double> body_noise_psd;
  std::optional<double> wheel_noise_psd;
  // Gaussian priors on free parameters, as a data sheet states its values (mean ± sd, in the
  // parameter's SI unit). Each adds the residual s·(p − mean)/sd, s the standard deviation of a
  // bin's log-PSD residual (√ψ′(ν/2) for Welch bins of ν degrees of freedom), so that one prior
  // weighs as one bin's scatter would at one standard deviation. A parameter without one has
  // only its bounds. The mean is the sheet's value, not the fit's start: a fit that starts from
  // a refitted model keeps the prior where the sheet put it.
  struct GaussianPrior {
    double mean = 0.0;
    double sd = 0.0;
  };
  std::map<std::string, GaussianPrior> priors;

  // At most this many free parameters: a baseline whose masses, stiffnesses, damping and tyre
  // are all uncertain (with priors) and an effect's two or three; beyond it the Jets' width
  // makes a fit slower than a diagnosis can wait for.
  static constexpr std::size_t kMaxFree = 12;

  // InputError naming the option for: an unknown or repeated free parameter or more than
  // kMaxFree of them (and none at all when `fitting`), bounds with lower >= upper or not
  // finite, a prior on a parameter that is not free or with sd <= 0 or not finite, a band
  // that is not 0 < low < high, a segment, loss scale, tolerance or start count that is not > 0,
  // a negative iteration limit.
  void validate(bool fitting = true) const;
};

}  // namespace ridefit::fitting
