// ridefit diagnose MODEL.yaml RIG.csv... : the diagnosis of strut rig tests (loop_diagnosis.h).
// The model file's strut is put on the rig (no gas force, no load-cell offset); the report shows
// the loops before and after, the loop-shape regions, and model.yaml with the model keys the
// diagnosis changed (rig-only ones, gas force and offset, are listed in its header comment).
#include <fmt/core.h>

#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "diagnose_common.h"
#include "ridefit/common/errors.h"
#include "ridefit/fitting/diagnose/loop_diagnosis.h"
#include "ridefit/fitting/diagnose/loop_figure.h"
#include "ridefit/fitting/diagnose/loop_report.h"
#include "ridefit/fitting/diagnose/model_changes.h"
#include "ridefit/fitting/strut_parameters.h"
#include "ridefit/io/quarter_car_file.h"

namespace ridefit::cli {

namespace dx = fitting::diagnose;

DiagnosisOutput diagnose_loops(const DiagnoseFlags& flags, bool figure,
                               const std::function<void()>& check_outputs) {
  if (!flags.excitations.empty()) {
    throw InputError(
        "--excitation: strut rig records carry their own excitation (the displacement column); "
        "give none");
  }
  dx::LoopDiagnosisOptions options;
  options.baseline_tolerances = tolerances_of(flags.tolerances, dx::strut_datasheet_tolerances(),
                                              dx::strut_datasheet_tolerances());
  for (const auto& [name, share] : options.baseline_tolerances) {
    try {
      fitting::strut_parameter_index(name);
    } catch (const InputError& e) {
      throw InputError(fmt::format("--tolerances: {}", e.what()));
    }
  }
  options.effects = effect_ids(flags.effects);
  for (const auto& name : flags.free) {
    try {
      fitting::strut_parameter_index(name);
    } catch (const InputError& e) {
      throw InputError(fmt::format("--free: {}", e.what()));
    }
  }
  options.baseline_free = flags.free;
  options.selection.threads = flags.threads;
  check_outputs();

  const io::QuarterCarFile model_file = io::load_quarter_car(flags.model_file);
  std::vector<std::filesystem::path> files(flags.records.begin(), flags.records.end());
  const dx::LoopDiagnosisData data = dx::load_loop_diagnosis_data(files);

  dx::DiagnosisModel baseline;
  baseline.car = model_file.make_model();
  baseline.kind = dx::DataKind::kStrutLoops;
  baseline.strut = fitting::strut_on_rig(model_file.make_model());
  const dx::DiagnosisResult result =
      dx::diagnose_loops(baseline, data, options, [&](const std::string& line) {
        if (!flags.quiet && !flags.json) std::cerr << "diagnose: " << line << "\n";
      });

  DiagnosisOutput output;
  DiagnosisFolder& folder = output.folder;
  std::ostringstream report;
  dx::write_loop_report(report, flags.model_file, result, data, figure ? "loops.png" : "");
  folder.report = report.str();
  const dx::StrutChanges changes =
      dx::changed_strut_values(baseline.strut, result.final_model.strut);
  folder.model_values = changes.model_values;
  folder.comment = fmt::format(
      "{} by ridefit diagnose from {}: {}{}", flags.model_file, flags.records.front(),
      result.verdict,
      changes.rig_only.empty() ? "" : "\n# rig only (not model keys): " + changes.rig_only);
  if (figure) folder.figure = dx::loop_figure(result, data);
  folder.figure_file = "loops.png";
  output.summary = dx::loop_summary_json(result);
  output.text = fmt::format("{}\ngap (force NRMSE) {:.2f} % before, {:.2f} % after\n",
                            result.verdict, result.gap_before, result.gap_after);
  return output;
}

}  // namespace ridefit::cli
