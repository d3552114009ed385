// ridefit fit psd MEAS.csv --model M.yaml --free a,b [--excitation EXC.yaml] [--band LO,HI]
//                 [--segment S] [--starts N] [-o fitted.yaml] [--plot FILE.png|svg] [--json]
// Fits quarter-car parameters to measured acceleration spectra (fitting/psd_fit.h), writes the
// fitted model file and reports the fit and its adequacy (fitting/psd_fit_report.h).
#include <fmt/core.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>

#include "command_options.h"
#include "command_outcome.h"
#include "fit_command.h"
#include "ridefit/common/errors.h"
#include "ridefit/fitting/fit_adequacy.h"
#include "ridefit/fitting/fit_convergence.h"
#include "ridefit/fitting/psd_fit.h"
#include "ridefit/fitting/psd_fit_report.h"
#include "ridefit/io/atomic_file.h"
#include "ridefit/io/gnuplot_figure.h"
#include "ridefit/io/model_values_file.h"
#include "ridefit/io/output_paths.h"
#include "ridefit/io/quarter_car_file.h"
#include "ridefit/model/quarter_car_parameter_table.h"

namespace ridefit::cli {
namespace {

struct FitPsdFlags {
  std::string file;
  std::string excitation_file;
  std::string model_file;
  std::vector<std::string> free;
  std::vector<std::string> priors;  // KEY=SHARE: a Gaussian prior at the model file's value
  std::vector<double> band_Hz = {0.5, 30.0};
  double segment_s = 10.0;
  int starts = 1;
  int max_iterations = 50;
  std::string loss = "none";
  double relative_tolerance = 1e-4;
  double body_noise_psd = std::nan("");  // not given: estimated
  double wheel_noise_psd = std::nan("");
  std::string output_file;
  std::string plot_file;
  double max_nrmse_percent = 10.0;
  bool keep = false;
  bool json = false;
};

// The measured and fitted PSD of each channel the record has.
io::Figure figure_of(const fitting::PsdFitResult& fit) {
  io::Figure figure;
  figure.title = "measured and fitted acceleration PSDs";
  auto panel_of = [&](const char* name, const std::vector<double>& measured,
                      const std::vector<double>& fitted) {
    if (measured.empty()) return;
    io::PlotPanel panel = io::psd_panel(name, "PSD [(m/s^2)^2/Hz]");
    panel.series.push_back(
        {"measured", fit.frequency_Hz, measured, {}, {}, io::SeriesStyle::kLines});
    panel.series.push_back({"fitted", fit.frequency_Hz, fitted, {}, {}, io::SeriesStyle::kLines});
    figure.panels.push_back(std::move(panel));
  };
  panel_of("body_acc", fit.measured_body_psd, fit.fitted_body_psd);
  panel_of("wheel_acc", fit.measured_wheel_psd, fit.fitted_wheel_psd);
  return figure;
}

struct PsdFitRun {
  fitting::PsdFitResult fit;
  fitting::FitAdequacy adequacy;
};

// Loads the model file and the measurement and fits the spectra: RunError when the fit did not
// converge.
PsdFitRun fit_measurement(const FitPsdFlags& flags) {
  if (flags.band_Hz.size() != 2 || !(flags.band_Hz[0] < flags.band_Hz[1])) {
    throw InputError("--band: expected LOW,HIGH in Hz with LOW < HIGH, e.g. 0.5,30");
  }
  const io::QuarterCarFile model_file = io::load_quarter_car(flags.model_file);
  const fitting::PsdMeasurement measurement =
      fitting::load_psd_measurement(flags.file, flags.excitation_file);
  fitting::PsdFitOptions options;
  options.free = flags.free;
  options.band_low_Hz = flags.band_Hz[0];
  options.band_high_Hz = flags.band_Hz[1];
  options.segment_s = flags.segment_s;
  options.starts = flags.starts;
  options.max_iterations = flags.max_iterations;
  options.loss = fitting::parse_robust_loss(flags.loss);
  options.relative_tolerance = flags.relative_tolerance;
  options.body_noise_psd = noise_psd_of(flags.body_noise_psd);
  options.wheel_noise_psd = noise_psd_of(flags.wheel_noise_psd);
  for (const auto& [name, share] : parse_value_shares(flags.priors, "--prior")) {
    const double mean = model::quarter_car_parameter(model_file.parameters,
                                                     *model::quarter_car_parameter_index(name));
    options.priors[name] = {mean, share * std::abs(mean)};
  }
  PsdFitRun run{fitting::fit_psd(measurement, model_file.make_model(), options), {}};
  run.adequacy =
      fitting::assess_psd_fit(run.fit, model_file.parameters, options, flags.max_nrmse_percent);
  fitting::require_convergence(run.fit.converged, run.adequacy.explains_data, "the PSD fit",
                               run.fit.iterations, run.fit.termination,
                               "--starts 5 or fewer free parameters");
  return run;
}

// The summary and the fitted model (model.yaml; none when the fit does not explain the data and
// --keep is not given).
CommandOutcome outcome_of(const FitPsdFlags& flags, const PsdFitRun& run) {
  CommandOutcome outcome;
  outcome.summary = fitting::summary_json(run.fit, run.adequacy);
  if (!run.adequacy.explains_data) outcome.failure = run.adequacy.note;
  if (!run.adequacy.explains_data && !flags.keep) return outcome;
  std::vector<std::pair<std::string, double>> values;
  for (std::size_t i = 0; i < run.fit.names.size(); ++i) {
    values.emplace_back(run.fit.names[i], run.fit.values[i]);
  }
  outcome.files.push_back({"model.yaml", io::model_with_values_text(
                                             flags.model_file, values,
                                             fmt::format("Fitted by ridefit fit psd from {} and {}",
                                                         flags.model_file, flags.file))});
  return outcome;
}

void run(const FitPsdFlags& flags) {
  std::vector<std::filesystem::path> inputs = {flags.file, flags.model_file};
  if (!flags.excitation_file.empty()) inputs.push_back(flags.excitation_file);
  io::RunOutputs outputs(inputs);
  outputs.add_file(flags.output_file, "-o");
  outputs.add_plot(flags.plot_file, "--plot");
  const PsdFitRun fitted = fit_measurement(flags);
  const CommandOutcome outcome = outcome_of(flags, fitted);
  const bool written = !flags.output_file.empty() && !outcome.files.empty();
  if (written) {
    io::write_atomically(flags.output_file,
                         [&](std::ostream& out) { out << outcome.files.front().text; });
  }
  if (!flags.plot_file.empty()) io::draw_figure(figure_of(fitted.fit), flags.plot_file);
  if (flags.json) {
    std::cout << outcome.summary.dump(2) << "\n";
  } else {
    fitting::write_summary(std::cout, flags.file, fitted.fit, fitted.adequacy);
    if (written) std::cout << "Fitted model: " << flags.output_file << "\n";
    if (!flags.plot_file.empty()) std::cout << "Figure: " << flags.plot_file << "\n";
  }
  require_explained(fitted.adequacy.explains_data, fitted.adequacy.note,
                    !flags.json && !flags.output_file.empty() && !flags.keep);
}

// The fit's inputs and settings (not its outputs): the command's and a batch job's.
void add_fit_options(CLI::App& command, FitPsdFlags& psd) {
  command.add_option("file", psd.file, "Measurement (CSV or .mat)")
      ->required()
      ->check(CLI::ExistingFile);
  command.add_option("--model", psd.model_file, "Quarter-car model file: start values")
      ->required()
      ->check(CLI::ExistingFile);
  command
      .add_option("--excitation", psd.excitation_file,
                  "The road as a known excitation file instead of a road column")
      ->check(CLI::ExistingFile);
  command.add_option("--free", psd.free, "Parameters to fit (1 to 12 model keys)")
      ->required()
      ->delimiter(',');
  command
      .add_option("--prior", psd.priors,
                  "Data-sheet priors KEY=SHARE on free parameters: a Gaussian at the model file's "
                  "value with SHARE of it as standard deviation (0.08 = ±8 %), separated by "
                  "commas")
      ->delimiter(',');
  command.add_option("--band", psd.band_Hz, "Fitted band LOW,HIGH [Hz]")
      ->delimiter(',')
      ->capture_default_str();
  command.add_option("--segment", psd.segment_s, "Welch segment length [s]")
      ->check(positive_number("s"))
      ->capture_default_str();
  command.add_option("--starts", psd.starts, "Multi-start: number of starting points")
      ->check(CLI::Range(1, 50))
      ->capture_default_str();
  command
      .add_option("--loss", psd.loss, "Robust loss on the log-PSD residuals: none, huber, cauchy")
      ->check(CLI::IsMember({"none", "huber", "cauchy"}))
      ->capture_default_str();
  command.add_option("--max-iterations", psd.max_iterations, "Solver iterations at most")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  add_tolerance_option(command, "--rtol", psd.relative_tolerance,
                       "Relative tolerance of the quarter car's adaptive ESDIRK integration");
  add_noise_psd_option(command, "body", psd.body_noise_psd);
  add_noise_psd_option(command, "wheel", psd.wheel_noise_psd);
  add_verdict_options(command, "Amplitude-spectrum NRMSE", psd.max_nrmse_percent, psd.keep);
}

}  // namespace

CommandJob fit_psd_job(std::vector<std::string> arguments) {
  return command_job<FitPsdFlags>(
      std::move(arguments), add_fit_options,
      [](const FitPsdFlags& flags) { return outcome_of(flags, fit_measurement(flags)); });
}

void register_fit_psd(CLI::App& fit) {
  auto psd = std::make_shared<FitPsdFlags>();
  CLI::App* command = fit.add_subcommand(
      "psd",
      "Fit quarter-car parameters (e.g. the top-mount stiffness) to measured body and wheel "
      "acceleration spectra (CSV or .mat: time, road, body_acc and/or wheel_acc)");
  add_fit_options(*command, *psd);
  command->add_option("-o,--output", psd->output_file, "Fitted model (YAML, the input's schema)");
  command->add_option("--plot", psd->plot_file, "Measured and fitted PSDs (.png or .svg)");
  command->add_flag("--json", psd->json, "Values, standard errors, cost, iterations");
  command->callback([psd] { run(*psd); });
}

}  // namespace ridefit::cli
