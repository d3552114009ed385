#include "ridefit/study/road_profile_figure.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace ridefit::study {
namespace {

constexpr double kLow = 0.011;  // ISO 8608's band, cycles/m
constexpr double kHigh = 2.83;

// Gd(n) = g0·(n/n0)^(−2) at the band's two ends: a straight line on log-log axes.
io::PlotSeries waviness_two_line(std::string label, double g0) {
  const double n0 = road::kIso8608ReferenceCyclesPerM;
  io::PlotSeries line{std::move(label), {kLow, kHigh}, {}, {}, {}, io::SeriesStyle::kLines};
  for (double n : line.x) line.y.push_back(g0 * std::pow(n / n0, -2.0));
  return line;
}

}  // namespace

io::Figure road_profile_figure(const std::string& title, const road::Iso8608Classification& iso,
                               const road::InternationalRoughnessIndex& iri) {
  io::PlotPanel psd = io::xy_panel("displacement PSD", "spatial frequency [cycles/m]", "Gd [m^3]");
  psd.x_scale = io::AxisScale::kLog;
  psd.y_scale = io::AxisScale::kLog;
  psd.key_position = "top right";
  io::PlotSeries measured{"profile", {}, {}, {}, {}, io::SeriesStyle::kLines};
  for (std::size_t k = 0; k < iso.spatial_frequency_cycles_per_m.size(); ++k) {
    if (!(iso.spatial_frequency_cycles_per_m[k] > 0.0)) continue;  // the mean's bin
    measured.x.push_back(iso.spatial_frequency_cycles_per_m[k]);
    measured.y.push_back(iso.psd_m3[k]);
    measured.lower.push_back(iso.psd_lower_m3[k]);
    measured.upper.push_back(iso.psd_upper_m3[k]);
  }
  // The axes show the fitted band's PSD a decade either side; class lines beyond are clipped.
  double low = 0.0, high = 0.0;
  for (std::size_t k = 0; k < measured.x.size(); ++k) {
    if (measured.x[k] < iso.band_low_cycles_per_m || measured.x[k] > iso.band_high_cycles_per_m ||
        !(measured.y[k] > 0.0)) {
      continue;
    }
    low = low == 0.0 ? measured.y[k] : std::min(low, measured.y[k]);
    high = std::max(high, measured.y[k]);
  }
  if (high > 0.0) {
    psd.y_range = std::pair{low / 10.0, high * 10.0};
    psd.x_range = std::pair{iso.band_low_cycles_per_m / 2.0, iso.band_high_cycles_per_m * 2.0};
  }
  psd.series.push_back(std::move(measured));
  psd.series.push_back(
      waviness_two_line(fmt::format("class {}: Gd(0.1) = {:.3g} m^3", road::to_char(iso.road_class),
                                    iso.reference_psd_m3),
                        iso.reference_psd_m3));
  // The boundaries lie a factor 2 above each class's geometric mean (iso8608_class_of).
  const road::Iso8608Class classes[] = {road::Iso8608Class::kA, road::Iso8608Class::kB,
                                        road::Iso8608Class::kC, road::Iso8608Class::kD,
                                        road::Iso8608Class::kE, road::Iso8608Class::kF,
                                        road::Iso8608Class::kG};
  for (std::size_t c = 0; c < std::size(classes); ++c) {
    psd.series.push_back(
        waviness_two_line(fmt::format("{}|{}", road::to_char(classes[c]),
                                      static_cast<char>(road::to_char(classes[c]) + 1)),
                          2.0 * road::iso8608_reference_psd_m3(classes[c])));
  }

  io::PlotPanel segments = io::xy_panel("IRI per segment", "distance [m]", "IRI [m/km]");
  segments.key_position = "top left";
  io::PlotSeries steps{fmt::format("IRI (whole: {:.2f} m/km)", iri.iri_m_per_km),
                       {},
                       {},
                       {},
                       {},
                       io::SeriesStyle::kLines};
  for (const auto& s : iri.segments) {  // a step per segment
    steps.x.insert(steps.x.end(), {s.start_m, s.end_m});
    steps.y.insert(steps.y.end(), {s.iri_m_per_km, s.iri_m_per_km});
  }
  double highest = 0.0;
  for (double y : steps.y) highest = std::max(highest, y);
  if (highest > 0.0) segments.y_range = std::pair{0.0, 1.1 * highest};  // IRI from zero
  if (!iri.segments.empty()) {
    segments.x_range = std::pair{iri.segments.front().start_m, iri.segments.back().end_m};
  }
  segments.series.push_back(std::move(steps));
  return {title, {std::move(psd), std::move(segments)}, 2};
}

}  // namespace ridefit::study
