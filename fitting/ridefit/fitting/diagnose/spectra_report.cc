#include "ridefit/fitting/diagnose/spectra_report.h"

#include <fmt/core.h>

#include <vector>

#include "ridefit/fitting/diagnose/diagnosis_report.h"

namespace ridefit::fitting::diagnose {
namespace {

void write_regions(std::ostream& out, const std::vector<DisagreementRegion>& regions) {
  if (regions.empty()) {
    out << "No significant disagreement.\n\n";
    return;
  }
  out << "| channel | band [Hz] | size [dB] | measured peak [Hz] | simulated peak [Hz] | where | "
         "evidence |\n| --- | --- | --- | --- | --- | --- | --- |\n";
  for (const auto& r : regions) {
    const std::string evidence =
        r.evidence == RegionEvidence::kPeakShift
            ? fmt::format("peak shift (resolves {:.2f} Hz)", r.resolution_Hz)
        : r.evidence == RegionEvidence::kPooledBand ? std::string("pooled bins")
                                                    : std::string("single bins");
    out << fmt::format("| {} | {:.2f}–{:.2f} | {:+.2f} | {:.2f} | {:.2f} | {} | {} |\n", r.channel,
                       r.low_Hz, r.high_Hz, r.size_dB, r.measured_peak_Hz, r.simulated_peak_Hz,
                       r.above_band ? "above the road's band" : "in band", evidence);
  }
  out << "\n";
}

void write_channels(std::ostream& out, const DisagreementMap& map) {
  out << "| channel | gap [dB] | measured peak [Hz] | simulated peak [Hz] | NRMSE | residual "
         "whiteness p |\n| --- | --- | --- | --- | --- | --- |\n";
  for (const auto& c : map.channels) {
    out << fmt::format("| {} | {:.2f} | {:.2f} | {:.2f} | {:.3f} | {:.2g} |\n", c.channel, c.gap_dB,
                       c.measured_peak_Hz, c.simulated_peak_Hz, c.nrmse, c.residual_whiteness_p);
  }
  out << "\n";
}

void write_shape(std::ostream& out, const SpectralShape& shape) {
  if (shape.terms.empty()) return;
  out << "## What the model still lacks, in named shapes\n\n";
  out << fmt::format(
      "Each channel's measured-over-simulated ratio 10·log10(P_meas/P_sim) over the band, from "
      "the final model's map, regressed on named shapes (a level, a tilt per decade, a resonance "
      "or a low-pass on a grid of six frequencies per octave, the model's spectrum shifted along "
      "frequency); each kept shape, fitted on the even bins, lowers the odd bins' sum of squares "
      "by at least {:.0f} % and stands {:.3g} standard errors from 0. A suggestion for a new "
      "effect, not an effect of the library. Together they take {:.0f} % of the judged ratio's "
      "sum of squares.\n\n",
      100.0 * shape.options.min_share, shape.options.min_z, 100.0 * shape.judged_share);
  out << "| shape | channel | frequency [Hz] | what it says | coefficient | of the judged ratio "
         "|\n| --- | --- | --- | --- | --- | --- |\n";
  for (const auto& t : shape.terms) {
    out << fmt::format("| {} | {} | {} | {} | {} | {:.1f} % |\n", t.id, t.channel,
                       t.frequency_Hz > 0.0 ? fmt::format("{:.3g}", t.frequency_Hz) : "", t.words,
                       coefficient_text(t), 100.0 * t.judged_share);
  }
  out << "\n";
}

nlohmann::json shape_json(const SpectralShape& shape) {
  nlohmann::json terms = nlohmann::json::array();
  for (const auto& t : shape.terms) {
    terms.push_back({{"shape", t.id},
                     {"channel", t.channel},
                     {"frequency_Hz", t.frequency_Hz},
                     {"words", t.words},
                     {"coefficient", t.coefficient},
                     {"standard_error", t.standard_error},
                     {"unit", t.unit},
                     {"judged_share", t.judged_share}});
  }
  return {{"terms", terms}, {"judged_share", shape.judged_share}};
}

nlohmann::json regions_json(const std::vector<DisagreementRegion>& regions) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& r : regions) {
    j.push_back({{"channel", r.channel},
                 {"low_Hz", r.low_Hz},
                 {"high_Hz", r.high_Hz},
                 {"size_dB", r.size_dB},
                 {"measured_peak_Hz", r.measured_peak_Hz},
                 {"simulated_peak_Hz", r.simulated_peak_Hz},
                 {"above_band", r.above_band},
                 {"evidence", r.evidence == RegionEvidence::kPeakShift    ? "peak_shift"
                              : r.evidence == RegionEvidence::kPooledBand ? "pooled_band"
                                                                          : "bins"}});
  }
  return j;
}

nlohmann::json peaks_json(const DisagreementMap& map) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& c : map.channels) {
    j[c.channel] = {{"gap_dB", c.gap_dB},
                    {"measured_peak_Hz", c.measured_peak_Hz},
                    {"simulated_peak_Hz", c.simulated_peak_Hz},
                    {"peak_shift_significant", c.peak.significant},
                    {"peak_shift_threshold_Hz", c.peak.threshold_Hz}};
  }
  return j;
}

}  // namespace

void write_spectra_report(std::ostream& out, const std::string& model_name,
                          const DiagnosisOptions& options, const DiagnosisResult& result,
                          const DiagnosisData& data, const std::string& figure_file) {
  const PsdFitOptions& fit = options.fit;
  out << "# Diagnosis of " << model_name << "\n\n";
  out << fmt::format(
      "Data: fitted on {} ({:.1f} s), judged on {} ({:.1f} s, not used by any fit). Band "
      "{:g}–{:g} Hz, Welch segments of {:g} s. Gap = RMS over the band of 10·log10(P_sim/P_meas), "
      "over the channels.\n\n",
      data.training.source, data.training.time_s.back() - data.training.time_s.front(),
      data.held_out.source, data.held_out.time_s.back() - data.held_out.time_s.front(),
      fit.band_low_Hz, fit.band_high_Hz, fit.segment_s);
  // The floors the maps compared with: those of the held-out record.
  const NoiseFloors floors = noise_floors(data.held_out, fit);
  out << fmt::format(
      "Sensor-noise floors added to the simulated PSDs before every comparison (held-out record): "
      "body_acc {:.3g} ({}), wheel_acc {:.3g} ({}) (m/s^2)^2/Hz. Regions: single bins outside "
      "their F interval, pooled windows of bins whose mean ratio is outside its interval, or a "
      "peak further from the measured one than the two estimates resolve.\n\n",
      floors.body_psd, fit.body_noise_psd ? "given" : "estimated", floors.wheel_psd,
      fit.wheel_noise_psd ? "given" : "estimated");
  out << "**Verdict: " << result.verdict << ".**\n\n";
  out << fmt::format(
      "Gap before {:.2f} dB, after {:.2f} dB ({:.0f} % smaller).\n\n", result.gap_before,
      result.gap_after,
      result.gap_before > 0 ? 100.0 * (1.0 - result.gap_after / result.gap_before) : 0.0);
  out << "## Before: the baseline, its free parameters fitted\n\n";
  write_parameters(out, result.baseline_parameters);
  write_channels(out, result.before);
  write_regions(out, result.before.regions);
  write_rounds(out, result, "½·Σ of squared log-PSD residuals", "dB");
  if (!result.named.empty()) {
    out << "## After: the model with the named effect(s), refitted\n\n";
    write_parameters(out, result.final_parameters);
    write_channels(out, result.after);
    write_regions(out, result.after.regions);
    out << "The model with the effect added: `model.yaml` (ready for simulate, fit and "
           "optimise).\n\n";
  }
  write_shape(out, result.spectral_shape);
  write_explanations(out, result);
  write_sheet_values(out, result.sheet_values,
                     "freed in every fit with a Gaussian prior at the sheet's value (its "
                     "tolerance one standard deviation)");
  if (!figure_file.empty()) {
    out << "![measured against simulated, before and after](" << figure_file
        << ")\n\nShaded: the measured PSD's confidence interval; the disagreement regions are "
           "listed above.\n";
  }
}

nlohmann::json spectra_summary_json(const DiagnosisResult& result) {
  return {{"verdict", result.verdict},
          {"named", result.named},
          {"gap_before_dB", result.before.gap_dB},
          {"gap_after_dB", result.after.gap_dB},
          {"channels_before", peaks_json(result.before)},
          {"channels_after", peaks_json(result.after)},
          {"regions_before", regions_json(result.before.regions)},
          {"unexplained", regions_json(result.unexplained)},
          {"spectral_shape", shape_json(result.spectral_shape)},
          {"baseline_parameters", values_json(result.baseline_parameters)},
          {"final_parameters", values_json(result.final_parameters)},
          {"sheet_values", sheet_values_json(result.sheet_values)},
          {"explanations", explanations_json(result.explanations)},
          {"named_probability", reported_probability(result)},
          {"separation", result.separation},
          {"rounds", rounds_json(result, "gap_dB")}};
}

}  // namespace ridefit::fitting::diagnose
