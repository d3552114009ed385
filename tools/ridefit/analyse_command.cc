// ridefit analyse DATA.csv... [--channel NAME]... [--weighting auto|none|Wk|...] [--band LO,HI]
//                 [--levels L1,L2,...] [--psd out.csv] [--plot FILE.svg|png] [--json]
// The numbers and figures a ride engineer reports for measured or simulated recordings.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>

#include "command_options.h"
#include "ridefit/common/errors.h"
#include "ridefit/io/atomic_file.h"
#include "ridefit/io/csv_table.h"
#include "ridefit/io/gnuplot_figure.h"
#include "ridefit/io/output_paths.h"
#include "ridefit/io/quarter_car_file.h"
#include "ridefit/study/recording_analysis.h"
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

std::string reactions_text(const std::vector<comfort::ComfortReaction>& reactions) {
  std::string text;
  for (const auto r : reactions) text += (text.empty() ? "" : " / ") + std::string(to_string(r));
  return text;
}

nlohmann::json channel_json(const study::ChannelMetrics& c) {
  nlohmann::json j = {{"channel", c.name}, {"unit", c.unit}};
  for (const auto& [name, value] : study::named_metrics(c)) j[name] = value;
  j["spectrum_peak_Hz"] = c.spectrum_peak.frequency_Hz;
  if (c.weighted) {
    const auto& w = *c.weighted;
    j["weighting"] = comfort::to_string(w.weighting);
    j["additional_methods_required"] = w.additional_methods.additional_methods_required();
    j["additional_methods_reasons"] = w.additional_methods.reasons;
    nlohmann::json reactions = nlohmann::json::array();
    for (const auto r : w.reactions) reactions.push_back(to_string(r));
    j["comfort_reactions"] = reactions;
  }
  if (c.tyre_load) j["min_total_tyre_load_N"] = c.tyre_load->min_total_load_N;
  if (c.travel) {
    j["max_compression_m"] = c.travel->max_compression_m;
    j["max_rebound_m"] = c.travel->max_rebound_m;
    if (c.travel->beyond_rattle_space_share) {
      j["beyond_rattle_space_share"] = *c.travel->beyond_rattle_space_share;
    }
  }
  if (c.impact) j["impact_onset_s"] = c.impact->onset_time_s;
  return j;
}

void print_recording(const study::RecordingMetrics& r, const study::RecordingAnalysisOptions& o) {
  std::cout << fmt::format("{}: {:.6g} s at {:.6g} Hz\n", r.source.string(), r.duration_s,
                           r.sample_rate_Hz);
  std::cout << fmt::format(
      "  {:<16} {:>11} {:>11} {:>11} {:>8}  {:>4} {:>9} {:>9} {:>9} {:>6}  {}\n", "channel", "rms",
      "peak", "band_rms", "pk[Hz]", "W", "a_w", "MTVV", "VDV", "CF", "comfort (ISO 2631-1 C.2.3)");
  for (const auto& c : r.channels) {
    std::string weighted = fmt::format("{:>4} {:>9} {:>9} {:>9} {:>6}", "-", "", "", "", "");
    std::string reading;
    if (c.weighted) {
      const auto& m = c.weighted->metrics;
      weighted = fmt::format("{:>4} {:>9.4g} {:>9.4g} {:>9.4g} {:>6.2f}",
                             comfort::to_string(c.weighted->weighting), m.weighted_rms_m_per_s2,
                             m.mtvv_m_per_s2, m.vdv_m_per_s1_75, m.crest_factor);
      reading = reactions_text(c.weighted->reactions);
      if (c.weighted->additional_methods.additional_methods_required()) {
        reading += (reading.empty() ? "" : "; ") + std::string("report MTVV and VDV");
      }
    }
    std::cout << fmt::format("  {:<16} {:>11.4g} {:>11.4g} {:>11.4g} {:>8.3f}  {}  {}\n",
                             c.name + "[" + c.unit + "]", c.rms, c.peak, c.band_rms,
                             c.spectrum_peak.frequency_Hz, weighted, reading);
  }
  for (const auto& c : r.channels) {
    if (c.tyre_load) {
      std::cout << fmt::format(
          "  {}: dynamic load RMS {:.4g} N = {:.3f} of the static {:.4g} N; lift-off {:.2f} % "
          "of the time\n",
          c.name, c.tyre_load->dynamic_load_rms_N, c.tyre_load->relative_dynamic_load,
          c.tyre_load->static_load_N, 100.0 * c.tyre_load->lift_off_share);
    }
    if (c.travel) {
      std::cout << fmt::format(
          "  {}: RMS {:.4g} m, peak {:.4g} m (compression {:.4g} m, rebound {:.4g} m){}\n", c.name,
          c.travel->rms_m, c.travel->peak_m, c.travel->max_compression_m, c.travel->max_rebound_m,
          c.travel->beyond_rattle_space_share
              ? fmt::format(", beyond the rattle space {:.2f} % of the time",
                            100.0 * *c.travel->beyond_rattle_space_share)
              : "");
    }
    if (c.impact) {
      std::cout << fmt::format(
          "  {}: impact hardness: onset {:.4g} s, peak-to-peak {:.4g}, RMS to the second "
          "negative peak {:.4g} ({})\n",
          c.name, c.impact->onset_time_s, c.impact->peak_to_peak, c.impact->rms, c.unit);
    }
  }
  (void)o;
}

// The averaged PSDs with their bands; with --levels, each recording's PSD by level instead
// (an average over different parameter levels means nothing).
void write_psd_csv(const study::RecordingAnalysis& analysis, const AnalyseFlags& flags) {
  io::CsvTable table;
  table.add("frequency", "Hz", analysis.spectra.front().psd.frequency_Hz);
  for (std::size_t c = 0; c < analysis.spectra.size(); ++c) {
    const auto& s = analysis.spectra[c];
    try {
      io::unit_to_si(s.psd_unit);
    } catch (const InputError&) {
      throw InputError(fmt::format(
          "--psd: channel {} is in a unit whose PSD unit ({}) a CSV cannot carry; leave it out "
          "with --channel",
          s.name, s.psd_unit));
    }
    if (flags.levels.empty()) {
      table.add(s.name + "_psd", s.psd_unit, s.psd.psd);
      table.add(s.name + "_psd_lower", s.psd_unit, s.interval.lower);
      table.add(s.name + "_psd_upper", s.psd_unit, s.interval.upper);
      continue;
    }
    for (std::size_t r = 0; r < analysis.recordings.size(); ++r) {
      // The run number keeps names unique when runs share a level (replicates).
      table.add(
          fmt::format("{}_psd_run{}_{}_{:g}", s.name, r + 1, flags.level_name, flags.levels[r]),
          s.psd_unit, analysis.recordings[r].channels[c].psd.psd);
    }
  }
  table.write(flags.psd_file);
}

// The unit of a named metric of a channel in `unit`.
std::string metric_unit(const std::string& metric, const std::string& unit) {
  if (metric == "vdv") return unit == "m/s^2" ? "m/s^1.75" : unit + "·s^0.25";
  if (metric == "crest_factor" || metric.ends_with("_ratio") || metric.ends_with("_share")) {
    return "1";
  }
  return unit;
}

// The metric a person compares across levels: the weighted RMS where there is one.
std::string headline_metric(const study::ChannelMetrics& c) {
  if (c.weighted) return "weighted_rms";
  if (c.tyre_load) return "dynamic_tyre_load_ratio";
  return "rms";
}

io::Figure figure_of(const study::RecordingAnalysis& analysis, const AnalyseFlags& flags,
                     const std::vector<study::LevelCorrelation>& correlations,
                     const study::RecordingAnalysisOptions& options) {
  io::Figure figure;
  const bool levels = !flags.levels.empty();
  figure.title =
      levels ? fmt::format("{} recordings against {}", analysis.recordings.size(), flags.level_name)
             : fmt::format("PSDs averaged over {} recording(s), {:g} % confidence band",
                           analysis.recordings.size(), 100.0 * options.confidence);
  const auto x_range = std::make_pair(std::max(options.band_low_Hz, 1e-3), options.band_high_Hz);
  for (std::size_t c = 0; c < analysis.spectra.size(); ++c) {
    const auto& s = analysis.spectra[c];
    io::PlotPanel panel = io::psd_panel(s.name, fmt::format("PSD [{}]", s.psd_unit));
    panel.x_range = x_range;
    if (levels) {
      for (std::size_t r = 0; r < analysis.recordings.size(); ++r) {
        const auto& psd = analysis.recordings[r].channels[c].psd;
        panel.series.push_back({fmt::format("{} = {:g}", flags.level_name, flags.levels[r]),
                                psd.frequency_Hz,
                                psd.psd,
                                {},
                                {},
                                io::SeriesStyle::kLines});
      }
    } else {
      panel.series.push_back({fmt::format("{} ({:g} % band)", s.name, 100.0 * options.confidence),
                              s.psd.frequency_Hz, s.psd.psd, s.interval.lower, s.interval.upper,
                              io::SeriesStyle::kLines});
    }
    figure.panels.push_back(std::move(panel));
    if (!levels) continue;
    const std::string metric = headline_metric(analysis.recordings.front().channels[c]);
    for (const auto& row : correlations) {
      if (row.channel != s.name || row.metric != metric) continue;
      io::PlotPanel trend = io::xy_panel(
          fmt::format("{} {}: R = {:.3f}", s.name, metric, row.pearson_r), flags.level_name,
          fmt::format("{} [{}]", metric,
                      metric_unit(metric, analysis.recordings.front().channels[c].unit)));
      trend.series.push_back(
          {"recordings", row.levels, row.values, {}, {}, io::SeriesStyle::kPoints});
      const auto [lo, hi] = std::minmax_element(row.levels.begin(), row.levels.end());
      // The least-squares line through the points: y = ȳ + S·(x − x̄).
      double x_mean = 0.0, y_mean = 0.0;
      for (std::size_t i = 0; i < row.levels.size(); ++i) {
        x_mean += row.levels[i] / static_cast<double>(row.levels.size());
        y_mean += row.values[i] / static_cast<double>(row.levels.size());
      }
      trend.series.push_back(
          {fmt::format("fit, S = {:.3g}", row.slope),
           {*lo, *hi},
           {y_mean + row.slope * (*lo - x_mean), y_mean + row.slope * (*hi - x_mean)},
           {},
           {},
           io::SeriesStyle::kLines});
      figure.panels.push_back(std::move(trend));
    }
  }
  figure.columns = levels ? 2 : std::min<int>(3, static_cast<int>(figure.panels.size()));
  return figure;
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
        "--level-name '{}': use letters, digits and underscores (it names CSV columns), e.g. "
        "coulomb_force_N",
        flags.level_name));
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
  std::vector<study::LevelCorrelation> correlations;
  if (!flags.levels.empty()) correlations = study::correlate_with_levels(analysis, flags.levels);

  // The figure first: it is the output that can still fail (gnuplot), and a failed run must
  // leave no file behind.
  if (!flags.plot_file.empty())
    io::draw_figure(figure_of(analysis, flags, correlations, options), flags.plot_file);
  if (!flags.psd_file.empty()) write_psd_csv(analysis, flags);

  if (flags.json) {
    nlohmann::json j;
    j["band_Hz"] = {options.band_low_Hz, options.band_high_Hz};
    j["recordings"] = nlohmann::json::array();
    for (const auto& r : analysis.recordings) {
      nlohmann::json rj = {{"file", r.source.string()},
                           {"sample_rate_Hz", r.sample_rate_Hz},
                           {"duration_s", r.duration_s},
                           {"channels", nlohmann::json::array()}};
      for (const auto& c : r.channels) rj["channels"].push_back(channel_json(c));
      j["recordings"].push_back(rj);
    }
    j["averaged_spectra"] = nlohmann::json::array();
    for (const auto& s : analysis.spectra) {
      j["averaged_spectra"].push_back({{"channel", s.name},
                                       {"band_rms", s.band_rms},
                                       {"peak_Hz", s.peak.frequency_Hz},
                                       {"segments", s.psd.segment_count},
                                       {"resolution_Hz", s.psd.frequency_resolution_Hz}});
    }
    if (!flags.levels.empty()) {
      j["correlations"] = nlohmann::json::array();
      for (const auto& c : correlations) {
        j["correlations"].push_back(
            {{"channel", c.channel},
             {"metric", c.metric},
             {"levels", c.levels},
             {"values", c.values},
             {"pearson_r", c.pearson_r},
             {"slope", c.slope},
             {"relative_increase",
              c.relative_increase ? nlohmann::json(*c.relative_increase) : nlohmann::json()}});
      }
    }
    if (!flags.psd_file.empty()) j["psd_file"] = flags.psd_file;
    if (!flags.plot_file.empty()) j["plot_file"] = flags.plot_file;
    std::cout << j.dump(2) << "\n";
    return;
  }
  for (const auto& r : analysis.recordings) print_recording(r, options);
  if (analysis.recordings.size() > 1 && flags.levels.empty()) {
    std::cout << fmt::format("PSDs averaged over {} recordings:\n", analysis.recordings.size());
    for (const auto& s : analysis.spectra) {
      std::cout << fmt::format("  {:<16} band RMS {:.4g}, peak at {:.3f} Hz ({} segments)\n",
                               s.name, s.band_rms, s.peak.frequency_Hz, s.psd.segment_count);
    }
  }
  if (!correlations.empty()) {
    std::cout << fmt::format("Correlation with {} ({} levels):\n", flags.level_name,
                             flags.levels.size());
    std::cout << fmt::format("  {:<16} {:<24} {:>8} {:>12} {:>10}\n", "channel", "metric", "R",
                             "slope S", "increase");
    for (const auto& c : correlations) {
      std::cout << fmt::format(
          "  {:<16} {:<24} {:>8.3f} {:>12.4g} {:>10}\n", c.channel, c.metric, c.pearson_r, c.slope,
          c.relative_increase ? fmt::format("{:+.1f} %", 100.0 * *c.relative_increase) : "-");
    }
  }
  if (!flags.psd_file.empty()) std::cout << "PSDs: " << flags.psd_file << "\n";
  if (!flags.plot_file.empty()) std::cout << "Figure: " << flags.plot_file << "\n";
}

}  // namespace

void register_analyse(CLI::App& app) {
  auto flags = std::make_shared<AnalyseFlags>();
  CLI::App* command = app.add_subcommand(
      "analyse",
      "Spectra, ISO 2631-1 comfort values, tyre-load, travel and impact figures of recordings "
      "(CSV with time[s] and name[unit] columns); with --levels, their correlation with a "
      "parameter");
  command->add_option("files", flags->files, "Recordings (CSV); PSDs are averaged over them")
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
  command->add_option("--psd", flags->psd_file, "Write the averaged PSDs and bands to this CSV");
  command->add_option("--plot", flags->plot_file, "Draw the figure (.png or .svg)");
  command->add_flag("--json", flags->json, "Print the results as JSON");
  command->callback([flags] { run(*flags); });
}

}  // namespace ridefit::cli
