#include "ridefit/study/recording_analysis.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "ridefit/comfort/weighting_filter.h"
#include "ridefit/common/errors.h"
#include "ridefit/io/measurement_file.h"
#include "ridefit/signal/band_power.h"
#include "ridefit/signal/correlation.h"
#include "ridefit/signal/psd_average.h"
#include "ridefit/signal/psd_smoothing.h"
#include "ridefit/signal/signal_presence.h"
#include "ridefit/signal/statistics.h"
#include "ridefit/signal/uniform_sample_rate.h"

namespace ridefit::study {
namespace {

bool is_acceleration(const std::string& si_unit) {
  return si_unit == "m/s^2" || si_unit == "rad/s^2";
}

std::optional<comfort::Weighting> weighting_for(const io::CsvColumn& column,
                                                const WeightingChoice& choice) {
  if (!is_acceleration(column.unit)) return std::nullopt;
  if (!choice.by_channel_name) return choice.weighting;
  static const std::set<std::string> kVertical = {"seat_acc", "body_acc", "upper_body_acc",
                                                  "lower_body_acc"};
  if (kVertical.count(column.name) && column.unit == "m/s^2") return comfort::Weighting::kWk;
  if ((column.name == "pitch_acc" || column.name == "roll_acc") && column.unit == "rad/s^2") {
    return comfort::Weighting::kWe;
  }
  return std::nullopt;
}

std::vector<std::string> chosen_channels(const Recording& first,
                                         const RecordingAnalysisOptions& options) {
  if (!options.channels.empty()) return options.channels;
  std::vector<std::string> names;
  for (const auto& column : first.table.columns()) {
    if (column.name != "time" && column.name != "stuck") names.push_back(column.name);
  }
  if (names.empty()) {
    throw InputError(fmt::format("{}: no channel besides time to analyse", first.source.string()));
  }
  return names;
}

WeightedValues weighted_values(comfort::Weighting weighting, const std::vector<double>& values,
                               double sample_rate_Hz, double integration_time_s) {
  WeightedValues result;
  result.weighting = weighting;
  // Every weighting blocks DC (its band-limiting high-pass), so removing the record's mean
  // changes nothing in steady state; it only spares the filter, which starts from rest, the
  // start-up transient of a step to a sensor offset.
  double mean = 0.0;
  for (double v : values) mean += v / static_cast<double>(values.size());
  std::vector<double> centred(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) centred[i] = values[i] - mean;
  const std::vector<double> weighted = comfort::apply_weighting(weighting, centred, sample_rate_Hz);
  result.metrics = comfort::vibration_metrics(weighted, sample_rate_Hz, integration_time_s);
  result.additional_methods = comfort::check_additional_methods(result.metrics);
  // Annex C's comfort reactions are for translational comfort weightings (not We, rotational,
  // nor Wf, motion sickness); the caller passes m/s² channels only.
  if (weighting != comfort::Weighting::kWe && weighting != comfort::Weighting::kWf) {
    result.reactions = comfort::comfort_reactions(result.metrics.weighted_rms_m_per_s2);
  }
  return result;
}

ChannelMetrics channel_metrics(const Recording& recording, const io::CsvColumn& column,
                               const signal::PowerSpectralDensity& psd,
                               const RecordingAnalysisOptions& options) {
  ChannelMetrics m;
  m.name = column.name;
  m.unit = column.unit;
  m.rms = signal::rms(column.values);
  for (double v : column.values) m.peak = std::max(m.peak, std::abs(v));
  m.band_rms = signal::band_rms(psd, options.band_low_Hz, options.band_high_Hz);
  m.spectrum_peak = signal::find_peak(psd, options.band_low_Hz, options.band_high_Hz);
  if (const auto weighting = weighting_for(column, options.weighting)) {
    m.weighted = weighted_values(*weighting, column.values, recording.sample_rate_Hz,
                                 options.integration_time_s);
    if (column.unit != "m/s^2") m.weighted->reactions.clear();
  }
  if (column.name == "tyre_force" && options.static_tyre_load_N) {
    m.tyre_load = comfort::tyre_load_metrics(column.values, *options.static_tyre_load_N);
  }
  if (column.name == "travel") {
    m.travel = comfort::suspension_travel_metrics(column.values, options.rattle_space);
  }
  if (options.impact_hardness && is_acceleration(column.unit)) {
    try {
      m.impact = comfort::impact_hardness(column.values, recording.sample_rate_Hz);
      // impact_hardness counts from the record's first sample; report times on its time axis.
      const double t0 = recording.table.time_s().front();
      m.impact->onset_time_s += t0;
      for (auto* peak : {&m.impact->first_positive_peak, &m.impact->first_negative_peak,
                         &m.impact->second_negative_peak}) {
        peak->time_s += t0;
      }
    } catch (const InputError& e) {
      throw InputError(
          fmt::format("{}: channel {}: {}", recording.source.string(), column.name, e.what()));
    }
  }
  return m;
}

}  // namespace

Recording load_recording(const std::filesystem::path& csv_file) {
  Recording recording;
  recording.source = csv_file;
  recording.table = io::read_measurement_table(csv_file);
  recording.sample_rate_Hz =
      signal::uniform_sample_rate_Hz(recording.table.time_s(), csv_file.string());
  return recording;
}

void RecordingAnalysisOptions::validate() const {
  if (!std::isfinite(band_low_Hz) || !std::isfinite(band_high_Hz) || band_low_Hz < 0.0 ||
      !(band_high_Hz > band_low_Hz)) {
    throw InputError(
        fmt::format("band {},{} Hz: expected 0 <= low < high, both finite (e.g. 0.5,30)",
                    band_low_Hz, band_high_Hz));
  }
  if (!(confidence > 0.0 && confidence < 1.0)) {
    throw InputError(
        fmt::format("confidence {}: expected a level in (0, 1), e.g. 0.9", confidence));
  }
  if (smoothing_bins > 101) {
    throw InputError(fmt::format(
        "smoothing over {} bins: at most 101 (a longer Welch segment gives finer bins instead)",
        smoothing_bins));
  }
  if (smoothing_bins == 0 || smoothing_bins % 2 == 0) {
    throw InputError(
        fmt::format("smoothing over {} bins: expected an odd number of bins (1 = no smoothing)",
                    smoothing_bins));
  }
  if (!(integration_time_s > 0.0) || !std::isfinite(integration_time_s)) {
    throw InputError(
        fmt::format("integration time {} s: expected > 0 (ISO 2631-1: 1 s)", integration_time_s));
  }
  if (static_tyre_load_N && !(*static_tyre_load_N > 0.0 && std::isfinite(*static_tyre_load_N))) {
    throw InputError(fmt::format("static tyre load {} N: expected > 0, e.g. (m_s + m_u)·g",
                                 *static_tyre_load_N));
  }
}

RecordingAnalysis analyse_recordings(std::span<const Recording> recordings,
                                     const RecordingAnalysisOptions& options) {
  options.validate();
  if (recordings.empty()) throw InputError("no recording to analyse");
  std::vector<std::string> names = chosen_channels(recordings.front(), options);
  const double nyquist_Hz = recordings.front().sample_rate_Hz / 2.0;
  if (options.band_low_Hz >= nyquist_Hz) {
    throw InputError(fmt::format(
        "band {},{} Hz: starts above the Nyquist frequency {:.6g} Hz of {}", options.band_low_Hz,
        options.band_high_Hz, nyquist_Hz, recordings.front().source.string()));
  }
  for (std::size_t c = 0; c < names.size(); ++c) {
    for (std::size_t d = c + 1; d < names.size(); ++d) {
      if (names[c] == names[d]) {
        throw InputError(fmt::format("channel {} is asked for twice; give it once", names[c]));
      }
    }
  }
  for (std::size_t r = 0; r < recordings.size(); ++r) {
    for (std::size_t q = r + 1; q < recordings.size(); ++q) {
      if (recordings[r].source == recordings[q].source) {
        throw InputError(
            fmt::format("{} is given twice; a repeated file would count as an independent record",
                        recordings[r].source.string()));
      }
    }
    for (const auto& name : names) {
      const auto& unit = recordings[r].table.column(name).unit;
      const auto& first = recordings.front().table.column(name).unit;
      if (unit != first) {
        throw InputError(fmt::format(
            "{}: channel {} is in {}, but in {} it is in {}; the files "
            "must measure the same quantity",
            recordings[r].source.string(), name, unit, recordings.front().source.string(), first));
      }
    }
  }
  // A channel with no signal (zero or constant) would give a PSD peak and a crest factor of
  // round-off: a channel asked for is refused; of the channels chosen by default, those flat in
  // some recording are left out (a simulation writes friction_force = 0 without friction), and
  // a recording with none left is refused.
  std::vector<std::string> kept;
  std::string flat;
  for (const auto& name : names) {
    bool has_signal = true;
    for (const Recording& recording : recordings) {
      const auto& column = recording.table.column(name);
      try {
        signal::require_signal(column.values, recording.source.string(), name, column.unit);
      } catch (const InputError&) {
        if (!options.channels.empty()) throw;
        has_signal = false;
      }
    }
    if (has_signal) {
      kept.push_back(name);
    } else {
      flat += (flat.empty() ? "" : ", ") + name;
    }
  }
  if (kept.empty()) {
    throw InputError(fmt::format(
        "{}: no channel carries a signal ({} are zero or constant in at least one recording); "
        "check the sensors and the logger",
        recordings.front().source.string(), flat));
  }
  names = kept;
  RecordingAnalysis analysis;
  std::vector<std::vector<signal::PowerSpectralDensity>> spectra(names.size());
  std::vector<std::string> sources;
  for (const Recording& recording : recordings) {
    sources.push_back(recording.source.string());
    RecordingMetrics metrics;
    metrics.source = recording.source;
    metrics.sample_rate_Hz = recording.sample_rate_Hz;
    const auto& time = recording.table.time_s();
    metrics.duration_s = time.back() - time.front();
    for (std::size_t c = 0; c < names.size(); ++c) {
      const io::CsvColumn& column = recording.table.column(names[c]);
      signal::PowerSpectralDensity psd;
      try {
        psd = signal::welch_psd(column.values, recording.sample_rate_Hz, options.welch);
      } catch (const InputError& e) {
        throw InputError(
            fmt::format("{}: channel {}: {}", recording.source.string(), names[c], e.what()));
      }
      try {
        metrics.channels.push_back(channel_metrics(recording, column, psd, options));
        for (const auto& [metric, value] : named_metrics(metrics.channels.back())) {
          if (!std::isfinite(value)) {
            throw InputError(fmt::format(
                "{} overflows ({}); the values are out of range for this analysis", metric, value));
          }
        }
      } catch (const InputError& e) {
        const std::string message = e.what();
        if (message.starts_with(recording.source.string())) throw;
        throw InputError(
            fmt::format("{}: channel {}: {}", recording.source.string(), names[c], message));
      }
      metrics.channels.back().psd = psd;
      spectra[c].push_back(std::move(psd));
    }
    analysis.recordings.push_back(std::move(metrics));
  }
  for (std::size_t c = 0; c < names.size(); ++c) {
    ChannelSpectrum spectrum;
    spectrum.name = names[c];
    spectrum.psd_unit = io::psd_unit_of(recordings.front().table.column(names[c]).unit);
    spectrum.psd = signal::average_psd(spectra[c], sources);
    if (options.smoothing_bins > 1) {
      spectrum.psd = signal::smooth_psd(spectrum.psd, options.smoothing_bins);
    }
    spectrum.interval = signal::psd_confidence_interval(spectrum.psd, options.confidence);
    spectrum.band_rms = signal::band_rms(spectrum.psd, options.band_low_Hz, options.band_high_Hz);
    spectrum.peak = signal::find_peak(spectrum.psd, options.band_low_Hz, options.band_high_Hz);
    analysis.spectra.push_back(std::move(spectrum));
  }
  return analysis;
}

std::vector<std::pair<std::string, double>> named_metrics(const ChannelMetrics& channel) {
  std::vector<std::pair<std::string, double>> metrics = {
      {"rms", channel.rms}, {"peak", channel.peak}, {"band_rms", channel.band_rms}};
  if (channel.weighted) {
    const auto& w = channel.weighted->metrics;
    metrics.insert(metrics.end(), {{"weighted_rms", w.weighted_rms_m_per_s2},
                                   {"mtvv", w.mtvv_m_per_s2},
                                   {"vdv", w.vdv_m_per_s1_75},
                                   {"crest_factor", w.crest_factor}});
  }
  if (channel.tyre_load) {
    metrics.insert(metrics.end(),
                   {{"dynamic_tyre_load_ratio", channel.tyre_load->relative_dynamic_load},
                    {"lift_off_share", channel.tyre_load->lift_off_share}});
  }
  if (channel.travel) {
    metrics.insert(metrics.end(), {{"travel_rms", channel.travel->rms_m},
                                   {"travel_peak", channel.travel->peak_m}});
  }
  if (channel.impact) {
    metrics.insert(metrics.end(), {{"impact_peak_to_peak", channel.impact->peak_to_peak},
                                   {"impact_rms", channel.impact->rms}});
  }
  return metrics;
}

std::vector<LevelCorrelation> correlate_with_levels(const RecordingAnalysis& analysis,
                                                    std::span<const double> levels) {
  if (levels.size() != analysis.recordings.size()) {
    throw InputError(fmt::format("{} levels for {} recordings: give one level per recording",
                                 levels.size(), analysis.recordings.size()));
  }
  const std::set<double> distinct(levels.begin(), levels.end());
  if (distinct.size() < 3) {
    throw InputError(fmt::format(
        "{} distinct level(s): a correlation needs at least 3 (with 2, R is ±1 by construction)",
        distinct.size()));
  }
  std::vector<LevelCorrelation> correlations;
  const auto& first = analysis.recordings.front();
  for (std::size_t c = 0; c < first.channels.size(); ++c) {
    const auto names = named_metrics(first.channels[c]);
    for (std::size_t m = 0; m < names.size(); ++m) {
      LevelCorrelation row;
      row.channel = first.channels[c].name;
      row.metric = names[m].first;
      row.levels.assign(levels.begin(), levels.end());
      for (const auto& recording : analysis.recordings) {
        row.values.push_back(named_metrics(recording.channels[c])[m].second);
      }
      const signal::LinearCorrelation fit = signal::linear_correlation(row.levels, row.values);
      // A metric constant up to round-off has nothing to correlate (R of noise is meaningless).
      const auto [lo, hi] = std::minmax_element(row.values.begin(), row.values.end());
      const double size = std::max(std::abs(*lo), std::abs(*hi));
      if (!fit.pearson_r || !(*hi - *lo > 1e-9 * size)) continue;
      row.pearson_r = *fit.pearson_r;
      row.slope = fit.slope;
      row.relative_increase = fit.relative_increase;
      correlations.push_back(std::move(row));
    }
  }
  return correlations;
}

}  // namespace ridefit::study
