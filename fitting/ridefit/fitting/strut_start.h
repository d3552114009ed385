#pragma once

#include <map>
#include <optional>
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
// Where the command takes more than two values, u enters as sgn(u)·|u|^p and the exponent p
// (command_exponent) is the one of a grid from 0.2 to 3 that fits these rows best.
// σ0 comes from the force's rise after each reversal (estimate_pre_sliding_stiffness) once Fc is
// known; the top-mount stiffness is not estimated (in series with σ0, the rise shows their series
// value). Keys are kStrutParameters names.
std::map<std::string, double> estimate_strut_start(const std::vector<HysteresisRecord>& records);

// The pre-sliding (Dahl) stiffness σ0 [N/m] read off the records: after each reversal (the
// displacement turning by more than 2 % of its stroke), the secant from the reversal to where the
// force has moved by `friction_N`, times 2·ln 2 (Dahl's law from a reversal reaches Fc there); the
// median over reversals. None with fewer than two reversals that show it.
std::optional<double> estimate_pre_sliding_stiffness(const std::vector<HysteresisRecord>& records,
                                                     double friction_N);

// Fits from each start (the same free parameters and options) and keeps the lowest final cost.
// Without per-file parameters each start first gets four iterations, and only the lowest cost
// then is fitted on to convergence (its iterations counted in); when that fit ends with a
// parameter on a bound, the next starts are fitted on too, and the lowest cost with no parameter
// on a bound is kept (the lowest cost when every start ends on one).
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
