// ridefit optimise STUDY.yaml [-o result.yaml] [--resume JOURNAL] [--journal FILE]
//                             [--plot FILE.png|svg] [--json] [--threads N]
// mpirun -np N ridefit optimise …: the searches spread over the ranks, the same result.
// Damper tuning with NLopt under friction: the optimum, its verified constraint margins, the
// cost of ignoring friction and the comfort / road-holding trade-off. The study, its report
// and its result files are the library's (optimisation/tuning_*); here are the flags, the
// journal and what goes to the terminal.
#include <fmt/core.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "distributed_tuning.h"
#include "ridefit/common/errors.h"
#include "ridefit/distributed/mpi_session.h"
#include "ridefit/io/gnuplot_figure.h"
#include "ridefit/io/output_paths.h"
#include "ridefit/optimisation/evaluation_journal.h"
#include "ridefit/optimisation/tuning_figure.h"
#include "ridefit/optimisation/tuning_files.h"
#include "ridefit/optimisation/tuning_outcome.h"
#include "ridefit/optimisation/tuning_report.h"
#include "ridefit/optimisation/tuning_result.h"
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

// Every output checked against the inputs and each other before any work is done; a resumed
// journal is an input of the run.
void check_outputs(const OptimiseFlags& flags, const opt::TuningStudy& study,
                   const opt::TuningFiles& files) {
  const std::vector<std::filesystem::path> inputs = opt::study_inputs(study);
  if (!flags.resume_file.empty()) {
    for (const auto& input : inputs) {
      if (io::same_file(input, files.journal)) {
        throw InputError(fmt::format("--resume {}: that is an input of the study, not a journal",
                                     files.journal.string()));
      }
    }
  }
  io::RunOutputs outputs(inputs);
  outputs.add_file(files.result, "-o");
  outputs.add_file(files.model, "-o (the optimised model)");
  outputs.add_file(files.tradeoff_csv, "-o (the trade-off CSV)");
  if (flags.resume_file.empty()) {
    outputs.add_file(files.journal, "--journal");
  } else {
    outputs.add_input(files.journal);
  }
  outputs.add_plot(flags.plot_file, "--plot");
}

// The journal continued (--resume) or started; its errors name the flag that helps.
opt::EvaluationJournal open_journal(const OptimiseFlags& flags, const opt::TuningStudy& study,
                                    const std::filesystem::path& path) {
  const std::string fingerprint = opt::study_fingerprint(study);
  if (!flags.resume_file.empty()) {
    const opt::EvaluationJournal::Shape shape{study.design.size(), study.load_cases.size(),
                                              opt::metric_names(study.kind).size()};
    try {
      return opt::EvaluationJournal::resume(path, fingerprint, shape);
    } catch (const InputError& e) {
      throw InputError(fmt::format("--resume: {}", e.what()));
    }
  }
  try {
    return opt::EvaluationJournal::create(path, fingerprint, flags.force);
  } catch (const InputError& e) {
    const std::string what = e.what();
    if (what.find("did not finish") == std::string::npos) throw;
    throw InputError(
        fmt::format("{} (--resume {} continues it; --force starts afresh)", what, path.string()));
  }
}

void run(const OptimiseFlags& flags) {
  if (!flags.resume_file.empty() && !flags.journal_file.empty()) {
    throw InputError(
        "--resume JOURNAL continues that journal; give --resume or --journal, not both");
  }
  // Under mpirun every rank runs the study alike and the searches are spread over the ranks;
  // rank 0 alone checks and writes files, owns the journal and prints.
  const distributed::MpiSession* session = distributed::MpiSession::current();
  // Under mpirun (even -np 1) the searches go through the task farm, which reports the share.
  const bool under_mpirun = session != nullptr && session->active();
  const bool over_ranks = under_mpirun && session->size() > 1;
  const bool root = session == nullptr || session->root();
  const bool quiet = flags.quiet || !root;
  opt::TuningStudy study = opt::load_tuning_study(flags.study_file);
  if (flags.threads >= 0) study.evaluation.threads = static_cast<unsigned>(flags.threads);
  const opt::TuningFiles files =
      opt::tuning_files(study, flags.output_file,
                        !flags.resume_file.empty() ? flags.resume_file : flags.journal_file);
  if (root) check_outputs(flags, study, files);
  // The roads are made (and every remaining check done) before the journal is opened, so a
  // study that cannot run never replaces an existing journal.
  opt::TuningProblem problem(study);
  std::optional<opt::EvaluationJournal> journal;
  if (root) {
    journal.emplace(open_journal(flags, study, files.journal));
    problem.attach_journal(&*journal);
  }
  std::optional<RankSearchRunner> ranks;
  if (under_mpirun) {
    share_journal(*session, problem, journal ? &*journal : nullptr);
    ranks.emplace(*session, flags.threads > 0 ? static_cast<unsigned>(flags.threads) : 0u,
                  journal ? &*journal : nullptr);
  }
  if (!quiet) {
    std::cerr << fmt::format(
        "optimise: journal {}{}{}\n", journal->path().string(),
        flags.resume_file.empty() ? "" : fmt::format(" ({} evaluations to reuse)", journal->size()),
        over_ranks ? fmt::format(", {} ranks", session->size()) : "");
  }
  const auto started = std::chrono::steady_clock::now();
  const opt::TuningOutcome outcome = opt::run_tuning_study(
      problem,
      [&](const std::string& stage, const std::string& line) {
        if (quiet) return;
        std::cerr << "optimise" << (stage.empty() ? "" : " (" + stage + ")") << ": " << line
                  << "\n";
      },
      ranks ? &*ranks : nullptr);
  const double wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (!root) return;

  const opt::WrittenFiles written = opt::written_files(files, outcome, flags.plot_file);
  nlohmann::json result = opt::tuning_result(problem, outcome, written, wall_time_s);
  opt::write_tuning_result(problem, outcome, written, result, files.result,
                           "ridefit optimise " + flags.study_file);
  if (!flags.plot_file.empty()) {
    io::draw_figure(opt::tuning_figure(problem, outcome), flags.plot_file);
  }
  journal->mark_finished();
  if (flags.json) {
    if (ranks) {
      // How the work was shared (stdout only: the result file is the one-process run's).
      const SearchShare& share = ranks->share();
      nlohmann::json stages = nlohmann::json::array();
      for (const StageShare& stage : share.stages) {
        stages.push_back({{"searches", stage.searches},
                          {"wall_time_s", stage.wall_time_s},
                          {"longest_search_s", stage.longest_search_s}});
      }
      result["ranks"] = {{"count", session->size()},
                         {"stages", stages},
                         {"searches", share.searches},
                         {"searches_on_rank0", share.searches_on_rank0},
                         {"evaluations", share.evaluations},
                         {"search_time_s", share.search_time_s},
                         {"bytes_received_by_rank0", share.bytes_received},
                         {"bytes_sent_by_rank0", share.bytes_sent},
                         {"bytes_broadcast_by_rank0", share.bytes_broadcast}};
    }
    std::cout << result.dump(2) << "\n";
  } else {
    opt::write_tuning_report(std::cout, problem, outcome, wall_time_s);
    if (!files.result.empty()) std::cout << "Result: " << files.result << "\n";
    if (!written.model.empty()) std::cout << "Optimised model: " << written.model << "\n";
    if (!written.tradeoff_csv.empty()) std::cout << "Trade-off: " << written.tradeoff_csv << "\n";
    if (!flags.plot_file.empty()) std::cout << "Figure: " << flags.plot_file << "\n";
  }
  if (!outcome.aware.feasible) throw RunError(opt::infeasibility_message(outcome.aware));
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
  command
      ->add_option("--threads", flags->threads,
                   "Threads for the searches and load cases (0: every core; under mpirun, per "
                   "rank, default: its share of the cores)")
      ->check(CLI::Range(0, 256));
  command->add_flag("--json", flags->json, "Print the result as JSON");
  command->add_flag("-q,--quiet", flags->quiet, "No progress on stderr");
  command->callback([flags] { run(*flags); });
}

}  // namespace ridefit::cli
