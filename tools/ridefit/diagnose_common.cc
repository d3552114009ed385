// The parts of `ridefit diagnose` both data kinds share (diagnose_common.h).
#include "diagnose_common.h"

#include <fmt/core.h>

#include <algorithm>

#include "command_options.h"
#include "ridefit/common/errors.h"
#include "ridefit/fitting/diagnose/effect.h"
#include "ridefit/io/atomic_file.h"
#include "ridefit/io/finite_report.h"
#include "ridefit/io/model_values_file.h"
#include "ridefit/io/output_paths.h"
#include "ridefit/io/staged_folder.h"

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
      fitting::diagnose::find_effect(id);
    } catch (const InputError& e) {
      throw InputError(fmt::format("--effects: {}", e.what()));
    }
    ids.push_back(id);
    start = comma + 1;
  }
  return ids;
}

std::map<std::string, double> tolerances_of(const std::vector<std::string>& items,
                                            const std::map<std::string, double>& datasheet,
                                            const std::map<std::string, double>& fallback) {
  if (items.empty()) return fallback;
  std::map<std::string, double> tolerances;
  std::vector<std::string> entries;
  for (const auto& item : items) {
    if (item == "datasheet") {
      tolerances = datasheet;
    } else if (item == "none") {
      tolerances.clear();
    } else {
      entries.push_back(item);
    }
  }
  for (const auto& [name, share] : parse_value_shares(entries, "--tolerances")) {
    tolerances[name] = share;
  }
  return tolerances;
}

std::vector<std::string> check_output_folder(const DiagnoseFlags& flags,
                                             const std::string& figure) {
  if (const auto repeated = io::first_repeated_file({flags.records.begin(), flags.records.end()})) {
    throw InputError(
        fmt::format("{} is given twice; a record judging the fit must not be the one fitted (give "
                    "another record, or one record to be split in halves)",
                    repeated->string()));
  }
  std::vector<std::filesystem::path> inputs{flags.model_file};
  for (const auto& f : flags.records) inputs.push_back(f);
  for (const auto& f : flags.excitations) inputs.push_back(f);
  std::vector<std::string> files = {"report.md", "model.yaml"};
  if (io::gnuplot_available()) files.push_back(figure);
  io::RunOutputs outputs(inputs);
  outputs.add_folder(flags.output_dir, "-o", files, flags.force, "--force");
  return files;
}

void write_diagnosis_folder(const DiagnoseFlags& flags, const std::vector<std::string>& files,
                            const DiagnosisFolder& folder) {
  const std::filesystem::path dir = flags.output_dir;
  io::require_finite_report(folder.report, dir / "report.md");
  // Written into a staged copy of the folder, put in place as a whole.
  io::StagedFolder staged(dir, files);
  const std::filesystem::path out = staged.path();
  if (folder.figure) io::draw_figure(*folder.figure, out / folder.figure_file);
  io::write_model_with_values(flags.model_file, folder.model_values, out / "model.yaml",
                              folder.comment);
  io::write_atomically(out / "report.md", [&](std::ostream& s) { s << folder.report; });
  staged.commit();
}

}  // namespace ridefit::cli
