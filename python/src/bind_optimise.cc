// optimise: damper tuning from a study file (optimisation/tuning_*), the result tree of
// `ridefit optimise --json` as a dict.
#include <pybind11/stl.h>

#include <fmt/core.h>

#include <chrono>
#include <optional>
#include <string>

#include "bindings.h"
#include "json_to_python.h"
#include "progress_callback.h"
#include "ridefit/common/errors.h"
#include "ridefit/io/output_paths.h"
#include "ridefit/optimisation/evaluation_journal.h"
#include "ridefit/optimisation/tuning_files.h"
#include "ridefit/optimisation/tuning_outcome.h"
#include "ridefit/optimisation/tuning_problem.h"
#include "ridefit/optimisation/tuning_result.h"
#include "ridefit/optimisation/tuning_study.h"

namespace ridefit::python {

namespace py = pybind11;
namespace opt = optimisation;

namespace {

// Without `journal` nothing is journalled; without `output` no file is written (the CLI always
// journals and writes where -o says).
py::object optimise(const std::string& study_file, const std::string& output,
                    const std::string& journal_file, std::optional<int> threads,
                    const py::object& progress) {
  opt::TuningStudy study = opt::load_tuning_study(study_file);
  if (threads) {
    if (*threads < 0 || *threads > 256) {
      throw InputError(fmt::format("threads: {} is not in [0, 256]", *threads));
    }
    study.evaluation.threads = static_cast<unsigned>(*threads);
  }
  const opt::TuningFiles files = opt::tuning_files(study, output, journal_file);
  if (!output.empty()) {
    io::RunOutputs outputs(opt::study_inputs(study));
    outputs.add_file(files.result, "output");
    outputs.add_file(files.model, "output (the optimised model)");
    outputs.add_file(files.tradeoff_csv, "output (the trade-off CSV)");
  }
  opt::TuningProblem problem(study);
  std::optional<opt::EvaluationJournal> journal;
  if (!journal_file.empty()) {
    journal.emplace(opt::EvaluationJournal::create(files.journal, opt::study_fingerprint(study),
                                                   /*force=*/true));
    problem.attach_journal(&*journal);
  }
  const auto started = std::chrono::steady_clock::now();
  nlohmann::json result;
  {
    py::gil_scoped_release unlocked;
    const auto line_of = progress_callback(progress);
    opt::StageProgress stage_progress;
    if (line_of) {
      stage_progress = [&line_of](const std::string& stage, const std::string& line) {
        line_of(stage.empty() ? line : "(" + stage + ") " + line);
      };
    }
    const opt::TuningOutcome outcome = opt::run_tuning_study(problem, stage_progress);
    const double wall_time_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    // Only the files this call writes are named in the result.
    opt::TuningFiles written_paths;
    if (!output.empty()) written_paths = files;
    if (journal) written_paths.journal = files.journal;
    const opt::WrittenFiles written = opt::written_files(written_paths, outcome, "");
    result = opt::tuning_result(problem, outcome, written, wall_time_s);
    if (!output.empty()) {
      opt::write_tuning_result(problem, outcome, written, result, files.result,
                               "ridefit.optimise " + study_file);
    }
    if (journal) journal->mark_finished();
  }
  return to_python(result);
}

}  // namespace

void bind_optimise(py::module_& m) {
  m.def("_optimise", &optimise, py::arg("study"), py::arg("output") = "", py::arg("journal") = "",
        py::arg("threads") = py::none(), py::arg("progress") = py::none(),
        R"(Damper tuning with NLopt under friction from a study file (YAML), as `ridefit optimise
STUDY --json` runs it. Returns the result tree (status, variables, objective, constraint margins,
load cases, friction, the cost of ignoring it, the trade-off). output: a result YAML to write (with
NAME_model.yaml and NAME_tradeoff.csv beside it); journal: a journal file of the evaluations
(started afresh); threads: for the load cases (0 = every core; default the study's).
An infeasible optimum is reported in the result ('status'), not raised.)");
}

}  // namespace ridefit::python
