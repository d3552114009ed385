#include "ridefit/io/output_paths.h"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <set>

#include "ridefit/common/errors.h"
#include "ridefit/io/atomic_file.h"
#include "ridefit/io/gnuplot_figure.h"
#include "ridefit/io/path_type.h"
#include "ridefit/io/temporary_files.h"

namespace ridefit::io {

namespace fs = std::filesystem;

namespace {

fs::path resolved(const fs::path& path) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(path), ec);
  return ec ? fs::absolute(path).lexically_normal() : p;
}

std::set<std::string> manifest_names(const fs::path& dir) {
  std::set<std::string> names;
  std::ifstream in(dir / kOutputManifest);
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] != '#') names.insert(line);
  }
  return names;
}

// A folder a ridefit run wrote (it holds the run's manifest).
bool is_output_folder(const fs::path& path) {
  return fs::is_directory(path) && fs::is_regular_file(path / kOutputManifest);
}

}  // namespace

bool same_file(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec) && fs::equivalent(a, b, ec)) return true;
  return resolved(a) == resolved(b);
}

std::optional<fs::path> first_repeated_file(const std::vector<fs::path>& files) {
  for (std::size_t i = 0; i < files.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (same_file(files[i], files[j])) return files[i];
    }
  }
  return std::nullopt;
}

fs::path output_for_input(const fs::path& output, const fs::path& input) {
  return output.parent_path() /
         (output.stem().string() + "_" + input.stem().string() + output.extension().string());
}

bool is_ridefit_temporary(const std::string& filename) { return temporary_owner(filename) != 0; }

RunOutputs::RunOutputs(std::vector<fs::path> inputs) : inputs_(std::move(inputs)) {}

void RunOutputs::add_input(const fs::path& input) { inputs_.push_back(input); }

void RunOutputs::check_distinct(const fs::path& path, const std::string& flag) {
  for (const auto& o : outputs_) {
    if (same_file(o.path, path)) {
      throw InputError(fmt::format("{} {} is also the {} output {}; give each output its own path",
                                   flag, path.string(), o.flag, o.path.string()));
    }
  }
  outputs_.push_back({path, flag});
}

void RunOutputs::add_file(const fs::path& path, const std::string& flag) {
  if (path.empty()) return;
  check_output_file(path, inputs_, flag);
  for (const auto& input : inputs_) {
    if (same_file(path, input)) {
      throw InputError(fmt::format("{} {}: is also an input of this run; choose another file", flag,
                                   path.string()));
    }
  }
  check_distinct(path, flag);
}

void RunOutputs::add_plot(const fs::path& path, const std::string& flag) {
  if (path.empty()) return;
  add_file(path, flag);
  check_plot_file(path, inputs_, flag);
}

void RunOutputs::add_folder(const fs::path& dir, const std::string& flag,
                            const std::vector<std::string>& files, bool force,
                            const std::string& force_flag) {
  for (const auto& input : inputs_) {
    if (same_file(input, dir)) {
      throw InputError(fmt::format("{} {}: that is an input of this run", flag, dir.string()));
    }
  }
  if (path_exists(dir) && !is_folder(dir)) {
    throw InputError(fmt::format("{} {}: exists and is not a directory", flag, dir.string()));
  }
  std::set<std::string> planned;
  for (const auto& name : files) {
    if (!planned.insert(name).second) {
      throw InputError(fmt::format(
          "{} {}: this run would write {} twice (two outputs of the same name); give them "
          "different names",
          flag, dir.string(), (dir / name).string()));
    }
  }
  for (const auto& input : inputs_) {
    for (const auto& name : files) {
      if (same_file(input, dir / name)) {
        throw InputError(fmt::format(
            "{} {}: this run writes {} there, which is one of its inputs; choose another "
            "output folder",
            flag, dir.string(), (dir / name).string()));
      }
    }
  }
  for (const auto& name : files) check_distinct(dir / name, flag);
  if (!fs::is_directory(dir) || force) return;
  const std::set<std::string> ours = manifest_names(dir);
  std::vector<std::string> foreign;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name == kOutputManifest || is_ridefit_temporary(name)) continue;
    // A listed file, or a listed folder ridefit wrote (`batch`'s job folders, each checked
    // against its own manifest when the run writes it).
    if (ours.count(name) != 0 && (entry.is_regular_file() || is_output_folder(entry.path()))) {
      continue;
    }
    foreign.push_back(name);
  }
  if (foreign.empty()) return;
  std::sort(foreign.begin(), foreign.end());
  std::string list;
  for (std::size_t k = 0; k < foreign.size() && k < 5; ++k) {
    list += (k == 0 ? "" : ", ") + foreign[k];
  }
  if (foreign.size() > 5) list += fmt::format(" and {} more", foreign.size() - 5);
  throw InputError(fmt::format(
      "{} {}: the folder holds files ridefit did not write there ({}); choose a new or empty "
      "folder, or give {} to write into it anyway (files of the same name are replaced)",
      flag, dir.string(), list, force_flag));
}

void finish_output_folder(const fs::path& dir, const std::vector<std::string>& files) {
  std::set<std::string> names = manifest_names(dir);
  for (auto it = names.begin(); it != names.end();) {
    const bool kept = fs::is_regular_file(dir / *it) || is_output_folder(dir / *it);
    it = kept ? std::next(it) : names.erase(it);
  }
  names.insert(files.begin(), files.end());
  write_atomically(dir / kOutputManifest, [&](std::ostream& out) {
    out << "# Files ridefit wrote into this folder; a later run may replace them\n";
    for (const auto& name : names) out << name << "\n";
  });
}

}  // namespace ridefit::io
