#include "ridefit/study/recording_report.h"

#include <fmt/core.h>

#include <string>
#include <vector>

namespace ridefit::study {
namespace {

std::string reactions_text(const std::vector<comfort::ComfortReaction>& reactions) {
  std::string text;
  for (const auto r : reactions) text += (text.empty() ? "" : " / ") + std::string(to_string(r));
  return text;
}

void write_channel_row(std::ostream& out, const ChannelMetrics& c) {
  std::string weighted = fmt::format("{:>4} {:>9} {:>9} {:>9} {:>6}", "-", "", "", "", "");
  std::string reading;
  if (c.weighted) {
    const auto& m = c.weighted->metrics;
    weighted = fmt::format("{:>4} {:>9.4g} {:>9.4g} {:>9.4g} {:>6.2f}",
                           comfort::to_string(c.weighted->weighting), m.weighted_rms_m_per_s2,
                           m.mtvv_m_per_s2, m.vdv_m_per_s1_75, m.crest_factor);
    reading = reactions_text(c.weighted->reactions);
    if (c.weighted->additional_methods.additional_methods_required()) {
      reading += (reading.empty() ? "" : "; ") + std::string("report MTVV and VDV");
    }
  }
  out << fmt::format("  {:<16} {:>11.4g} {:>11.4g} {:>11.4g} {:>8.3f}  {}  {}\n",
                     c.name + "[" + c.unit + "]", c.rms, c.peak, c.band_rms,
                     c.spectrum_peak.frequency_Hz, weighted, reading);
}

// Tyre load, travel and impact hardness: a line each where the channel has them.
void write_channel_details(std::ostream& out, const ChannelMetrics& c) {
  if (c.tyre_load) {
    out << fmt::format(
        "  {}: dynamic load RMS {:.4g} N = {:.3f} of the static {:.4g} N; lift-off {:.2f} % "
        "of the time\n",
        c.name, c.tyre_load->dynamic_load_rms_N, c.tyre_load->relative_dynamic_load,
        c.tyre_load->static_load_N, 100.0 * c.tyre_load->lift_off_share);
  }
  if (c.travel) {
    out << fmt::format(
        "  {}: RMS {:.4g} m, peak {:.4g} m (compression {:.4g} m, rebound {:.4g} m){}\n", c.name,
        c.travel->rms_m, c.travel->peak_m, c.travel->max_compression_m, c.travel->max_rebound_m,
        c.travel->beyond_rattle_space_share
            ? fmt::format(", beyond the rattle space {:.2f} % of the time",
                          100.0 * *c.travel->beyond_rattle_space_share)
            : "");
  }
  if (c.impact) {
    out << fmt::format(
        "  {}: impact hardness: onset {:.4g} s, peak-to-peak {:.4g}, RMS to the second "
        "negative peak {:.4g} ({})\n",
        c.name, c.impact->onset_time_s, c.impact->peak_to_peak, c.impact->rms, c.unit);
  }
}

void write_recording(std::ostream& out, const RecordingMetrics& r) {
  out << fmt::format("{}: {:.6g} s at {:.6g} Hz\n", r.source.string(), r.duration_s,
                     r.sample_rate_Hz);
  out << fmt::format("  {:<16} {:>11} {:>11} {:>11} {:>8}  {:>4} {:>9} {:>9} {:>9} {:>6}  {}\n",
                     "channel", "rms", "peak", "band_rms", "pk[Hz]", "W", "a_w", "MTVV", "VDV",
                     "CF", "comfort (ISO 2631-1 C.2.3)");
  for (const auto& c : r.channels) write_channel_row(out, c);
  for (const auto& c : r.channels) write_channel_details(out, c);
}

}  // namespace

void write_recording_report(std::ostream& out, const RecordingAnalysis& analysis,
                            const std::optional<ParameterLevels>& levels) {
  for (const auto& r : analysis.recordings) write_recording(out, r);
  if (analysis.recordings.size() > 1 && !levels) {
    out << fmt::format("PSDs averaged over {} recordings:\n", analysis.recordings.size());
    for (const auto& s : analysis.spectra) {
      out << fmt::format("  {:<16} band RMS {:.4g}, peak at {:.3f} Hz ({} segments)\n", s.name,
                         s.band_rms, s.peak.frequency_Hz, s.psd.segment_count);
    }
  }
  if (!levels || levels->correlations.empty()) return;
  out << fmt::format("Correlation with {} ({} levels):\n", levels->parameter,
                     levels->values.size());
  out << fmt::format("  {:<16} {:<24} {:>8} {:>12} {:>10}\n", "channel", "metric", "R", "slope S",
                     "increase");
  for (const auto& c : levels->correlations) {
    out << fmt::format(
        "  {:<16} {:<24} {:>8.3f} {:>12.4g} {:>10}\n", c.channel, c.metric, c.pearson_r, c.slope,
        c.relative_increase ? fmt::format("{:+.1f} %", 100.0 * *c.relative_increase) : "-");
  }
}

}  // namespace ridefit::study
