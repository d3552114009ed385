#pragma once

#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "ridefit/fitting/robust_loss.h"
#include "ridefit/fitting/strut_parameters.h"
#include "ridefit/simulate/strut_test_response.h"

namespace ridefit::fitting {

// How the records of one fit weigh against each other. kNewtons: every residual in newtons, so a
// test at 1 A (±1.5 kN) outweighs one at 0 A (±0.2 kN) fifty-fold and the weak test's levels are
// whatever the strong ones leave. kRelative: each record's residuals over its force's spread
// (the RMS about its mean), rescaled so that records of equal spread keep weight 1; every test
// then counts by its relative misfit, which is how per-test NRMSE judges a pooled fit.
enum class RecordWeighting { kNewtons, kRelative };

// "newtons" or "relative"; InputError naming the choices otherwise.
RecordWeighting parse_record_weighting(const std::string& text);

// What a hysteresis fit frees, within which bounds, and how it weighs residuals (Ceres'
// Solver::Options style: plain fields with defaults, checked as a whole by validate()).
struct HysteresisFitOptions {
  std::vector<std::string> free;      // parameters to fit (names of kStrutParameters)
  std::vector<std::string> per_file;  // of those, the ones each file gets its own value of
  std::map<std::string, std::pair<double, double>> bounds;  // overrides of the defaults
  RobustLoss loss = RobustLoss::kNone;                      // robust against outlying samples
  double loss_scale_N = 5.0;  // where the robust loss starts to discount a residual
  RecordWeighting record_weighting = RecordWeighting::kNewtons;
  int max_iterations = 100;
  // End the fit where the integration no longer resolves its cost (integration_resolution.h);
  // false runs on to Ceres' own tolerances (to check that the stop ends where they would).
  bool stop_at_integration_resolution = true;
  simulate::StrutTestSolverOptions solver;
  // Above this NRMSE (%, the residual's RMS over the measured force's spread about its mean) the
  // fitted model is flagged as not explaining the data.
  double max_nrmse_percent = 10.0;
  // The records' largest force magnitude [N] (0: not known). The default bounds of the force
  // levels (friction, breakaway, the command's friction slope, gas force, offset) are wide enough
  // for a passenger-car strut; a 10 kN friction damper needs more, so they widen to 5× this where
  // it is larger. fit_hysteresis fills it from its records when it is 0. Explicit `bounds` win.
  double force_scale_N = 0.0;

  // InputError naming the option for: no free parameter, an unknown or repeated one, a per-file
  // parameter that is not free, bounds of an unknown parameter or with lower >= upper or not
  // finite, a loss scale or NRMSE threshold that is not > 0, a negative iteration limit.
  void validate() const;

  // Every strut parameter's bounds: kStrutParameters' defaults, widened for force_scale_N, with
  // `bounds` applied.
  std::array<std::pair<double, double>, kStrutParameters.size()> resolved_bounds() const;
};

}  // namespace ridefit::fitting
