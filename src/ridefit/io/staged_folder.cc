#include "ridefit/io/staged_folder.h"

#include <fcntl.h>
#include <fmt/core.h>
#include <stdio.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <set>

#include "ridefit/common/errors.h"
#include "ridefit/io/atomic_file.h"
#include "ridefit/io/output_paths.h"
#include "ridefit/io/temporary_files.h"

namespace ridefit::io {

namespace fs = std::filesystem;

namespace {

// True when `dir` is the working directory or one of its ancestors.
bool holds_working_directory(const fs::path& dir) {
  std::error_code ec;
  const fs::path cwd = fs::weakly_canonical(fs::current_path(ec), ec);
  const fs::path d = fs::weakly_canonical(dir, ec);
  if (ec) return true;
  auto c = cwd.begin();
  for (auto p = d.begin(); p != d.end(); ++p, ++c) {
    if (c == cwd.end() || *p != *c) return p->empty();
  }
  return true;
}

// Links (or, where the file system cannot, copies) `from` to `to`, recursively.
void carry_over(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  if (fs::is_directory(fs::symlink_status(from))) {
    fs::create_directory(to, ec);
    for (const auto& entry : fs::directory_iterator(from)) {
      carry_over(entry.path(), to / entry.path().filename());
    }
    return;
  }
  if (fs::is_symlink(fs::symlink_status(from))) {
    fs::copy_symlink(from, to, ec);
    return;
  }
  fs::create_hard_link(from, to, ec);
  if (ec) fs::copy_file(from, to, fs::copy_options::overwrite_existing);
}

}  // namespace

StagedFolder::StagedFolder(const fs::path& dir, const std::vector<std::string>& files)
    : dir_(fs::weakly_canonical(fs::absolute(dir))), files_(files) {
  // Resolved: a symbolic link to the folder keeps pointing at it; the swap happens where the
  // files are.
  if (!dir_.has_filename()) dir_ = dir_.parent_path();  // a trailing slash
  const fs::path parent = dir_.parent_path();
  if (dir_.filename().empty() || dir_ == parent || holds_working_directory(dir_)) {
    in_place_ = true;
    staging_ = dir_;
    prepare_output_directory(dir_, "-o");
    return;
  }
  prepare_output_directory(parent, "-o");
  remove_stale_temporaries(parent, dir_.filename().string());
  staging_ =
      parent / fmt::format(".{}.tmp{}", dir_.filename().string(), static_cast<long>(getpid()));
  std::error_code ec;
  fs::remove_all(staging_, ec);
  fs::create_directory(staging_, ec);
  if (ec) {
    throw InputError(fmt::format("-o {}: cannot create {} beside it: {}", dir_.string(),
                                 staging_.string(), ec.message()));
  }
  if (fs::is_directory(dir_)) {
    try {
      const std::set<std::string> written(files.begin(), files.end());
      for (const auto& entry : fs::directory_iterator(dir_)) {
        const std::string name = entry.path().filename().string();
        if (written.count(name) != 0 || is_ridefit_temporary(name)) continue;
        carry_over(entry.path(), staging_ / name);
      }
    } catch (const fs::filesystem_error& e) {
      std::error_code ignored;
      fs::remove_all(staging_, ignored);
      throw InputError(fmt::format(
          "-o {}: cannot carry its other files over into the new folder ({}); choose a new or "
          "empty folder",
          dir_.string(), e.what()));
    }
  }
}

StagedFolder::~StagedFolder() {
  if (committed_ || in_place_) return;
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
}

void StagedFolder::commit() {
  finish_output_folder(staging_, files_);
  committed_ = true;
  if (in_place_) return;
  if (!fs::exists(dir_)) {
    fs::rename(staging_, dir_);
    return;
  }
  // One atomic step: the staged folder takes the folder's name, the old folder the staging name.
  if (renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, dir_.c_str(), RENAME_EXCHANGE) != 0) {
    const int error = errno;
    // A file system without RENAME_EXCHANGE: two renames (a short window without the folder).
    if (error != EINVAL && error != ENOSYS) {
      committed_ = false;
      throw RunError(fmt::format("{}: cannot put the new folder in place: {}", dir_.string(),
                                 std::strerror(error)));
    }
    const fs::path old = staging_.string() + ".old";
    fs::rename(dir_, old);
    fs::rename(staging_, dir_);
    std::error_code ignored;
    fs::remove_all(old, ignored);
    return;
  }
  std::error_code ignored;
  fs::remove_all(staging_, ignored);  // now the old folder
}

}  // namespace ridefit::io
