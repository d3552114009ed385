#pragma once

#include <ceres/cost_function.h>

#include <Eigen/Core>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ridefit/fitting/hysteresis_fit_options.h"
#include "ridefit/fitting/hysteresis_record.h"
#include "ridefit/model/strut_test.h"
#include "ridefit/simulate/strut_test_response.h"

namespace ridefit::fitting {

struct FittedParameter {
  std::string name;
  std::string file;  // the file it belongs to (per-file parameters), else empty
  double value = 0.0;
  std::optional<double> standard_error;  // empty when the data cannot determine it
};

struct HysteresisFitResult {
  std::vector<FittedParameter> parameters;  // the free ones, shared first, then per file
  Eigen::MatrixXd correlation;              // of `parameters`; empty when not computable
  double initial_cost = 0.0;
  double final_cost = 0.0;  // ½·Σ r²
  double residual_rms_N = 0.0;
  // Samples per independent residual at the end (signal::correlation_time_samples, pooled over
  // the records): the standard errors are widened by its square root.
  double residual_correlation_samples = 1.0;
  int iterations = 0;
  bool converged = false;
  std::string termination;  // Ceres' own words
  // Parameters the data cannot tell apart or determine: those that carry the Jacobian's
  // near-null directions (singular value below 1e-6 of the largest, after scaling each column
  // by its parameter's value), with the reason in words.
  std::vector<std::string> unidentifiable;
  std::string identifiability_note;
  // Whether the model explains the data: the NRMSE of the fitted force over all records (%),
  // the free parameters that ended on a bound, and the verdict. A fit is flagged when its NRMSE
  // is above max_nrmse_percent, or when parameters end on bounds while the data leave some
  // parameters undetermined (a collapsed fit: the model gave up a mechanism to imitate another).
  double nrmse_percent = 0.0;
  // Each record's own NRMSE (%; its residual over its own force's spread), in record order.
  std::vector<double> record_nrmse_percent;
  std::vector<std::string> on_bounds;
  bool explains_data = true;
  std::string adequacy_note;                               // why not, in words ("" when it does)
  std::vector<std::vector<double>> fitted_force_N;         // per record, at the fitted parameters
  std::vector<model::StrutTestParameters<double>> fitted;  // per record
};

// Fits the free strut-test parameters to one or several records at once by nonlinear least
// squares (Ceres, Levenberg-Marquardt within bounds) on the force residuals. The Jacobian is
// exact: Jets run through the implicit solver (strut_test_response.h). Standard errors come
// from ceres::Covariance, scaled by the residual variance s² = 2·cost/(m − n) and by the
// residuals' correlation time τ (m/τ independent residuals). InputError for
// an unknown or repeated parameter, a per-file parameter that is not free, bounds with
// lower >= upper, or a start outside its bounds; RunError when the model cannot be solved at
// the start.
// How a record's Jacobian is evaluated: 7 to 12 free values in two halves of Jet lanes on two
// threads over one recorded run (what fit_hysteresis does), or every value in one pass of Jets
// (the reference the split is checked against; always so below 7).
enum class JacobianPasses { kSplitAcrossTwoCores, kOnePass };

struct HysteresisCostOptions {
  JacobianPasses passes = JacobianPasses::kSplitAcrossTwoCores;
  // Each run in doubles records its steps, and a Jacobian at the same values replays them
  // instead of running the record again (what fit_hysteresis does: Ceres asks for the Jacobian
  // at the trial point it has just accepted).
  bool keep_steps = false;
};

// The residual block of one record (force residuals, N) with one parameter block of size 1 per
// name in `free`, in the parameters' own units: what fit_hysteresis hands to Ceres, exposed for
// the gradient check. The caller owns it.
ceres::CostFunction* make_hysteresis_cost(const HysteresisRecord& record,
                                          const model::StrutTestParameters<double>& base,
                                          const std::vector<std::string>& free,
                                          const simulate::StrutTestSolverOptions& solver = {},
                                          const HysteresisCostOptions& cost = {});

// Each record's residual weight under `weighting` (RecordWeighting): all 1 for kNewtons; for
// kRelative the records' RMS spread over the record's own (its force's RMS about its mean).
std::vector<double> record_weights(const std::vector<HysteresisRecord>& records,
                                   RecordWeighting weighting);

// The largest force magnitude in the records [N] (HysteresisFitOptions::force_scale_N).
double largest_force_N(const std::vector<HysteresisRecord>& records);

HysteresisFitResult fit_hysteresis(const std::vector<HysteresisRecord>& records,
                                   const model::StrutTestParameters<double>& start,
                                   const HysteresisFitOptions& options);

}  // namespace ridefit::fitting
