#include "ridefit/fitting/fit_adequacy.h"

#include <fmt/core.h>

#include <cmath>

#include "ridefit/model/quarter_car_parameter_table.h"

namespace ridefit::fitting {

FitAdequacy judge_fit(double nrmse_percent, std::vector<std::string> on_bounds,
                      const std::vector<std::string>& unidentifiable, double max_nrmse_percent,
                      std::string_view output) {
  FitAdequacy a;
  a.nrmse_percent = nrmse_percent;
  a.on_bounds = std::move(on_bounds);
  std::vector<std::string> reasons;
  if (!(nrmse_percent <= max_nrmse_percent)) {
    reasons.push_back(
        fmt::format("the fitted {} misses the measured one by {:.1f} % NRMSE (more "
                    "than {:.3g} %)",
                    output, nrmse_percent, max_nrmse_percent));
  }
  if (!a.on_bounds.empty() && !unidentifiable.empty()) {
    std::string list;
    for (const auto& b : a.on_bounds) list += (list.empty() ? "" : ", ") + b;
    reasons.push_back(fmt::format(
        "the fit collapsed: {} ended on a bound while the data leave {} undetermined", list,
        unidentifiable.size() > 1 ? "several parameters" : unidentifiable.front()));
  }
  a.explains_data = reasons.empty();
  if (!reasons.empty()) {
    std::string text;
    for (const auto& r : reasons) text += (text.empty() ? "" : "; ") + r;
    a.note = "the model does not explain this data: " + text +
             ". Run `ridefit diagnose` to find what it is missing";
  }
  return a;
}

std::string on_bound(std::string_view name, double value, double lower, double upper) {
  auto near = [&](double bound) {
    const double tolerance = bound != 0.0 ? 1e-4 * std::abs(bound) : 1e-6 * (upper - lower);
    return std::abs(value - bound) <= tolerance;
  };
  if (near(lower)) return fmt::format("{} = {:.4g} (lower bound)", name, value);
  if (near(upper)) return fmt::format("{} = {:.4g} (upper bound)", name, value);
  return "";
}

FitAdequacy assess_psd_fit(const PsdFitResult& fit,
                           const model::QuarterCarParameters<double>& start,
                           const PsdFitOptions& options, double max_nrmse_percent) {
  double squares = 0.0;
  std::size_t count = 0;
  auto add = [&](const std::vector<double>& measured, const std::vector<double>& fitted) {
    for (std::size_t k = 0; k < measured.size() && k < fitted.size(); ++k) {
      if (!(measured[k] > 0.0) || !(fitted[k] >= 0.0)) continue;
      const double e = std::sqrt(fitted[k] / measured[k]) - 1.0;
      squares += e * e;
      ++count;
    }
  };
  add(fit.measured_body_psd, fit.fitted_body_psd);
  add(fit.measured_wheel_psd, fit.fitted_wheel_psd);
  const double nrmse = count > 0 ? 100.0 * std::sqrt(squares / static_cast<double>(count)) : 0.0;
  std::vector<std::string> on_bounds;
  for (std::size_t i = 0; i < fit.names.size(); ++i) {
    const auto index = model::quarter_car_parameter_index(fit.names[i]);
    if (!index) continue;
    const double v = model::quarter_car_parameter(start, *index);
    std::pair<double, double> b{v / 10.0, v * 10.0};
    if (auto it = options.bounds.find(fit.names[i]); it != options.bounds.end()) b = it->second;
    const std::string text = on_bound(fit.names[i], fit.values[i], b.first, b.second);
    if (!text.empty()) on_bounds.push_back(text);
  }
  return judge_fit(nrmse, on_bounds, fit.unidentifiable, max_nrmse_percent, "amplitude spectrum");
}

}  // namespace ridefit::fitting
