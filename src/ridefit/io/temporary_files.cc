#include "ridefit/io/temporary_files.h"

#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <mutex>
#include <regex>

namespace ridefit::io {

namespace fs = std::filesystem;

namespace {

constexpr int kSlots = 64;
constexpr std::size_t kPathBytes = 4096;

// Fixed storage the signal handler reads without allocating: a slot is in use while its flag
// is 1 (set after the path is written, cleared before it is reused).
std::array<std::array<char, kPathBytes>, kSlots> g_paths{};
std::array<std::atomic<int>, kSlots> g_path_used{};
std::array<std::atomic<pid_t>, kSlots> g_children{};
std::mutex g_mutex;

void on_signal(int signal_number) {
  for (int k = 0; k < kSlots; ++k) {
    const pid_t child = g_children[k].load();
    if (child > 0) kill(child, SIGTERM);
  }
  for (int k = 0; k < kSlots; ++k) {
    if (g_path_used[k].load() == 1) unlink(g_paths[k].data());
  }
  // Die of the signal, as the caller expects (exit status 128 + signal in a shell).
  struct sigaction action {};
  action.sa_handler = SIG_DFL;
  sigemptyset(&action.sa_mask);
  sigaction(signal_number, &action, nullptr);
  raise(signal_number);
}

bool process_runs(long pid) {
  if (pid <= 0) return true;
  return kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
}

}  // namespace

void install_temporary_cleanup() {
  static std::once_flag once;
  std::call_once(once, [] {
    struct sigaction action {};
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaction(s, &action, nullptr);
  });
}

TemporaryFile::TemporaryFile(const fs::path& path) {
  const std::string text = fs::absolute(path).string();
  if (text.size() >= kPathBytes) return;
  std::lock_guard lock(g_mutex);
  for (int k = 0; k < kSlots; ++k) {
    if (g_path_used[k].load() != 0) continue;
    std::memcpy(g_paths[k].data(), text.c_str(), text.size() + 1);
    g_path_used[k].store(1);
    slot_ = k;
    return;
  }
}

TemporaryFile::~TemporaryFile() {
  if (slot_ < 0) return;
  std::lock_guard lock(g_mutex);
  g_path_used[slot_].store(0);
}

ChildProcess::ChildProcess(pid_t pid) {
  std::lock_guard lock(g_mutex);
  for (int k = 0; k < kSlots; ++k) {
    if (g_children[k].load() != 0) continue;
    g_children[k].store(pid);
    slot_ = k;
    return;
  }
}

ChildProcess::~ChildProcess() {
  if (slot_ < 0) return;
  std::lock_guard lock(g_mutex);
  g_children[slot_].store(0);
}

long temporary_owner(const std::string& filename) {
  static const std::regex atomic(R"(^\..+\.tmp(\d+)$)");
  static const std::regex figure(R"(^\..+\.(\d+)\.(gp|log|png|svg)$)");
  std::smatch match;
  if (std::regex_match(filename, match, atomic) || std::regex_match(filename, match, figure)) {
    return std::stol(match[1].str());
  }
  return 0;
}

void remove_stale_temporaries(const fs::path& dir, const std::string& target) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir.empty() ? fs::path(".") : dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (!target.empty() && !name.starts_with("." + target + ".")) continue;
    const long owner = temporary_owner(name);
    if (owner == 0 || owner == static_cast<long>(getpid()) || process_runs(owner)) continue;
    std::error_code ignored;
    fs::remove_all(entry.path(), ignored);  // a staged folder (staged_folder.h) too
  }
}

}  // namespace ridefit::io
