// ridefit diagnose MODEL.yaml RIG.csv... : the diagnosis of strut rig tests (loop_diagnosis.h).
// The model file's strut is put on the rig (no gas force, no load-cell offset); the report shows
// the loops before and after, the loop-shape regions, and model.yaml with the model keys the
// diagnosis changed (rig-only ones, gas force and offset, are listed in its header comment).
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "diagnose_common.h"
#include "ridefit/common/errors.h"
#include "ridefit/fitting/diagnose/loop_diagnosis.h"
#include "ridefit/fitting/strut_parameters.h"
#include "ridefit/io/atomic_file.h"
#include "ridefit/io/gnuplot_figure.h"
#include "ridefit/io/model_values_file.h"
#include "ridefit/io/output_paths.h"
#include "ridefit/io/quarter_car_file.h"
#include "ridefit/io/staged_folder.h"

namespace ridefit::cli {
namespace {

std::string region_text(const dx::LoopRegion& r) {
  const bool velocity = r.quantity == "velocity";
  return fmt::format("| {} | {} | {:.3g} … {:.3g} {} | {:+.2f} | {:+.1f} % |\n", r.record,
                     r.quantity, 1e3 * r.low, 1e3 * r.high, velocity ? "mm/s" : "mm",
                     r.mean_residual_N, 100.0 * r.share);
}

void write_map(std::ostream& out, const dx::LoopDisagreementMap& map) {
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

void write_report(std::ostream& out, const DiagnoseFlags& flags, const dx::DiagnosisResult& r,
                  const dx::LoopDiagnosisData& data, bool figure) {
  auto names = [](const std::vector<fitting::HysteresisRecord>& records) {
    std::string text;
    for (const auto& record : records) text += (text.empty() ? "" : ", ") + record.source;
    return text;
  };
  out << "# Diagnosis of " << flags.model_file << " on the strut rig\n\n";
  out << fmt::format(
      "Data: fitted on {}; judged on {} (not used by any fit). Gap = NRMSE of the force over "
      "the judging records: 100·√(Σ(F_sim − F_meas)² / Σ(F_meas − mean)²). Regions: runs of "
      "velocity or displacement bins where the mean force residual is significant (3 standard "
      "errors, counting the residual's correlation in time) and at least 2 % of the force's "
      "RMS.\n\n",
      names(data.training), names(data.held_out));
  out << "**Verdict: " << r.verdict << ".**\n\n";
  out << fmt::format("Gap before {:.2f} %, after {:.2f} % ({:.0f} % smaller).\n\n", r.gap_before,
                     r.gap_after,
                     r.gap_before > 0 ? 100.0 * (1.0 - r.gap_after / r.gap_before) : 0.0);
  out << "## Before: the baseline, its free parameters fitted\n\n";
  write_parameters(out, r.baseline_parameters);
  write_map(out, r.loops_before);
  write_rounds(out, r, "½·Σ of squared force residuals", "NRMSE %");
  if (!r.named.empty()) {
    out << "## After: the model with the named effect(s), refitted\n\n";
    write_parameters(out, r.final_parameters);
    write_map(out, r.loops_after);
    out << "The model with the effect added: `model.yaml` (its model keys; the rig-only gas "
           "force and load-cell offset are in its header comment).\n\n";
  }
  if (figure) {
    out << "![measured against simulated loops, before and after](loops.png)\n";
  }
}

void draw_loops(const dx::DiagnosisResult& r, const dx::LoopDiagnosisData& data,
                const std::filesystem::path& path) {
  io::Figure figure;
  figure.title = "measured against simulated (judging records): before and after";
  figure.columns = 2;
  for (std::size_t i = 0; i < data.held_out.size() && i < 2; ++i) {
    const auto& record = data.held_out[i];
    const std::size_t n = record.displacement_m.size();
    const std::vector<double> v_m_per_s = dx::rig_velocity_m_per_s(record);
    std::vector<double> x_mm(n), v_mm_per_s(n);
    for (std::size_t k = 0; k < n; ++k) {
      x_mm[k] = 1e3 * record.displacement_m[k];
      v_mm_per_s[k] = 1e3 * v_m_per_s[k];
    }
    // Samples inside a region of `map` along `quantity`, as a points series over (x, y).
    auto marked = [&](const dx::LoopDisagreementMap& map, const std::string& quantity,
                      const std::vector<double>& along, const std::vector<double>& x,
                      const std::vector<double>& y) {
      io::PlotSeries points{"disagreement region", {}, {}, {}, {}, io::SeriesStyle::kPoints};
      for (std::size_t k = 0; k < n; ++k) {
        for (const auto& region : map.regions) {
          if (region.record == record.source && region.quantity == quantity &&
              along[k] >= region.low && along[k] <= region.high) {
            points.x.push_back(x[k]);
            points.y.push_back(y[k]);
            break;
          }
        }
      }
      return points;
    };
    const std::tuple<const char*, const std::vector<double>*, const dx::LoopDisagreementMap*>
        cases[] = {{"before", &r.before_force_N[i], &r.loops_before},
                   {"after", &r.after_force_N[i], &r.loops_after}};
    // Top row: the loops, force over displacement, regions along displacement marked.
    for (const auto& [when, force, map] : cases) {
      io::PlotPanel panel = io::xy_panel(fmt::format("{}: {} (NRMSE {:.2f} %)", record.source, when,
                                                     map->records[i].nrmse_percent),
                                         "displacement [mm]", "force [N]");
      panel.series.push_back({"measured", x_mm, record.force_N, {}, {}, io::SeriesStyle::kLines});
      panel.series.push_back({"simulated", x_mm, *force, {}, {}, io::SeriesStyle::kLines});
      auto points = marked(*map, "displacement", record.displacement_m, x_mm, *force);
      if (!points.x.empty()) panel.series.push_back(std::move(points));
      figure.panels.push_back(std::move(panel));
    }
    // Bottom row: the residual over velocity, where a friction or damper law that is wrong shows
    // as a shape (a hump at small |v|, a slope, a step at reversal) rather than a cloud; regions
    // along velocity marked.
    for (const auto& [when, force, map] : cases) {
      std::vector<double> residual(n);
      for (std::size_t k = 0; k < n; ++k) residual[k] = (*force)[k] - record.force_N[k];
      io::PlotPanel panel = io::xy_panel(fmt::format("{}: residual {}", record.source, when),
                                         "velocity [mm/s]", "simulated - measured force [N]");
      panel.series.push_back({"residual", v_mm_per_s, residual, {}, {}, io::SeriesStyle::kPoints});
      auto points = marked(*map, "velocity", v_m_per_s, v_mm_per_s, residual);
      if (!points.x.empty()) panel.series.push_back(std::move(points));
      figure.panels.push_back(std::move(panel));
    }
  }
  io::draw_figure(figure, path);
}

// The model keys the diagnosis changed, and the rig-only values in words.
std::pair<std::vector<std::pair<std::string, std::string>>, std::string> changed(
    const model::StrutTestParameters<double>& before,
    const model::StrutTestParameters<double>& after) {
  std::vector<std::pair<std::string, std::string>> keys;
  std::string rig_only;
  for (std::size_t i = 0; i < fitting::kStrutParameters.size(); ++i) {
    const double old_value = fitting::strut_parameter(before, i);
    const double new_value = fitting::strut_parameter(after, i);
    if (old_value == new_value) continue;
    const std::string name(fitting::kStrutParameters[i].name());
    if (fitting::kStrutParameters[i].in_model_file) {
      keys.emplace_back(name, fmt::format("{:.6g}", new_value));
    } else {
      rig_only += fmt::format("{}{}: {:.6g}", rig_only.empty() ? "" : ", ", name, new_value);
    }
  }
  return {keys, rig_only};
}

}  // namespace

void run_diagnose_loops(const DiagnoseFlags& flags) {
  if (!flags.excitations.empty()) {
    throw InputError(
        "--excitation: strut rig records carry their own excitation (the displacement column); "
        "give none");
  }
  dx::LoopDiagnosisOptions options;
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

  const std::vector<std::string> files = check_output_folder(flags, "loops.png");
  const std::filesystem::path dir = flags.output_dir;
  const io::QuarterCarFile model_file = io::load_quarter_car(flags.model_file);
  std::vector<fitting::HysteresisRecord> records;
  for (const auto& file : flags.records) records.push_back(fitting::load_hysteresis_record(file));
  const dx::LoopDiagnosisData data = dx::split_loops(records);
  for (const auto* part : {&data.training, &data.held_out}) {
    for (const auto& r : *part) {
      if (r.time_s.size() < 40) {
        throw InputError(
            fmt::format("{}: {} samples to fit or judge, too few for a loop; give a longer record",
                        r.source, r.time_s.size()));
      }
    }
  }
  const bool figure = io::gnuplot_available();
  io::prepare_output_directory(dir, "-o");

  dx::DiagnosisModel baseline;
  baseline.car = model_file.make_model();
  baseline.kind = dx::DataKind::kStrutLoops;
  baseline.strut = fitting::strut_on_rig(model_file.make_model());
  const dx::DiagnosisResult result =
      dx::diagnose_loops(baseline, data, options, [&](const std::string& line) {
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
  if (figure) draw_loops(result, data, out / "loops.png");
  const auto [keys, rig_only] = changed(baseline.strut, result.final_model.strut);
  io::write_model_with_values(
      flags.model_file, keys, out / "model.yaml",
      fmt::format("{} by ridefit diagnose from {}: {}{}", flags.model_file, flags.records.front(),
                  result.verdict,
                  rig_only.empty() ? "" : "\n# rig only (not model keys): " + rig_only));
  io::write_atomically(out / "report.md", [&](std::ostream& s) { s << report.str(); });
  staged.commit();

  if (flags.json) {
    auto regions = [](const std::vector<dx::LoopRegion>& list) {
      nlohmann::json j = nlohmann::json::array();
      for (const auto& r : list) {
        j.push_back({{"record", r.record},
                     {"quantity", r.quantity},
                     {"low", r.low},
                     {"high", r.high},
                     {"mean_residual_N", r.mean_residual_N},
                     {"share", r.share}});
      }
      return j;
    };
    nlohmann::json j = {{"data", "strut_loops"},
                        {"verdict", result.verdict},
                        {"named", result.named},
                        {"gap_before_nrmse_percent", result.gap_before},
                        {"gap_after_nrmse_percent", result.gap_after},
                        {"regions_before", regions(result.loops_before.regions)},
                        {"unexplained", regions(result.unexplained_loops)},
                        {"baseline_parameters", values_json(result.baseline_parameters)},
                        {"final_parameters", values_json(result.final_parameters)},
                        {"report", (dir / "report.md").string()},
                        {"model", (dir / "model.yaml").string()}};
    j["rounds"] = rounds_json(result, "gap_nrmse_percent");
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::cout << fmt::format("{}\ngap (force NRMSE) {:.2f} % before, {:.2f} % after\n",
                           result.verdict, result.gap_before, result.gap_after);
  std::cout << "Report: " << (dir / "report.md").string() << "\n";
}

}  // namespace ridefit::cli
