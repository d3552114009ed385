#include "ridefit/study/recording_figure.h"

#include <fmt/core.h>

#include <algorithm>
#include <string>
#include <utility>

namespace ridefit::study {
namespace {

// The unit of a named metric of a channel in `unit`.
std::string metric_unit(const std::string& metric, const std::string& unit) {
  if (metric == "vdv") return unit == "m/s^2" ? "m/s^1.75" : unit + "·s^0.25";
  if (metric == "crest_factor" || metric.ends_with("_ratio") || metric.ends_with("_share")) {
    return "1";
  }
  return unit;
}

// The metric a person compares across levels: the weighted RMS where there is one.
std::string headline_metric(const ChannelMetrics& c) {
  if (c.weighted) return "weighted_rms";
  if (c.tyre_load) return "dynamic_tyre_load_ratio";
  return "rms";
}

io::PlotPanel trend_panel(const LevelCorrelation& row, const std::string& parameter,
                          const std::string& unit) {
  io::PlotPanel trend =
      io::xy_panel(fmt::format("{} {}: R = {:.3f}", row.channel, row.metric, row.pearson_r),
                   parameter, fmt::format("{} [{}]", row.metric, metric_unit(row.metric, unit)));
  trend.series.push_back({"recordings", row.levels, row.values, {}, {}, io::SeriesStyle::kPoints});
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
  return trend;
}

}  // namespace

io::Figure recording_figure(const RecordingAnalysis& analysis,
                            const RecordingAnalysisOptions& options,
                            const std::optional<ParameterLevels>& levels) {
  io::Figure figure;
  figure.title = levels ? fmt::format("{} recordings against {}", analysis.recordings.size(),
                                      levels->parameter)
                        : fmt::format("PSDs averaged over {} recording(s), {:g} % confidence band",
                                      analysis.recordings.size(), 100.0 * options.confidence);
  const auto x_range = std::make_pair(std::max(options.band_low_Hz, 1e-3), options.band_high_Hz);
  for (std::size_t c = 0; c < analysis.spectra.size(); ++c) {
    const auto& s = analysis.spectra[c];
    io::PlotPanel panel = io::psd_panel(s.name, fmt::format("PSD [{}]", s.psd_unit));
    panel.x_range = x_range;
    if (!levels) {
      panel.series.push_back({fmt::format("{} ({:g} % band)", s.name, 100.0 * options.confidence),
                              s.psd.frequency_Hz, s.psd.psd, s.interval.lower, s.interval.upper,
                              io::SeriesStyle::kLines});
      figure.panels.push_back(std::move(panel));
      continue;
    }
    for (std::size_t r = 0; r < analysis.recordings.size(); ++r) {
      const auto& psd = analysis.recordings[r].channels[c].psd;
      panel.series.push_back({fmt::format("{} = {:g}", levels->parameter, levels->values[r]),
                              psd.frequency_Hz,
                              psd.psd,
                              {},
                              {},
                              io::SeriesStyle::kLines});
    }
    figure.panels.push_back(std::move(panel));
    const ChannelMetrics& first = analysis.recordings.front().channels[c];
    const std::string metric = headline_metric(first);
    for (const auto& row : levels->correlations) {
      if (row.channel != s.name || row.metric != metric) continue;
      figure.panels.push_back(trend_panel(row, levels->parameter, first.unit));
    }
  }
  figure.columns = levels ? 2 : std::min<int>(3, static_cast<int>(figure.panels.size()));
  return figure;
}

}  // namespace ridefit::study
