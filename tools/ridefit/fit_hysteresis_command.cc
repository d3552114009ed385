// ridefit fit hysteresis DATA.csv... --model M.yaml --free a,b,... [--per-file c]
//                       [--bounds name=lo:hi]... [--start name=value]... [--loss huber|cauchy]
//                       [--record-weights newtons|relative]
//                       [--compression mm,...] [-o fitted.yaml] [--plot FILE.png|svg] [--json]
// Fits the strut's parameters to rig tests (fitting/hysteresis_fit.h), writes the fitted model
// file(s) and reports the fit (fitting/hysteresis_fit_report.h).
#include <fmt/core.h>
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

#include "command_options.h"
#include "command_outcome.h"
#include "fit_command.h"
#include "ridefit/common/errors.h"
#include "ridefit/fitting/fit_convergence.h"
#include "ridefit/fitting/hysteresis_fit.h"
#include "ridefit/fitting/hysteresis_fit_report.h"
#include "ridefit/fitting/hysteresis_prediction.h"
#include "ridefit/fitting/rig_figure.h"
#include "ridefit/fitting/strut_parameters.h"
#include "ridefit/fitting/strut_start.h"
#include "ridefit/io/atomic_file.h"
#include "ridefit/io/model_values_file.h"
#include "ridefit/io/output_paths.h"
#include "ridefit/io/quarter_car_file.h"
#include "ridefit/model/quarter_car_parameter_table.h"

namespace ridefit::cli {
namespace {

struct FitHysteresisFlags {
  std::vector<std::string> files;
  std::string model_file;
  std::vector<std::string> free;
  std::vector<std::string> per_file;
  std::vector<std::string> bounds;
  std::vector<std::string> starts;
  std::string loss = "none";
  double loss_scale_N = 5.0;
  std::string record_weights = "newtons";
  double relative_tolerance = 1e-6;
  std::string interpolation = "spline";
  int max_iterations = 100;
  std::vector<double> compression_mm;
  std::vector<std::string> validate_files;
  double validate_from_s = 0.0;
  std::string output_file;
  std::string plot_file;
  double max_nrmse_percent = 10.0;
  bool keep = false;
  bool json = false;
};

// The model file's strut on the rig with the --start values.
model::StrutTestParameters<double> start_from(const io::QuarterCarFile& file,
                                              const std::vector<std::string>& starts) {
  const std::map<std::string, double> values = parse_overrides(starts);
  try {
    return fitting::with_strut_values(fitting::strut_on_rig(file.parameters), values);
  } catch (const InputError& e) {
    throw InputError(fmt::format("--start {}", e.what()));
  }
}

std::map<std::string, std::pair<double, double>> parse_bounds(
    const std::vector<std::string>& entries) {
  std::map<std::string, std::pair<double, double>> bounds;
  for (const auto& [name, text] : parse_key_values(entries)) {
    const auto colon = text.find(':');
    char* end = nullptr;
    const std::string lo_text = text.substr(0, colon);
    const std::string hi_text = colon == std::string::npos ? "" : text.substr(colon + 1);
    const double lo = std::strtod(lo_text.c_str(), &end);
    const bool lo_ok = end != lo_text.c_str() && *end == '\0';
    const double hi = std::strtod(hi_text.c_str(), &end);
    const bool hi_ok = end != hi_text.c_str() && *end == '\0';
    if (colon == std::string::npos || !lo_ok || !hi_ok) {
      throw InputError(fmt::format(
          "--bounds {}={}: expected NAME=LOWER:UPPER, e.g. coulomb_force_N=10:200", name, text));
    }
    fitting::strut_parameter_index(name);
    bounds[name] = {lo, hi};
  }
  return bounds;
}

// Flags that only make sense together, checked before the fit: a bound only acts on a fitted
// parameter (one on a fixed parameter would be ignored), and the friction-compression line
// needs a friction value per file.
void check_flag_combinations(const FitHysteresisFlags& flags,
                             const fitting::HysteresisFitOptions& options) {
  const auto fitted = [&](const std::string& name) {
    return std::ranges::count(flags.free, name) + std::ranges::count(flags.per_file, name) > 0;
  };
  for (const auto& [name, bound] : options.bounds) {
    if (fitted(name)) continue;
    throw InputError(fmt::format(
        "--bounds {}={}:{}: {} is not fitted (--free {}), so the bound would be ignored; add it "
        "to --free or leave the bound out",
        name, bound.first, bound.second, name, fmt::join(flags.free, ",")));
  }
  if (!flags.compression_mm.empty() &&
      (flags.compression_mm.size() != flags.files.size() ||
       std::ranges::count(flags.per_file, model::quarter_car_rows::coulomb_force_N.key) == 0)) {
    throw InputError(
        fmt::format("--compression: give one spring compression per file ({} files) and fit "
                    "coulomb_force_N per file (--per-file coulomb_force_N)",
                    flags.files.size()));
  }
}

// The records fitted, the fit and its report (fitting/hysteresis_fit_report.h).
struct HysteresisFitRun {
  std::vector<fitting::HysteresisRecord> records;
  fitting::HysteresisFitResult fit;
  fitting::HysteresisFitReport report;
  std::vector<fitting::RecordPrediction> validation;  // the --validate records, predicted
};

// The fitted strut run over the --validate records (tests it was not fitted to), scored from
// --validate-from on.
std::vector<fitting::RecordPrediction> validate(const FitHysteresisFlags& flags,
                                                const HysteresisFitRun& run,
                                                const simulate::StrutTestSolverOptions& solver) {
  std::vector<fitting::HysteresisRecord> held_out;
  for (const auto& file : flags.validate_files) {
    for (auto& test : fitting::load_hysteresis_tests(file)) held_out.push_back(std::move(test));
  }
  if (held_out.empty()) return {};
  return fitting::predict_records(held_out, run.fit.fitted.front(), solver, flags.validate_from_s);
}

nlohmann::json validation_json(const std::vector<fitting::RecordPrediction>& validation) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& p : validation) {
    j.push_back({{"file", p.source},
                 {"nrmse_percent", p.nrmse_percent},
                 {"residual_rms_N", p.residual_rms_N},
                 {"scored_from_s", p.score_from_s},
                 {"samples", p.scored},
                 {"excitation_band_Hz", p.excitation_band_Hz},
                 {"in_band_nrmse_percent", p.in_band_nrmse_percent}});
  }
  return j;
}

// Loads the model file and the records and fits them: RunError when the fit did not converge.
HysteresisFitRun fit_records(const FitHysteresisFlags& flags) {
  const io::QuarterCarFile model_file = io::load_quarter_car(flags.model_file);
  HysteresisFitRun run;
  run.records = fitting::load_rig_files(
      std::vector<std::filesystem::path>(flags.files.begin(), flags.files.end()),
      flags.per_file.empty() ? "" : fmt::format("--per-file {}", fmt::join(flags.per_file, ",")));
  fitting::HysteresisFitOptions options;
  options.free = flags.free;
  options.per_file = flags.per_file;
  options.bounds = parse_bounds(flags.bounds);
  options.loss = fitting::parse_robust_loss(flags.loss);
  options.loss_scale_N = flags.loss_scale_N;
  options.record_weighting = fitting::parse_record_weighting(flags.record_weights);
  options.solver.relative_tolerance = flags.relative_tolerance;
  options.solver.interpolation = flags.interpolation == "linear"
                                     ? simulate::RigInterpolation::kLinear
                                     : simulate::RigInterpolation::kSpline;
  options.max_iterations = flags.max_iterations;
  options.max_nrmse_percent = flags.max_nrmse_percent;
  check_flag_combinations(flags, options);
  if (!flags.validate_files.empty() && !flags.per_file.empty()) {
    throw InputError(fmt::format(
        "--validate with --per-file {}: a held-out record has no value of its own of a per-file "
        "parameter; leave one of them out",
        fmt::join(flags.per_file, ",")));
  }
  // From the model file's values (with --start) and from levels read off the records.
  std::string chosen;
  run.fit = fitting::fit_hysteresis_from_file_and_records(
      run.records, start_from(model_file, flags.starts), options, &chosen);
  fitting::require_convergence(run.fit.converged, run.fit.explains_data, "the fit",
                               run.fit.iterations, run.fit.termination,
                               "better start values (--start) or fewer free parameters");
  std::vector<double> compression_m;
  for (double mm : flags.compression_mm) compression_m.push_back(1e-3 * mm);
  run.report = fitting::report_hysteresis_fit(run.records, run.fit, chosen, compression_m);
  run.validation = validate(flags, run, options.solver);
  return run;
}

// The fitted models: one, or with per-file parameters and several files one per file (each
// file has its own values of them), named model.yaml or model_<file's stem>.yaml; none when the
// fit does not explain the data and --keep is not given.
CommandOutcome outcome_of(const FitHysteresisFlags& flags, const HysteresisFitRun& run) {
  CommandOutcome outcome;
  outcome.summary = fitting::summary_json(run.fit, run.report);
  if (!run.validation.empty()) outcome.summary["validation"] = validation_json(run.validation);
  if (!run.fit.explains_data) outcome.failure = run.fit.adequacy_note;
  if (!run.fit.explains_data && !flags.keep) return outcome;
  const bool per_file = flags.files.size() > 1 && !flags.per_file.empty();
  for (std::size_t r = 0; r < (per_file ? flags.files.size() : 1); ++r) {
    outcome.files.push_back(
        {per_file ? io::output_for_input("model.yaml", flags.files[r]).string() : "model.yaml",
         io::model_with_values_text(
             flags.model_file,
             fitting::model_file_values(
                 run.fit.fitted[r],
                 fitting::written_parameters(flags.free, parse_overrides(flags.starts))),
             "Fitted by ridefit fit hysteresis from " + flags.model_file)});
  }
  return outcome;
}

void run(const FitHysteresisFlags& flags) {
  if (const auto repeated = io::first_repeated_file({flags.files.begin(), flags.files.end()})) {
    throw InputError(fmt::format(
        "{} is given twice; a repeated record would count twice in the fit", repeated->string()));
  }
  std::vector<std::filesystem::path> inputs(flags.files.begin(), flags.files.end());
  inputs.insert(inputs.end(), flags.validate_files.begin(), flags.validate_files.end());
  inputs.push_back(flags.model_file);
  // With per-file parameters and several files, one model per file: -o's stem + the file's.
  std::vector<std::string> model_outputs;
  if (!flags.output_file.empty()) {
    if (flags.files.size() == 1 || flags.per_file.empty()) {
      model_outputs.push_back(flags.output_file);
    } else {
      for (const auto& file : flags.files) {
        model_outputs.push_back(io::output_for_input(flags.output_file, file).string());
      }
    }
  }
  io::RunOutputs outputs(inputs);
  for (const auto& path : model_outputs) {
    outputs.add_file(path, path == flags.output_file ? "-o" : "-o (a per-file model)");
  }
  outputs.add_plot(flags.plot_file, "--plot");
  const HysteresisFitRun fitted = fit_records(flags);
  const CommandOutcome outcome = outcome_of(flags, fitted);
  std::vector<std::string> written;
  for (std::size_t r = 0; r < model_outputs.size() && r < outcome.files.size(); ++r) {
    io::write_atomically(model_outputs[r],
                         [&](std::ostream& out) { out << outcome.files[r].text; });
    written.push_back(model_outputs[r]);
  }
  if (!flags.plot_file.empty()) {
    io::draw_figure(fitting::rig_fit_figure(fitted.records, fitted.fit.fitted_force_N),
                    flags.plot_file);
  }
  if (flags.json) {
    nlohmann::json j = outcome.summary;
    j["written"] = written;
    std::cout << j.dump(2) << "\n";
  } else {
    fitting::write_summary(std::cout, fitted.fit, fitted.report);
    for (const auto& p : fitted.validation) {
      std::cout << fmt::format("  validation: NRMSE {:6.2f} % (residual RMS {:.4g} N{}{})  {}\n",
                               p.nrmse_percent, p.residual_rms_N,
                               p.score_from_s > 0.0
                                   ? fmt::format(", scored from {:g} s", p.score_from_s)
                                   : std::string(),
                               p.excitation_band_Hz > 0.0
                                   ? fmt::format("; {:.2f} % within the motion's band, 0–{:.3g} Hz",
                                                 p.in_band_nrmse_percent, p.excitation_band_Hz)
                                   : std::string(),
                               p.source);
    }
    for (const auto& path : written) std::cout << "Fitted model: " << path << "\n";
    if (!flags.plot_file.empty()) std::cout << "Figure: " << flags.plot_file << "\n";
  }
  require_explained(fitted.fit.explains_data, fitted.fit.adequacy_note,
                    !flags.json && !flags.output_file.empty() && !flags.keep);
}

// The fit's inputs and settings (not its outputs): the command's and a batch job's.
void add_fit_options(CLI::App& command, FitHysteresisFlags& flags) {
  command.add_option("files", flags.files, "Rig tests (CSV or .mat); fitted together")
      ->required()
      ->check(CLI::ExistingFile);
  command.add_option("--model", flags.model_file, "Quarter-car model file: start values")
      ->required()
      ->check(CLI::ExistingFile);
  command
      .add_option("--free", flags.free,
                  "Parameters to fit, e.g. dahl_sigma0_N_per_m,coulomb_force_N")
      ->required()
      ->delimiter(',');
  command
      .add_option("--per-file", flags.per_file,
                  "Free parameters each file gets its own value of (e.g. coulomb_force_N)")
      ->delimiter(',');
  command.add_option("--bounds", flags.bounds, "NAME=LOWER:UPPER (repeatable)");
  command.add_option("--start", flags.starts,
                     "NAME=VALUE start for a parameter not in the model file (gas_force_N, "
                     "gas_stiffness_N_per_m, force_offset_N; stribeck_velocity_m_per_s and "
                     "static_friction_force_N when the file has no Stribeck curve) or to "
                     "override one");
  command.add_option("--loss", flags.loss, "Robust loss: none, huber, cauchy")
      ->check(CLI::IsMember({"none", "huber", "cauchy"}))
      ->capture_default_str();
  command.add_option("--loss-scale", flags.loss_scale_N, "Residual [N] where the loss bends")
      ->check(positive_number("N"))
      ->capture_default_str();
  command
      .add_option("--record-weights", flags.record_weights,
                  "How records weigh against each other: newtons (every residual in N: strong "
                  "tests dominate) or relative (each record over its own force's spread: every "
                  "test counts by its relative misfit, e.g. five coil currents pooled)")
      ->check(CLI::IsMember({"newtons", "relative"}))
      ->capture_default_str();
  add_tolerance_option(command, "--rtol", flags.relative_tolerance,
                       "Relative tolerance of the strut's adaptive ESDIRK integration");
  command
      .add_option("--interpolation", flags.interpolation,
                  "The displacement between samples: spline (C2, for smooth motions) or linear "
                  "(for piecewise-linear commands such as triangle waves)")
      ->check(CLI::IsMember({"spline", "linear"}))
      ->capture_default_str();
  command.add_option("--max-iterations", flags.max_iterations, "Solver iterations at most")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  command
      .add_option("--compression", flags.compression_mm,
                  "Spring compression [mm] per file: fits Fc against it (seed 000 Figure 4; "
                  "needs --per-file coulomb_force_N)")
      ->delimiter(',');
  command
      .add_option("--validate", flags.validate_files,
                  "Held-out rig tests (CSV or .mat) the fitted strut predicts, each scored by its "
                  "NRMSE (not fitted)")
      ->check(CLI::ExistingFile);
  command
      .add_option("--validate-from", flags.validate_from_s,
                  "Score the held-out tests from this time [s] on (the model runs from their "
                  "start), e.g. the second half of a record whose first half was fitted")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  add_verdict_options(command, "NRMSE", flags.max_nrmse_percent, flags.keep);
}

}  // namespace

CommandJob fit_hysteresis_job(std::vector<std::string> arguments) {
  return command_job<FitHysteresisFlags>(
      std::move(arguments), add_fit_options,
      [](const FitHysteresisFlags& flags) { return outcome_of(flags, fit_records(flags)); });
}

void register_fit_hysteresis(CLI::App& fit) {
  auto flags = std::make_shared<FitHysteresisFlags>();
  CLI::App* command = fit.add_subcommand(
      "hysteresis",
      "Fit Dahl friction, top mount and damping to strut rig tests (CSV: time, displacement, "
      "force)");
  add_fit_options(*command, *flags);
  command->add_option("-o,--output", flags->output_file, "Fitted model (YAML, the input's schema)");
  command->add_option("--plot", flags->plot_file,
                      "Measured and fitted force (.png or .svg): loops for periodic tests; force "
                      "over velocity, a time excerpt and the residual's spectrum for random ones");
  command->add_flag("--json", flags->json,
                    "Values, standard errors, correlation, cost, iterations");
  command->callback([flags] { run(*flags); });
}

}  // namespace ridefit::cli
