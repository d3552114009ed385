#include "ridefit/fitting/diagnose/loop_figure.h"

#include <fmt/core.h>

#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "ridefit/fitting/diagnose/loop_disagreement.h"

namespace ridefit::fitting::diagnose {

io::Figure loop_figure(const DiagnosisResult& result, const LoopDiagnosisData& data) {
  io::Figure figure;
  figure.title = "measured against simulated (judging records): before and after";
  if (const std::string p = leading_explanations(result.explanations); !p.empty()) {
    figure.title += " (probabilities: " + p + ")";
  }
  figure.columns = 2;
  for (std::size_t i = 0; i < data.held_out.size() && i < 2; ++i) {
    const auto& record = data.held_out[i];
    const std::size_t n = record.displacement_m.size();
    const std::vector<double> v_m_per_s = rig_velocity_m_per_s(record);
    std::vector<double> x_mm(n), v_mm_per_s(n);
    for (std::size_t k = 0; k < n; ++k) {
      x_mm[k] = 1e3 * record.displacement_m[k];
      v_mm_per_s[k] = 1e3 * v_m_per_s[k];
    }
    // Samples inside a region of `map` along `quantity`, as a points series over (x, y).
    auto marked = [&](const LoopDisagreementMap& map, const std::string& quantity,
                      const std::vector<double>& along, const std::vector<double>& x,
                      const std::vector<double>& y) {
      io::PlotSeries points{"disagreement region", {}, {}, {}, {}, io::SeriesStyle::kPoints};
      for (std::size_t k = 0; k < n; ++k) {
        for (const auto& region : map.regions) {
          if (region.record == record.source && region.quantity == quantity &&
              along[k] >= region.low && along[k] <= region.high) {
            points.x.push_back(x[k]);
            points.y.push_back(y[k]);
            break;
          }
        }
      }
      return points;
    };
    const std::tuple<const char*, const std::vector<double>*, const LoopDisagreementMap*> cases[] =
        {{"before", &result.before_force_N[i], &result.loops_before},
         {"after", &result.after_force_N[i], &result.loops_after}};
    // Top row: the loops, force over displacement, regions along displacement marked.
    for (const auto& [when, force, map] : cases) {
      io::PlotPanel panel = io::xy_panel(fmt::format("{}: {} (NRMSE {:.2f} %)", record.source, when,
                                                     map->records[i].nrmse_percent),
                                         "displacement [mm]", "force [N]");
      panel.series.push_back({"measured", x_mm, record.force_N, {}, {}, io::SeriesStyle::kLines});
      panel.series.push_back({"simulated", x_mm, *force, {}, {}, io::SeriesStyle::kLines});
      auto points = marked(*map, "displacement", record.displacement_m, x_mm, *force);
      if (!points.x.empty()) panel.series.push_back(std::move(points));
      figure.panels.push_back(std::move(panel));
    }
    // Bottom row: the residual over velocity, where a friction or damper law that is wrong shows
    // as a shape (a hump at small |v|, a slope, a step at reversal) rather than a cloud; regions
    // along velocity marked.
    for (const auto& [when, force, map] : cases) {
      std::vector<double> residual(n);
      for (std::size_t k = 0; k < n; ++k) residual[k] = (*force)[k] - record.force_N[k];
      io::PlotPanel panel = io::xy_panel(fmt::format("{}: residual {}", record.source, when),
                                         "velocity [mm/s]", "simulated - measured force [N]");
      panel.series.push_back({"residual", v_mm_per_s, residual, {}, {}, io::SeriesStyle::kPoints});
      auto points = marked(*map, "velocity", v_m_per_s, v_mm_per_s, residual);
      if (!points.x.empty()) panel.series.push_back(std::move(points));
      figure.panels.push_back(std::move(panel));
    }
  }
  return figure;
}

}  // namespace ridefit::fitting::diagnose
