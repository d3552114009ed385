#include "ridefit/io/atomic_file.h"

#include <fmt/core.h>
#include <unistd.h>

#include <fstream>

#include "ridefit/io/input_error.h"

namespace ridefit::io {

void write_atomically(const std::filesystem::path& path,
                      const std::function<void(std::ostream&)>& write) {
  const std::filesystem::path dir =
      path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  if (!std::filesystem::is_directory(dir)) {
    throw InputError(fmt::format("{}: cannot write, directory '{}' does not exist", path.string(),
                                 dir.string()));
  }
  const std::filesystem::path tmp =
      dir / fmt::format(".{}.tmp{}", path.filename().string(), static_cast<long>(getpid()));
  try {
    std::ofstream out(tmp);
    if (!out) throw InputError(fmt::format("{}: cannot open for writing", path.string()));
    write(out);
    out.close();
    if (!out) throw InputError(fmt::format("{}: write failed", path.string()));
    std::filesystem::rename(tmp, path);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw;
  }
}

}  // namespace ridefit::io
