#include "ridefit/fitting/hysteresis_fit_report.h"

#include <fmt/core.h>

#include <algorithm>
#include <utility>

#include "ridefit/common/errors.h"
#include "ridefit/fitting/fit_json.h"

namespace ridefit::fitting {

HysteresisFitReport report_hysteresis_fit(const std::vector<HysteresisRecord>& records,
                                          const HysteresisFitResult& fit, std::string start,
                                          std::span<const double> compression_m) {
  HysteresisFitReport report;
  report.start = std::move(start);
  for (const auto& r : records) {
    report.sources.push_back(r.source);
    report.displacement.push_back(r.displacement_low_pass);
    report.displacement_low_passed.push_back(r.displacement_low_passed);
    try {
      report.calibration.push_back(signal::hysteresis_friction(r.displacement_m, r.force_N));
    } catch (const InputError&) {
      report.calibration.push_back(std::nullopt);  // fewer than 2 cycles through zero: no value
    }
  }
  if (!compression_m.empty()) report.friction_line = fit_friction_compression(fit, compression_m);
  for (std::size_t r = 0; r < records.size() && r < fit.fitted.size(); ++r) {
    if (!records[r].command.empty() && !fit.fitted[r].commanded()) {
      report.unused_command = fmt::format(
          "{} carries a command column ({}) that this model does not use (no command law: "
          "damping_per_command_Ns_per_m and coulomb_force_per_command_N are 0); free them to fit "
          "it",
          records[r].source, records[r].command_unit.empty() ? "no unit" : records[r].command_unit);
      break;
    }
  }
  return report;
}

std::string describe_displacement_treatment(const signal::QuantisationLowPass& t, bool applied) {
  if (t.step == 0.0) return "displacement not quantised: " + t.reason;
  if (t.cutoff_Hz == 0.0) {
    return fmt::format("displacement quantised in {:.3g} µm steps, no low-pass: {}", 1e6 * t.step,
                       t.reason);
  }
  return fmt::format(
      "displacement quantised in {:.3g} µm steps: velocity noise of the steps {:.3g} mm/s RMS; a "
      "zero-phase low-pass at {:.4g} Hz {} it to {:.3g} mm/s, giving up only what lies above the "
      "cut-off (the record stands above its quantisation floor up to {:.4g} Hz)",
      1e6 * t.step, 1e3 * t.velocity_noise_rms_before, t.cutoff_Hz,
      applied ? "cut" : "(not applied) would cut", 1e3 * t.velocity_noise_rms_after,
      t.content_up_to_Hz);
}

void write_summary(std::ostream& out, const HysteresisFitResult& fit,
                   const HysteresisFitReport& report) {
  out << fmt::format(
      "fit of {} file(s) from {}: {} iterations, residual RMS {:.4g} N, NRMSE {:.2f} % ({})\n",
      report.sources.size(), report.start, fit.iterations, fit.residual_rms_N, fit.nrmse_percent,
      fit.explains_data ? fit.termination : "the model does not explain the data");
  for (const auto& p : fit.parameters) {
    out << fmt::format("  {:<30} {:>14.6g}  ± {:<12}{}\n", p.name, p.value,
                       p.standard_error ? fmt::format("{:.3g}", *p.standard_error) : "-",
                       p.file.empty() ? "" : "  " + p.file);
  }
  const bool any_error = std::any_of(fit.parameters.begin(), fit.parameters.end(),
                                     [](const FittedParameter& p) { return p.standard_error; });
  if (any_error && fit.residual_correlation_samples > 1.0) {
    out << fmt::format(
        "  (± one standard error, widened by √τ: the residuals are correlated over τ = {:.3g} "
        "samples)\n",
        fit.residual_correlation_samples);
  }
  if (report.sources.size() > 1) {
    for (std::size_t r = 0; r < report.sources.size() && r < fit.record_nrmse_percent.size(); ++r) {
      out << fmt::format("  NRMSE {:6.2f} %  {}\n", fit.record_nrmse_percent[r], report.sources[r]);
    }
  }
  for (std::size_t r = 0; r < report.sources.size(); ++r) {
    const auto& calibration = report.calibration[r];
    if (!calibration) continue;
    out << fmt::format(
        "  seed calibration (half the loop height at x = 0, cycles 2-{}): {:.4g}{} N  {}\n",
        calibration->cycles_used + 1, calibration->mean_N,
        calibration->cycles_used > 1 ? fmt::format(" ± {:.2g}", calibration->standard_deviation_N)
                                     : std::string(" (one cycle)"),
        report.sources[r]);
  }
  for (std::size_t r = 0; r < report.sources.size() && r < report.displacement.size(); ++r) {
    const auto& treatment = report.displacement[r];
    if (treatment && treatment->step > 0.0) {
      out << "  " << describe_displacement_treatment(*treatment, report.displacement_low_passed[r])
          << "  " << report.sources[r] << "\n";
    }
  }
  if (const auto& line = report.friction_line) {
    out << fmt::format(
        "  Fc = {:.4g} N + {:.4g} N/mm · compression (slope ± {} N/mm)\n", line->intercept_N,
        1e-3 * line->slope_N_per_m,
        line->slope_se_N_per_m ? fmt::format("{:.2g}", 1e-3 * *line->slope_se_N_per_m) : "-");
  }
  if (!fit.identifiability_note.empty()) out << "warning: " << fit.identifiability_note << "\n";
  if (!report.unused_command.empty()) out << "note: " << report.unused_command << "\n";
  for (const auto& bound : fit.on_bounds) out << "  on a bound: " << bound << "\n";
}

nlohmann::json summary_json(const HysteresisFitResult& fit, const HysteresisFitReport& report) {
  nlohmann::json j = {{"converged", fit.converged},
                      {"termination", fit.termination},
                      {"iterations", fit.iterations},
                      {"initial_cost", fit.initial_cost},
                      {"final_cost", fit.final_cost},
                      {"residual_rms_N", fit.residual_rms_N},
                      {"residual_correlation_samples", fit.residual_correlation_samples},
                      {"nrmse_percent", fit.nrmse_percent},
                      {"explains_data", fit.explains_data},
                      {"adequacy_note", fit.adequacy_note},
                      {"on_bounds", fit.on_bounds},
                      {"start", report.start},
                      {"unidentifiable", fit.unidentifiable},
                      {"identifiability_note", fit.identifiability_note},
                      {"parameters", nlohmann::json::array()},
                      {"correlation", correlation_json(fit.correlation)},
                      {"calibration_friction_N", nlohmann::json::array()}};
  for (const auto& p : fit.parameters) {
    j["parameters"].push_back({{"name", p.name},
                               {"file", p.file},
                               {"value", p.value},
                               {"standard_error", number_or_null(p.standard_error)}});
  }
  j["record_nrmse"] = nlohmann::json::array();
  for (std::size_t r = 0; r < report.sources.size() && r < fit.record_nrmse_percent.size(); ++r) {
    j["record_nrmse"].push_back(
        {{"file", report.sources[r]}, {"nrmse_percent", fit.record_nrmse_percent[r]}});
  }
  for (std::size_t r = 0; r < report.sources.size(); ++r) {
    const auto& calibration = report.calibration[r];
    j["calibration_friction_N"].push_back(
        calibration ? nlohmann::json{{"file", report.sources[r]},
                                     {"mean", calibration->mean_N},
                                     {"standard_deviation", calibration->standard_deviation_N},
                                     {"cycles", calibration->cycles_used}}
                    : nlohmann::json{{"file", report.sources[r]}, {"mean", nullptr}});
  }
  if (const auto& line = report.friction_line) {
    j["friction_against_compression"] = {
        {"intercept_N", line->intercept_N},
        {"slope_N_per_m", line->slope_N_per_m},
        {"intercept_se_N", number_or_null(line->intercept_se_N)},
        {"slope_se_N_per_m", number_or_null(line->slope_se_N_per_m)}};
  }
  if (!report.unused_command.empty()) j["unused_command"] = report.unused_command;
  j["displacement_treatment"] = nlohmann::json::array();
  for (std::size_t r = 0; r < report.sources.size() && r < report.displacement.size(); ++r) {
    const auto& t = report.displacement[r];
    if (!t) continue;
    j["displacement_treatment"].push_back(
        {{"file", report.sources[r]},
         {"quantisation_step_m", t->step},
         {"low_pass_Hz", t->cutoff_Hz > 0.0 ? nlohmann::json(t->cutoff_Hz) : nlohmann::json()},
         {"content_up_to_Hz", t->content_up_to_Hz},
         {"velocity_noise_rms_before_m_per_s", t->velocity_noise_rms_before},
         {"velocity_noise_rms_after_m_per_s", t->velocity_noise_rms_after},
         {"low_pass_applied", static_cast<bool>(report.displacement_low_passed[r])},
         {"note", describe_displacement_treatment(*t, report.displacement_low_passed[r])}});
  }
  return j;
}

}  // namespace ridefit::fitting
