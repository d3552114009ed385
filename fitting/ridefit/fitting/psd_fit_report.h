#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

#include "ridefit/fitting/fit_adequacy.h"
#include "ridefit/fitting/psd_fit.h"

namespace ridefit::fitting {

// What a PSD fit reports, with its adequacy (assess_psd_fit): the summary a person reads (the
// fit of `source`, its cost, verdict, parameters with their standard errors, warnings and the
// parameters on bounds)...
void write_summary(std::ostream& out, const std::string& source, const PsdFitResult& fit,
                   const FitAdequacy& adequacy);

// ... and the same as JSON (with the noise floors and the correlation).
nlohmann::json summary_json(const PsdFitResult& fit, const FitAdequacy& adequacy);

}  // namespace ridefit::fitting
