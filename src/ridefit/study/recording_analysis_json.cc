#include "ridefit/study/recording_analysis_json.h"

namespace ridefit::study {
namespace {

nlohmann::json channel_json(const ChannelMetrics& c) {
  nlohmann::json j = {{"channel", c.name}, {"unit", c.unit}};
  for (const auto& [name, value] : named_metrics(c)) j[name] = value;
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

nlohmann::json correlation_json(const LevelCorrelation& c) {
  return {{"channel", c.channel},
          {"metric", c.metric},
          {"levels", c.levels},
          {"values", c.values},
          {"pearson_r", c.pearson_r},
          {"slope", c.slope},
          {"relative_increase",
           c.relative_increase ? nlohmann::json(*c.relative_increase) : nlohmann::json()}};
}

}  // namespace

nlohmann::json to_json(const RecordingAnalysis& analysis, const RecordingAnalysisOptions& options,
                       const std::optional<ParameterLevels>& levels) {
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
  if (levels) {
    j["correlations"] = nlohmann::json::array();
    for (const auto& c : levels->correlations) j["correlations"].push_back(correlation_json(c));
  }
  return j;
}

}  // namespace ridefit::study
