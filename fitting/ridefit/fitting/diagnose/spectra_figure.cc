#include "ridefit/fitting/diagnose/spectra_figure.h"

#include <fmt/core.h>

#include <string>
#include <utility>
#include <vector>

namespace ridefit::fitting::diagnose {
namespace {

void add_panels(io::Figure& figure, const DisagreementMap& map, const std::string& when) {
  for (const auto& c : map.channels) {
    io::PlotPanel panel = io::psd_panel(
        fmt::format("{}: {} (gap {:.2f} dB)", c.channel, when, c.gap_dB), "PSD [(m/s^2)^2/Hz]");
    panel.series.push_back({"measured", c.frequency_Hz, c.measured_psd, c.measured_lower,
                            c.measured_upper, io::SeriesStyle::kLines});
    panel.series.push_back(
        {"simulated", c.frequency_Hz, c.simulated_psd, {}, {}, io::SeriesStyle::kLines});
    // Regions as points on the simulated curve, so they read against both curves.
    std::vector<double> fx, fy;
    for (std::size_t k = 0; k < c.frequency_Hz.size(); ++k) {
      for (const auto& region : map.regions) {
        if (region.channel == c.channel && c.frequency_Hz[k] >= region.low_Hz &&
            c.frequency_Hz[k] <= region.high_Hz) {
          fx.push_back(c.frequency_Hz[k]);
          fy.push_back(c.simulated_psd[k]);
          break;
        }
      }
    }
    if (!fx.empty()) {
      panel.series.push_back({"disagreement region", fx, fy, {}, {}, io::SeriesStyle::kPoints});
    }
    figure.panels.push_back(std::move(panel));
  }
}

}  // namespace

io::Figure spectra_figure(const DiagnosisResult& result) {
  io::Figure figure;
  figure.title = "measured against simulated (held-out record): before and after";
  if (const std::string p = leading_explanations(result.explanations); !p.empty()) {
    figure.title += " (probabilities: " + p + ")";
  }
  figure.columns = 2;
  // Row by row: before | after per channel.
  for (std::size_t i = 0; i < result.before.channels.size(); ++i) {
    DisagreementMap one_before = result.before, one_after = result.after;
    one_before.channels = {result.before.channels[i]};
    one_after.channels = {result.after.channels[i]};
    add_panels(figure, one_before, "before");
    add_panels(figure, one_after, "after");
  }
  return figure;
}

}  // namespace ridefit::fitting::diagnose
