#include "ridefit/fitting/diagnose/diagnosis.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

#include "ridefit/common/errors.h"
#include "ridefit/common/parallel_for.h"
#include "ridefit/fitting/diagnose/damper_speed.h"
#include "ridefit/model/quarter_car_parameter_table.h"
#include "ridefit/signal/correlation_time.h"
#include "ridefit/signal/welch_psd.h"

namespace ridefit::fitting::diagnose {
namespace {

PsdMeasurement slice(const PsdMeasurement& m, std::size_t begin, std::size_t end) {
  PsdMeasurement part;
  part.source = m.source;
  part.sample_rate_Hz = m.sample_rate_Hz;
  part.road = m.road;
  part.time_s.assign(m.time_s.begin() + static_cast<std::ptrdiff_t>(begin),
                     m.time_s.begin() + static_cast<std::ptrdiff_t>(end));
  auto cut = [&](const std::vector<double>& v) {
    return v.empty() ? v
                     : std::vector<double>(v.begin() + static_cast<std::ptrdiff_t>(begin),
                                           v.begin() + static_cast<std::ptrdiff_t>(end));
  };
  part.body_acc_m_per_s2 = cut(m.body_acc_m_per_s2);
  part.wheel_acc_m_per_s2 = cut(m.wheel_acc_m_per_s2);
  return part;
}

// The priors of the baseline's uncertain values (DiagnosisOptions::baseline_tolerances) that
// apply to it: a value that is off (0: no tyre damping, no friction; a rigid top mount) or that a
// locked damper does not use has no data sheet tolerance to speak of.
std::map<std::string, PsdFitOptions::GaussianPrior> sheet_priors(
    const model::QuarterCar& car, const std::map<std::string, double>& tolerances) {
  namespace rows = model::quarter_car_rows;
  std::map<std::string, PsdFitOptions::GaussianPrior> priors;
  for (const auto& [name, share] : tolerances) {
    const double v = parameter_value(car, name);
    if (!(v > 0.0) || !std::isfinite(v)) continue;
    if (name == rows::top_mount_stiffness_N_per_m.key_string() && v >= 1e9) continue;
    const bool damper_path =
        name == rows::damping_Ns_per_m.key_string() || name == rows::coulomb_force_N.key_string();
    if (damper_path && car.damper_state() == model::DamperState::kStick) continue;
    if (name == rows::coulomb_force_N.key_string() &&
        car.damper_state() != model::DamperState::kStickSlip) {
      continue;
    }
    priors[name] = {v, share * v};
  }
  return priors;
}

std::vector<std::string> default_free(const model::QuarterCar& car) {
  // A locked damper has no damping to fit; the body's mass (payload) is the usual unknown, and
  // it cannot stand in for a missing effect at the wheel mode as a stiffness would.
  namespace rows = model::quarter_car_rows;
  if (car.damper_state() == model::DamperState::kStick) return {rows::sprung_mass_kg.key_string()};
  std::vector<std::string> free{rows::damping_Ns_per_m.key_string()};
  if (car.damper_state() == model::DamperState::kStickSlip &&
      car.parameters().coulomb_force_N > 0) {
    free.push_back(rows::coulomb_force_N.key_string());
  }
  return free;
}

// The map of `m` against a simulation of `car`, the simulated PSDs as its fits show them: through
// the car's accelerometer chain (gains, low-pass) and with the record's noise floors added (given,
// or estimated from `m`).
DisagreementMap map_of(const PsdMeasurement& m, const model::QuarterCar& car,
                       const std::vector<double>& body, const std::vector<double>& wheel,
                       const PsdFitOptions& fit_options, const DisagreementOptions& options) {
  const NoiseFloors noise = noise_floors(m, fit_options);
  const model::AccelerationSensors<double> sensors = car.parameters().sensors;
  std::vector<ChannelPair> channels;
  if (!m.body_acc_m_per_s2.empty()) {
    channels.push_back({"body_acc", m.body_acc_m_per_s2, body, noise.body_psd,
                        [sensors](double f) { return sensors.body_power_gain(f); }});
  }
  if (!m.wheel_acc_m_per_s2.empty()) {
    channels.push_back({"wheel_acc", m.wheel_acc_m_per_s2, wheel, noise.wheel_psd,
                        [sensors](double f) { return sensors.wheel_power_gain(f); }});
  }
  return map_disagreement(channels, m.sample_rate_Hz, options);
}

ScoredFit fit_and_score(const DiagnosisModel& start, const std::vector<std::string>& free,
                        const ParameterBounds& bounds, const DiagnosisData& data,
                        const PsdFitOptions& fit_options, const DisagreementOptions& map_options) {
  ScoredFit s;
  PsdFitOptions options = fit_options;
  options.free = free;
  options.bounds = bounds;
  const PsdFitResult fit = fit_psd(data.training, start.car, options);
  if (!std::isfinite(fit.final_cost)) {
    s.failure = "the fit found no model it could simulate";
    return s;
  }
  s.model = start;
  s.model.car = model::QuarterCar(start.car.damper_state(), fit.fitted);
  for (std::size_t i = 0; i < fit.names.size(); ++i) {
    s.values.push_back({fit.names[i], fit.values[i], fit.standard_errors[i]});
  }
  s.training_cost = fit.final_cost;
  s.iterations = fit.iterations;
  s.unidentifiable = fit.unidentifiable;
  s.training_residuals =
      fit.frequency_Hz.size() * ((data.training.body_acc_m_per_s2.empty() ? 0 : 1) +
                                 (data.training.wheel_acc_m_per_s2.empty() ? 0 : 1));
  const auto held_out = psd_mismatch(data.held_out, s.model.car, options);
  if (!held_out) {
    s.failure = "the fitted model cannot be simulated on the held-out record";
    return s;
  }
  s.held_out_cost = held_out->cost;
  s.held_out_residuals = held_out->residuals;
  double correlated = 0.0;
  for (const auto& r : held_out->channel_residuals) {
    correlated += signal::correlation_time_samples(r) * static_cast<double>(r.size());
  }
  s.correlation_time =
      correlated / static_cast<double>(std::max<std::size_t>(held_out->residuals, 1));
  s.held_out_signals = {held_out->body_acc_m_per_s2, held_out->wheel_acc_m_per_s2};
  s.held_out_gap = map_of(data.held_out, s.model.car, s.held_out_signals[0], s.held_out_signals[1],
                          options, map_options)
                       .gap_dB;
  return s;
}

std::string describe(const DisagreementRegion& r) {
  if (r.evidence == RegionEvidence::kPeakShift) {
    return fmt::format(
        "{} peak at {:.1f} Hz measured, {:.1f} Hz simulated: a shift of {:.1f} Hz, beyond the "
        "{:.1f} Hz the two estimates resolve",
        r.channel, r.measured_peak_Hz, r.simulated_peak_Hz,
        std::abs(r.measured_peak_Hz - r.simulated_peak_Hz), r.resolution_Hz);
  }
  return fmt::format(
      "{} {:.1f}–{:.1f} Hz: simulated {:+.1f} dB against measured (peak {:.1f} Hz "
      "measured, {:.1f} Hz simulated){}",
      r.channel, r.low_Hz, r.high_Hz, r.size_dB, r.measured_peak_Hz, r.simulated_peak_Hz,
      r.above_band ? ", above the road's band" : "");
}

// Where the predictions of two explanations for the held-out record differ most: the channel and
// frequency (within the fitted band) of the largest level difference between their spectra.
std::string spectra_separation(const Explanation& a, const Explanation& b, double sample_rate_Hz,
                               const DisagreementOptions& options) {
  static const char* const kChannels[] = {"body_acc", "wheel_acc"};
  signal::WelchOptions welch;
  welch.segment_length_s = options.segment_s;
  double largest = 0.0, at_Hz = 0.0;
  std::string channel;
  for (std::size_t c = 0; c < 2; ++c) {
    if (c >= a.held_out_signals.size() || c >= b.held_out_signals.size() ||
        a.held_out_signals[c].size() < 4 || b.held_out_signals[c].size() < 4) {
      continue;
    }
    const auto pa = signal::welch_psd(a.held_out_signals[c], sample_rate_Hz, welch);
    const auto pb = signal::welch_psd(b.held_out_signals[c], sample_rate_Hz, welch);
    for (std::size_t k = 0; k < pa.psd.size() && k < pb.psd.size(); ++k) {
      const double f = pa.frequency_Hz[k];
      if (f < options.band_low_Hz || f > options.band_high_Hz) continue;
      if (!(pa.psd[k] > 0.0) || !(pb.psd[k] > 0.0)) continue;
      const double dB = 10.0 * std::log10(pa.psd[k] / pb.psd[k]);
      if (std::abs(dB) > std::abs(largest)) {
        largest = dB;
        at_Hz = f;
        channel = kChannels[c];
      }
    }
  }
  if (channel.empty()) return "";
  return fmt::format("their predictions differ most in {} near {:.1f} Hz ({:+.1f} dB)", channel,
                     at_Hz, largest);
}

}  // namespace

DiagnosisData split_record(const PsdMeasurement& record) {
  const std::size_t half = record.time_s.size() / 2;
  return {slice(record, 0, half), slice(record, half, record.time_s.size())};
}

bool reports_outside_library(const DiagnosisResult& result) {
  const bool unexplained = !result.unexplained.empty() || !result.unexplained_loops.empty() ||
                           result.unexplained_shape_share > 0.0;
  return result.named.empty() && unexplained &&
         std::any_of(result.explanations.begin(), result.explanations.end(),
                     [](const Explanation& e) { return e.outside_library && e.effects.empty(); });
}

double reported_probability(const DiagnosisResult& result) {
  return reports_outside_library(result) ? outside_probability(result.explanations, {})
                                         : named_probability(result.explanations, result.named);
}

std::string verdict_evidence(const DiagnosisResult& result) {
  return reports_outside_library(result)
             ? outside_evidence_words(result.explanations)
             : evidence_words(result.explanations, result.named, result.separation);
}

DiagnosisResult result_of(const Selection& selection, DataKind kind) {
  DiagnosisResult result;
  result.kind = kind;
  result.baseline = selection.baseline.model;
  result.baseline_parameters = selection.baseline.values;
  result.baseline_held_out_cost = selection.baseline.held_out_cost;
  result.rounds = selection.rounds;
  result.named = selection.named;
  result.not_identifiable = selection.not_identifiable;
  result.final_model = selection.final_fit.model;
  result.final_parameters = selection.final_fit.values;
  result.explanations = selection.explanations;
  weigh_explanations(result.explanations);
  return result;
}

DiagnosisResult diagnose(const DiagnosisModel& baseline, const DiagnosisData& data,
                         const DiagnosisOptions& options,
                         const std::function<void(const std::string&)>& progress) {
  options.validate();
  auto say = [&](const std::string& line) {
    if (progress) progress(line);
  };
  DisagreementOptions map_options = options.map;
  map_options.band_low_Hz = options.fit.band_low_Hz;
  map_options.band_high_Hz = options.fit.band_high_Hz;
  auto with_tolerance = [&](double relative_tolerance) {
    PsdFitOptions o = options.fit;
    o.relative_tolerance = relative_tolerance;
    return o;
  };
  PsdFitOptions screening = with_tolerance(options.screening_relative_tolerance);
  // An effect the data cannot see wanders along a flat cost; screening stops it sooner.
  screening.max_iterations = std::min(screening.max_iterations, options.screening_iterations);
  // The reported fits (baseline and with the named effects) take the tight tolerance, from the
  // screening fit's optimum: what the report, the map and model.yaml show.
  const PsdFitOptions final_fit = with_tolerance(options.final_relative_tolerance);
  // The data sheet's uncertain values: freed in every fit, each with its prior at the sheet's
  // value.
  std::vector<std::string> baseline_free =
      options.baseline_free.empty() ? default_free(baseline.car) : options.baseline_free;
  const auto priors = sheet_priors(baseline.car, options.baseline_tolerances);
  for (const auto& [name, prior] : priors) {
    if (std::find(baseline_free.begin(), baseline_free.end(), name) == baseline_free.end()) {
      baseline_free.push_back(name);
    }
  }
  const FitAndScore fit = [&](const DiagnosisModel& start, const std::vector<std::string>& free,
                              const ParameterBounds& bounds, FitPurpose purpose) {
    PsdFitOptions settings = purpose == FitPurpose::kReported ? final_fit : screening;
    if (purpose == FitPurpose::kProbe) settings.max_iterations = 0;
    for (const auto& [name, prior] : priors) {  // an effect may have taken the parameter over
      if (std::find(free.begin(), free.end(), name) != free.end()) settings.priors[name] = prior;
    }
    return fit_and_score(start, free, bounds, data, settings, map_options);
  };
  SelectionOptions selection_options = options.selection;
  selection_options.gap_unit = "dB";
  selection_options.refine = final_fit.relative_tolerance != screening.relative_tolerance;
  DiagnosisModel start = baseline;
  start.kind = DataKind::kVehicleSpectra;
  start.has_command = data.training.road != nullptr && data.training.road->has_command();
  start.damper_speed_rms_m_per_s = damper_speed_rms_m_per_s(baseline.car, data.training);
  const Selection selection =
      select_effects(start, baseline_free, options.fit.bounds, effects_to_try(options.effects), fit,
                     selection_options, say);

  DiagnosisResult result = result_of(selection, DataKind::kVehicleSpectra);
  for (const auto& [name, prior] : priors) {
    DiagnosisResult::SheetValue v{name, prior.mean, prior.sd / prior.mean,
                                  parameter_value(result.final_model.car, name), std::nullopt};
    for (const auto& p : result.final_parameters) {
      if (p.name == name) v.standard_error = p.standard_error;
    }
    result.sheet_values.push_back(v);
  }
  const ScoredFit& before = selection.baseline;
  const ScoredFit& after = selection.final_fit;
  result.before = map_of(data.held_out, before.model.car, before.held_out_signals[0],
                         before.held_out_signals[1], final_fit, map_options);
  result.before_body = before.held_out_signals[0];
  result.before_wheel = before.held_out_signals[1];
  result.after = map_of(data.held_out, after.model.car, after.held_out_signals[0],
                        after.held_out_signals[1], final_fit, map_options);
  result.after_body = after.held_out_signals[0];
  result.after_wheel = after.held_out_signals[1];
  result.gap_before = result.before.gap_dB;
  result.gap_after = result.after.gap_dB;
  // A narrow region on the flank of a sharp mode is the PSD estimate's bias there (the
  // interval does not cover bias), not a missing effect: it must also be wide enough.
  // Above the road's band the measured side is sensor noise as much as response, and the
  // simulation's accuracy falls with the step: those regions stay in the map as evidence but do
  // not by themselves make a disagreement "unexplained".
  // A peak shift beyond what the estimates resolve counts whatever its size in dB: a mode in
  // the wrong place that no effect moved.
  for (const auto& region : result.after.regions) {
    const bool shift = region.evidence == RegionEvidence::kPeakShift;
    if (!region.above_band &&
        (shift ||
         (std::abs(region.size_dB) >= options.unexplained_dB &&
          region.high_Hz - region.low_Hz >= options.unexplained_width_Hz) ||
         (std::abs(region.size_dB) >= options.unexplained_wide_dB &&
          region.high_Hz - region.low_Hz >= options.unexplained_wide_width_Hz))) {
      result.unexplained.push_back(region);
    }
  }
  std::vector<std::string> unexplained;
  for (const auto& region : result.unexplained) unexplained.push_back(describe(region));
  if (!result.unexplained.empty()) {
    result.spectral_shape =
        spectral_shape(result.after, map_options.band_low_Hz, map_options.band_high_Hz);
    // The shape is fitted on the even bins of the map's ratio and judged on the odd ones, in dB,
    // not on the fit's residuals: its judged share is taken as the share of the named
    // explanation's judging cost it would remove (optimistic, as spectral_shape.h says; the
    // terms' parameters and the choice outside the library pay for it in the BIC).
    if (const Explanation* named = find_explanation(result.explanations, result.named)) {
      add_outside_library(result.explanations, result.named,
                          result.spectral_shape.judged_share * named->held_out_cost,
                          static_cast<int>(result.spectral_shape.terms.size()));
    }
  }
  if (const Explanation* chosen = find_explanation(result.explanations, result.named);
      chosen && chosen->probability < kConfidentProbability) {
    if (const Explanation* rival = strongest_rival(result.explanations, result.named)) {
      result.separation =
          spectra_separation(*chosen, *rival, data.held_out.sample_rate_Hz, map_options);
    }
  }
  result.verdict =
      verdict_of(result.named, unexplained, result.not_identifiable, verdict_evidence(result));
  if (!result.spectral_shape.terms.empty()) {
    result.verdict += fmt::format(
        "; the ratio of the measured to the simulated spectra looks like {} (a suggestion for a "
        "new effect, not one of the library)",
        diagnose::describe(result.spectral_shape));
  }
  return result;
}

}  // namespace ridefit::fitting::diagnose
