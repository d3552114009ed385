#include "ridefit/fitting/diagnose/loop_report.h"

#include <fmt/core.h>

#include <vector>

#include "ridefit/fitting/diagnose/diagnosis_report.h"

namespace ridefit::fitting::diagnose {
namespace {

std::string region_text(const LoopRegion& r) {
  const bool velocity = r.quantity == "velocity";
  return fmt::format("| {} | {} | {:.3g} … {:.3g} {} | {:+.2f} | {:+.1f} % |\n", r.record,
                     r.quantity, 1e3 * r.low, 1e3 * r.high, velocity ? "mm/s" : "mm",
                     r.mean_residual_N, 100.0 * r.share);
}

void write_map(std::ostream& out, const LoopDisagreementMap& map) {
  out << "| record | NRMSE [%] | residual RMS [N] | residual whiteness p | amplitude dependence "
         "|\n| --- | --- | --- | --- | --- |\n";
  for (const auto& r : map.records) {
    out << fmt::format("| {} | {:.2f} | {:.3g} | {:.2g} | {:.2f} |\n", r.record, r.nrmse_percent,
                       r.residual_rms_N, r.residual_whiteness_p, r.amplitude_dependence);
  }
  out << "\n";
  if (map.regions.empty()) {
    out << "No significant loop-shape disagreement.\n\n";
    return;
  }
  out << "| record | along | range | simulated − measured [N] | of the force's RMS |\n| --- | "
         "--- | --- | --- | --- |\n";
  for (const auto& r : map.regions) out << region_text(r);
  out << "\n";
}

std::string names(const std::vector<HysteresisRecord>& records) {
  std::string text;
  for (const auto& record : records) text += (text.empty() ? "" : ", ") + record.source;
  return text;
}

nlohmann::json regions_json(const std::vector<LoopRegion>& regions) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& r : regions) {
    j.push_back({{"record", r.record},
                 {"quantity", r.quantity},
                 {"low", r.low},
                 {"high", r.high},
                 {"mean_residual_N", r.mean_residual_N},
                 {"share", r.share}});
  }
  return j;
}

void write_shape(std::ostream& out, const ResidualShape& shape) {
  if (shape.terms.empty()) return;
  out << "## What the model still lacks, in named terms\n\n";
  out << fmt::format(
      "The force the final model lacks (measured − simulated) regressed on terms of travel about "
      "mid-stroke ({:.4g} mm, half stroke {:.3g} mm), velocity, acceleration and the model's own "
      "force; each kept term, fitted on the training records, lowers the judging records' residual "
      "by at least {:.0f} % and stands {:.3g} standard errors from 0. A suggestion for a new "
      "effect, not an effect of the library. Together the terms take {:.0f} % of the judged "
      "residual's sum of squares.\n\n",
      1e3 * shape.travel_centre_m, 1e3 * shape.half_stroke_m, 100.0 * shape.options.min_share,
      shape.options.min_z, 100.0 * shape.judged_share);
  out << "| term | what it says | coefficient | of the judged residual |\n| --- | --- | --- | "
         "--- |\n";
  for (const auto& t : shape.terms) {
    out << fmt::format("| {} | {} | {} | {:.1f} % |\n", t.id, t.words, coefficient_text(t),
                       100.0 * t.judged_share);
  }
  out << "\n";
}

nlohmann::json shape_json(const ResidualShape& shape) {
  nlohmann::json terms = nlohmann::json::array();
  for (const auto& t : shape.terms) {
    terms.push_back({{"term", t.id},
                     {"words", t.words},
                     {"coefficient", t.coefficient},
                     {"standard_error", t.standard_error},
                     {"unit", t.unit},
                     {"judged_share", t.judged_share}});
  }
  return {{"terms", terms},
          {"judged_share", shape.judged_share},
          {"travel_centre_m", shape.travel_centre_m},
          {"half_stroke_m", shape.half_stroke_m}};
}

}  // namespace

void write_loop_report(std::ostream& out, const std::string& model_name,
                       const DiagnosisResult& result, const LoopDiagnosisData& data,
                       const std::string& figure_file) {
  out << "# Diagnosis of " << model_name << " on the strut rig\n\n";
  out << fmt::format(
      "Data: fitted on {}; judged on {} (not used by any fit). Gap = NRMSE of the force over "
      "the judging records: 100·√(Σ(F_sim − F_meas)² / Σ(F_meas − mean)²). Regions: runs of "
      "velocity or displacement bins where the mean force residual is significant (3 standard "
      "errors, counting the residual's correlation in time) and at least 2 % of the force's "
      "RMS.\n\n",
      names(data.training), names(data.held_out));
  out << "**Verdict: " << result.verdict << ".**\n\n";
  out << fmt::format(
      "Gap before {:.2f} %, after {:.2f} % ({:.0f} % smaller).\n\n", result.gap_before,
      result.gap_after,
      result.gap_before > 0 ? 100.0 * (1.0 - result.gap_after / result.gap_before) : 0.0);
  out << "## Before: the baseline, its free parameters fitted\n\n";
  write_parameters(out, result.baseline_parameters);
  write_map(out, result.loops_before);
  write_rounds(out, result, "½·Σ of squared force residuals", "NRMSE %");
  if (!result.named.empty()) {
    out << "## After: the model with the named effect(s), refitted\n\n";
    write_parameters(out, result.final_parameters);
    write_map(out, result.loops_after);
    out << "The model with the effect added: `model.yaml` (its model keys; the rig-only gas "
           "force and load-cell offset are in its header comment).\n\n";
  }
  write_shape(out, result.residual_shape);
  write_explanations(out, result);
  write_sheet_values(out, result.sheet_values,
                     "freed in every fit within three of its tolerances of the sheet's value");
  if (!figure_file.empty()) {
    out << "![measured against simulated loops, before and after](" << figure_file << ")\n";
  }
}

nlohmann::json loop_summary_json(const DiagnosisResult& result) {
  return {{"data", "strut_loops"},
          {"verdict", result.verdict},
          {"named", result.named},
          {"gap_before_nrmse_percent", result.gap_before},
          {"gap_after_nrmse_percent", result.gap_after},
          {"regions_before", regions_json(result.loops_before.regions)},
          {"unexplained", regions_json(result.unexplained_loops)},
          {"unexplained_shape_share", result.unexplained_shape_share},
          {"residual_shape", shape_json(result.residual_shape)},
          {"baseline_parameters", values_json(result.baseline_parameters)},
          {"final_parameters", values_json(result.final_parameters)},
          {"sheet_values", sheet_values_json(result.sheet_values)},
          {"explanations", explanations_json(result.explanations)},
          {"named_probability", reported_probability(result)},
          {"separation", result.separation},
          {"rounds", rounds_json(result, "gap_nrmse_percent")}};
}

}  // namespace ridefit::fitting::diagnose
