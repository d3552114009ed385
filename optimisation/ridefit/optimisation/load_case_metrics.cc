#include "ridefit/optimisation/load_case_metrics.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "ridefit/common/errors.h"

namespace ridefit::optimisation {
namespace {

std::vector<double> values_of(const std::vector<std::pair<std::string, double>>& named) {
  std::vector<double> values;
  for (const auto& [name, value] : named) values.push_back(value);
  return values;
}

study::LoadCaseSettings settings_of(const TuningStudy& study, Accuracy accuracy,
                                    bool frequency_allowed) {
  const EvaluationSettings& e = study.evaluation;
  study::LoadCaseSettings settings;
  settings.method = frequency_allowed ? e.method : study::EvaluationMethod::kTime;
  // The verification: four times the frequency points, a tighter integrator tolerance.
  settings.frequency_points =
      static_cast<std::size_t>(e.frequency_points * (accuracy == Accuracy::kVerify ? 4 : 1));
  settings.output_rate_Hz = e.output_rate_Hz;
  settings.settle_s = e.settle_s;
  settings.duration_s = e.duration_s;
  settings.integrator.relative_tolerance =
      accuracy == Accuracy::kVerify ? e.verify_relative_tolerance : e.relative_tolerance;
  return settings;
}

}  // namespace

LoadCaseRoad prepare_load_case_road(const TuningStudy& study, std::size_t load_case) {
  const LoadCase& c = study.load_cases[load_case];
  LoadCaseRoad road;
  try {
    road.spectrum = road::load_road_spectrum(c.road_file, c.speed_m_per_s);
    road.input = c.speed_m_per_s ? road::load_excitation(c.road_file, *c.speed_m_per_s)
                                 : road::load_excitation(c.road_file);
  } catch (const InputError& e) {
    throw InputError(
        fmt::format("{}: load case '{}': {}", study.study_file.string(), c.name, e.what()));
  }
  return road;
}

LoadCaseMetrics evaluate_load_case(const TuningStudy& study, const TuningModel& model,
                                   const LoadCaseRoad& road, Accuracy accuracy,
                                   bool frequency_allowed) {
  const study::LoadCaseSettings settings = settings_of(study, accuracy, frequency_allowed);
  const std::string where = study.study_file.string();
  LoadCaseMetrics result;
  if (model.quarter) {
    const auto e = study::evaluate_on_load_case(model.quarter->make_model(), road, settings, where);
    result = {values_of(e.metrics.named()), e.frequency_domain};
  } else {
    const auto e = study::evaluate_on_load_case(model.half->make_model(), road, settings, where);
    result = {values_of(e.metrics.named()), e.frequency_domain};
    result.values.push_back(e.front_travel_peak_m);
    result.values.push_back(e.rear_travel_peak_m);
  }
  for (std::size_t m = 0; m < result.values.size(); ++m) {
    if (!std::isfinite(result.values[m])) {
      throw RunError(fmt::format("metric {} is {} (the run diverged)", metric_names(study.kind)[m],
                                 result.values[m]));
    }
  }
  return result;
}

}  // namespace ridefit::optimisation
