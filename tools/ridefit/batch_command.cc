// ridefit batch JOBS.yaml [-o DIR] [--threads N] [--json] [-q] [--force]
// Independent fits and diagnoses of many records (batch_jobs.h), one job per task over the ranks
// of mpirun (distributed/task_farm.h): every job's outputs go into DIR/<name>/ and the summary
// into DIR/summary.csv and DIR/summary.json, all written by rank 0 alone as jobs finish.
#include <fmt/core.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "batch_job_result.h"
#include "batch_jobs.h"
#include "batch_summary.h"
#include "collective_run_error.h"
#include "command_options.h"
#include "ridefit/common/errors.h"
#include "ridefit/distributed/mpi_session.h"
#include "ridefit/distributed/task_farm.h"
#include "ridefit/io/atomic_file.h"
#include "ridefit/io/output_paths.h"
#include "ridefit/io/path_type.h"
#include "ridefit/io/staged_folder.h"
#include "subcommands.h"

namespace ridefit::cli {
namespace {

namespace fs = std::filesystem;

struct BatchFlags {
  std::string job_file;
  std::string output_dir = "batch";
  unsigned threads = 0;
  bool json = false;
  bool quiet = false;
  bool force = false;
};

// Every output of the run checked before any job runs: each job's folder in -o (a message
// names the job), then -o itself with the summaries; none of them an input, no foreign files
// unless --force.
void check_outputs(const BatchFlags& flags, const std::vector<BatchJob>& jobs) {
  io::RunOutputs outputs({flags.job_file});
  for (const auto& job : jobs) {
    for (const auto& input : job.inputs) outputs.add_input(input);
  }
  std::vector<std::string> names = {"summary.csv", "summary.json"};
  for (const auto& job : jobs) {
    names.push_back(job.name);
    try {
      outputs.add_folder(fs::path(flags.output_dir) / job.name, "-o", job.files, flags.force,
                         "--force");
    } catch (const InputError& e) {
      throw InputError(
          fmt::format("{}: job {} ({}): {}", flags.job_file, job.number, job.name, e.what()));
    }
  }
  outputs.add_folder(flags.output_dir, "-o", names, flags.force, "--force");
}

// A finished job's folder, written as a whole; what an earlier run wrote there and this one
// does not (a failed job's model) goes. A failed job without results makes no new folder.
void write_job_folder(const fs::path& dir, const BatchJob& job, const BatchJobResult& result) {
  if (result.files.empty() && !io::path_exists(dir)) return;
  std::vector<std::string> names = job.files;
  for (const auto& file : result.files) {
    if (std::find(names.begin(), names.end(), file.name) == names.end()) names.push_back(file.name);
  }
  io::StagedFolder staged(dir, names);
  for (const auto& file : result.files) {
    io::write_atomically(staged.path() / file.name, [&](std::ostream& out) { out << file.text; });
  }
  staged.commit();
}

void print_table(const nlohmann::json& summary, const fs::path& dir) {
  for (const auto& row : summary.at("jobs")) {
    std::string what;
    if (row.contains("gap_unit")) {
      what = fmt::format(
          "{}, gap {:.3g} -> {:.3g} {}",
          row["top_effect"].is_string() ? row["top_effect"].get<std::string>() : "no effect named",
          row.value("gap_before", 0.0), row.value("gap_after", 0.0), row.value("gap_unit", ""));
    } else if (row.contains("nrmse_percent") && row["nrmse_percent"].is_number()) {
      what = fmt::format("NRMSE {:.3g} %", row["nrmse_percent"].get<double>());
    }
    std::cout << fmt::format(
        "{:<24} {:<15} {:<7} {}{}\n", row.at("name").get<std::string>(),
        row.at("command").get<std::string>(), row.at("status").get<std::string>(), what,
        row.contains("message") ? fmt::format("  {}", row["message"].get<std::string>()) : "");
  }
  std::cout << fmt::format("{} ok, {} failed; summary: {}\n", summary.at("ok").get<int>(),
                           summary.at("failed").get<int>(), (dir / "summary.csv").string());
}

void run(const BatchFlags& flags) {
  const distributed::MpiSession& session = *distributed::MpiSession::current();
  // Every rank reads the job file (a job is its index); rank 0 alone checks and writes outputs.
  const std::vector<BatchJob> jobs = load_batch_jobs(flags.job_file);
  const fs::path dir = flags.output_dir;
  std::vector<BatchJobResult> results(jobs.size());
  std::size_t done = 0;
  if (session.root()) {
    check_outputs(flags, jobs);
    io::prepare_output_directory(dir, "-o");
    std::vector<std::string> names = {"summary.csv", "summary.json"};
    for (const auto& job : jobs) names.push_back(job.name);
    io::finish_output_folder(dir, names);
    write_batch_summary(dir, batch_summary_json(flags.job_file, jobs, results));
  }
  distributed::TaskFarmStatistics farm;
  distributed::TaskFarmOptions options;
  options.threads = flags.threads;
  options.chunk = 1;
  options.statistics = &farm;
  options.on_result = [&](std::size_t task, const std::string& bytes) {
    results[task] = decode_batch_job_result(bytes);
    write_job_folder(dir / jobs[task].name, jobs[task], results[task]);
    write_batch_summary(dir, batch_summary_json(flags.job_file, jobs, results));
    ++done;
    if (flags.quiet || flags.json) return;
    std::cerr << fmt::format(
        "batch: {}/{} {}: {} ({:.2f} s){}\n", done, jobs.size(), jobs[task].name,
        results[task].status, results[task].wall_time_s,
        results[task].message.empty() ? "" : fmt::format(": {}", results[task].message));
  };
  distributed::run_task_farm(
      session, jobs.size(), [&](std::size_t i) { return encode(run_batch_job(jobs[i])); }, options);
  std::size_t failed = 0;
  if (session.root()) {
    const nlohmann::json summary = batch_summary_json(flags.job_file, jobs, results);
    if (flags.json) {
      // Under mpirun, how the jobs were shared (printed only: the files are any run's).
      nlohmann::json printed = summary;
      if (session.size() > 1) {
        printed["ranks"] = {{"count", session.size()},
                            {"jobs_on_rank0", farm.tasks_on_rank0},
                            {"jobs_to_other_ranks", farm.chunks_handed_out},
                            {"bytes_received_by_rank0", farm.bytes_received},
                            {"bytes_sent_by_rank0", farm.bytes_sent}};
      }
      std::cout << printed.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    } else {
      print_table(summary, dir);
    }
    failed = summary.at("failed").get<std::size_t>();
  }
  // Every rank ends alike: exit 1 on all of them when a job failed (no MPI_Abort).
  failed = std::stoul(distributed::broadcast_from_root(session, std::to_string(failed)));
  if (failed > 0) {
    throw CollectiveRunError(fmt::format("{} of {} jobs failed (see {})", failed, jobs.size(),
                                         (dir / "summary.csv").string()));
  }
}

}  // namespace

void register_batch(CLI::App& app) {
  auto flags = std::make_shared<BatchFlags>();
  CLI::App* command = app.add_subcommand(
      "batch",
      "Run many independent fits or diagnoses listed in a job file (`fit hysteresis`, `fit psd`, "
      "`diagnose`, one per record), spread over the ranks of mpirun; each job's files go into "
      "DIR/<name>/, a summary of all into DIR/summary.csv and DIR/summary.json");
  command
      ->add_option("jobs", flags->job_file,
                   "Job file (YAML): `defaults:` {command, model, options} and `jobs:`, each a "
                   "`record:` (file or list) or `records:` (a glob: one job per file), an "
                   "optional `name:` and its own command, model or options; paths relative to "
                   "the job file; options are the command's flags without the dashes")
      ->required()
      ->check(CLI::ExistingFile);
  command
      ->add_option("-o,--output", flags->output_dir,
                   "Output folder: summary.csv, summary.json and a folder per job (result.json, "
                   "model.yaml, a diagnosis' report.md)")
      ->capture_default_str();
  command
      ->add_option("--threads", flags->threads,
                   "Jobs run at once on each rank (default: every core; under mpirun, each "
                   "rank's share of its machine's cores)")
      ->check(CLI::Range(1u, 256u));
  command->add_flag("--json", flags->json, "Print the summary (summary.json) on stdout");
  command->add_flag("-q,--quiet", flags->quiet, "No progress on stderr");
  add_force_flag(*command, flags->force);
  command->callback([flags] { run(*flags); });
}

}  // namespace ridefit::cli
