#pragma once

// What `ridefit diagnose` shares between its two kinds of data (vehicle spectra in
// diagnose_command.cc, strut rig loops in diagnose_loops_command.cc): the flags, their checks,
// and the output folder (diagnose_common.cc).

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ridefit/io/gnuplot_figure.h"

namespace ridefit::cli {

struct DiagnoseFlags {
  std::string model_file;
  std::vector<std::string> records;
  std::vector<std::string> excitations;
  std::string effects = "all";
  std::string output_dir = "diagnosis";
  std::vector<std::string> free;
  std::vector<std::string> tolerances;  // "datasheet", "none" and/or key=share
  std::vector<double> band_Hz = {0.5, 30.0};
  double segment_s = 4.0;
  double screening_rtol = 1e-3;
  double final_rtol = 1e-4;
  double body_noise_psd = std::nan("");  // not given: estimated from each record
  double wheel_noise_psd = std::nan("");
  unsigned threads = 0;
  bool json = false;
  bool quiet = false;
  bool force = false;
};

// --effects: all (empty) or ids separated by commas; InputError naming the library's ids.
std::vector<std::string> effect_ids(const std::string& text);

// --tolerances: "datasheet" (`datasheet`), "none", and KEY=SHARE items, which win; not given:
// `fallback` (the data kind's default). Names are checked by the diagnosis' options.
std::map<std::string, double> tolerances_of(const std::vector<std::string>& items,
                                            const std::map<std::string, double>& datasheet,
                                            const std::map<std::string, double>& fallback);

// The files a diagnosis writes into -o (report.md, model.yaml and, with gnuplot on PATH,
// `figure`), checked before any work (io::RunOutputs): none is an input (the model, a record,
// an excitation), and an existing folder holding files ridefit did not write is refused
// unless --force. Also refuses a record given twice (the held-out record would be the fitted
// one). InputError naming -o or the record otherwise.
std::vector<std::string> check_output_folder(const DiagnoseFlags& flags, const std::string& figure);

// What a diagnosis writes into -o: the report (report.md), the model with the values the
// diagnosis changed (model.yaml, `comment` as its first line) and the figure when gnuplot is
// there (`files` from check_output_folder: figure_file among them).
struct DiagnosisFolder {
  std::string report;
  std::vector<std::pair<std::string, std::string>> model_values;
  std::string comment;
  std::optional<io::Figure> figure;  // none without gnuplot
  std::string figure_file;
};

// Writes the folder as a whole (io::StagedFolder): the report is checked first, so a value that
// is not a number stops the run before any file is written.
void write_diagnosis_folder(const DiagnoseFlags& flags, const std::vector<std::string>& files,
                            const DiagnosisFolder& folder);

// A diagnosis done, nothing written yet: its folder, what --json prints (without the paths of
// the files) and the lines printed without --json.
struct DiagnosisOutput {
  DiagnosisFolder folder;
  nlohmann::json summary;
  std::string text;
};

// The diagnosis of strut rig records (diagnose_loops_command.cc), with the figure when `figure`;
// `check_outputs` is called once the flags are checked, before any file is read (the command's
// check_output_folder). Progress on stderr unless --quiet or --json.
DiagnosisOutput diagnose_loops(const DiagnoseFlags& flags, bool figure,
                               const std::function<void()>& check_outputs);

}  // namespace ridefit::cli
