#pragma once

#include <optional>

#include "ridefit/common/setting_error.h"
#include "ridefit/study/load_case_evaluation.h"

namespace ridefit::optimisation {

enum class Algorithm { kCobyla, kBobyqa, kIsres, kDirectL, kMlsl };
// The one choice between the frequency domain and simulation (study/load_case_evaluation.h).
using study::EvaluationMethod;

// How the search runs (the study file's `optimiser:` section, tuning_study.h). Plain fields with
// defaults, checked as a whole by error(); the keys are the file's.
struct OptimiserSettings {
  static constexpr int kMaxStarts = 1000;
  static constexpr int kMaxEvaluations = 1'000'000;

  Algorithm algorithm = Algorithm::kCobyla;
  int starts = 1;  // 1 … kMaxStarts; DIRECT-L: 1 (it has no start point)
  unsigned seed = 1;
  double x_tolerance = 1e-3;           // (0, 0.5]
  double f_tolerance = 1e-6;           // [0, 0.5]
  int max_evaluations = 200;           // 1 … kMaxEvaluations, per start
  double max_time_s = 0.0;             // [0, 1e7]; 0 = no limit
  double initial_step = 0.1;           // (0, 1]
  double constraint_tolerance = 1e-3;  // [0, 0.01]

  // The first setting that breaks its rule, or none.
  std::optional<common::SettingError> error() const;
  // InputError "optimiser setting 'KEY' MESSAGE" for the first error().
  void validate() const;
};

// How a design is evaluated on each load case (the study file's `evaluation:` section).
struct EvaluationSettings {
  EvaluationMethod method = EvaluationMethod::kAuto;
  double output_rate_Hz = 1000.0;  // (0, 1e5]
  double settle_s = 2.0;           // [0, 1e4]
  double duration_s = 0.0;         // [0, 1e5]; 0 = the road's own
  // Time-domain cases run the default integrator (ESDIRK, simulate/integrator.h) at 1e-4 during
  // the search (when the search ran CVODE, its optimum on the Passat study lay within 0.2 % of the
  // one found at 1e-6, in 40 % less time); the reported optimum is checked at 1e-6, the accuracy
  // of every other ridefit result. Both in [1e-12, 1e-2].
  double relative_tolerance = 1e-4;
  double verify_relative_tolerance = 1e-6;
  int frequency_points = 1000;  // 50 … 100000
  unsigned threads = 0;         // 0 (every core) … 1024

  std::optional<common::SettingError> error() const;
  // InputError "evaluation setting 'KEY' MESSAGE" for the first error().
  void validate() const;
};

}  // namespace ridefit::optimisation
