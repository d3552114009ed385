#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ridefit/optimisation/tuning_settings.h"
#include "ridefit/study/load_case_evaluation.h"

namespace ridefit::optimisation {

// A damper-tuning study, read from YAML (datasets/studies/passat_damper_tuning.yaml and
// ajayi_damper_tuning.yaml use every key):
//
//   model: ../vehicles/passat_b8_front.yaml   # quarter_car or half_car; relative to this file
//   set: {front.suspension: strut}            # optional: model keys changed for the whole study
//                                             # (numbers, or words such as damper_state)
//   design:                                   # the variables the optimiser may change
//     - parameter: damping_Ns_per_m           # a numeric model key by its dotted path, or a
//       lower: 300                            #   list of keys set to the same value
//       upper: 6000
//       start: 887                            # default: the model's own value
//       scale: log                            # linear (default) | log: steps in ratios
//       name: damping_Ns_per_m                # default: the first key
//   load_cases:                               # road × speed × vehicle load, each with a weight
//     - name: smooth_50                       # default: case1, case2, …
//       road: ../excitations/iso8608_class_a_50kmh.yaml
//       speed_km_per_h: 50                    # or speed_m_per_s; default: the road's own
//       weight: 1                             # in the weighted mean; default 1
//       set: {sprung_mass_kg: 460}            # model keys for this case (payload); optional
//   friction:                                 # optional; default: as in the model
//     coulomb_force_N: 60                     # fixed level on every stick/slip strut, or
//     # fitted_model: ../../out/demo/passat_fitted.yaml   # σ0, Fc and d of a fitted strut
//   objective:
//     metric: body_acc_wk_rms_m_per_s2        # seat_/upper_body_acc_wk_rms_m_per_s2 (half car)
//     aggregate: weighted_mean                # weighted_mean | worst_case
//   constraints:                              # optional; each on any metric
//     - {metric: dynamic_load_ratio, max: 0.3}           # aggregate: worst_case by default
//     - {metric: travel_peak_m, max: 0.07}               # peak travel against the rattle space
//   optimiser:                                # optional
//     algorithm: cobyla        # cobyla | bobyqa | isres | direct_l | mlsl
//     starts: 1                # local algorithms: more starts from seeded random points
//     seed: 1                  # for the extra starts, ISRES and MLSL
//     x_tolerance: 1.0e-3      # stop when steps are below this share of each variable's range
//     f_tolerance: 1.0e-6      # … or the objective changes by less than this, relatively
//     max_evaluations: 200     # per start
//     max_time_s: 0            # per start; 0 = no limit (a time limit is not reproducible)
//     initial_step: 0.1        # first step as a share of each range (cobyla, bobyqa)
//     constraint_tolerance: 1.0e-3   # the search aims this share inside each limit, and a
//                                    # limit broken by less than it counts as held (≤ 0.01)
//   evaluation:                # optional
//     method: auto             # auto | frequency | time (auto: frequency when exact)
//     output_rate_Hz: 1000     # time domain: output rate, settle time left out, duration
//     settle_s: 2
//     duration_s: 0            # 0 = the road's own
//     relative_tolerance: 1.0e-4     # the integrator's, during the search
//     verify_relative_tolerance: 1.0e-6   # the reported optimum is re-evaluated with this
//     frequency_points: 1000   # frequency domain (the verification uses four times as many)
//     threads: 0               # load cases in parallel; 0 = every core
//   tradeoff:                  # optional ε-constraint sweep: the Pareto front
//     metric: dynamic_load_ratio     # a constrained metric whose limit is swept
//     limits: [0.10, 0.12, 0.14]     # or range: {from: 0.1, to: 0.2, count: 6}
//   friction_cost: true        # default true when the model has friction: optimise blind too
//
// Every bad entry is an InputError naming the study file and the key; design keys, bounds and
// case settings are tried on the model before anything runs.
enum class ModelKind { kQuarterCar, kHalfCar };
enum class Aggregate { kWeightedMean, kWorstCase };

struct DesignVariable {
  std::string name;
  std::vector<std::string> keys;
  double lower = 0.0;
  double upper = 0.0;
  double start = 0.0;
  bool log_scale = false;
};

// A numeric model key by its dotted path and its value.
using ModelValue = std::pair<std::string, double>;

struct LoadCase {
  std::string name;
  std::filesystem::path road_file;
  std::optional<double> speed_m_per_s;
  double weight = 1.0;
  std::vector<ModelValue> model_values;
};

struct Objective {
  std::string metric;
  Aggregate aggregate = Aggregate::kWeightedMean;
};

struct Constraint {
  std::string metric;
  double limit = 0.0;
  bool is_upper = true;  // metric <= limit (max:) or metric >= limit (min:)
  Aggregate aggregate = Aggregate::kWorstCase;

  // "dynamic_load_ratio <= 0.3 (worst case)"
  std::string describe() const;
};

struct Tradeoff {
  std::size_t constraint = 0;  // index into TuningStudy::constraints
  std::vector<double> limits;
};

struct TuningStudy {
  std::filesystem::path study_file;
  std::filesystem::path model_file;
  ModelKind kind = ModelKind::kQuarterCar;
  std::vector<std::pair<std::string, std::string>> model_settings;  // `set:`, as written
  std::vector<DesignVariable> design;
  std::vector<LoadCase> load_cases;
  // Friction keys set on every stick/slip strut (quarter car: top level; half car: per axle),
  // from the study or a fitted model; empty: as in the model.
  std::vector<ModelValue> friction_values;
  std::filesystem::path fitted_model;  // where friction_values came from, if a fit
  bool model_has_friction = false;     // some damper is stick/slip with Coulomb force > 0
  Objective objective;
  std::vector<Constraint> constraints;
  OptimiserSettings optimiser;
  EvaluationSettings evaluation;
  std::optional<Tradeoff> tradeoff;
  bool friction_cost = false;
};

TuningStudy load_tuning_study(const std::filesystem::path& study_file);

// The metrics a study may name for a model kind, in output order.
const std::vector<std::string>& metric_names(ModelKind kind);

const char* to_string(Algorithm algorithm);
const char* to_string(Aggregate aggregate);

}  // namespace ridefit::optimisation
