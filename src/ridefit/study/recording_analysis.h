#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "ridefit/comfort/additional_methods_rule.h"
#include "ridefit/comfort/comfort_reaction.h"
#include "ridefit/comfort/frequency_weighting.h"
#include "ridefit/comfort/impact_hardness.h"
#include "ridefit/comfort/suspension_travel_metrics.h"
#include "ridefit/comfort/tyre_load_metrics.h"
#include "ridefit/comfort/vibration_metrics.h"
#include "ridefit/io/csv_table.h"
#include "ridefit/signal/psd_confidence.h"
#include "ridefit/signal/spectrum_peak.h"
#include "ridefit/signal/welch_psd.h"

namespace ridefit::study {

// A time-series CSV (design.md: `time[s]` plus `name[unit]` columns, converted to SI) with the
// uniform sample rate that spectra and weighting filters need.
struct Recording {
  std::filesystem::path source;
  io::CsvTable table;
  double sample_rate_Hz = 0.0;
};

// Reads and checks a recording: a `time` column, strictly increasing and uniform (within 1 %),
// at least 2 samples; every value finite. InputErrors name the file, the row and the column.
Recording load_recording(const std::filesystem::path& csv_file);

// Which ISO 2631-1 weighting an acceleration channel gets.
struct WeightingChoice {
  // By channel name: vertical accelerations at a person or the body (`seat_acc`, `body_acc`,
  // `upper_body_acc`, `lower_body_acc`) get Wk, rotational ones (`pitch_acc`, `roll_acc`) We;
  // other channels (e.g. `wheel_acc`, not at a person) are left unweighted.
  bool by_channel_name = true;
  // Otherwise this weighting for every acceleration channel (m/s^2 or rad/s^2), or none.
  std::optional<comfort::Weighting> weighting;
};

struct RecordingAnalysisOptions {
  std::vector<std::string> channels;  // empty: every column but `time` and `stuck`
  WeightingChoice weighting;
  double band_low_Hz = 0.5;  // band RMS and peak search
  double band_high_Hz = 30.0;
  signal::WelchOptions welch;       // the same settings for every recording
  std::size_t smoothing_bins = 1;   // centred moving average of the averaged PSD (odd, 1 = off)
  double confidence = 0.9;          // of the PSD's χ² band
  double integration_time_s = 1.0;  // running RMS / MTVV
  std::optional<double> static_tyre_load_N;          // enables tyre-load metrics on `tyre_force`
  std::optional<comfort::RattleSpace> rattle_space;  // for `travel`
  bool impact_hardness = false;  // single-obstacle records: impact hardness of accelerations

  // Throws InputError for a band that is empty or not finite, a confidence outside (0, 1),
  // an even smoothing width, a non-positive integration time or static load.
  void validate() const;
};

// ISO 2631-1 values of one weighted acceleration channel.
struct WeightedValues {
  comfort::Weighting weighting = comfort::Weighting::kWk;
  comfort::VibrationMetrics metrics;
  comfort::AdditionalMethodsCheck additional_methods;
  // The comfort reactions of ISO 2631-1 Annex C (overlapping ranges, so one or two); empty for
  // rotational weightings, whose values are not in m/s^2.
  std::vector<comfort::ComfortReaction> reactions;
};

struct ChannelMetrics {
  std::string name;
  std::string unit;                    // SI
  double rms = 0.0;                    // of the values as recorded (no mean removed)
  double peak = 0.0;                   // max |value|
  double band_rms = 0.0;               // sqrt of the PSD integrated over the band (mean removed)
  signal::SpectrumPeak spectrum_peak;  // in the band
  signal::PowerSpectralDensity psd;    // this recording's own (before averaging/smoothing)
  std::optional<WeightedValues> weighted;
  std::optional<comfort::TyreLoadMetrics> tyre_load;
  std::optional<comfort::SuspensionTravelMetrics> travel;
  std::optional<comfort::ImpactHardness> impact;
};

struct RecordingMetrics {
  std::filesystem::path source;
  double sample_rate_Hz = 0.0;
  double duration_s = 0.0;
  std::vector<ChannelMetrics> channels;
};

// A channel's PSD averaged over all recordings (Bartlett: degrees of freedom add), smoothed,
// with its confidence band.
struct ChannelSpectrum {
  std::string name;
  std::string psd_unit;  // e.g. (m/s^2)^2/Hz
  signal::PowerSpectralDensity psd;
  signal::PsdConfidenceInterval interval;
  double band_rms = 0.0;
  signal::SpectrumPeak peak;
};

struct RecordingAnalysis {
  std::vector<RecordingMetrics> recordings;
  std::vector<ChannelSpectrum> spectra;
};

// Metrics of every chosen channel in every recording, and the averaged spectra. Every
// recording must hold the chosen channels (InputError naming the file and the columns it has)
// and share the sample rate (for the average; InputError naming the file).
RecordingAnalysis analyse_recordings(std::span<const Recording> recordings,
                                     const RecordingAnalysisOptions& options);

// The scalar metrics of a channel by name (`rms`, `peak`, `band_rms`, and where they apply
// `weighted_rms`, `mtvv`, `vdv`, `crest_factor`, `dynamic_tyre_load_ratio`, `lift_off_share`,
// `beyond_rattle_space_share`, `impact_peak_to_peak`, `impact_rms`), in that order. Units are
// the channel's (m/s^2 for weighted values of m/s^2 channels; VDV in m/s^1.75).
std::vector<std::pair<std::string, double>> named_metrics(const ChannelMetrics& channel);

// One metric of one channel across recordings taken at different levels of a parameter (seed
// 000 Table 3: objective values against friction), with Pearson R, slope and increase.
struct LevelCorrelation {
  std::string channel;
  std::string metric;
  std::vector<double> levels;
  std::vector<double> values;
  double pearson_r = 0.0;                   // NaN-free: metrics with no variance are left out
  double slope = 0.0;                       // [metric unit] per [level unit]
  std::optional<double> relative_increase;  // from the lowest to the highest level (data)
};

// Correlates every metric of every channel with `levels` (one per recording; InputError when
// the counts differ or fewer than 3 distinct levels are given). A metric constant over the
// recordings has no correlation and is left out.
std::vector<LevelCorrelation> correlate_with_levels(const RecordingAnalysis& analysis,
                                                    std::span<const double> levels);

// Recordings taken at levels of one parameter and what correlates with it: what a level study's
// outputs (report, JSON, figure, PSD table) show beside the analysis.
struct ParameterLevels {
  std::string parameter;                       // names CSV columns and axes, e.g. coulomb_force_N
  std::vector<double> values;                  // one per recording, in their order
  std::vector<LevelCorrelation> correlations;  // correlate_with_levels(analysis, values)
};

}  // namespace ridefit::study
