#pragma once

// What `ridefit diagnose` shares between its two kinds of data: the flags, and the parts of the
// report and of the JSON that do not depend on the kind (diagnose_command.cc).

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "ridefit/fitting/diagnose/diagnosis.h"

namespace ridefit::cli {

namespace dx = fitting::diagnose;

struct DiagnoseFlags {
  std::string model_file;
  std::vector<std::string> records;
  std::vector<std::string> excitations;
  std::string effects = "all";
  std::string output_dir = "diagnosis";
  std::vector<std::string> free;
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

std::string se_text(const std::optional<double>& se);

// A markdown table of parameters with their standard errors.
void write_parameters(std::ostream& out, const std::vector<dx::FittedValue>& values);

// Each round's ranked effects, the skipped and failed ones with why, and the accepted one.
void write_rounds(std::ostream& out, const dx::DiagnosisResult& r, const std::string& cost_words,
                  const std::string& gap_unit);

nlohmann::json values_json(const std::vector<dx::FittedValue>& values);
nlohmann::json rounds_json(const dx::DiagnosisResult& result, const std::string& gap_key);

// RunError when the report's text shows a value that is not a number (nan, inf): a report never
// presents one as a result. `path` names the report in the message.
void require_finite_report(const std::string& text, const std::filesystem::path& path);

// The files a diagnosis writes into -o (report.md, model.yaml and, with gnuplot on PATH,
// `figure`), checked before any work (io::RunOutputs): none is an input (the model, a record,
// an excitation), and an existing folder holding files ridefit did not write is refused
// unless --force. Also refuses a record given twice (the held-out record would be the fitted
// one). InputError naming -o or the record otherwise.
std::vector<std::string> check_output_folder(const DiagnoseFlags& flags, const std::string& figure);

// True when the CSV's header names a displacement column: a strut rig test (whose loader then
// names any column it misses).
bool is_rig_record(const std::filesystem::path& csv_file);

// The diagnosis of strut rig records (diagnose_loops_command.cc).
void run_diagnose_loops(const DiagnoseFlags& flags);

}  // namespace ridefit::cli
