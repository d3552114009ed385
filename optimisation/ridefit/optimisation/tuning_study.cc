#include "ridefit/optimisation/tuning_study.h"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "ridefit/comfort/weighting_filter.h"
#include "ridefit/common/errors.h"
#include "ridefit/io/closest_names.h"
#include "ridefit/io/half_car_file.h"
#include "ridefit/io/model_kind.h"
#include "ridefit/io/path_type.h"
#include "ridefit/io/quarter_car_file.h"
#include "ridefit/io/value_range.h"
#include "ridefit/io/yaml_map.h"
#include "ridefit/model/half_car_parameter_table.h"
#include "ridefit/model/quarter_car_parameter_table.h"
#include "ridefit/optimisation/tuning_model.h"
#include "ridefit/road/excitation_file.h"
#include "ridefit/study/half_car_metrics.h"
#include "ridefit/study/quarter_car_metrics.h"

namespace ridefit::optimisation {
namespace {

constexpr std::size_t kMaxLoadCases = 1000;
namespace rows = model::quarter_car_rows;
// The friction section's keys: the Dahl element's.
constexpr const model::ParameterInfo* kFrictionRows[] = {
    &rows::dahl_sigma0_N_per_m, &rows::coulomb_force_N, &rows::dahl_exponent};

Aggregate read_aggregate(const io::YamlMap& map, Aggregate fallback) {
  if (!map.has("aggregate")) return fallback;
  return map.choice("aggregate", {"weighted_mean", "worst_case"}) == "worst_case"
             ? Aggregate::kWorstCase
             : Aggregate::kWeightedMean;
}

void check_metric(const io::YamlMap& map, const std::string& metric, ModelKind kind) {
  const auto& names = metric_names(kind);
  if (std::find(names.begin(), names.end(), metric) == names.end()) {
    throw InputError(fmt::format(
        "{}: unknown metric '{}' for a {}; expected one of: {}", map.locate("metric"), metric,
        kind == ModelKind::kQuarterCar ? "quarter car" : "half car", fmt::join(names, ", ")));
  }
}

// What the study knows of its model before the design: the model with the study's `set:`
// values (read once), and the numeric keys its file gives.
struct StudyModel {
  TuningModel base;
  std::vector<std::string> file_keys;  // dotted, as io::yaml_number_keys gives them
};

// The start of a design variable without a `start:`: the model's value of `key` when its file
// or the study's `set:` gives it, or the default of an optional key that stands alone.
std::optional<double> model_value(const StudyModel& model, const TuningStudy& study,
                                  const std::string& key) {
  const bool given =
      std::find(model.file_keys.begin(), model.file_keys.end(), key) != model.file_keys.end() ||
      std::any_of(study.model_settings.begin(), study.model_settings.end(),
                  [&](const auto& setting) { return setting.first == key; });
  if (!given && !key.ends_with(rows::compression_to_rebound_ratio.key)) return std::nullopt;
  TuningModel base = model.base;
  if (base.quarter) {
    const auto index = model::quarter_car_parameter_index(key);
    if (!index) return std::nullopt;
    return model::quarter_car_parameter(base.quarter->parameters, *index);
  }
  const auto field = model::half_car_field(base.half->parameters, base.half->topology.control, key);
  if (!field) return std::nullopt;
  return *field->value;
}

// A design parameter must be a number of the model: the topology is not, and a misspelt key
// is named as an unknown parameter with the closest names.
void check_design_key(const io::YamlMap& entry, const TuningStudy& study, const StudyModel& model,
                      const std::string& key) {
  const std::string leaf = key.substr(key.rfind('.') == std::string::npos ? 0 : key.rfind('.') + 1);
  if (leaf == "damper_state" || leaf == "model" || leaf == "tyre_lift_off") {
    throw InputError(fmt::format(
        "{}: '{}' is a setting of the model, not a number to tune; give a numeric model key "
        "such as damping_Ns_per_m (a setting goes under the study's model settings)",
        entry.locate("parameter"), key));
  }
  std::vector<std::string> candidates = model.file_keys;
  bool known = false;
  if (study.kind == ModelKind::kQuarterCar) {
    known = model::quarter_car_parameter_index(key).has_value();
    for (const auto& row : model::kQuarterCarParameters) candidates.emplace_back(row.key);
  } else {
    known = io::half_car_has_key(study.model_file, key);
  }
  known = known || std::find(candidates.begin(), candidates.end(), key) != candidates.end();
  if (!known) {
    throw InputError(fmt::format("{}: unknown parameter '{}' of model {}{}",
                                 entry.locate("parameter"), key, study.model_file.string(),
                                 io::closest_names_text(key, candidates)));
  }
}

DesignVariable read_design(const io::YamlMap& entry, const TuningStudy& study,
                           const StudyModel& model) {
  DesignVariable v;
  v.keys = entry.texts("parameter");
  for (const auto& key : v.keys) check_design_key(entry, study, model, key);
  v.name = entry.has("name") ? entry.text("name") : v.keys.front();
  v.lower = entry.number("lower");
  v.upper = entry.number("upper");
  if (!(v.lower < v.upper)) {
    throw InputError(fmt::format("{} is {}, not below upper {}; a variable needs lower < upper",
                                 entry.locate("lower"), v.lower, v.upper));
  }
  v.log_scale = entry.has("scale") && entry.choice("scale", {"linear", "log"}) == "log";
  if (v.log_scale && !(v.lower > 0.0)) {
    throw InputError(
        fmt::format("{}: scale log needs lower > 0 (got {})", entry.locate("scale"), v.lower));
  }
  if (entry.has("start")) {
    v.start = entry.number("start");
  } else {
    const std::optional<double> value = model_value(model, study, v.keys.front());
    if (!value) {
      throw InputError(fmt::format("{}: '{}' has no number in model {} to start from; give start",
                                   entry.locate("parameter"), v.keys.front(),
                                   study.model_file.string()));
    }
    v.start = *value;
  }
  if (!(v.start >= v.lower && v.start <= v.upper)) {
    throw InputError(fmt::format(
        "{} is {}, outside [{}, {}]; the start must lie within the bounds",
        entry.has("start") ? entry.locate("start") : entry.locate("parameter") + " (model value)",
        v.start, v.lower, v.upper));
  }
  entry.finish();
  return v;
}

LoadCase read_load_case(const io::YamlMap& entry, std::size_t index) {
  LoadCase c;
  c.name = entry.has("name") ? entry.text("name") : fmt::format("case{}", index + 1);
  c.road_file = entry.file("road");
  if (!io::exists_as_file(c.road_file)) {
    throw InputError(
        fmt::format("{}: no such excitation file {}", entry.locate("road"), c.road_file.string()));
  }
  if (entry.has("speed_km_per_h") && entry.has("speed_m_per_s")) {
    throw InputError(fmt::format("{}: give speed_km_per_h or speed_m_per_s, not both",
                                 entry.locate("speed_km_per_h")));
  }
  if (entry.has("speed_km_per_h"))
    c.speed_m_per_s = entry.positive_up_to("speed_km_per_h", 540) / 3.6;
  if (entry.has("speed_m_per_s")) c.speed_m_per_s = entry.positive_up_to("speed_m_per_s", 150);
  if (entry.has("weight")) c.weight = entry.positive_up_to("weight", 1e6);
  if (entry.has("set")) {
    const io::YamlMap set = entry.map("set");
    for (const auto& key : set.keys()) c.model_values.emplace_back(key, set.number(key));
  }
  entry.finish();
  return c;
}

void read_friction(const io::YamlMap& friction, const TuningModel& base, TuningStudy& study) {
  std::vector<ModelValue> values;
  if (friction.has("fitted_model")) {
    for (const auto* row : kFrictionRows) {
      if (friction.has(*row)) {
        throw InputError(fmt::format("{}: give fitted_model or friction values, not both",
                                     friction.locate(*row)));
      }
    }
    study.fitted_model = friction.file("fitted_model");
    io::QuarterCarFile fitted;
    try {
      fitted = io::load_quarter_car(study.fitted_model);
    } catch (const InputError& e) {
      throw InputError(
          fmt::format("{}: a fitted quarter-car model is needed (as `ridefit fit` writes it): {}",
                      friction.locate("fitted_model"), e.what()));
    }
    values = {{rows::dahl_sigma0_N_per_m.key_string(), fitted.parameters.dahl_sigma0_N_per_m},
              {rows::coulomb_force_N.key_string(), fitted.parameters.coulomb_force_N},
              {rows::dahl_exponent.key_string(), fitted.parameters.dahl_exponent}};
  } else {
    const auto& sigma0 = rows::dahl_sigma0_N_per_m;
    const auto& fc = rows::coulomb_force_N;
    const auto& exponent = rows::dahl_exponent;
    if (friction.has(sigma0)) {
      values.emplace_back(sigma0.key, friction.parameter(sigma0));
    }
    if (friction.has(fc)) values.emplace_back(fc.key, friction.parameter(fc));
    if (friction.has(exponent)) {
      values.emplace_back(exponent.key, friction.parameter(exponent));
    }
    if (values.empty()) {
      throw InputError(fmt::format(
          "{}: give coulomb_force_N (and optionally dahl_sigma0_N_per_m, dahl_exponent) or "
          "fitted_model",
          friction.locate(rows::coulomb_force_N)));
    }
  }
  friction.finish();
  if (study.kind == ModelKind::kQuarterCar) {
    const auto& model = *base.quarter;
    if (model.damper_state != model::DamperState::kStickSlip) {
      throw InputError(
          fmt::format("{}: model {} has no friction element (damper_state {}); "
                      "friction needs damper_state: stick_slip",
                      friction.locate(rows::coulomb_force_N), study.model_file.string(),
                      model::to_string(model.damper_state)));
    }
    study.friction_values = values;
    return;
  }
  const auto& model = *base.half;
  for (const auto& [axle, topology] :
       {std::pair{"front", model.topology.front}, std::pair{"rear", model.topology.rear}}) {
    if (topology.suspension == model::AxleSuspension::kStrut &&
        topology.damper_state == model::DamperState::kStickSlip) {
      for (const auto& [key, value] : values) {
        study.friction_values.emplace_back(fmt::format("{}.{}", axle, key), value);
      }
    }
  }
  if (study.friction_values.empty()) {
    throw InputError(fmt::format(
        "{}: model {} has no stick/slip strut; friction needs an axle with suspension: strut "
        "and damper_state: stick_slip",
        friction.locate(rows::coulomb_force_N), study.model_file.string()));
  }
}

// An integer key as `int`: the range rules are the settings' own (tuning_settings.h); this only
// refuses what an int cannot hold.
int int_of(const io::YamlMap& map, const char* key, int fallback) {
  if (!map.has(key)) return fallback;
  const long v = map.integer(key);
  if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max()) {
    throw InputError(fmt::format("{} is {}, far beyond any meaningful value", map.locate(key), v));
  }
  return static_cast<int>(v);
}

double number_or(const io::YamlMap& map, const char* key, double fallback) {
  return map.has(key) ? map.number(key) : fallback;
}

// The first rule `settings` break, located at its key in `map`.
template <typename Settings>
void check_settings(const io::YamlMap& map, const Settings& settings) {
  if (const auto e = settings.error()) {
    throw InputError(fmt::format("{} {}", map.locate(e->key), e->message));
  }
}

void read_optimiser(const io::YamlMap& map, OptimiserSettings& o) {
  if (map.has("algorithm")) {
    const std::string a =
        map.choice("algorithm", {"cobyla", "bobyqa", "isres", "direct_l", "mlsl"});
    o.algorithm = a == "bobyqa"     ? Algorithm::kBobyqa
                  : a == "isres"    ? Algorithm::kIsres
                  : a == "direct_l" ? Algorithm::kDirectL
                  : a == "mlsl"     ? Algorithm::kMlsl
                                    : Algorithm::kCobyla;
  }
  o.starts = int_of(map, "starts", o.starts);
  if (map.has("seed")) {
    const long v = map.integer("seed");
    if (v < 0 || v > 4294967295L) {
      throw InputError(fmt::format("{} is {}, expected 0 … 4294967295", map.locate("seed"), v));
    }
    o.seed = static_cast<unsigned>(v);
  }
  o.max_evaluations = int_of(map, "max_evaluations", o.max_evaluations);
  o.x_tolerance = number_or(map, "x_tolerance", o.x_tolerance);
  o.f_tolerance = number_or(map, "f_tolerance", o.f_tolerance);
  o.max_time_s = number_or(map, "max_time_s", o.max_time_s);
  o.initial_step = number_or(map, "initial_step", o.initial_step);
  o.constraint_tolerance = number_or(map, "constraint_tolerance", o.constraint_tolerance);
  check_settings(map, o);
  map.finish();
}

void read_evaluation(const io::YamlMap& map, EvaluationSettings& e) {
  if (map.has("method")) {
    const std::string m = map.choice("method", {"auto", "frequency", "time"});
    e.method = m == "frequency" ? EvaluationMethod::kFrequency
               : m == "time"    ? EvaluationMethod::kTime
                                : EvaluationMethod::kAuto;
  }
  e.output_rate_Hz = number_or(map, "output_rate_Hz", e.output_rate_Hz);
  e.settle_s = number_or(map, "settle_s", e.settle_s);
  e.duration_s = number_or(map, "duration_s", e.duration_s);
  e.relative_tolerance = number_or(map, "relative_tolerance", e.relative_tolerance);
  e.verify_relative_tolerance =
      number_or(map, "verify_relative_tolerance", e.verify_relative_tolerance);
  e.frequency_points = int_of(map, "frequency_points", e.frequency_points);
  if (map.has("threads")) {
    const long n = map.integer("threads");
    if (n < 0) {
      throw InputError(
          fmt::format("{} is {}, expected 0 (every core) or more", map.locate("threads"), n));
    }
    e.threads = static_cast<unsigned>(std::min<long>(n, std::numeric_limits<unsigned>::max()));
  }
  check_settings(map, e);
  map.finish();
}

// The time settings against each case's road: the run must fit in the road, leave something
// after the settling time, and sample fast enough for the weightings.
void check_record_lengths(const io::YamlMap& file, const TuningStudy& study) {
  const auto& e = study.evaluation;
  for (const auto weighting : {comfort::Weighting::kWk, comfort::Weighting::kWe}) {
    if (e.output_rate_Hz < comfort::minimum_sample_rate_Hz(weighting)) {
      throw InputError(fmt::format(
          "{}: evaluation.output_rate_Hz is {:g} Hz; the ISO 2631-1 weightings need at least {:g} "
          "Hz",
          study.study_file.string(), e.output_rate_Hz, comfort::minimum_sample_rate_Hz(weighting)));
    }
  }
  for (const auto& c : study.load_cases) {
    std::unique_ptr<road::RoadInput> road;
    try {
      road = c.speed_m_per_s ? road::load_excitation(c.road_file, *c.speed_m_per_s)
                             : road::load_excitation(c.road_file);
    } catch (const InputError& error) {
      throw InputError(
          fmt::format("{}: load case '{}': {}", file.locate("load_cases"), c.name, error.what()));
    }
    const double length = road->duration_s();
    if (e.duration_s > length) {
      throw InputError(fmt::format(
          "{}: evaluation.duration_s is {:g} s, longer than load case '{}''s road ({:g} s)",
          study.study_file.string(), e.duration_s, c.name, length));
    }
    const double used = e.duration_s > 0.0 ? e.duration_s : length;
    if (e.settle_s >= used - 1.0) {
      throw InputError(fmt::format(
          "{}: evaluation.settle_s is {:g} s, which leaves less than 1 s of load case '{}' ({:g} "
          "s) to evaluate",
          study.study_file.string(), e.settle_s, c.name, used));
    }
  }
}

}  // namespace

std::string Constraint::describe() const {
  return fmt::format("{} {} {:g} ({})", metric, is_upper ? "<=" : ">=", limit,
                     to_string(aggregate));
}

const std::vector<std::string>& metric_names(ModelKind kind) {
  static const std::vector<std::string> quarter = [] {
    std::vector<std::string> names;
    for (const auto& [name, value] : study::QuarterCarMetrics{}.named()) names.push_back(name);
    return names;
  }();
  static const std::vector<std::string> half = [] {
    std::vector<std::string> names;
    for (const auto& [name, value] : study::HalfCarMetrics{}.named()) names.push_back(name);
    names.push_back("front_travel_peak_m");
    names.push_back("rear_travel_peak_m");
    return names;
  }();
  return kind == ModelKind::kQuarterCar ? quarter : half;
}

const char* to_string(Algorithm algorithm) {
  switch (algorithm) {
    case Algorithm::kCobyla:
      return "cobyla";
    case Algorithm::kBobyqa:
      return "bobyqa";
    case Algorithm::kIsres:
      return "isres";
    case Algorithm::kDirectL:
      return "direct_l";
    case Algorithm::kMlsl:
      return "mlsl";
  }
  return "?";
}

const char* to_string(Aggregate aggregate) {
  return aggregate == Aggregate::kWorstCase ? "worst_case" : "weighted_mean";
}

namespace {

// The model, its kind, the study's `set:` and friction: what every later section checks against.
StudyModel read_model(const io::YamlMap& file, TuningStudy& study) {
  study.model_file = file.file("model");
  std::string kind;
  try {
    kind = io::model_kind(study.model_file);
  } catch (const InputError& e) {
    throw InputError(
        fmt::format("{}: not a vehicle model file ({})", file.locate("model"), e.what()));
  }
  study.kind = kind == "half_car" ? ModelKind::kHalfCar : ModelKind::kQuarterCar;

  if (file.has("set")) {
    if (!file.is_mapping("set")) {
      throw InputError(
          fmt::format("{} must be a mapping of model keys, e.g. {{front.suspension: strut}}",
                      file.locate("set")));
    }
    const io::YamlMap settings = file.map("set");
    for (const auto& key : settings.keys()) {
      study.model_settings.emplace_back(key, settings.text(key));
    }
  }
  // The model as the study uses it, before the design or the cases change it.
  StudyModel model{load_base_model(study, fmt::format("{}: set", study.study_file.string())),
                   io::yaml_number_keys(study.model_file)};
  if (file.has("friction")) read_friction(file.map("friction"), model.base, study);
  return model;
}

void read_design_section(const io::YamlMap& file, TuningStudy& study, const StudyModel& model) {
  std::set<std::string> names, keys;
  for (const auto& entry : file.maps("design")) {
    study.design.push_back(read_design(entry, study, model));
    if (!names.insert(study.design.back().name).second) {
      throw InputError(fmt::format("{}: the name '{}' is used twice", entry.locate("parameter"),
                                   study.design.back().name));
    }
    for (const auto& key : study.design.back().keys) {
      if (!keys.insert(key).second) {
        throw InputError(
            fmt::format("{}: '{}' is set by two design variables", entry.locate("parameter"), key));
      }
    }
  }
}

void read_load_cases(const io::YamlMap& file, TuningStudy& study) {
  if (!file.has("load_cases")) {
    throw InputError(fmt::format("{} is missing; give at least one case with a road",
                                 file.locate("load_cases")));
  }
  const std::optional<std::size_t> length = file.list_length("load_cases");
  if (!length) {
    throw InputError(fmt::format("{} is not a list; write each case as `- {{name: …, road: …}}`",
                                 file.locate("load_cases")));
  }
  if (*length == 0) {
    throw InputError(
        fmt::format("{} is empty; give at least one case, e.g. - {{road: ../excitations/x.yaml}}",
                    file.locate("load_cases")));
  }
  const auto case_maps = file.maps("load_cases");
  if (case_maps.size() > kMaxLoadCases) {
    throw InputError(
        fmt::format("{}: more than {} cases", file.locate("load_cases"), kMaxLoadCases));
  }
  std::set<std::string> case_names;
  for (std::size_t i = 0; i < case_maps.size(); ++i) {
    study.load_cases.push_back(read_load_case(case_maps[i], i));
    if (!case_names.insert(study.load_cases.back().name).second) {
      throw InputError(fmt::format("{}: the case name '{}' is used twice",
                                   case_maps[i].locate("name"), study.load_cases.back().name));
    }
  }
}

// A key set by a design variable cannot also be fixed by a case or by the friction level.
void check_design_not_fixed(const io::YamlMap& file, const TuningStudy& study) {
  for (const auto& v : study.design) {
    for (const auto& key : v.keys) {
      for (const auto& c : study.load_cases) {
        for (const auto& [k, value] : c.model_values) {
          if (k == key) {
            throw InputError(fmt::format(
                "{}: load case '{}' sets '{}', which the design variable '{}' varies; remove one",
                file.locate("load_cases"), c.name, key, v.name));
          }
        }
      }
      for (const auto& [k, value] : study.friction_values) {
        if (k == key || k.ends_with("." + key) || key.ends_with("." + k)) {
          throw InputError(
              fmt::format("{}: '{}' is set by friction and varied by the design variable '{}'; "
                          "remove one",
                          file.locate("friction"), k, v.name));
        }
      }
    }
  }
}

void read_objective_and_constraints(const io::YamlMap& file, TuningStudy& study) {
  const io::YamlMap objective = file.map("objective");
  study.objective.metric = objective.text("metric");
  check_metric(objective, study.objective.metric, study.kind);
  study.objective.aggregate = read_aggregate(objective, Aggregate::kWeightedMean);
  objective.finish();

  if (file.has("constraints")) {
    for (const auto& entry : file.maps("constraints")) {
      Constraint c;
      c.metric = entry.text("metric");
      check_metric(entry, c.metric, study.kind);
      if (entry.has("max") == entry.has("min")) {
        throw InputError(fmt::format("{}: give exactly one of max and min", entry.locate("max")));
      }
      c.is_upper = entry.has("max");
      c.limit = entry.number(c.is_upper ? "max" : "min");
      if (!(c.limit > 0.0)) {
        throw InputError(fmt::format("{} is {}; a limit on a ride metric must be above 0",
                                     entry.locate(c.is_upper ? "max" : "min"), c.limit));
      }
      c.aggregate = read_aggregate(entry, Aggregate::kWorstCase);
      entry.finish();
      study.constraints.push_back(c);
    }
  }
}

void read_tradeoff(const io::YamlMap& t, TuningStudy& study) {
  const std::string metric = t.text("metric");
  Tradeoff tradeoff;
  bool found = false;
  for (std::size_t i = 0; i < study.constraints.size() && !found; ++i) {
    if (study.constraints[i].metric == metric) {
      tradeoff.constraint = i;
      found = true;
    }
  }
  if (!found) {
    throw InputError(fmt::format(
        "{}: '{}' is not constrained; the trade-off sweeps the limit of a constraint (add it "
        "under constraints)",
        t.locate("metric"), metric));
  }
  if (t.has("limits") == t.has("range")) {
    throw InputError(
        fmt::format("{}: give limits: [..] or range: {{from, to, count}}", t.locate("limits")));
  }
  tradeoff.limits = t.has("limits") ? t.numbers("limits") : io::read_value_range(t.map("range"));
  for (double limit : tradeoff.limits) {
    if (!(limit > 0.0)) {
      throw InputError(fmt::format("{}: limit {} is not above 0", t.locate("limits"), limit));
    }
  }
  t.finish();
  study.tradeoff = tradeoff;
}

// Every case and both ends of every variable on the model, so that a value the model rejects
// is reported now, not in the middle of the search.
void check_design_box(TuningStudy& study) {
  std::vector<double> start;
  for (const auto& v : study.design) start.push_back(v.start);
  for (std::size_t c = 0; c < study.load_cases.size(); ++c) {
    const auto origin =
        fmt::format("{}: load case '{}'", study.study_file.string(), study.load_cases[c].name);
    const TuningModel model =
        build_tuning_model(study, FrictionVariant::kStudy, study.load_cases[c], start, origin);
    if (c == 0) study.model_has_friction = has_friction(model);
  }
  // Both ends of every variable, and every corner of the design box (up to 10 variables):
  // rules between keys (min_damping <= max_damping) fail at a corner if anywhere.
  for (std::size_t v = 0; v < study.design.size(); ++v) {
    for (double value : {study.design[v].lower, study.design[v].upper}) {
      std::vector<double> x = start;
      x[v] = value;
      build_tuning_model(study, FrictionVariant::kStudy, study.load_cases.front(), x,
                         fmt::format("{}: design variable '{}' = {:g}", study.study_file.string(),
                                     study.design[v].name, value));
    }
  }
  const std::size_t n = study.design.size();
  if (n >= 2 && n <= 10) {
    for (std::size_t corner = 0; corner < (std::size_t{1} << n); ++corner) {
      std::vector<double> x(n);
      std::string where;
      for (std::size_t v = 0; v < n; ++v) {
        x[v] = (corner >> v) & 1 ? study.design[v].upper : study.design[v].lower;
        where += fmt::format(" {}={:g}", study.design[v].name, x[v]);
      }
      build_tuning_model(
          study, FrictionVariant::kStudy, study.load_cases.front(), x,
          fmt::format("{}: design corner{} (every combination within the bounds must be a valid "
                      "model; narrow the bounds)",
                      study.study_file.string(), where));
    }
  }
}

}  // namespace

TuningStudy load_tuning_study(const std::filesystem::path& study_file) {
  const io::YamlMap file = io::YamlMap::load(study_file);
  TuningStudy study;
  study.study_file = study_file;
  const StudyModel model = read_model(file, study);
  read_design_section(file, study, model);
  read_load_cases(file, study);
  check_design_not_fixed(file, study);
  read_objective_and_constraints(file, study);
  if (file.has("optimiser")) read_optimiser(file.map("optimiser"), study.optimiser);
  if (file.has("evaluation")) read_evaluation(file.map("evaluation"), study.evaluation);
  if (file.has("tradeoff")) read_tradeoff(file.map("tradeoff"), study);
  check_design_box(study);
  check_record_lengths(file, study);
  if (file.has("friction_cost")) {
    const std::string s = file.choice("friction_cost", {"true", "false"});
    study.friction_cost = s == "true";
    if (study.friction_cost && !study.model_has_friction) {
      throw InputError(fmt::format(
          "{}: the model has no friction (no stick/slip damper with coulomb_force_N > 0), so "
          "there is nothing to ignore",
          file.locate("friction_cost")));
    }
  } else {
    study.friction_cost = study.model_has_friction;
  }
  file.finish();
  return study;
}

}  // namespace ridefit::optimisation
