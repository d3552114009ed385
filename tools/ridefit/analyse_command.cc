// ridefit analyse DATA.csv... [--channel NAME]... [--weighting auto|none|Wk|...] [--band LO,HI]
//                 [--levels L1,L2,...] [--psd out.csv] [--plot FILE.svg|png] [--json]
// The numbers and figures a ride engineer reports for measured or simulated recordings.
#include <fmt/core.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <optional>

#include "command_options.h"
#include "ridefit/common/errors.h"
#include "ridefit/io/csv_table.h"
#include "ridefit/io/gnuplot_figure.h"
#include "ridefit/io/measurement_file.h"
#include "ridefit/io/output_paths.h"
#include "ridefit/io/quarter_car_file.h"
#include "ridefit/model/quarter_car_parameter_table.h"
#include "ridefit/study/recording_analysis.h"
#include "ridefit/study/recording_analysis_json.h"
#include "ridefit/study/recording_figure.h"
#include "ridefit/study/recording_psd_table.h"
#include "ridefit/study/recording_report.h"
#include "subcommands.h"

namespace ridefit::cli {
namespace {

struct AnalyseFlags {
  std::vector<std::string> files;
  std::vector<std::string> channels;
  std::string weighting = "auto";
  std::vector<double> band_Hz = {0.5, 30.0};
  double segment_s = 0.0;
  double overlap = 0.5;
  std::string detrend = "mean";
  int smooth_bins = 1;
  double confidence = 0.9;
  double static_tyre_load_N = 0.0;
  std::string model_file;
  std::vector<double> rattle_space_m;
  bool impact = false;
  std::vector<double> levels;
  std::string level_name = "level";
  std::string psd_file;
  std::string plot_file;
  bool json = false;
};

study::RecordingAnalysisOptions options_from(const AnalyseFlags& flags) {
  study::RecordingAnalysisOptions options;
  options.channels = flags.channels;
  if (flags.weighting == "auto") {
    options.weighting.by_channel_name = true;
  } else {
    options.weighting.by_channel_name = false;
    if (flags.weighting != "none") {
      try {
        options.weighting.weighting = comfort::parse_weighting(flags.weighting);
      } catch (const InputError& e) {
        throw InputError(fmt::format("--weighting: {} (or auto, none)", e.what()));
      }
    }
  }
  if (flags.band_Hz.size() != 2) {
    throw InputError(fmt::format("--band: {} values; expected two, LOW,HIGH in Hz (e.g. 0.5,30)",
                                 flags.band_Hz.size()));
  }
  options.band_low_Hz = flags.band_Hz[0];
  options.band_high_Hz = flags.band_Hz[1];
  options.welch.segment_length_s = flags.segment_s;
  options.welch.overlap_fraction = flags.overlap;
  options.welch.detrend = signal::parse_detrend(flags.detrend);
  if (flags.smooth_bins < 1) {
    throw InputError(
        fmt::format("--smooth {}: expected an odd number of bins >= 1", flags.smooth_bins));
  }
  options.smoothing_bins = static_cast<std::size_t>(flags.smooth_bins);
  options.confidence = flags.confidence;
  if (flags.static_tyre_load_N != 0.0) options.static_tyre_load_N = flags.static_tyre_load_N;
  if (!flags.model_file.empty()) {
    if (options.static_tyre_load_N) {
      throw InputError("--model and --static-tyre-load both set the static load; give one");
    }
    options.static_tyre_load_N =
        comfort::static_tyre_load_N(io::load_quarter_car(flags.model_file).parameters);
  }
  if (!flags.rattle_space_m.empty()) {
    if (flags.rattle_space_m.size() != 2 || !(flags.rattle_space_m[0] > 0.0) ||
        !(flags.rattle_space_m[1] > 0.0) || !std::isfinite(flags.rattle_space_m[0]) ||
        !std::isfinite(flags.rattle_space_m[1])) {
      throw InputError(
          "--rattle-space: expected two distances > 0 in m, COMPRESSION,REBOUND (e.g. "
          "0.08,0.09)");
    }
    options.rattle_space = comfort::RattleSpace{flags.rattle_space_m[0], flags.rattle_space_m[1]};
  }
  options.impact_hardness = flags.impact;
  options.validate();
  return options;
}

io::CsvTable psd_table(const study::RecordingAnalysis& analysis,
                       const std::optional<study::ParameterLevels>& levels) {
  try {
    return study::recording_psd_table(analysis, levels);
  } catch (const InputError& e) {
    throw InputError(fmt::format("--psd: {}; leave it out with --channel", e.what()));
  }
}

void run(const AnalyseFlags& flags) {
  std::vector<std::filesystem::path> inputs(flags.files.begin(), flags.files.end());
  if (!flags.model_file.empty()) inputs.push_back(flags.model_file);
  io::RunOutputs outputs(inputs);
  outputs.add_file(flags.psd_file, "--psd");
  outputs.add_plot(flags.plot_file, "--plot");
  const study::RecordingAnalysisOptions options = options_from(flags);
  if (flags.level_name.empty() ||
      flags.level_name.find_first_not_of(
          "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") != std::string::npos) {
    throw InputError(fmt::format(
        "--level-name '{}': use letters, digits and underscores (it names CSV columns), e.g. {}",
        flags.level_name, model::quarter_car_rows::coulomb_force_N.key));
  }
  if (!flags.levels.empty() && flags.levels.size() != flags.files.size()) {
    throw InputError(
        fmt::format("--levels: {} values for {} files; give one level per file, in "
                    "the order of the files",
                    flags.levels.size(), flags.files.size()));
  }
  for (double level : flags.levels) {
    if (!std::isfinite(level)) {
      throw InputError(fmt::format("--levels: {} is not a finite number", level));
    }
  }
  std::vector<study::Recording> recordings;
  for (const auto& file : flags.files) recordings.push_back(study::load_recording(file));
  const study::RecordingAnalysis analysis = study::analyse_recordings(recordings, options);
  std::optional<study::ParameterLevels> levels;
  if (!flags.levels.empty()) {
    levels = study::ParameterLevels{flags.level_name, flags.levels,
                                    study::correlate_with_levels(analysis, flags.levels)};
  }

  // The figure first: it is the output that can still fail (gnuplot), and a failed run must
  // leave no file behind.
  if (!flags.plot_file.empty()) {
    io::draw_figure(study::recording_figure(analysis, options, levels), flags.plot_file);
  }
  if (!flags.psd_file.empty())
    io::write_measurement_table(psd_table(analysis, levels), flags.psd_file);
  if (flags.json) {
    nlohmann::json j = study::to_json(analysis, options, levels);
    if (!flags.psd_file.empty()) j["psd_file"] = flags.psd_file;
    if (!flags.plot_file.empty()) j["plot_file"] = flags.plot_file;
    std::cout << j.dump(2) << "\n";
    return;
  }
  study::write_recording_report(std::cout, analysis, levels);
  if (!flags.psd_file.empty()) std::cout << "PSDs: " << flags.psd_file << "\n";
  if (!flags.plot_file.empty()) std::cout << "Figure: " << flags.plot_file << "\n";
}

}  // namespace

void register_analyse(CLI::App& app) {
  auto flags = std::make_shared<AnalyseFlags>();
  CLI::App* command = app.add_subcommand(
      "analyse",
      "Spectra, ISO 2631-1 comfort values, tyre-load, travel and impact figures of recordings "
      "(CSV with time[s] and name[unit] columns, or .mat); with --levels, their correlation with a "
      "parameter");
  command
      ->add_option("files", flags->files, "Recordings (CSV or .mat); PSDs are averaged over them")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--channel", flags->channels,
                      "Channel to analyse (repeatable; default: every column but time and stuck)");
  command
      ->add_option("--weighting", flags->weighting,
                   "ISO 2631-1 weighting of acceleration channels: auto (Wk for seat/body, We for "
                   "pitch/roll, none for others), none, Wk, Wd, Wf, Wc, We or Wj")
      ->capture_default_str();
  command->add_option("--band", flags->band_Hz, "Band for band RMS and peak, LOW,HIGH [Hz]")
      ->delimiter(',')
      ->capture_default_str();
  command
      ->add_option("--segment", flags->segment_s,
                   "Welch segment length [s] (default: 8 segments over the record)")
      ->check(positive_number("s"));
  command->add_option("--overlap", flags->overlap, "Welch segment overlap, in [0, 0.95]")
      ->check(CLI::Range(0.0, 0.95))
      ->capture_default_str();
  command->add_option("--detrend", flags->detrend, "Per-segment detrending: none, mean, linear")
      ->check(CLI::IsMember({"none", "mean", "linear"}))
      ->capture_default_str();
  command
      ->add_option("--smooth", flags->smooth_bins,
                   "Moving-average smoothing of the PSD over this many bins (odd; 1 = off)")
      ->capture_default_str();
  command->add_option("--confidence", flags->confidence, "Level of the PSD's chi-squared band")
      ->check(CLI::Range(0.5, 0.999))
      ->capture_default_str();
  command
      ->add_option("--static-tyre-load", flags->static_tyre_load_N,
                   "Static wheel load [N] for the tyre_force channel (dynamic part, compression "
                   "positive): (m_s + m_u)·g")
      ->check(positive_number("N"));
  command
      ->add_option("--model", flags->model_file,
                   "Quarter-car model file: the static wheel load (m_s + m_u)·g for tyre_force")
      ->check(CLI::ExistingFile);
  command
      ->add_option("--rattle-space", flags->rattle_space_m,
                   "Travel to the bump and rebound stops, COMPRESSION,REBOUND [m]")
      ->delimiter(',');
  command->add_flag("--impact", flags->impact,
                    "Impact hardness of acceleration channels (single-obstacle recordings)");
  command
      ->add_option("--levels", flags->levels,
                   "One parameter level per file (e.g. friction 0,30,60,120): correlate every "
                   "metric with it (Pearson R, slope, increase)")
      ->delimiter(',');
  command->add_option("--level-name", flags->level_name,
                      "Name of the levels' parameter, e.g. coulomb_force_N");
  command->add_option("--psd", flags->psd_file,
                      "Write the averaged PSDs and bands to this CSV (or .mat)");
  command->add_option("--plot", flags->plot_file, "Draw the figure (.png or .svg)");
  command->add_flag("--json", flags->json, "Print the results as JSON");
  command->callback([flags] { run(*flags); });
}

}  // namespace ridefit::cli
