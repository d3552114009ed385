#include "ridefit/optimisation/tuning_result.h"

#include <fmt/core.h>

#include "ridefit/io/atomic_file.h"
#include "ridefit/io/json_to_yaml.h"
#include "ridefit/io/model_values_file.h"
#include "ridefit/optimisation/tradeoff_csv.h"

namespace ridefit::optimisation {
namespace {

nlohmann::json variables_json(const TuningStudy& study, const std::vector<double>& x) {
  nlohmann::json j = nlohmann::json::object();
  for (std::size_t v = 0; v < x.size(); ++v) j[study.design[v].name] = x[v];
  return j;
}

nlohmann::json margins_json(const std::vector<ConstraintMargin>& margins) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& m : margins) {
    j.push_back({{"constraint", m.description},
                 {"limit", m.limit},
                 {"value", m.value},
                 {"margin", m.margin},
                 {"relative_margin", m.relative_margin},
                 {"holds", m.holds}});
  }
  return j;
}

nlohmann::json cases_json(const TuningStudy& study, const Evaluation& e) {
  nlohmann::json j = nlohmann::json::array();
  const auto& names = metric_names(study.kind);
  for (std::size_t c = 0; c < e.case_values.size(); ++c) {
    nlohmann::json metrics = nlohmann::json::object();
    for (std::size_t m = 0; m < names.size(); ++m) metrics[names[m]] = e.case_values[c][m];
    j.push_back({{"name", study.load_cases[c].name},
                 {"method", e.frequency_domain[c] ? "frequency" : "time"},
                 {"weight", study.load_cases[c].weight},
                 {"metrics", metrics}});
  }
  return j;
}

nlohmann::json friction_cost_json(const TuningStudy& study, const OptimisationRun& aware,
                                  const FrictionCost& f) {
  return {{"blind_variables", variables_json(study, f.blind.best.x)},
          {"blind_status", f.blind.feasible ? "optimum" : "infeasible"},
          {"blind_objective_without_friction", f.blind.verified.objective},
          {"blind_objective_with_friction", f.blind_with_friction.objective},
          {"aware_objective_with_friction", aware.verified.objective},
          {"comfort_loss", f.comfort_loss},
          {"comfort_loss_percent", f.comfort_loss_percent},
          {"blind_feasible_with_friction", f.blind_feasible_with_friction},
          {"blind_constraints_with_friction", margins_json(f.blind_margins_with_friction)},
          {"evaluations", f.blind.evaluations}};
}

nlohmann::json tradeoff_json(const TuningStudy& study, const std::vector<TradeoffPoint>& tradeoff,
                             const std::string& csv) {
  nlohmann::json points = nlohmann::json::array();
  for (const auto& p : tradeoff) {
    points.push_back({{"limit", p.limit},
                      {"status", p.run.feasible ? "optimum" : "infeasible"},
                      {"objective", p.run.verified.objective},
                      {"achieved", p.achieved},
                      {"variables", variables_json(study, p.run.best.x)},
                      {"evaluations", p.run.evaluations}});
  }
  nlohmann::json j = {{"metric", study.constraints[study.tradeoff->constraint].metric},
                      {"points", points}};
  if (!csv.empty()) j["csv"] = csv;
  return j;
}

}  // namespace

WrittenFiles written_files(const TuningFiles& files, const TuningOutcome& outcome,
                           const std::string& plot) {
  return {outcome.aware.feasible ? files.model : "",
          outcome.tradeoff.empty() ? "" : files.tradeoff_csv, files.journal.string(), plot};
}

nlohmann::json tuning_result(const TuningProblem& problem, const TuningOutcome& o,
                             const WrittenFiles& written, double wall_time_s) {
  const auto& study = problem.study();
  const auto& run = o.aware;
  nlohmann::json j = {{"study", study.study_file.string()},
                      {"model", study.model_file.string()},
                      {"status", run.feasible ? "optimum" : "infeasible"},
                      {"algorithm", to_string(study.optimiser.algorithm)},
                      {"nlopt_result", run.nlopt_result},
                      {"starts", study.optimiser.starts},
                      {"evaluations", run.evaluations},
                      {"computed_evaluations", run.computed},
                      {"reused_evaluations", run.evaluations - run.computed},
                      {"variables", variables_json(study, run.best.x)},
                      {"objective",
                       {{"metric", study.objective.metric},
                        {"aggregate", to_string(study.objective.aggregate)},
                        {"value", run.verified.objective},
                        {"search_value", run.best.objective}}},
                      {"constraints", margins_json(run.margins)},
                      {"load_cases", cases_json(study, run.verified)},
                      {"journal", written.journal},
                      {"wall_time_s", wall_time_s}};
  if (!study.friction_values.empty()) {
    nlohmann::json f = nlohmann::json::object();
    for (const auto& [key, value] : study.friction_values) f[key] = value;
    j["friction"] = f;
    if (!study.fitted_model.empty()) j["friction_from"] = study.fitted_model.string();
  }
  if (!written.model.empty()) j["optimised_model"] = written.model;
  if (o.friction) j["friction_cost"] = friction_cost_json(study, run, *o.friction);
  if (!o.tradeoff.empty()) j["tradeoff"] = tradeoff_json(study, o.tradeoff, written.tradeoff_csv);
  if (!written.plot.empty()) j["plot"] = written.plot;
  return j;
}

void write_tuning_result(const TuningProblem& problem, const TuningOutcome& outcome,
                         const WrittenFiles& written, const nlohmann::json& result,
                         const std::string& result_file, const std::string& origin) {
  const auto& study = problem.study();
  if (!written.tradeoff_csv.empty()) {
    write_tradeoff_csv(study, outcome.tradeoff, written.tradeoff_csv);
  }
  if (!written.model.empty()) {
    io::write_model_with_values(
        study.model_file, tuned_values(study, outcome.aware.best.x), written.model,
        fmt::format("Optimised by {} from {}", origin, study.model_file.string()));
  }
  if (!result_file.empty()) {
    io::write_atomically(result_file, [&](std::ostream& out) {
      out << "# " << origin << "\n" << io::to_yaml(result) << "\n";
    });
  }
}

}  // namespace ridefit::optimisation
