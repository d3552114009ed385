#pragma once

#include <sys/types.h>
#include <filesystem>
#include <string>

namespace ridefit::io {

// ridefit's temporary files (an output written before its rename, gnuplot's script, log and
// figure) and child processes (gnuplot), known to a SIGINT / SIGTERM / SIGHUP handler that
// removes the files and ends the children before the process dies of the signal. Nothing is
// left behind by a run that is interrupted; a run killed outright (SIGKILL) leaves its
// temporaries, which the next write into the same place removes (remove_stale_temporaries).

// Installs the handler (once; the command line calls it at start).
void install_temporary_cleanup();

// A temporary file the handler removes while it is registered.
class TemporaryFile {
 public:
  explicit TemporaryFile(const std::filesystem::path& path);
  ~TemporaryFile();
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

 private:
  int slot_ = -1;
};

// A child process the handler ends (SIGTERM) while it is registered.
class ChildProcess {
 public:
  explicit ChildProcess(pid_t pid);
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

 private:
  int slot_ = -1;
};

// The process id a ridefit temporary name carries (`.NAME.tmpPID`, `.NAME.PID.gp|log|png|svg`),
// or 0 when `filename` is none of them.
long temporary_owner(const std::string& filename);

// Removes, in `dir`, the temporaries (files, and staged folders `.NAME.tmpPID`) of `target` (a file
// name in `dir`; empty: of any file) whose process no longer runs: what a killed run left behind.
void remove_stale_temporaries(const std::filesystem::path& dir, const std::string& target = "");

}  // namespace ridefit::io
