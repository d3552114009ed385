#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "ridefit/fitting/friction_compression.h"
#include "ridefit/fitting/hysteresis_fit.h"
#include "ridefit/fitting/hysteresis_record.h"
#include "ridefit/signal/hysteresis_friction.h"

namespace ridefit::fitting {

// What a hysteresis fit reports beside the fit itself: the start it kept, each record's seed
// calibration value (seed 000's half loop height at x = 0, to compare with the fitted Fc), and,
// given each record's spring compression, the line of the per-file friction against it.
struct HysteresisFitReport {
  std::string start;                 // the label of the start the fit kept
  std::vector<std::string> sources;  // the records, in order
  // Per record; none for a record with fewer than 2 cycles through zero (a random test).
  std::vector<std::optional<signal::HysteresisFriction>> calibration;
  std::optional<FrictionCompressionLine> friction_line;  // only with compressions
  // When the records carry a command column that the fitted model has no law for: which
  // column, and how to fit it; empty otherwise.
  std::string unused_command;
  // Per record: how its displacement was treated for quantisation (empty: not examined, as for
  // a record built in memory).
  std::vector<std::optional<signal::QuantisationLowPass>> displacement;
  std::vector<bool> displacement_low_passed;  // per record: the low-pass was applied
};

// One line on a record's quantised displacement: the step, the velocity noise its steps make, the
// cut-off with what it costs in bandwidth and what it gains (applied or not), or why no low-pass
// would help.
std::string describe_displacement_treatment(const signal::QuantisationLowPass& treatment,
                                            bool applied);

// The report of `fit` on `records`. `compression_m`, when not empty, holds one compression per
// record, and `fit` has coulomb_force_N per file; InputError from fit_friction_compression
// otherwise.
HysteresisFitReport report_hysteresis_fit(const std::vector<HysteresisRecord>& records,
                                          const HysteresisFitResult& fit, std::string start,
                                          std::span<const double> compression_m = {});

// The summary a person reads: the fit's cost and verdict, the parameters with their standard
// errors, the calibration values, the line, warnings and the parameters on bounds.
void write_summary(std::ostream& out, const HysteresisFitResult& fit,
                   const HysteresisFitReport& report);

// The same as JSON (converged, iterations, costs, NRMSE, verdict, parameters, correlation,
// calibration_friction_N, friction_against_compression).
nlohmann::json summary_json(const HysteresisFitResult& fit, const HysteresisFitReport& report);

}  // namespace ridefit::fitting
