// ridefit diagnose MODEL.yaml MEAS.csv... [--excitation EXC.yaml]... [--effects all|id,...]
//                  [-o DIR] [--free k,...] [--band LOW,HIGH] [--segment S] [--threads N] [--json]
// Finds where the model and the measurement disagree, which effect of the library explains it,
// adds it, and shows the gap before and after: vehicle spectra here (fitting/diagnose/
// diagnosis.h), strut rig loops in diagnose_loops_command.cc (loop_diagnosis.h).
#include <fmt/core.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "command_options.h"
#include "diagnose_common.h"
#include "ridefit/common/errors.h"
#include "ridefit/fitting/diagnose/diagnosis.h"
#include "ridefit/io/atomic_file.h"
#include "ridefit/io/gnuplot_figure.h"
#include "ridefit/io/model_values_file.h"
#include "ridefit/io/output_paths.h"
#include "ridefit/io/quarter_car_file.h"
#include "ridefit/io/staged_folder.h"
#include "ridefit/model/quarter_car_parameter_table.h"
#include "ridefit/road/road_input.h"
#include "subcommands.h"

namespace ridefit::cli {

std::vector<std::string> effect_ids(const std::string& text) {
  if (text == "all") return {};
  std::vector<std::string> ids;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string id = text.substr(start, comma - start);
    if (id.empty()) throw InputError(fmt::format("--effects '{}': an empty id", text));
    try {
      dx::find_effect(id);
    } catch (const InputError& e) {
      throw InputError(fmt::format("--effects: {}", e.what()));
    }
    ids.push_back(id);
    start = comma + 1;
  }
  return ids;
}

std::string se_text(const std::optional<double>& se) {
  return se ? fmt::format("{:.3g}", *se) : std::string("—");
}

void write_parameters(std::ostream& out, const std::vector<dx::FittedValue>& values) {
  out << "| parameter | value | standard error |\n| --- | --- | --- |\n";
  for (const auto& p : values) {
    out << fmt::format("| {} | {:.6g} | {} |\n", p.name, p.value, se_text(p.standard_error));
  }
  out << "\n";
}

void write_rounds(std::ostream& out, const dx::DiagnosisResult& r, const std::string& cost_words,
                  const std::string& gap_unit) {
  for (std::size_t k = 0; k < r.rounds.size(); ++k) {
    out << fmt::format("## Round {}: effects tried\n\n", k + 1);
    out << fmt::format(
        "Held-out improvement: how much the held-out cost ({}) falls; ΔBIC on the training data "
        "(negative is better; extra parameters pay ln n each).\n\n| rank | effect | free | "
        "held-out improvement | ΔBIC | gap [{}] | significant |\n| --- | --- | --- | --- | --- | "
        "--- | --- |\n",
        cost_words, gap_unit);
    int rank = 0;
    for (const auto& t : r.rounds[k].trials) {
      if (!t.skipped.empty() || !t.failed.empty()) continue;
      out << fmt::format("| {} | `{}` | {} | {:+.1f} % | {:+.1f} | {:.2f} | {} |\n", ++rank, t.id,
                         t.free_parameters, 100.0 * t.held_out_improvement, t.bic_change,
                         t.held_out_gap, t.significant ? "yes" : "no");
    }
    out << "\n";
    for (const auto& t : r.rounds[k].trials) {
      if (!t.failed.empty()) out << fmt::format("- `{}` failed: {}\n", t.id, t.failed);
      if (!t.skipped.empty()) out << fmt::format("- `{}` skipped: {}\n", t.id, t.skipped);
    }
    out << "\n"
        << (r.rounds[k].accepted.empty()
                ? std::string("No effect is significant.")
                : fmt::format("Accepted: `{}` — {}.", r.rounds[k].accepted,
                              dx::find_effect(r.rounds[k].accepted).description()))
        << "\n\n";
  }
}

nlohmann::json values_json(const std::vector<dx::FittedValue>& values) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& v : values) {
    j.push_back({{"name", v.name},
                 {"value", v.value},
                 {"standard_error",
                  v.standard_error ? nlohmann::json(*v.standard_error) : nlohmann::json()}});
  }
  return j;
}

nlohmann::json rounds_json(const dx::DiagnosisResult& result, const std::string& gap_key) {
  nlohmann::json rounds = nlohmann::json::array();
  for (const auto& round : result.rounds) {
    nlohmann::json ranked = nlohmann::json::array();
    for (const auto& t : round.trials) {
      nlohmann::json e = {{"id", t.id}};
      if (!t.skipped.empty()) {
        e["skipped"] = t.skipped;
      } else if (!t.failed.empty()) {
        e["failed"] = t.failed;
      } else {
        e["held_out_improvement"] = t.held_out_improvement;
        e["bic_change"] = t.bic_change;
        e["held_out_cost"] = t.held_out_cost;
        e[gap_key] = t.held_out_gap;
        e["significant"] = t.significant;
        e["parameters"] = values_json(t.parameters);
      }
      ranked.push_back(e);
    }
    rounds.push_back({{"accepted", round.accepted}, {"effects", ranked}});
  }
  return rounds;
}

void require_finite_report(const std::string& text, const std::filesystem::path& path) {
  static const std::regex non_finite(R"((^|[^A-Za-z_/.])[-+]?(nan|inf)([^A-Za-z_/.]|$))",
                                     std::regex::icase);
  std::smatch match;
  if (std::regex_search(text, match, non_finite)) {
    const auto at = static_cast<std::size_t>(match.position(0));
    const std::size_t line_start =
        text.rfind('\n', at) == std::string::npos ? 0 : text.rfind('\n', at) + 1;
    const std::size_t line_end = std::min(text.find('\n', at), text.size());
    throw RunError(fmt::format(
        "{} would show a value that is not a number, in: {}; nothing was written (the data may "
        "be degenerate: check the records)",
        path.string(), text.substr(line_start, line_end - line_start)));
  }
}

std::vector<std::string> check_output_folder(const DiagnoseFlags& flags,
                                             const std::string& figure) {
  for (std::size_t i = 0; i < flags.records.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (io::same_file(flags.records[i], flags.records[j])) {
        throw InputError(fmt::format(
            "{} is given twice; a record judging the fit must not be the one fitted (give "
            "another record, or one record to be split in halves)",
            flags.records[i]));
      }
    }
  }
  std::vector<std::filesystem::path> inputs{flags.model_file};
  for (const auto& f : flags.records) inputs.push_back(f);
  for (const auto& f : flags.excitations) inputs.push_back(f);
  std::vector<std::string> files = {"report.md", "model.yaml"};
  if (io::gnuplot_available()) files.push_back(figure);
  io::RunOutputs outputs(inputs);
  outputs.add_folder(flags.output_dir, "-o", files, flags.force);
  return files;
}

bool is_rig_record(const std::filesystem::path& csv_file) {
  std::ifstream in(csv_file);
  std::string header;
  std::getline(in, header);
  return header.find("displacement") != std::string::npos;
}

namespace {

// The excitation must cover the record and not be much longer (a road for another record).
void check_excitation_length(const fitting::PsdMeasurement& m, const std::string& excitation) {
  const double record_s = m.time_s.back() - m.time_s.front();
  const double excitation_s = m.road->duration_s();
  if (excitation_s > record_s + std::max(1.0, 0.02 * record_s)) {
    throw InputError(fmt::format(
        "{}: the excitation lasts {:.6g} s but the record {} only {:.6g} s; give the excitation "
        "that drove this record",
        excitation, excitation_s, m.source, record_s));
  }
}

std::string value_text(double v) { return fmt::format("{:.6g}", v); }

std::string damper_state_name(model::DamperState state) {
  switch (state) {
    case model::DamperState::kSlip:
      return "slip";
    case model::DamperState::kStick:
      return "stick";
    default:
      return "stick_slip";
  }
}

// The keys the diagnosis changed or fitted, as model-file values.
std::vector<std::pair<std::string, std::string>> changed_keys(const model::QuarterCar& before,
                                                              const model::QuarterCar& after) {
  std::vector<std::pair<std::string, std::string>> values;
  if (before.damper_state() != after.damper_state()) {
    values.emplace_back("damper_state", damper_state_name(after.damper_state()));
  }
  for (std::size_t i = 0; i < model::kQuarterCarParameters.size(); ++i) {
    const double a = model::quarter_car_parameter(before.parameters(), i);
    const double b = model::quarter_car_parameter(after.parameters(), i);
    if (a != b)
      values.emplace_back(std::string(model::kQuarterCarParameters[i].key), value_text(b));
  }
  if (before.parameters().tyre_lift_off != after.parameters().tyre_lift_off) {
    values.emplace_back("tyre_lift_off", after.parameters().tyre_lift_off ? "true" : "false");
  }
  if (before.parameters().sensors.acc_sensor_order != after.parameters().sensors.acc_sensor_order) {
    values.emplace_back("acc_sensor_order",
                        std::to_string(after.parameters().sensors.acc_sensor_order));
  }
  return values;
}

void write_regions(std::ostream& out, const std::vector<dx::DisagreementRegion>& regions) {
  if (regions.empty()) {
    out << "No significant disagreement.\n\n";
    return;
  }
  out << "| channel | band [Hz] | size [dB] | measured peak [Hz] | simulated peak [Hz] | where | "
         "evidence |\n| --- | --- | --- | --- | --- | --- | --- |\n";
  for (const auto& r : regions) {
    const std::string evidence =
        r.evidence == dx::RegionEvidence::kPeakShift
            ? fmt::format("peak shift (resolves {:.2f} Hz)", r.resolution_Hz)
        : r.evidence == dx::RegionEvidence::kPooledBand ? std::string("pooled bins")
                                                        : std::string("single bins");
    out << fmt::format("| {} | {:.2f}–{:.2f} | {:+.2f} | {:.2f} | {:.2f} | {} | {} |\n", r.channel,
                       r.low_Hz, r.high_Hz, r.size_dB, r.measured_peak_Hz, r.simulated_peak_Hz,
                       r.above_band ? "above the road's band" : "in band", evidence);
  }
  out << "\n";
}

void write_channels(std::ostream& out, const dx::DisagreementMap& map) {
  out << "| channel | gap [dB] | measured peak [Hz] | simulated peak [Hz] | NRMSE | residual "
         "whiteness p |\n| --- | --- | --- | --- | --- | --- |\n";
  for (const auto& c : map.channels) {
    out << fmt::format("| {} | {:.2f} | {:.2f} | {:.2f} | {:.3f} | {:.2g} |\n", c.channel, c.gap_dB,
                       c.measured_peak_Hz, c.simulated_peak_Hz, c.nrmse, c.residual_whiteness_p);
  }
  out << "\n";
}

void write_report(std::ostream& out, const DiagnoseFlags& flags, const dx::DiagnosisResult& r,
                  const dx::DiagnosisData& data, bool figure) {
  out << "# Diagnosis of " << flags.model_file << "\n\n";
  out << fmt::format(
      "Data: fitted on {} ({:.1f} s), judged on {} ({:.1f} s, not used by any fit). Band "
      "{:g}–{:g} Hz, Welch segments of {:g} s. Gap = RMS over the band of 10·log10(P_sim/P_meas), "
      "over the channels.\n\n",
      data.training.source, data.training.time_s.back() - data.training.time_s.front(),
      data.held_out.source, data.held_out.time_s.back() - data.held_out.time_s.front(),
      flags.band_Hz[0], flags.band_Hz[1], flags.segment_s);
  fitting::PsdFitOptions floors_options;
  floors_options.band_high_Hz = flags.band_Hz[1];
  floors_options.body_noise_psd = noise_psd_of(flags.body_noise_psd);
  floors_options.wheel_noise_psd = noise_psd_of(flags.wheel_noise_psd);
  const fitting::NoiseFloors floors = fitting::noise_floors(data.held_out, floors_options);
  out << fmt::format(
      "Sensor-noise floors added to the simulated PSDs before every comparison (held-out record): "
      "body_acc {:.3g} ({}), wheel_acc {:.3g} ({}) (m/s^2)^2/Hz. Regions: single bins outside "
      "their F interval, pooled windows of bins whose mean ratio is outside its interval, or a "
      "peak further from the measured one than the two estimates resolve.\n\n",
      floors.body_psd, std::isnan(flags.body_noise_psd) ? "estimated" : "given", floors.wheel_psd,
      std::isnan(flags.wheel_noise_psd) ? "estimated" : "given");
  out << "**Verdict: " << r.verdict << ".**\n\n";
  out << fmt::format("Gap before {:.2f} dB, after {:.2f} dB ({:.0f} % smaller).\n\n", r.gap_before,
                     r.gap_after,
                     r.gap_before > 0 ? 100.0 * (1.0 - r.gap_after / r.gap_before) : 0.0);
  out << "## Before: the baseline, its free parameters fitted\n\n";
  write_parameters(out, r.baseline_parameters);
  write_channels(out, r.before);
  write_regions(out, r.before.regions);
  write_rounds(out, r, "½·Σ of squared log-PSD residuals", "dB");
  if (!r.named.empty()) {
    out << "## After: the model with the named effect(s), refitted\n\n";
    write_parameters(out, r.final_parameters);
    write_channels(out, r.after);
    write_regions(out, r.after.regions);
    out << "The model with the effect added: `model.yaml` (ready for simulate, fit and "
           "optimise).\n\n";
  }
  if (figure) {
    out << "![measured against simulated, before and after](spectra.png)\n\nShaded: the "
           "measured PSD's confidence interval; the disagreement regions are listed above.\n";
  }
}

nlohmann::json regions_json(const std::vector<dx::DisagreementRegion>& regions) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& r : regions) {
    j.push_back({{"channel", r.channel},
                 {"low_Hz", r.low_Hz},
                 {"high_Hz", r.high_Hz},
                 {"size_dB", r.size_dB},
                 {"measured_peak_Hz", r.measured_peak_Hz},
                 {"simulated_peak_Hz", r.simulated_peak_Hz},
                 {"above_band", r.above_band},
                 {"evidence", r.evidence == dx::RegionEvidence::kPeakShift    ? "peak_shift"
                              : r.evidence == dx::RegionEvidence::kPooledBand ? "pooled_band"
                                                                              : "bins"}});
  }
  return j;
}

nlohmann::json peaks_json(const dx::DisagreementMap& map) {
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

void draw_spectra(const dx::DiagnosisResult& r, const std::filesystem::path& path) {
  io::Figure figure;
  figure.title = "measured against simulated (held-out record): before and after";
  figure.columns = 2;
  auto add = [&](const dx::DisagreementMap& map, const std::string& when) {
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
  };
  // Row by row: before | after per channel.
  for (std::size_t i = 0; i < r.before.channels.size(); ++i) {
    dx::DisagreementMap one_before = r.before, one_after = r.after;
    one_before.channels = {r.before.channels[i]};
    one_after.channels = {r.after.channels[i]};
    add(one_before, "before");
    add(one_after, "after");
  }
  io::draw_figure(figure, path);
}

void run(const DiagnoseFlags& flags) {
  std::size_t rig_records = 0;
  for (const auto& file : flags.records) rig_records += is_rig_record(file) ? 1 : 0;
  if (rig_records > 0 && rig_records == flags.records.size()) {
    run_diagnose_loops(flags);
    return;
  }
  if (rig_records > 0) {
    throw InputError(
        "the records mix strut rig tests (time, displacement, force) with vehicle measurements "
        "(time, road or --excitation, body_acc and/or wheel_acc); diagnose one kind at a time");
  }
  if (flags.records.empty() || flags.records.size() > 2) {
    throw InputError(
        "give one record (its first half is fitted, its second half judges) or two (the first "
        "is fitted, the second judges)");
  }
  if (flags.excitations.size() > 1 && flags.excitations.size() != flags.records.size()) {
    throw InputError(
        fmt::format("--excitation: give one for all records or one per record ({} "
                    "records, {} excitations)",
                    flags.records.size(), flags.excitations.size()));
  }
  if (flags.band_Hz.size() != 2 || !(flags.band_Hz[0] > 0.0) ||
      !(flags.band_Hz[0] < flags.band_Hz[1])) {
    throw InputError("--band: expected LOW,HIGH in Hz with 0 < LOW < HIGH, e.g. 0.5,30");
  }
  dx::DiagnosisOptions options;
  options.effects = effect_ids(flags.effects);
  for (const auto& name : flags.free) {
    if (!model::quarter_car_parameter_index(name)) {
      throw InputError(fmt::format("--free: '{}' is not a quarter-car parameter", name));
    }
  }
  options.baseline_free = flags.free;
  options.fit.band_low_Hz = flags.band_Hz[0];
  options.fit.band_high_Hz = flags.band_Hz[1];
  options.fit.segment_s = flags.segment_s;
  options.screening_relative_tolerance = flags.screening_rtol;
  options.final_relative_tolerance = flags.final_rtol;
  options.map.segment_s = flags.segment_s;
  options.fit.body_noise_psd = noise_psd_of(flags.body_noise_psd);
  options.fit.wheel_noise_psd = noise_psd_of(flags.wheel_noise_psd);
  options.selection.threads = flags.threads;

  const std::vector<std::string> files = check_output_folder(flags, "spectra.png");
  const std::filesystem::path dir = flags.output_dir;
  const io::QuarterCarFile model_file = io::load_quarter_car(flags.model_file);
  std::vector<fitting::PsdMeasurement> records;
  for (std::size_t i = 0; i < flags.records.size(); ++i) {
    const std::string excitation = flags.excitations.empty()       ? std::string()
                                   : flags.excitations.size() == 1 ? flags.excitations[0]
                                                                   : flags.excitations[i];
    records.push_back(fitting::load_psd_measurement(flags.records[i], excitation));
    if (!excitation.empty()) check_excitation_length(records.back(), excitation);
  }
  if (records.size() == 2 &&
      (records[0].body_acc_m_per_s2.empty() != records[1].body_acc_m_per_s2.empty() ||
       records[0].wheel_acc_m_per_s2.empty() != records[1].wheel_acc_m_per_s2.empty())) {
    throw InputError(
        fmt::format("{} and {} hold different channels (body_acc, wheel_acc); the "
                    "held-out record must show what the fitted one shows",
                    flags.records[0], flags.records[1]));
  }
  const dx::DiagnosisData data = records.size() == 2 ? dx::DiagnosisData{records[0], records[1]}
                                                     : dx::split_record(records[0]);
  for (const auto* m : {&data.training, &data.held_out}) {
    const double length_s = m->time_s.back() - m->time_s.front();
    if (length_s < 2.0 * flags.segment_s) {
      throw InputError(fmt::format(
          "{}: {:.3g} s of data for fitting or judging, fewer than two {:g} s segments; give a "
          "longer record, a second record, or a shorter --segment",
          m->source, length_s, flags.segment_s));
    }
    if (flags.band_Hz[1] >= 0.5 * m->sample_rate_Hz) {
      throw InputError(
          fmt::format("--band: {:g} Hz is at or above the Nyquist frequency of {} "
                      "({:g} Hz)",
                      flags.band_Hz[1], m->source, 0.5 * m->sample_rate_Hz));
    }
  }
  // The noise floors (given, or estimated above the band: InputError when the band leaves no room
  // below the Nyquist frequency), before any output.
  for (const auto* m : {&data.training, &data.held_out}) fitting::noise_floors(*m, options.fit);
  const bool figure = io::gnuplot_available();
  io::prepare_output_directory(dir, "-o");

  const dx::DiagnosisResult result =
      dx::diagnose({model_file.make_model()}, data, options, [&](const std::string& line) {
        if (!flags.quiet && !flags.json) std::cerr << "diagnose: " << line << "\n";
      });

  // The report first, in memory: a value that is not a number stops the run before any file
  // is written.
  std::ostringstream report;
  write_report(report, flags, result, data, figure);
  require_finite_report(report.str(), dir / "report.md");
  // Written into a staged copy of the folder, put in place as a whole.
  io::StagedFolder staged(dir, files);
  const std::filesystem::path out = staged.path();
  if (figure) draw_spectra(result, out / "spectra.png");
  const auto values = changed_keys(model_file.make_model(), result.final_model.car);
  io::write_model_with_values(flags.model_file, values, out / "model.yaml",
                              fmt::format("{} by ridefit diagnose from {}: {}", flags.model_file,
                                          flags.records.front(), result.verdict));
  io::write_atomically(out / "report.md", [&](std::ostream& s) { s << report.str(); });
  staged.commit();

  if (flags.json) {
    nlohmann::json j = {{"verdict", result.verdict},
                        {"named", result.named},
                        {"gap_before_dB", result.before.gap_dB},
                        {"gap_after_dB", result.after.gap_dB},
                        {"channels_before", peaks_json(result.before)},
                        {"channels_after", peaks_json(result.after)},
                        {"regions_before", regions_json(result.before.regions)},
                        {"unexplained", regions_json(result.unexplained)},
                        {"baseline_parameters", values_json(result.baseline_parameters)},
                        {"final_parameters", values_json(result.final_parameters)},
                        {"report", (dir / "report.md").string()},
                        {"model", (dir / "model.yaml").string()}};
    j["rounds"] = rounds_json(result, "gap_dB");
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::cout << fmt::format("{}\ngap {:.2f} dB before, {:.2f} dB after\n", result.verdict,
                           result.before.gap_dB, result.after.gap_dB);
  for (const auto& c : result.after.channels) {
    const auto& b = *std::find_if(result.before.channels.begin(), result.before.channels.end(),
                                  [&](const auto& x) { return x.channel == c.channel; });
    std::cout << fmt::format(
        "{}: peak measured {:.2f} Hz, simulated {:.2f} Hz before, {:.2f} Hz "
        "after\n",
        c.channel, c.measured_peak_Hz, b.simulated_peak_Hz, c.simulated_peak_Hz);
  }
  std::cout << "Report: " << (dir / "report.md").string() << "\n";
}

}  // namespace

void register_diagnose(CLI::App& app) {
  auto flags = std::make_shared<DiagnoseFlags>();
  CLI::App* command = app.add_subcommand(
      "diagnose",
      "Find where a quarter-car model and measured acceleration spectra (or strut rig loops) "
      "disagree, name the missing physical effect from a library, add it, refit, and show the gap "
      "before and after");
  command->add_option("model", flags->model_file, "Quarter-car model (YAML), the baseline")
      ->required()
      ->check(CLI::ExistingFile);
  command
      ->add_option("records", flags->records,
                   "Vehicle: one or two measurements (CSV: time, road unless --excitation, "
                   "body_acc and/or wheel_acc); the first is fitted, the second (or the second "
                   "half) judges. Rig: strut tests (CSV: time, displacement, force); the 1st, "
                   "3rd, ... are fitted, the 2nd, 4th, ... judge (one: its halves)")
      ->required()
      ->check(CLI::ExistingFile);
  command
      ->add_option("--excitation", flags->excitations,
                   "The road as a known excitation file: one for all records or one per record")
      ->check(CLI::ExistingFile);
  command
      ->add_option("--effects", flags->effects, "Effects to try: all, or ids separated by commas")
      ->capture_default_str();
  command
      ->add_option("-o,--output", flags->output_dir,
                   "Output folder: report.md, model.yaml, spectra.png")
      ->capture_default_str();
  command
      ->add_option("--free", flags->free,
                   "Baseline parameters every fit frees (default: damping_Ns_per_m, and "
                   "coulomb_force_N with Dahl friction; sprung_mass_kg with a locked damper; "
                   "rig loops: damping_Ns_per_m, force_offset_N, coulomb_force_N)")
      ->delimiter(',');
  command->add_option("--band", flags->band_Hz, "Compared band LOW,HIGH [Hz]")
      ->delimiter(',')
      ->capture_default_str();
  command->add_option("--segment", flags->segment_s, "Welch segment length [s]")
      ->check(positive_number("s"))
      ->capture_default_str();
  add_tolerance_option(
      *command, "--screening-rtol", flags->screening_rtol,
      "Vehicle spectra: the integrator's relative tolerance when effects are screened");
  add_tolerance_option(*command, "--rtol", flags->final_rtol,
                       "Vehicle spectra: the integrator's relative tolerance of the reported "
                       "fits (baseline and named effects)");
  add_noise_psd_option(*command, "body", flags->body_noise_psd);
  add_noise_psd_option(*command, "wheel", flags->wheel_noise_psd);
  command->add_option("--threads", flags->threads, "Effects fitted at once (0 = every core)")
      ->capture_default_str();
  command->add_flag("--json", flags->json,
                    "Ranked effects, scores, parameters, the gap before and after");
  command->add_flag("-q,--quiet", flags->quiet, "No progress on stderr");
  command->add_flag("--force", flags->force,
                    "Write into an existing -o folder that holds files ridefit did not write "
                    "there (files of the same name are replaced; inputs never are)");
  command->callback([flags] { run(*flags); });
}

}  // namespace ridefit::cli
