#include "ridefit/fitting/psd_fit_report.h"

#include <fmt/core.h>

#include <algorithm>
#include <optional>

#include "ridefit/fitting/fit_json.h"

namespace ridefit::fitting {

void write_summary(std::ostream& out, const std::string& source, const PsdFitResult& fit,
                   const FitAdequacy& adequacy) {
  out << fmt::format(
      "PSD fit of {}: {} iterations, cost {:.4g}, amplitude-spectrum NRMSE {:.2f} % ({})\n", source,
      fit.iterations, fit.final_cost, adequacy.nrmse_percent,
      adequacy.explains_data ? fit.termination : "the model does not explain the data");
  for (std::size_t i = 0; i < fit.names.size(); ++i) {
    out << fmt::format(
        "  {:<30} {:>14.6g}  ± {}\n", fit.names[i], fit.values[i],
        fit.standard_errors[i] ? fmt::format("{:.3g}", *fit.standard_errors[i]) : "-");
  }
  const bool any_error = std::any_of(fit.standard_errors.begin(), fit.standard_errors.end(),
                                     [](const std::optional<double>& e) { return e.has_value(); });
  if (any_error && fit.residual_correlation_samples > 1.0) {
    out << fmt::format(
        "  (± one standard error, widened by √τ: the bins' residuals are correlated over τ = "
        "{:.3g} bins)\n",
        fit.residual_correlation_samples);
  }
  if (!fit.identifiability_note.empty()) out << "warning: " << fit.identifiability_note << "\n";
  for (const auto& bound : adequacy.on_bounds) out << "  on a bound: " << bound << "\n";
}

nlohmann::json summary_json(const PsdFitResult& fit, const FitAdequacy& adequacy) {
  nlohmann::json j = {
      {"converged", fit.converged},
      {"termination", fit.termination},
      {"iterations", fit.iterations},
      {"final_cost", fit.final_cost},
      {"residual_correlation_samples", fit.residual_correlation_samples},
      {"unidentifiable", fit.unidentifiable},
      {"identifiability_note", fit.identifiability_note},
      {"nrmse_percent", adequacy.nrmse_percent},
      {"explains_data", adequacy.explains_data},
      {"adequacy_note", adequacy.note},
      {"on_bounds", adequacy.on_bounds},
      {"noise_psd",
       {{"body_acc", fit.noise_floors.body_psd}, {"wheel_acc", fit.noise_floors.wheel_psd}}},
      {"parameters", nlohmann::json::array()},
      {"correlation", correlation_json(fit.correlation)}};
  for (std::size_t i = 0; i < fit.names.size(); ++i) {
    j["parameters"].push_back({{"name", fit.names[i]},
                               {"value", fit.values[i]},
                               {"standard_error", number_or_null(fit.standard_errors[i])}});
  }
  return j;
}

}  // namespace ridefit::fitting
