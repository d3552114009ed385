#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "ridefit/optimisation/tuning_model.h"
#include "ridefit/optimisation/tuning_study.h"
#include "ridefit/road/excitation_file.h"
#include "ridefit/road/road_input.h"
#include "ridefit/study/load_case_evaluation.h"

namespace ridefit::optimisation {

// The road of one load case (study/load_case_evaluation.h), made once per study and shared by
// every evaluation.
using study::LoadCaseRoad;

// Loads the case's road; InputError naming the study file and the case.
LoadCaseRoad prepare_load_case_road(const TuningStudy& study, std::size_t load_case);

// How carefully a case is evaluated: the search's settings, or the verification's (tighter
// integrator tolerance, four times the frequency points).
enum class Accuracy { kSearch, kVerify };

struct LoadCaseMetrics {
  std::vector<double> values;  // in metric_names(kind) order
  bool frequency_domain = false;
};

// The metrics of one model on one case. The half car is evaluated in the frequency domain when
// the study allows it, the car is linear and the road has a spectrum (exact, about 2 ms);
// otherwise by simulation with the study's time settings. In the frequency domain the peak
// travel is the expected largest |travel| of the Gaussian response over the road's duration
// (signal/expected_peak.h); in the time domain it is the largest after the settling time.
// `frequency_allowed` false forces simulation (the friction-blind model is simulated on the
// same road records as the friction model it is compared with, so that the comparison carries
// no record-to-record scatter).
LoadCaseMetrics evaluate_load_case(const TuningStudy& study, const TuningModel& model,
                                   const LoadCaseRoad& road, Accuracy accuracy,
                                   bool frequency_allowed = true);

}  // namespace ridefit::optimisation
