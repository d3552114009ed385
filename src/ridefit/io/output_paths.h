#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ridefit::io {

// True when `a` and `b` name the same file: the same resolved path (symbolic links and `..`
// followed as far as the path exists), or the same existing file under two names (a hard link).
bool same_file(const std::filesystem::path& a, const std::filesystem::path& b);

// The first of `files` that names the same file (same_file) as an earlier one, if any: an input
// given twice.
std::optional<std::filesystem::path> first_repeated_file(
    const std::vector<std::filesystem::path>& files);

// The output for one of several inputs: `output`'s name with the input's stem appended, in
// `output`'s folder ("out/fitted.yaml" and "shim_2mm.csv" give "out/fitted_shim_2mm.yaml").
std::filesystem::path output_for_input(const std::filesystem::path& output,
                                       const std::filesystem::path& input);

// The name of the file a folder output keeps the list of the files ridefit wrote into it.
inline constexpr const char* kOutputManifest = ".ridefit-outputs";

// The outputs of one run, checked together before any work is done: no output is an input of
// the run (resolved paths, also for the files inside an output folder), no two outputs are
// the same path, and an existing output folder holding files ridefit did not write there is
// refused unless `force` is given. Every failure is an InputError naming the flag and path.
// The one place every command checks its outputs.
class RunOutputs {
 public:
  explicit RunOutputs(std::vector<std::filesystem::path> inputs);

  // An input discovered later (a file a study or spec names).
  void add_input(const std::filesystem::path& input);

  // A file output (check_output_file) that is no other output of the run. `flag` names the
  // option in messages (e.g. "-o", "--plot", "-o (the optimised model)"); an empty path is
  // ignored.
  void add_file(const std::filesystem::path& path, const std::string& flag);

  // A figure: add_file plus check_plot_file (extension, gnuplot on PATH).
  void add_plot(const std::filesystem::path& path, const std::string& flag);

  // An output folder and the names of the files the run writes into it (no two alike). The
  // folder may be missing or empty, or hold only files a ridefit run listed in its manifest
  // (kOutputManifest); any other file is refused unless `force`, which the refusal names as
  // `force_flag` (e.g. "--force"). No input may be one of the files the run writes, even with
  // `force`. The folder is not created here.
  void add_folder(const std::filesystem::path& dir, const std::string& flag,
                  const std::vector<std::string>& files, bool force, const std::string& force_flag);

 private:
  struct Output {
    std::filesystem::path path;
    std::string flag;
  };
  void check_distinct(const std::filesystem::path& path, const std::string& flag);
  std::vector<std::filesystem::path> inputs_;
  std::vector<Output> outputs_;
};

// After a run has written its files into `dir`: removes the files a previous ridefit run listed
// in the folder's manifest that this run did not write (so the folder never mixes two runs'
// outputs) and writes the manifest of `files`, atomically.
void finish_output_folder(const std::filesystem::path& dir, const std::vector<std::string>& files);

// True for the names of ridefit's own temporary files (`.NAME.tmpPID`, gnuplot's
// `.NAME.PID.gp|log|png|svg`), which a folder check ignores.
bool is_ridefit_temporary(const std::string& filename);

}  // namespace ridefit::io
