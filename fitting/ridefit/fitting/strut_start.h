#pragma once

#include <map>
#include <string>
#include <vector>

#include "ridefit/fitting/hysteresis_fit.h"
#include "ridefit/fitting/hysteresis_record.h"
#include "ridefit/model/strut_test.h"

namespace ridefit::fitting {

// Start values read off rig records, so a fit does not depend on a model file's guess alone.
// Away from reversals (|v| above a fifth of its RMS, where the pre-sliding branch has ended) the
// rig force is close to
//   F ≈ F_0 + k_g·x + (c + c_b·u)·v + (Fc + Fc_b·u)·sgn(v)
// and these are found by linear least squares (v by central differences of x; the u terms only
// with a command column). Quantities the records cannot separate are left out: on a constant-speed
// triangle |v| hardly varies, v and sgn(v) are collinear and only the friction is estimated, since
// a constant-speed test shows a force level, not a slope. Negative damping or friction is dropped.
// The top-mount stiffness and σ0 are not estimated (they show only in the few samples after each
// reversal). Keys are kStrutParameters names.
std::map<std::string, double> estimate_strut_start(const std::vector<HysteresisRecord>& records);

// Fits from each start (the same free parameters and options) and keeps the lowest final cost.
// Without per-file parameters each start first gets four iterations, and only the lowest cost
// then is fitted on to convergence (its iterations counted in).
// Starts whose free values equal an earlier start's are skipped; a start outside the bounds is
// moved inside them; a start the model cannot be solved at is skipped (RunError only when every
// start fails). `start_labels` (same size as `starts`, may be empty) name the starts; the winner's
// label is returned in `chosen` when given.
HysteresisFitResult fit_hysteresis_from_starts(
    const std::vector<HysteresisRecord>& records,
    const std::vector<model::StrutTestParameters<double>>& starts,
    const HysteresisFitOptions& options, const std::vector<std::string>& start_labels = {},
    std::string* chosen = nullptr);

// The two starts of `ridefit fit hysteresis`, the better fit kept: `start` (a model file's
// values) and the same with the levels read off the records (estimate_strut_start) for the free
// parameters. `chosen` gets "the model file" or "levels read off the records".
HysteresisFitResult fit_hysteresis_from_file_and_records(
    const std::vector<HysteresisRecord>& records, const model::StrutTestParameters<double>& start,
    const HysteresisFitOptions& options, std::string* chosen = nullptr);

// `base` with the free parameters of `estimate` (those in `free`) set to its values.
model::StrutTestParameters<double> with_estimates(model::StrutTestParameters<double> base,
                                                  const std::map<std::string, double>& estimate,
                                                  const std::vector<std::string>& free);

}  // namespace ridefit::fitting
