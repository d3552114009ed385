#include "ridefit/io/atomic_file.h"

#include <fmt/core.h>
#include <unistd.h>

#include <fstream>

#include "ridefit/common/errors.h"
#include "ridefit/io/path_type.h"
#include "ridefit/io/temporary_files.h"

namespace ridefit::io {

void write_file_atomically(
    const std::filesystem::path& path,
    const std::function<void(const std::filesystem::path& temporary)>& write) {
  const std::filesystem::path dir =
      path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  if (!is_folder(dir)) {
    throw InputError(fmt::format("{}: cannot write, directory '{}' does not exist", path.string(),
                                 dir.string()));
  }
  if (path_exists(path) && !exists_as_file(path)) {
    throw InputError(
        fmt::format("{}: cannot write, it exists and is not a regular file", path.string()));
  }
  // What a killed run left behind for this file goes first; this run's own temporary is
  // removed by the signal handler if the run is interrupted (temporary_files.h).
  remove_stale_temporaries(dir, path.filename().string());
  const std::filesystem::path tmp =
      dir / fmt::format(".{}.tmp{}", path.filename().string(), static_cast<long>(getpid()));
  const TemporaryFile registered(tmp);
  try {
    write(tmp);
    std::filesystem::rename(tmp, path);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw;
  }
}

void write_atomically(const std::filesystem::path& path,
                      const std::function<void(std::ostream&)>& write) {
  write_file_atomically(path, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp);
    if (!out) throw InputError(fmt::format("{}: cannot open for writing", path.string()));
    write(out);
    out.close();
    if (!out) throw InputError(fmt::format("{}: write failed", path.string()));
  });
}

void check_output_file(const std::filesystem::path& path,
                       const std::vector<std::filesystem::path>& inputs, const std::string& flag) {
  namespace fs = std::filesystem;
  const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
  if (!is_folder(dir)) {
    throw InputError(
        fmt::format("{} {}: directory '{}' does not exist", flag, path.string(), dir.string()));
  }
  if (is_folder(path)) {
    throw InputError(fmt::format("{} {}: is a directory, expected a file path such as {}/out.csv",
                                 flag, path.string(), path.string()));
  }
  if (path_exists(path) && !exists_as_file(path)) {
    throw InputError(fmt::format("{} {}: exists and is not a regular file", flag, path.string()));
  }
  for (const auto& input : inputs) {
    std::error_code ec;
    if (fs::exists(path) && fs::equivalent(path, input, ec)) {
      throw InputError(fmt::format("{} {}: is also an input of this run; choose another file", flag,
                                   path.string()));
    }
  }
}

void prepare_output_directory(const std::filesystem::path& path, const std::string& flag) {
  namespace fs = std::filesystem;
  if (path_exists(path) && !is_folder(path)) {
    throw InputError(fmt::format("{} {}: exists and is not a directory", flag, path.string()));
  }
  std::error_code ec;
  fs::create_directories(path, ec);
  if (ec) {
    throw InputError(
        fmt::format("{} {}: cannot create the directory: {}", flag, path.string(), ec.message()));
  }
}

}  // namespace ridefit::io
