// ridefit fit hysteresis DATA.csv... --model M.yaml --free a,b,... [--per-file c]
//                       [--bounds name=lo:hi]... [--start name=value]... [--loss huber|cauchy]
//                       [-o fitted.yaml] [--plot FILE.png|svg] [--json]
#include <fmt/core.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "command_options.h"
#include "ridefit/common/errors.h"
#include "ridefit/fitting/fit_adequacy.h"
#include "ridefit/fitting/friction_compression.h"
#include "ridefit/fitting/hysteresis_fit.h"
#include "ridefit/fitting/psd_fit.h"
#include "ridefit/fitting/rig_figure.h"
#include "ridefit/fitting/strut_parameters.h"
#include "ridefit/fitting/strut_start.h"
#include "ridefit/io/atomic_file.h"
#include "ridefit/io/gnuplot_figure.h"
#include "ridefit/io/output_paths.h"
#include "ridefit/io/quarter_car_file.h"
#include "ridefit/signal/hysteresis_friction.h"
#include "subcommands.h"

namespace ridefit::cli {
namespace {

// A correlation matrix as rows of numbers (empty when it could not be computed).
nlohmann::json correlation_json(const Eigen::MatrixXd& correlation) {
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index a = 0; a < correlation.rows(); ++a) {
    std::vector<double> row;
    for (Eigen::Index b = 0; b < correlation.cols(); ++b) row.push_back(correlation(a, b));
    rows.push_back(row);
  }
  return rows;
}

struct FitHysteresisFlags {
  std::vector<std::string> files;
  std::string model_file;
  std::vector<std::string> free;
  std::vector<std::string> per_file;
  std::vector<std::string> bounds;
  std::vector<std::string> starts;
  std::string loss = "none";
  double loss_scale_N = 5.0;
  double relative_tolerance = 1e-6;
  std::string interpolation = "spline";
  int max_iterations = 100;
  std::vector<double> compression_mm;
  std::string output_file;
  std::string plot_file;
  double max_nrmse_percent = 10.0;
  bool keep = false;
  bool json = false;
};

model::StrutTestParameters<double> start_from(const io::QuarterCarFile& file,
                                              const std::vector<std::string>& starts) {
  model::StrutTestParameters<double> p = fitting::strut_on_rig(file.parameters);
  for (const auto& [name, value] : parse_overrides(starts)) {
    try {
      fitting::strut_parameter(p, fitting::strut_parameter_index(name)) = value;
    } catch (const InputError& e) {
      throw InputError(fmt::format("--start {}: {}", name, e.what()));
    }
  }
  return p;
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

// The model file with the fitted model keys replaced; rig-only parameters (gas, offset) are not
// model keys and stay in the JSON.
void write_model(const std::string& model_file, model::StrutTestParameters<double> fitted,
                 const std::vector<std::string>& free, const std::string& path) {
  YAML::Node root = YAML::LoadFile(model_file);
  for (const auto& name : free) {
    const auto index = fitting::strut_parameter_index(name);
    if (!fitting::kStrutParameters[index].in_model_file) continue;
    root[name] = fitting::strut_parameter(fitted, index);
  }
  io::write_atomically(path, [&](std::ostream& out) {
    out << "# Fitted by ridefit fit hysteresis from " << model_file << "\n" << root << "\n";
  });
}

void run(const FitHysteresisFlags& flags) {
  for (std::size_t i = 0; i < flags.files.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (io::same_file(flags.files[i], flags.files[j])) {
        throw InputError(fmt::format(
            "{} is given twice; a repeated record would count twice in the fit", flags.files[i]));
      }
    }
  }
  std::vector<std::filesystem::path> inputs(flags.files.begin(), flags.files.end());
  inputs.push_back(flags.model_file);
  // With per-file parameters and several files, one model per file: -o's stem + the file's.
  std::vector<std::string> model_outputs;
  if (!flags.output_file.empty()) {
    if (flags.files.size() == 1 || flags.per_file.empty()) {
      model_outputs.push_back(flags.output_file);
    } else {
      const std::filesystem::path out(flags.output_file);
      for (const auto& file : flags.files) {
        model_outputs.push_back((out.parent_path() / (out.stem().string() + "_" +
                                                      std::filesystem::path(file).stem().string() +
                                                      out.extension().string()))
                                    .string());
      }
    }
  }
  io::RunOutputs outputs(inputs);
  for (const auto& path : model_outputs) {
    outputs.add_file(path, path == flags.output_file ? "-o" : "-o (a per-file model)");
  }
  outputs.add_plot(flags.plot_file, "--plot");
  const io::QuarterCarFile model_file = io::load_quarter_car(flags.model_file);
  std::vector<fitting::HysteresisRecord> records;
  for (const auto& file : flags.files) records.push_back(fitting::load_hysteresis_record(file));
  fitting::HysteresisFitOptions options;
  options.free = flags.free;
  options.per_file = flags.per_file;
  options.bounds = parse_bounds(flags.bounds);
  // A bound only acts on a fitted parameter: one on a fixed parameter would be ignored.
  for (const auto& [name, bound] : options.bounds) {
    const bool fitted =
        std::find(flags.free.begin(), flags.free.end(), name) != flags.free.end() ||
        std::find(flags.per_file.begin(), flags.per_file.end(), name) != flags.per_file.end();
    if (!fitted) {
      std::string free;
      for (const auto& f : flags.free) free += (free.empty() ? "" : ",") + f;
      throw InputError(fmt::format(
          "--bounds {}={}:{}: {} is not fitted (--free {}), so the bound would be ignored; add it "
          "to --free or leave the bound out",
          name, bound.first, bound.second, name, free));
    }
  }
  options.loss = fitting::parse_robust_loss(flags.loss);
  options.loss_scale_N = flags.loss_scale_N;
  options.solver.relative_tolerance = flags.relative_tolerance;
  options.solver.interpolation = flags.interpolation == "linear"
                                     ? simulate::RigInterpolation::kLinear
                                     : simulate::RigInterpolation::kSpline;
  options.max_iterations = flags.max_iterations;
  options.max_nrmse_percent = flags.max_nrmse_percent;
  // Two starts, the better fit kept: the model file's values (with --start), and the same with
  // the levels read off the records (friction, damping, offset, gas rate and their command
  // slopes: fitting/strut_start.h) for the free parameters.
  const auto start = start_from(model_file, flags.starts);
  const auto estimate = fitting::estimate_strut_start(records);
  std::string chosen;
  const fitting::HysteresisFitResult fit = fitting::fit_hysteresis_from_starts(
      records, {start, fitting::with_estimates(start, estimate, flags.free)}, options,
      {"the model file", "levels read off the records"}, &chosen);
  const bool write_anyway = fit.explains_data || flags.keep;
  if (!fit.converged && fit.explains_data) {
    throw RunError(fmt::format(
        "the fit did not converge after {} iterations ({}); no fitted model was written. Try "
        "better start values (--start) or fewer free parameters",
        fit.iterations, fit.termination));
  }
  // Seed 000's calibration value beside the fitted Fc: half the loop height at x = 0.
  std::vector<std::optional<signal::HysteresisFriction>> calibration;
  for (const auto& r : records) {
    try {
      calibration.push_back(signal::hysteresis_friction(r.displacement_m, r.force_N));
    } catch (const InputError&) {
      calibration.push_back(std::nullopt);  // fewer than 2 cycles through zero: no value
    }
  }
  std::optional<fitting::FrictionCompressionLine> line;
  if (!flags.compression_mm.empty()) {
    if (flags.compression_mm.size() != records.size() ||
        std::find(flags.per_file.begin(), flags.per_file.end(), "coulomb_force_N") ==
            flags.per_file.end()) {
      throw InputError(
          fmt::format("--compression: give one spring compression per file ({} files) and fit "
                      "coulomb_force_N per file (--per-file coulomb_force_N)",
                      records.size()));
    }
    std::vector<double> x, fc, se;
    for (const auto& p : fit.parameters) {
      if (p.name != "coulomb_force_N" || p.file.empty()) continue;
      fc.push_back(p.value);
      if (p.standard_error) se.push_back(*p.standard_error);
    }
    for (double mm : flags.compression_mm) x.push_back(1e-3 * mm);
    line = fitting::fit_friction_compression(x, fc,
                                             se.size() == fc.size() ? se : std::vector<double>());
  }
  std::vector<std::string> written;
  if (!flags.output_file.empty() && write_anyway) {
    // Each file has its own values of the per-file parameters: one model per file.
    for (std::size_t r = 0; r < model_outputs.size(); ++r) {
      write_model(flags.model_file, fit.fitted[r], flags.free, model_outputs[r]);
      written.push_back(model_outputs[r]);
    }
  }
  if (!flags.plot_file.empty()) {
    io::Figure figure;
    figure.title = "measured and fitted rig force";
    for (std::size_t r = 0; r < records.size(); ++r) {
      for (auto& panel : fitting::rig_record_panels(records[r], fit.fitted_force_N[r], "fitted")) {
        figure.panels.push_back(std::move(panel));
      }
    }
    io::draw_figure(figure, flags.plot_file);
  }
  if (flags.json) {
    nlohmann::json j = {{"converged", fit.converged},
                        {"termination", fit.termination},
                        {"iterations", fit.iterations},
                        {"initial_cost", fit.initial_cost},
                        {"final_cost", fit.final_cost},
                        {"residual_rms_N", fit.residual_rms_N},
                        {"nrmse_percent", fit.nrmse_percent},
                        {"explains_data", fit.explains_data},
                        {"adequacy_note", fit.adequacy_note},
                        {"on_bounds", fit.on_bounds},
                        {"start", chosen},
                        {"unidentifiable", fit.unidentifiable},
                        {"identifiability_note", fit.identifiability_note},
                        {"parameters", nlohmann::json::array()},
                        {"written", written}};
    for (const auto& p : fit.parameters) {
      j["parameters"].push_back(
          {{"name", p.name},
           {"file", p.file},
           {"value", p.value},
           {"standard_error",
            p.standard_error ? nlohmann::json(*p.standard_error) : nlohmann::json()}});
    }
    j["correlation"] = correlation_json(fit.correlation);
    j["calibration_friction_N"] = nlohmann::json::array();
    for (std::size_t r = 0; r < records.size(); ++r) {
      j["calibration_friction_N"].push_back(
          calibration[r]
              ? nlohmann::json{{"file", records[r].source},
                               {"mean", calibration[r]->mean_N},
                               {"standard_deviation", calibration[r]->standard_deviation_N},
                               {"cycles", calibration[r]->cycles_used}}
              : nlohmann::json{{"file", records[r].source}, {"mean", nullptr}});
    }
    if (line) {
      j["friction_against_compression"] = {
          {"intercept_N", line->intercept_N},
          {"slope_N_per_m", line->slope_N_per_m},
          {"intercept_se_N",
           line->intercept_se_N ? nlohmann::json(*line->intercept_se_N) : nlohmann::json()},
          {"slope_se_N_per_m",
           line->slope_se_N_per_m ? nlohmann::json(*line->slope_se_N_per_m) : nlohmann::json()}};
    }
    std::cout << j.dump(2) << "\n";
    if (!fit.explains_data) throw RunError(fit.adequacy_note);
    return;
  }
  std::cout << fmt::format(
      "fit of {} file(s) from {}: {} iterations, residual RMS {:.4g} N, NRMSE {:.2f} % ({})\n",
      records.size(), chosen, fit.iterations, fit.residual_rms_N, fit.nrmse_percent,
      fit.explains_data ? fit.termination : "the model does not explain the data");
  for (const auto& p : fit.parameters) {
    std::cout << fmt::format("  {:<30} {:>14.6g}  ± {:<12}{}\n", p.name, p.value,
                             p.standard_error ? fmt::format("{:.3g}", *p.standard_error) : "-",
                             p.file.empty() ? "" : "  " + p.file);
  }
  for (std::size_t r = 0; r < records.size(); ++r) {
    if (!calibration[r]) continue;
    std::cout << fmt::format(
        "  seed calibration (half the loop height at x = 0, cycles 2-{}): {:.4g}{} N  {}\n",
        calibration[r]->cycles_used + 1, calibration[r]->mean_N,
        calibration[r]->cycles_used > 1
            ? fmt::format(" ± {:.2g}", calibration[r]->standard_deviation_N)
            : std::string(" (one cycle)"),
        records[r].source);
  }
  if (line) {
    std::cout << fmt::format(
        "  Fc = {:.4g} N + {:.4g} N/mm · compression (slope ± {} N/mm)\n", line->intercept_N,
        1e-3 * line->slope_N_per_m,
        line->slope_se_N_per_m ? fmt::format("{:.2g}", 1e-3 * *line->slope_se_N_per_m) : "-");
  }
  if (!fit.identifiability_note.empty()) {
    std::cout << "warning: " << fit.identifiability_note << "\n";
  }
  for (const auto& bound : fit.on_bounds) std::cout << "  on a bound: " << bound << "\n";
  for (const auto& path : written) std::cout << "Fitted model: " << path << "\n";
  if (!flags.plot_file.empty()) std::cout << "Figure: " << flags.plot_file << "\n";
  if (!fit.explains_data) {
    throw RunError(fit.adequacy_note + (flags.output_file.empty() || flags.keep
                                            ? ""
                                            : "; no fitted model was written (--keep writes it)"));
  }
}

struct FitPsdFlags {
  std::string file;
  std::string excitation_file;
  std::string model_file;
  std::vector<std::string> free;
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

void run_psd(const FitPsdFlags& flags) {
  std::vector<std::filesystem::path> inputs = {flags.file, flags.model_file};
  if (!flags.excitation_file.empty()) inputs.push_back(flags.excitation_file);
  io::RunOutputs outputs(inputs);
  outputs.add_file(flags.output_file, "-o");
  outputs.add_plot(flags.plot_file, "--plot");
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
  const fitting::PsdFitResult fit = fitting::fit_psd(measurement, model_file.make_model(), options);
  const fitting::FitAdequacy adequacy =
      fitting::assess_psd_fit(fit, model_file.parameters, options, flags.max_nrmse_percent);
  if (!fit.converged && adequacy.explains_data) {
    throw RunError(fmt::format(
        "the PSD fit did not converge after {} iterations ({}); no fitted model was written. Try "
        "--starts 5 or fewer free parameters",
        fit.iterations, fit.termination));
  }
  if (!flags.output_file.empty() && (adequacy.explains_data || flags.keep)) {
    YAML::Node root = YAML::LoadFile(flags.model_file);
    for (std::size_t i = 0; i < fit.names.size(); ++i) root[fit.names[i]] = fit.values[i];
    io::write_atomically(flags.output_file, [&](std::ostream& out) {
      out << "# Fitted by ridefit fit psd from " << flags.model_file << " and " << flags.file
          << "\n"
          << root << "\n";
    });
  }
  if (!flags.plot_file.empty()) {
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
    io::draw_figure(figure, flags.plot_file);
  }
  if (flags.json) {
    nlohmann::json j = {
        {"converged", fit.converged},
        {"termination", fit.termination},
        {"iterations", fit.iterations},
        {"final_cost", fit.final_cost},
        {"unidentifiable", fit.unidentifiable},
        {"identifiability_note", fit.identifiability_note},
        {"nrmse_percent", adequacy.nrmse_percent},
        {"explains_data", adequacy.explains_data},
        {"adequacy_note", adequacy.note},
        {"on_bounds", adequacy.on_bounds},
        {"noise_psd",
         {{"body_acc", fit.noise_floors.body_psd}, {"wheel_acc", fit.noise_floors.wheel_psd}}},
        {"parameters", nlohmann::json::array()}};
    j["correlation"] = correlation_json(fit.correlation);
    for (std::size_t i = 0; i < fit.names.size(); ++i) {
      j["parameters"].push_back(
          {{"name", fit.names[i]},
           {"value", fit.values[i]},
           {"standard_error",
            fit.standard_errors[i] ? nlohmann::json(*fit.standard_errors[i]) : nlohmann::json()}});
    }
    std::cout << j.dump(2) << "\n";
    if (!adequacy.explains_data) throw RunError(adequacy.note);
    return;
  }
  std::cout << fmt::format(
      "PSD fit of {}: {} iterations, cost {:.4g}, amplitude-spectrum NRMSE {:.2f} % ({})\n",
      flags.file, fit.iterations, fit.final_cost, adequacy.nrmse_percent,
      adequacy.explains_data ? fit.termination : "the model does not explain the data");
  for (std::size_t i = 0; i < fit.names.size(); ++i) {
    std::cout << fmt::format(
        "  {:<30} {:>14.6g}  ± {}\n", fit.names[i], fit.values[i],
        fit.standard_errors[i] ? fmt::format("{:.3g}", *fit.standard_errors[i]) : "-");
  }
  if (!fit.identifiability_note.empty()) {
    std::cout << "warning: " << fit.identifiability_note << "\n";
  }
  for (const auto& bound : adequacy.on_bounds) std::cout << "  on a bound: " << bound << "\n";
  const bool written = !flags.output_file.empty() && (adequacy.explains_data || flags.keep);
  if (written) std::cout << "Fitted model: " << flags.output_file << "\n";
  if (!flags.plot_file.empty()) std::cout << "Figure: " << flags.plot_file << "\n";
  if (!adequacy.explains_data) {
    throw RunError(adequacy.note + (flags.output_file.empty() || flags.keep
                                        ? ""
                                        : "; no fitted model was written (--keep writes it)"));
  }
}

}  // namespace

void register_fit(CLI::App& app) {
  CLI::App* fit = app.add_subcommand("fit", "Identify model parameters from lab data (Ceres)");
  fit->require_subcommand(1);
  auto flags = std::make_shared<FitHysteresisFlags>();
  CLI::App* command = fit->add_subcommand(
      "hysteresis",
      "Fit Dahl friction, top mount and damping to strut rig tests (CSV: time, displacement, "
      "force)");
  command->add_option("files", flags->files, "Rig tests (CSV); fitted together")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--model", flags->model_file, "Quarter-car model file: start values")
      ->required()
      ->check(CLI::ExistingFile);
  command
      ->add_option("--free", flags->free,
                   "Parameters to fit, e.g. dahl_sigma0_N_per_m,coulomb_force_N")
      ->required()
      ->delimiter(',');
  command
      ->add_option("--per-file", flags->per_file,
                   "Free parameters each file gets its own value of (e.g. coulomb_force_N)")
      ->delimiter(',');
  command->add_option("--bounds", flags->bounds, "NAME=LOWER:UPPER (repeatable)");
  command->add_option("--start", flags->starts,
                      "NAME=VALUE start for a parameter not in the model file (gas_force_N, "
                      "gas_stiffness_N_per_m, force_offset_N; stribeck_velocity_m_per_s and "
                      "static_friction_force_N when the file has no Stribeck curve) or to "
                      "override one");
  command->add_option("--loss", flags->loss, "Robust loss: none, huber, cauchy")
      ->check(CLI::IsMember({"none", "huber", "cauchy"}))
      ->capture_default_str();
  command->add_option("--loss-scale", flags->loss_scale_N, "Residual [N] where the loss bends")
      ->check(positive_number("N"))
      ->capture_default_str();
  add_tolerance_option(*command, "--rtol", flags->relative_tolerance,
                       "Relative tolerance of the strut's adaptive ESDIRK integration");
  command
      ->add_option("--interpolation", flags->interpolation,
                   "The displacement between samples: spline (C2, for smooth motions) or linear "
                   "(for piecewise-linear commands such as triangle waves)")
      ->check(CLI::IsMember({"spline", "linear"}))
      ->capture_default_str();
  command->add_option("--max-iterations", flags->max_iterations, "Solver iterations at most")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  command
      ->add_option("--compression", flags->compression_mm,
                   "Spring compression [mm] per file: fits Fc against it (seed 000 Figure 4; "
                   "needs --per-file coulomb_force_N)")
      ->delimiter(',');
  command->add_option("-o,--output", flags->output_file, "Fitted model (YAML, the input's schema)");
  command->add_option("--plot", flags->plot_file,
                      "Measured and fitted force (.png or .svg): loops for periodic tests; force "
                      "over velocity, a time excerpt and the residual's spectrum for random ones");
  command
      ->add_option("--max-nrmse", flags->max_nrmse_percent,
                   "NRMSE [%] above which the model is reported as not explaining the data")
      ->check(CLI::Range(0.0, 1000.0).description("in (0, 1000]"));
  command->add_flag("--keep", flags->keep,
                    "Write the fitted model even when it does not explain the data (exit 1 all the "
                    "same)");
  command->add_flag("--json", flags->json,
                    "Values, standard errors, correlation, cost, iterations");
  command->callback([flags] { run(*flags); });

  auto psd = std::make_shared<FitPsdFlags>();
  CLI::App* psd_command = fit->add_subcommand(
      "psd",
      "Fit quarter-car parameters (e.g. the top-mount stiffness) to measured body and wheel "
      "acceleration spectra (CSV: time, road, body_acc and/or wheel_acc)");
  psd_command->add_option("file", psd->file, "Measurement (CSV)")
      ->required()
      ->check(CLI::ExistingFile);
  psd_command->add_option("--model", psd->model_file, "Quarter-car model file: start values")
      ->required()
      ->check(CLI::ExistingFile);
  psd_command
      ->add_option("--excitation", psd->excitation_file,
                   "The road as a known excitation file instead of a road column")
      ->check(CLI::ExistingFile);
  psd_command->add_option("--free", psd->free, "Parameters to fit (1 to 4 model keys)")
      ->required()
      ->delimiter(',');
  psd_command->add_option("--band", psd->band_Hz, "Fitted band LOW,HIGH [Hz]")
      ->delimiter(',')
      ->capture_default_str();
  psd_command->add_option("--segment", psd->segment_s, "Welch segment length [s]")
      ->check(positive_number("s"))
      ->capture_default_str();
  psd_command->add_option("--starts", psd->starts, "Multi-start: number of starting points")
      ->check(CLI::Range(1, 50))
      ->capture_default_str();
  psd_command
      ->add_option("--loss", psd->loss, "Robust loss on the log-PSD residuals: none, huber, cauchy")
      ->check(CLI::IsMember({"none", "huber", "cauchy"}))
      ->capture_default_str();
  psd_command->add_option("--max-iterations", psd->max_iterations, "Solver iterations at most")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  add_tolerance_option(*psd_command, "--rtol", psd->relative_tolerance,
                       "Relative tolerance of the quarter car's adaptive ESDIRK integration");
  add_noise_psd_option(*psd_command, "body", psd->body_noise_psd);
  add_noise_psd_option(*psd_command, "wheel", psd->wheel_noise_psd);
  psd_command->add_option("-o,--output", psd->output_file,
                          "Fitted model (YAML, the input's schema)");
  psd_command->add_option("--plot", psd->plot_file, "Measured and fitted PSDs (.png or .svg)");
  psd_command
      ->add_option("--max-nrmse", psd->max_nrmse_percent,
                   "Amplitude-spectrum NRMSE [%] above which the model is reported as not "
                   "explaining the data")
      ->check(CLI::Range(0.0, 1000.0).description("in (0, 1000]"));
  psd_command->add_flag("--keep", psd->keep,
                        "Write the fitted model even when it does not explain the data (exit 1 "
                        "all the same)");
  psd_command->add_flag("--json", psd->json, "Values, standard errors, cost, iterations");
  psd_command->callback([psd] { run_psd(*psd); });
}

}  // namespace ridefit::cli
