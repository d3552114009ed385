// ridefit optimise STUDY.yaml [-o result.yaml] [--resume JOURNAL] [--journal FILE]
//                             [--plot FILE.png|svg] [--json] [--threads N]
// Damper tuning with NLopt under friction: the optimum, its verified constraint margins, the
// cost of ignoring friction and the comfort / road-holding trade-off.
#include <fmt/core.h>
#include <yaml-cpp/yaml.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "ridefit/common/errors.h"
#include "ridefit/io/atomic_file.h"
#include "ridefit/io/gnuplot_figure.h"
#include "ridefit/io/model_values_file.h"
#include "ridefit/io/output_paths.h"
#include "ridefit/optimisation/evaluation_journal.h"
#include "ridefit/optimisation/friction_cost.h"
#include "ridefit/optimisation/nlopt_tuner.h"
#include "ridefit/optimisation/tradeoff_curve.h"
#include "ridefit/optimisation/tuning_model.h"
#include "ridefit/study/half_car_sweep.h"
#include "subcommands.h"

namespace ridefit::cli {
namespace {

namespace opt = optimisation;

struct OptimiseFlags {
  std::string study_file;
  std::string output_file;
  std::string resume_file;
  std::string journal_file;
  bool force = false;
  std::string plot_file;
  int threads = -1;
  bool json = false;
  bool quiet = false;
};

// Everything the command found.
struct Outcome {
  opt::OptimisationRun aware;
  std::optional<opt::FrictionCost> friction;
  std::vector<opt::TradeoffPoint> tradeoff;
};

std::filesystem::path sibling(const std::filesystem::path& path, const std::string& suffix) {
  return path.parent_path() / (path.stem().string() + suffix);
}

nlohmann::json variables_json(const opt::TuningStudy& study, const std::vector<double>& x) {
  nlohmann::json j = nlohmann::json::object();
  for (std::size_t v = 0; v < x.size(); ++v) j[study.design[v].name] = x[v];
  return j;
}

nlohmann::json margins_json(const std::vector<opt::ConstraintMargin>& margins) {
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

nlohmann::json cases_json(const opt::TuningStudy& study, const opt::Evaluation& e) {
  nlohmann::json j = nlohmann::json::array();
  const auto& names = opt::metric_names(study.kind);
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

// The whole result as JSON; the YAML result file is the same tree.
nlohmann::json result_json(const opt::TuningProblem& problem, const Outcome& o,
                           const OptimiseFlags& flags, const std::string& model_out,
                           const std::string& tradeoff_csv, const std::string& journal,
                           double wall_time_s) {
  const auto& study = problem.study();
  const auto& run = o.aware;
  nlohmann::json j = {{"study", study.study_file.string()},
                      {"model", study.model_file.string()},
                      {"status", run.feasible ? "optimum" : "infeasible"},
                      {"algorithm", opt::to_string(study.optimiser.algorithm)},
                      {"nlopt_result", run.nlopt_result},
                      {"starts", study.optimiser.starts},
                      {"evaluations", run.evaluations},
                      {"computed_evaluations", run.computed},
                      {"reused_evaluations", run.evaluations - run.computed},
                      {"variables", variables_json(study, run.best.x)},
                      {"objective",
                       {{"metric", study.objective.metric},
                        {"aggregate", opt::to_string(study.objective.aggregate)},
                        {"value", run.verified.objective},
                        {"search_value", run.best.objective}}},
                      {"constraints", margins_json(run.margins)},
                      {"load_cases", cases_json(study, run.verified)},
                      {"journal", journal},
                      {"wall_time_s", wall_time_s}};
  if (!study.friction_values.empty()) {
    nlohmann::json f = nlohmann::json::object();
    for (const auto& [key, value] : study.friction_values) f[key] = value;
    j["friction"] = f;
    if (!study.fitted_model.empty()) j["friction_from"] = study.fitted_model.string();
  }
  if (!model_out.empty()) j["optimised_model"] = model_out;
  if (o.friction) {
    const auto& f = *o.friction;
    j["friction_cost"] = {
        {"blind_variables", variables_json(study, f.blind.best.x)},
        {"blind_status", f.blind.feasible ? "optimum" : "infeasible"},
        {"blind_objective_without_friction", f.blind.verified.objective},
        {"blind_objective_with_friction", f.blind_with_friction.objective},
        {"aware_objective_with_friction", run.verified.objective},
        {"comfort_loss", f.comfort_loss},
        {"comfort_loss_percent", f.comfort_loss_percent},
        {"blind_feasible_with_friction", f.blind_feasible_with_friction},
        {"blind_constraints_with_friction", margins_json(f.blind_margins_with_friction)},
        {"evaluations", f.blind.evaluations}};
  }
  if (!o.tradeoff.empty()) {
    nlohmann::json points = nlohmann::json::array();
    for (const auto& p : o.tradeoff) {
      points.push_back({{"limit", p.limit},
                        {"status", p.run.feasible ? "optimum" : "infeasible"},
                        {"objective", p.run.verified.objective},
                        {"achieved", p.achieved},
                        {"variables", variables_json(study, p.run.best.x)},
                        {"evaluations", p.run.evaluations}});
    }
    j["tradeoff"] = {{"metric", study.constraints[study.tradeoff->constraint].metric},
                     {"points", points}};
    if (!tradeoff_csv.empty()) j["tradeoff"]["csv"] = tradeoff_csv;
  }
  if (!flags.plot_file.empty()) j["plot"] = flags.plot_file;
  return j;
}

YAML::Node to_yaml(const nlohmann::json& j) {
  if (j.is_object()) {
    YAML::Node node(YAML::NodeType::Map);
    for (const auto& [key, value] : j.items()) node[key] = to_yaml(value);
    return node;
  }
  if (j.is_array()) {
    YAML::Node node(YAML::NodeType::Sequence);
    for (const auto& value : j) node.push_back(to_yaml(value));
    return node;
  }
  if (j.is_boolean()) return YAML::Node(j.get<bool>());
  if (j.is_number_integer()) return YAML::Node(j.get<long>());
  if (j.is_number()) return YAML::Node(j.get<double>());
  return YAML::Node(j.get<std::string>());
}

void write_tradeoff_csv(const opt::TuningProblem& problem, const Outcome& o,
                        const std::filesystem::path& path) {
  const auto& study = problem.study();
  const std::string metric = study.constraints[study.tradeoff->constraint].metric;
  // Named copies, not structured bindings: Clang 14 cannot capture those in a lambda.
  const std::pair<std::string, std::string> limit = study::split_unit_suffix(metric);
  const std::pair<std::string, std::string> goal = study::split_unit_suffix(study.objective.metric);
  const std::string& name = limit.first;
  const std::string& unit = limit.second;
  const std::string& objective = goal.first;
  const std::string& objective_unit = goal.second;
  io::write_atomically(path, [&](std::ostream& out) {
    out << fmt::format("limit_{}[{}],feasible[1],{}[{}],{}[{}]", name, unit, objective,
                       objective_unit, name, unit);
    for (const auto& v : study.design) {
      const auto [vname, vunit] = study::split_unit_suffix(v.name);
      out << fmt::format(",{}[{}]", vname, vunit);
    }
    out << "\n";
    for (const auto& p : o.tradeoff) {
      out << fmt::format("{:.10g},{},{:.10g},{:.10g}", p.limit, p.run.feasible ? 1 : 0,
                         p.run.verified.objective, p.achieved);
      for (double x : p.run.best.x) out << fmt::format(",{:.10g}", x);
      out << "\n";
    }
  });
}

io::Figure figure_of(const opt::TuningProblem& problem, const Outcome& o) {
  const auto& study = problem.study();
  const auto [objective, objective_unit] = study::split_unit_suffix(study.objective.metric);
  const std::string objective_label = fmt::format("{} [{}]", objective, objective_unit);
  io::Figure figure;
  figure.title = fmt::format("ridefit optimise {}", study.study_file.filename().string());
  io::PlotPanel history = io::xy_panel("search", "evaluation", objective_label);
  io::PlotSeries feasible{"limits hold", {}, {}, {}, {}, io::SeriesStyle::kPoints};
  io::PlotSeries infeasible{"a limit exceeded", {}, {}, {}, {}, io::SeriesStyle::kPoints};
  for (std::size_t i = 0; i < o.aware.history.size(); ++i) {
    const auto& step = o.aware.history[i];
    auto& s = step.max_violation <= study.optimiser.constraint_tolerance ? feasible : infeasible;
    s.x.push_back(static_cast<double>(i + 1));
    s.y.push_back(step.objective);
  }
  for (auto* s : {&feasible, &infeasible}) {
    if (!s->x.empty()) history.series.push_back(*s);
  }
  history.x_range = std::pair{0.0, static_cast<double>(o.aware.history.size() + 1)};
  figure.panels.push_back(history);
  if (!o.tradeoff.empty() || (o.friction && !study.constraints.empty())) {
    const std::string metric = study.tradeoff
                                   ? study.constraints[study.tradeoff->constraint].metric
                                   : (study.constraints.empty() ? study.objective.metric
                                                                : study.constraints.front().metric);
    const std::size_t index = problem.metric_index(metric);
    const auto& c =
        study.tradeoff ? study.constraints[study.tradeoff->constraint] : study.constraints.front();
    const auto [name, unit] = study::split_unit_suffix(metric);
    io::PlotPanel front = io::xy_panel(std::string(study.tradeoff ? "trade-off" : "optima") +
                                           (study.model_has_friction ? " (with friction)" : ""),
                                       fmt::format("{} [{}]", name, unit), objective_label);
    if (!o.tradeoff.empty()) {
      io::PlotSeries curve{"optimum per limit", {}, {}, {}, {}, io::SeriesStyle::kLinesPoints};
      for (const auto& p : o.tradeoff) {
        if (!p.run.feasible) continue;
        curve.x.push_back(p.achieved);
        curve.y.push_back(p.run.verified.objective);
      }
      if (!curve.x.empty()) front.series.push_back(curve);
    }
    auto point = [&](const std::string& label, const opt::Evaluation& e) {
      const double value = problem.aggregate(e, index, c.aggregate, c.is_upper);
      front.series.push_back({label, {value}, {e.objective}, {}, {}, io::SeriesStyle::kPoints});
    };
    point(study.model_has_friction ? "friction-aware optimum" : "optimum", o.aware.verified);
    if (o.friction) point("friction-blind optimum, with friction", o.friction->blind_with_friction);
    front.key_position = "top right";
    figure.panels.push_back(front);
  }
  return figure;
}

void print_table(const opt::TuningProblem& problem, const Outcome& o, double wall_time_s) {
  const auto& study = problem.study();
  const auto& run = o.aware;
  std::cout << fmt::format(
      "{}: {} with {} start(s), NLopt: {}; {} evaluations ({} computed, {} "
      "from the journal or repeated), {:.1f} s\n",
      study.study_file.string(), opt::to_string(study.optimiser.algorithm), study.optimiser.starts,
      run.nlopt_result, run.evaluations, run.computed, run.evaluations - run.computed, wall_time_s);
  std::cout << (run.feasible ? "Optimum (limits hold at the re-evaluated point):\n"
                             : "INFEASIBLE: the search found no design that holds every limit; "
                               "the least violating design:\n");
  if (run.feasible && run.nlopt_result.starts_with("max")) {
    std::cout << "  (the search stopped at its evaluation or time limit: the best design found, "
                 "perhaps not converged)\n";
  }
  for (std::size_t v = 0; v < run.best.x.size(); ++v) {
    std::cout << fmt::format("  {:<36} {:>12.6g}   (start {:g}, bounds {:g} … {:g})\n",
                             study.design[v].name, run.best.x[v], study.design[v].start,
                             study.design[v].lower, study.design[v].upper);
  }
  std::cout << fmt::format("  objective {} ({}): {:.6g}\n", study.objective.metric,
                           opt::to_string(study.objective.aggregate), run.verified.objective);
  for (const auto& m : run.margins) {
    std::cout << fmt::format("  {:<52} value {:>10.5g}  margin {:>+10.4g} ({:+.2f} %) {}\n",
                             m.description, m.value, m.margin, 100 * m.relative_margin,
                             !m.holds          ? "VIOLATED"
                             : m.margin >= 0.0 ? "holds"
                                               : "within tolerance");
  }
  for (std::size_t c = 0; c < study.load_cases.size(); ++c) {
    std::cout << fmt::format(
        "  case {:<16} ({}) {} = {:.5g}\n", study.load_cases[c].name,
        run.verified.frequency_domain[c] ? "frequency domain" : "simulated", study.objective.metric,
        run.verified.case_values[c][problem.metric_index(study.objective.metric)]);
  }
  if (o.friction) {
    const auto& f = *o.friction;
    std::cout << "What ignoring friction costs (both optima evaluated with friction):\n";
    for (std::size_t v = 0; v < run.best.x.size(); ++v) {
      std::cout << fmt::format("  {:<36} aware {:>12.6g}   blind {:>12.6g}\n", study.design[v].name,
                               run.best.x[v], f.blind.best.x[v]);
    }
    std::cout << fmt::format(
        "  objective with friction: aware {:.6g}, blind {:.6g} ({:+.2f} %); the blind model "
        "predicted {:.6g}\n",
        run.verified.objective, f.blind_with_friction.objective, f.comfort_loss_percent,
        f.blind.verified.objective);
    if (!f.blind_feasible_with_friction) {
      std::cout << "  and the blind optimum breaks a limit once friction is present:\n";
      for (const auto& m : f.blind_margins_with_friction) {
        if (!m.holds) std::cout << fmt::format("    {} value {:.5g}\n", m.description, m.value);
      }
    }
  }
  if (!o.tradeoff.empty()) {
    const auto& c = study.constraints[study.tradeoff->constraint];
    std::cout << fmt::format("Trade-off: {} against the limit on {}\n", study.objective.metric,
                             c.metric);
    for (const auto& p : o.tradeoff) {
      std::cout << fmt::format("  limit {:>10.5g}  {}", p.limit,
                               p.run.feasible ? fmt::format("objective {:.5g}, achieved {:.5g}",
                                                            p.run.verified.objective, p.achieved)
                                              : std::string("infeasible"));
      for (std::size_t v = 0; v < p.run.best.x.size(); ++v) {
        std::cout << fmt::format("  {}={:.5g}", study.design[v].name, p.run.best.x[v]);
      }
      std::cout << "\n";
    }
  }
}

void run(const OptimiseFlags& flags) {
  const std::filesystem::path study_path = flags.study_file;
  if (!flags.resume_file.empty() && !flags.journal_file.empty()) {
    throw InputError(
        "--resume JOURNAL continues that journal; give --resume or --journal, not both");
  }
  opt::TuningStudy study = opt::load_tuning_study(study_path);
  if (flags.threads >= 0) study.evaluation.threads = static_cast<unsigned>(flags.threads);
  // Every file the study reads: no output may replace one of them, nor another output.
  std::vector<std::filesystem::path> inputs = {study_path, study.model_file};
  if (!study.fitted_model.empty()) inputs.push_back(study.fitted_model);
  for (const auto& c : study.load_cases) inputs.push_back(c.road_file);
  const std::string model_out =
      flags.output_file.empty() ? "" : sibling(flags.output_file, "_model.yaml").string();
  const std::string tradeoff_csv = flags.output_file.empty() || !study.tradeoff
                                       ? ""
                                       : sibling(flags.output_file, "_tradeoff.csv").string();
  const std::filesystem::path journal_path =
      !flags.resume_file.empty()    ? std::filesystem::path(flags.resume_file)
      : !flags.journal_file.empty() ? std::filesystem::path(flags.journal_file)
      : !flags.output_file.empty()  ? sibling(flags.output_file, ".journal")
                                   : std::filesystem::path(study_path.stem().string() + ".journal");
  if (!flags.resume_file.empty()) {
    for (const auto& input : inputs) {
      if (io::same_file(input, journal_path)) {
        throw InputError(fmt::format("--resume {}: that is an input of the study, not a journal",
                                     journal_path.string()));
      }
    }
  }
  io::RunOutputs outputs(inputs);
  outputs.add_file(flags.output_file, "-o");
  outputs.add_file(model_out, "-o (the optimised model)");
  outputs.add_file(tradeoff_csv, "-o (the trade-off CSV)");
  if (flags.resume_file.empty()) {
    outputs.add_file(journal_path, "--journal");
  } else {
    outputs.add_input(journal_path);
  }
  outputs.add_plot(flags.plot_file, "--plot");
  // The roads are made (and every remaining check done) before the journal is opened, so a
  // study that cannot run never replaces an existing journal.
  opt::TuningProblem problem(study);
  const std::string fingerprint = opt::study_fingerprint(study);
  const opt::EvaluationJournal::Shape shape{study.design.size(), study.load_cases.size(),
                                            opt::metric_names(study.kind).size()};
  std::optional<opt::EvaluationJournal> journal;
  if (!flags.resume_file.empty()) {
    try {
      journal.emplace(opt::EvaluationJournal::resume(journal_path, fingerprint, shape));
    } catch (const InputError& e) {
      throw InputError(fmt::format("--resume: {}", e.what()));
    }
  } else {
    try {
      journal.emplace(opt::EvaluationJournal::create(journal_path, fingerprint, flags.force));
    } catch (const InputError& e) {
      const std::string what = e.what();
      if (what.find("did not finish") == std::string::npos) throw;
      throw InputError(fmt::format("{} (--resume {} continues it; --force starts afresh)", what,
                                   journal_path.string()));
    }
  }
  problem.attach_journal(&*journal);
  if (!flags.quiet) {
    std::cerr << fmt::format("optimise: journal {}{}\n", journal->path().string(),
                             flags.resume_file.empty()
                                 ? ""
                                 : fmt::format(" ({} evaluations to reuse)", journal->size()));
  }
  const auto started = std::chrono::steady_clock::now();
  std::string stage;
  const opt::ProgressSink progress = [&](const std::string& line) {
    if (!flags.quiet) std::cerr << "optimise" << stage << ": " << line << "\n";
  };
  Outcome o;
  o.aware = opt::optimise(problem, opt::FrictionVariant::kStudy, problem.study_limits(),
                          opt::study_start(problem.study()), progress);
  // The comparisons need an optimum to compare with.
  if (problem.study().friction_cost && o.aware.feasible) {
    stage = " (friction-blind)";
    o.friction = opt::friction_cost(problem, o.aware, progress);
  }
  if (problem.study().tradeoff && o.aware.feasible) {
    stage = " (trade-off)";
    o.tradeoff = opt::tradeoff_curve(problem, o.aware.best.x, progress);
  }
  const double wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  const std::string written_model = o.aware.feasible ? model_out : "";
  const std::string written_tradeoff = o.tradeoff.empty() ? "" : tradeoff_csv;
  const nlohmann::json result = result_json(problem, o, flags, written_model, written_tradeoff,
                                            journal->path().string(), wall_time_s);
  if (!written_tradeoff.empty()) write_tradeoff_csv(problem, o, written_tradeoff);
  if (!written_model.empty()) {
    io::write_model_with_values(
        problem.study().model_file, opt::tuned_values(problem.study(), o.aware.best.x),
        written_model,
        fmt::format("Optimised by ridefit optimise {} from {}", study_path.string(),
                    problem.study().model_file.string()));
  }
  if (!flags.output_file.empty()) {
    io::write_atomically(flags.output_file, [&](std::ostream& out) {
      out << "# ridefit optimise " << study_path.string() << "\n" << to_yaml(result) << "\n";
    });
  }
  if (!flags.plot_file.empty()) io::draw_figure(figure_of(problem, o), flags.plot_file);
  journal->mark_finished();
  if (flags.json) {
    std::cout << result.dump(2) << "\n";
  } else {
    print_table(problem, o, wall_time_s);
    if (!flags.output_file.empty()) std::cout << "Result: " << flags.output_file << "\n";
    if (!written_model.empty()) std::cout << "Optimised model: " << written_model << "\n";
    if (!written_tradeoff.empty()) std::cout << "Trade-off: " << written_tradeoff << "\n";
    if (!flags.plot_file.empty()) std::cout << "Figure: " << flags.plot_file << "\n";
  }
  if (!o.aware.feasible) {
    std::string violated;
    for (const auto& m : o.aware.margins) {
      if (!m.holds) violated += fmt::format("; {} reaches {:.5g}", m.description, m.value);
    }
    throw RunError(
        fmt::format("infeasible: no design within the bounds holds every limit{}; no "
                    "optimised model was written",
                    violated));
  }
}

}  // namespace

void register_optimise(CLI::App& app) {
  auto flags = std::make_shared<OptimiseFlags>();
  CLI::App* command = app.add_subcommand(
      "optimise",
      "Tune damping with NLopt under friction: minimise ISO 2631 Wk seat acceleration with "
      "limits on tyre load and travel; trade-off curve and the cost of ignoring friction");
  command->add_option("study", flags->study_file, "Study file (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("-o,--output", flags->output_file,
                      "Result (YAML, written atomically); also writes NAME_model.yaml (the "
                      "optimised model) and NAME_tradeoff.csv");
  command->add_option("--resume", flags->resume_file,
                      "Continue a killed run from its journal, reusing finished evaluations");
  command->add_flag("--force", flags->force,
                    "Start afresh even when the journal holds evaluations of a run that did not "
                    "finish (they are lost; --resume continues them instead)");
  command->add_option("--journal", flags->journal_file,
                      "Journal file (default: next to -o, else STUDY.journal here)");
  command->add_option("--plot", flags->plot_file, "Search history and trade-off (.png or .svg)");
  command->add_option("--threads", flags->threads, "Threads for the load cases (0: every core)")
      ->check(CLI::Range(0, 256));
  command->add_flag("--json", flags->json, "Print the result as JSON");
  command->add_flag("-q,--quiet", flags->quiet, "No progress on stderr");
  command->callback([flags] { run(*flags); });
}

}  // namespace ridefit::cli
