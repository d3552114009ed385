// ridefit diagnose MODEL.yaml MEAS.csv... [--excitation EXC.yaml]... [--effects all|id,...]
//                  [-o DIR] [--free k,...] [--band LOW,HIGH] [--segment S] [--threads N] [--json]
// Finds where the model and the measurement disagree, which effect of the library explains it,
// adds it, and shows the gap before and after: vehicle spectra here (fitting/diagnose/
// diagnosis.h), strut rig loops in diagnose_loops_command.cc (loop_diagnosis.h).
#include <fmt/core.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "command_options.h"
#include "command_outcome.h"
#include "diagnose_common.h"
#include "ridefit/common/errors.h"
#include "ridefit/fitting/diagnose/diagnosis.h"
#include "ridefit/fitting/diagnose/diagnosis_records.h"
#include "ridefit/fitting/diagnose/model_changes.h"
#include "ridefit/fitting/diagnose/spectra_figure.h"
#include "ridefit/fitting/diagnose/spectra_report.h"
#include "ridefit/fitting/record_kind.h"
#include "ridefit/io/atomic_file.h"
#include "ridefit/io/finite_report.h"
#include "ridefit/io/gnuplot_figure.h"
#include "ridefit/io/model_values_file.h"
#include "ridefit/io/quarter_car_file.h"
#include "ridefit/model/quarter_car_parameter_table.h"
#include "subcommands.h"

namespace ridefit::cli {
namespace {

namespace dx = fitting::diagnose;

// The flags' counts and ranges, before any file is read.
void check_flags(const DiagnoseFlags& flags) {
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
}

dx::DiagnosisOptions options_of(const DiagnoseFlags& flags) {
  dx::DiagnosisOptions options;
  options.effects = effect_ids(flags.effects);
  for (const auto& name : flags.free) {
    if (!model::quarter_car_parameter_index(name)) {
      throw InputError(fmt::format("--free: '{}' is not a quarter-car parameter", name));
    }
  }
  options.baseline_free = flags.free;
  options.baseline_tolerances = tolerances_of(flags.tolerances, dx::datasheet_tolerances(), {});
  options.fit.band_low_Hz = flags.band_Hz[0];
  options.fit.band_high_Hz = flags.band_Hz[1];
  options.fit.segment_s = flags.segment_s;
  options.screening_relative_tolerance = flags.screening_rtol;
  options.final_relative_tolerance = flags.final_rtol;
  options.map.segment_s = flags.segment_s;
  options.fit.body_noise_psd = noise_psd_of(flags.body_noise_psd);
  options.fit.wheel_noise_psd = noise_psd_of(flags.wheel_noise_psd);
  options.selection.threads = flags.threads;
  return options;
}

// Each part of the data holds two Welch segments or more, and the band ends below its Nyquist
// frequency.
void check_data(const DiagnoseFlags& flags, const dx::DiagnosisData& data) {
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
}

// The diagnosis of vehicle spectra, with the figure when `figure`; `check_outputs` as for
// diagnose_loops.
DiagnosisOutput diagnose_spectra(const DiagnoseFlags& flags, bool figure,
                                 const std::function<void()>& check_outputs) {
  check_flags(flags);
  const dx::DiagnosisOptions options = options_of(flags);
  check_outputs();
  const io::QuarterCarFile model_file = io::load_quarter_car(flags.model_file);
  const dx::DiagnosisData data =
      dx::load_diagnosis_data({flags.records.begin(), flags.records.end()},
                              {flags.excitations.begin(), flags.excitations.end()});
  check_data(flags, data);
  // The noise floors (given, or estimated above the band: InputError when the band leaves no room
  // below the Nyquist frequency), before the work.
  for (const auto* m : {&data.training, &data.held_out}) fitting::noise_floors(*m, options.fit);

  const dx::DiagnosisResult result =
      dx::diagnose({model_file.make_model()}, data, options, [&](const std::string& line) {
        if (!flags.quiet && !flags.json) std::cerr << "diagnose: " << line << "\n";
      });

  DiagnosisOutput output;
  DiagnosisFolder& folder = output.folder;
  std::ostringstream report;
  dx::write_spectra_report(report, flags.model_file, options, result, data,
                           figure ? "spectra.png" : "");
  folder.report = report.str();
  folder.model_values = dx::changed_model_values(model_file.make_model(), result.final_model.car);
  folder.comment = fmt::format("{} by ridefit diagnose from {}: {}", flags.model_file,
                               flags.records.front(), result.verdict);
  if (figure) folder.figure = dx::spectra_figure(result);
  folder.figure_file = "spectra.png";
  output.summary = dx::spectra_summary_json(result);
  std::ostringstream text;
  text << fmt::format("{}\ngap {:.2f} dB before, {:.2f} dB after\n", result.verdict,
                      result.before.gap_dB, result.after.gap_dB);
  for (const auto& c : result.after.channels) {
    const auto& b = *std::find_if(result.before.channels.begin(), result.before.channels.end(),
                                  [&](const auto& x) { return x.channel == c.channel; });
    text << fmt::format(
        "{}: peak measured {:.2f} Hz, simulated {:.2f} Hz before, {:.2f} Hz "
        "after\n",
        c.channel, c.measured_peak_Hz, b.simulated_peak_Hz, c.simulated_peak_Hz);
  }
  output.text = text.str();
  return output;
}

// True for strut rig records, false for vehicle measurements; InputError for a mix.
bool rig_records(const DiagnoseFlags& flags) {
  std::size_t rig_records = 0;
  for (const auto& file : flags.records) rig_records += fitting::is_rig_record(file) ? 1 : 0;
  if (rig_records > 0 && rig_records < flags.records.size()) {
    throw InputError(
        "the records mix strut rig tests (time, displacement, force) with vehicle measurements "
        "(time, road or --excitation, body_acc and/or wheel_acc); diagnose one kind at a time");
  }
  return rig_records > 0;
}

void run(const DiagnoseFlags& flags) {
  const bool rig = rig_records(flags);
  std::vector<std::string> files;
  const auto check_outputs = [&] {
    files = check_output_folder(flags, rig ? "loops.png" : "spectra.png");
  };
  const std::filesystem::path dir = flags.output_dir;
  const bool figure = io::gnuplot_available();
  const DiagnosisOutput output = rig ? diagnose_loops(flags, figure, check_outputs)
                                     : diagnose_spectra(flags, figure, check_outputs);
  io::prepare_output_directory(dir, "-o");
  write_diagnosis_folder(flags, files, output.folder);
  if (flags.json) {
    nlohmann::json j = output.summary;
    j["report"] = (dir / "report.md").string();
    j["model"] = (dir / "model.yaml").string();
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::cout << output.text << "Report: " << (dir / "report.md").string() << "\n";
}

// The diagnosis' inputs and settings (not its outputs, threads or progress): the command's and
// a batch job's.
void add_diagnose_options(CLI::App& command, DiagnoseFlags& flags) {
  command.add_option("model", flags.model_file, "Quarter-car model (YAML), the baseline")
      ->required()
      ->check(CLI::ExistingFile);
  command
      .add_option(
          "records", flags.records,
          "Vehicle: one or two measurements (CSV or .mat: time, road unless --excitation, "
          "body_acc and/or wheel_acc); the first is fitted, the second (or the second "
          "half) judges. Rig: strut tests (CSV or .mat: time, displacement, force); the 1st, "
          "3rd, ... are fitted, the 2nd, 4th, ... judge (one: its halves); a file with a segment "
          "or test column gives one test per segment")
      ->required()
      ->check(CLI::ExistingFile);
  command
      .add_option("--excitation", flags.excitations,
                  "The road as a known excitation file: one for all records or one per record")
      ->check(CLI::ExistingFile);
  command.add_option("--effects", flags.effects, "Effects to try: all, or ids separated by commas")
      ->capture_default_str();
  command
      .add_option("--free", flags.free,
                  "Baseline parameters every fit frees (default: damping_Ns_per_m, and "
                  "coulomb_force_N with Dahl friction; sprung_mass_kg with a locked damper; "
                  "rig loops: damping_Ns_per_m, force_offset_N, coulomb_force_N)")
      ->delimiter(',');
  command
      .add_option("--tolerances", flags.tolerances,
                  "Baseline values the data sheet is unsure of, freed in every fit: 'datasheet', "
                  "'none' (hold them), and KEY=SHARE items (one standard deviation as a share "
                  "of the value) that add or change one, separated by commas. Vehicle spectra: "
                  "a Gaussian prior at the sheet's value; 'datasheet' is masses 3 %, tyre and "
                  "spring 8 %, damping 12 %, top mount 15 %, Coulomb force 25 %; default none. "
                  "Rig loops: within three tolerances of the sheet's value; 'datasheet' is "
                  "damping 12 %, top mount 15 %, Coulomb force 25 %, dahl_sigma0 100 %, and the "
                  "default")
      ->delimiter(',');
  command.add_option("--band", flags.band_Hz, "Compared band LOW,HIGH [Hz]")
      ->delimiter(',')
      ->capture_default_str();
  command.add_option("--segment", flags.segment_s, "Welch segment length [s]")
      ->check(positive_number("s"))
      ->capture_default_str();
  add_tolerance_option(
      command, "--screening-rtol", flags.screening_rtol,
      "Vehicle spectra: the integrator's relative tolerance when effects are screened");
  add_tolerance_option(command, "--rtol", flags.final_rtol,
                       "Vehicle spectra: the integrator's relative tolerance of the reported "
                       "fits (baseline and named effects)");
  add_noise_psd_option(command, "body", flags.body_noise_psd);
  add_noise_psd_option(command, "wheel", flags.wheel_noise_psd);
}

}  // namespace

CommandJob diagnose_job(std::vector<std::string> arguments) {
  return command_job<DiagnoseFlags>(
      std::move(arguments), add_diagnose_options, [](DiagnoseFlags flags) {
        flags.threads = 1;  // the batch runs its jobs side by side
        flags.quiet = true;
        const auto none = [] {};  // the batch checked its outputs before any job
        const DiagnosisOutput output = rig_records(flags) ? diagnose_loops(flags, false, none)
                                                          : diagnose_spectra(flags, false, none);
        io::require_finite_report(output.folder.report, "report.md");
        return CommandOutcome{
            output.summary,
            {{"report.md", output.folder.report},
             {"model.yaml", io::model_with_values_text(flags.model_file, output.folder.model_values,
                                                       output.folder.comment)}},
            ""};
      });
}

void register_diagnose(CLI::App& app) {
  auto flags = std::make_shared<DiagnoseFlags>();
  CLI::App* command = app.add_subcommand(
      "diagnose",
      "Find where a quarter-car model and measured acceleration spectra (or strut rig loops) "
      "disagree, name the missing physical effect from a library, add it, refit, and show the gap "
      "before and after");
  add_diagnose_options(*command, *flags);
  command
      ->add_option("-o,--output", flags->output_dir,
                   "Output folder: report.md, model.yaml, spectra.png")
      ->capture_default_str();
  command->add_option("--threads", flags->threads, "Effects fitted at once (0 = every core)")
      ->capture_default_str();
  command->add_flag("--json", flags->json,
                    "Ranked effects, scores, parameters, the gap before and after");
  command->add_flag("-q,--quiet", flags->quiet, "No progress on stderr");
  add_force_flag(*command, flags->force);
  command->callback([flags] { run(*flags); });
}

}  // namespace ridefit::cli
