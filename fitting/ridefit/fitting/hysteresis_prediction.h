#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ridefit/fitting/hysteresis_record.h"
#include "ridefit/model/strut_test.h"
#include "ridefit/simulate/strut_test_response.h"

namespace ridefit::fitting {

// A fitted strut's force on a record it was not fitted to (a held-out test: the second half of
// a random record, another file's sine tests), scored as a fit is.
struct RecordPrediction {
  std::string source;
  std::vector<double> force_N;  // at every sample of the record
  double score_from_s = 0.0;    // samples before this time are run through but not scored
  std::size_t scored = 0;       // samples scored
  double residual_rms_N = 0.0;
  // RMS of the residual over the scored samples' measured spread about their own mean (%): each
  // test normalised by its own force, as the fit's per-record NRMSE is.
  double nrmse_percent = 0.0;
  // A random motion's band (signal/excitation_band.h: 99 % of the rig velocity's power below it)
  // and the NRMSE of the residual's part within it: what a model driven by the motion could reach
  // when the rest is the load cell's noise. 0 and nrmse_percent for a periodic test (its
  // velocity repeats: ExcitationBand::repeat_correlation; its force's harmonics are the damper's)
  // and when the scored part is under 128 samples.
  double excitation_band_Hz = 0.0;
  double in_band_nrmse_percent = 0.0;
};

// NRMSE (%) of `model_N` against `measured_N` over samples [first, n): RMS residual over the
// measured spread about its mean; 0 for a record with no spread.
double nrmse_percent(const std::vector<double>& measured_N, const std::vector<double>& model_N,
                     std::size_t first = 0);

// `strut`'s force on one record from rest at its first sample; none when the integrator fails.
// A single run, not a fit's evaluation: when the step budget (max_steps_per_s, which keeps a
// fit from lingering in an extreme corner) runs out it tries once more with 20 times the
// budget. A fitted free play of micrometres with a rigid mount crosses its slack on every
// quantisation step of a 2 mm test, about 6 000 steps per second plus as many retries, and the
// fitted model is not wrong for needing them.
std::optional<std::vector<double>> run_fitted_strut(const HysteresisRecord& record,
                                                    const model::StrutTestParameters<double>& strut,
                                                    const simulate::StrutTestSolverOptions& solver);

// Runs `strut` over each record from rest at its first sample and scores samples at times >=
// score_from_s. RunError naming the record when the model cannot be solved on it.
std::vector<RecordPrediction> predict_records(const std::vector<HysteresisRecord>& records,
                                              const model::StrutTestParameters<double>& strut,
                                              const simulate::StrutTestSolverOptions& solver,
                                              double score_from_s = 0.0);

}  // namespace ridefit::fitting
