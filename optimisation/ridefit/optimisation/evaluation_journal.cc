#include "ridefit/optimisation/evaluation_journal.h"

#include <fmt/core.h>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>
#include <sstream>

#include "ridefit/common/errors.h"
#include "ridefit/io/path_type.h"
#include "ridefit/optimisation/tuning_files.h"

namespace ridefit::optimisation {
namespace {

constexpr const char* kFormat = "ridefit-optimise-journal-1";
constexpr const char* kFinished = "{\"finished\":true}";

std::string read_all(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot be read", path.string()));
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

JournalRecord record_of(const nlohmann::json& j) {
  JournalRecord r;
  r.variant = j.at("variant").get<std::string>();
  r.x = j.at("x").get<std::vector<double>>();
  r.case_values = j.at("cases").get<std::vector<std::vector<double>>>();
  r.frequency_domain = j.at("frequency_domain").get<std::vector<bool>>();
  if (r.case_values.size() != r.frequency_domain.size())
    throw std::runtime_error("case counts differ");
  return r;
}

std::string json_number(double v) { return fmt::format("{:.17g}", v); }

// The process holding a flock on the file `fd` refers to, from /proc/locks (Linux); 0 unknown.
long lock_holder(int fd) {
  struct stat st {};
  if (fstat(fd, &st) != 0) return 0;
  std::ifstream locks("/proc/locks");
  std::string line;
  while (std::getline(locks, line)) {
    std::istringstream fields(line);
    std::string number, kind, mode, access, pid, device;
    fields >> number >> kind;
    if (kind == "->") fields >> kind;  // a waiter
    fields >> mode >> access >> pid >> device;
    if (kind != "FLOCK") continue;
    const auto last = device.rfind(':');
    if (last == std::string::npos) continue;
    if (device.substr(last + 1) == std::to_string(st.st_ino)) {
      const long holder = std::strtol(pid.c_str(), nullptr, 10);
      if (holder != getpid()) return holder;
    }
  }
  return 0;
}

// Opens (creating if missing, never truncating) and locks the journal at `path`.
int lock_journal(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) {
    throw InputError(
        fmt::format("journal {}: cannot be opened: {}", path.string(), std::strerror(errno)));
  }
  if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    const long holder = lock_holder(fd);
    ::close(fd);
    if (error == EWOULDBLOCK) {
      throw InputError(fmt::format(
          "journal {}: in use by {} (another optimisation writes it); wait for it to finish or "
          "give another journal",
          path.string(), holder > 0 ? fmt::format("process {}", holder) : "another process"));
    }
    throw InputError(
        fmt::format("journal {}: cannot be locked: {}", path.string(), std::strerror(error)));
  }
  return fd;
}

}  // namespace

EvaluationJournal::EvaluationJournal(std::filesystem::path path, std::ofstream out, int lock_fd)
    : path_(std::move(path)), out_(std::move(out)), lock_fd_(lock_fd) {}

EvaluationJournal::EvaluationJournal(EvaluationJournal&& other) noexcept
    : path_(std::move(other.path_)),
      out_(std::move(other.out_)),
      lock_fd_(other.lock_fd_),
      records_(std::move(other.records_)) {
  other.lock_fd_ = -1;
}

EvaluationJournal::~EvaluationJournal() {
  if (lock_fd_ >= 0) ::close(lock_fd_);  // releases the flock
}

std::string EvaluationJournal::key(const std::string& variant, std::span<const double> x) {
  std::string k = variant;
  for (double v : x) k += fmt::format("|{:.17g}", v);
  return k;
}

EvaluationJournal EvaluationJournal::create(const std::filesystem::path& path,
                                            const std::string& fingerprint,
                                            bool replace_evaluations) {
  if (io::is_folder(path)) {
    throw InputError(fmt::format("journal {}: is a directory, not a journal file", path.string()));
  }
  const int fd = lock_journal(path);
  try {
    if (!replace_evaluations) {
      // Lines after the header are evaluations (a torn last one included), up to the last
      // mark of a finished run.
      std::istringstream lines(read_all(path));
      std::string line;
      std::size_t number = 0, unfinished = 0;
      while (std::getline(lines, line)) {
        if (++number == 1 || line.empty()) continue;
        unfinished = line == kFinished ? 0 : unfinished + 1;
      }
      if (unfinished > 0) {
        throw InputError(fmt::format(
            "journal {}: holds {} evaluations of a run that did not finish, which starting afresh "
            "would lose; resume it, or replace it explicitly",
            path.string(), unfinished));
      }
    }
    std::ofstream out(path, std::ios::trunc);
    if (!out) throw InputError(fmt::format("journal {}: cannot be written", path.string()));
    out << nlohmann::json{{"format", kFormat}, {"study", fingerprint}}.dump() << "\n" << std::flush;
    return EvaluationJournal(path, std::move(out), fd);
  } catch (...) {
    ::close(fd);
    throw;
  }
}

EvaluationJournal EvaluationJournal::resume(const std::filesystem::path& path,
                                            const std::string& fingerprint, const Shape& shape) {
  if (io::is_folder(path)) {
    throw InputError(fmt::format("journal {}: is a directory, not a journal file", path.string()));
  }
  if (!io::exists_as_file(path)) {
    throw InputError(fmt::format("journal {}: no such journal file", path.string()));
  }
  const int fd = lock_journal(path);
  struct Unlock {
    int fd;
    ~Unlock() {
      if (fd >= 0) ::close(fd);
    }
  } unlock{fd};
  const std::string text = read_all(path);
  // A run killed while writing leaves a last line without its newline: it is not read, and cut
  // off once the journal is known to be this study's.
  const std::size_t complete = text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1;
  std::istringstream lines(text.substr(0, complete));
  std::string line;
  // Line 1 first: nothing is touched unless this is the study's own journal.
  nlohmann::json header;
  if (!std::getline(lines, line) || line.empty()) {
    throw InputError(
        fmt::format("journal {}: the journal is empty (or its first line is torn)", path.string()));
  }
  try {
    header = nlohmann::json::parse(line);
  } catch (const nlohmann::json::exception&) {
    throw InputError(
        fmt::format("journal {}: line 1 is not JSON; is this a ridefit journal?", path.string()));
  }
  // A string member read only when it is one: json::value() throws on another type.
  const auto text_of = [&](const char* key) -> std::string {
    const auto it = header.find(key);
    return it != header.end() && it->is_string() ? it->get<std::string>() : std::string();
  };
  if (!header.is_object() || text_of("format") != kFormat) {
    throw InputError(
        fmt::format("journal {}: not a ridefit optimise journal (line 1 has no \"format\": \"{}\")",
                    path.string(), kFormat));
  }
  if (text_of("study") != fingerprint) {
    throw InputError(fmt::format(
        "journal {}: the journal belongs to another study or to different model or road "
        "files (fingerprint {} here, {} in the journal); start a new journal",
        path.string(), fingerprint, text_of("study")));
  }
  std::map<std::string, JournalRecord> records;
  std::size_t number = 1;
  while (std::getline(lines, line)) {
    ++number;
    auto bad = [&](const std::string& why) {
      return InputError(fmt::format("journal {}: line {} is not an evaluation of this study ({})",
                                    path.string(), number, why));
    };
    if (line == kFinished) continue;
    JournalRecord r;
    try {
      r = record_of(nlohmann::json::parse(line));
    } catch (const std::exception& e) {
      throw bad(e.what());
    }
    if (r.x.size() != shape.variables) {
      throw bad(fmt::format("{} design values, the study has {}", r.x.size(), shape.variables));
    }
    if (r.case_values.size() != shape.cases) {
      throw bad(fmt::format("{} load cases, the study has {}", r.case_values.size(), shape.cases));
    }
    for (const auto& values : r.case_values) {
      if (values.size() != shape.metrics) {
        throw bad(fmt::format("{} metrics per case, expected {}", values.size(), shape.metrics));
      }
      for (double v : values) {
        if (!std::isfinite(v) || v < 0.0) throw bad(fmt::format("a metric is {}", v));
      }
    }
    for (double v : r.x) {
      if (!std::isfinite(v)) throw bad("a design value is not finite");
    }
    records[key(r.variant, r.x)] = std::move(r);
  }
  if (complete < text.size()) std::filesystem::resize_file(path, complete);
  std::ofstream out(path, std::ios::app);
  if (!out) throw InputError(fmt::format("journal {}: cannot be appended to", path.string()));
  EvaluationJournal journal(path, std::move(out), fd);
  unlock.fd = -1;
  journal.records_ = std::move(records);
  return journal;
}

std::optional<JournalRecord> EvaluationJournal::find(const std::string& variant,
                                                     std::span<const double> x) const {
  std::lock_guard lock(mutex_);
  const auto it = records_.find(key(variant, x));
  if (it == records_.end()) return std::nullopt;
  return it->second;
}

void EvaluationJournal::append(const JournalRecord& r) {
  // Numbers are formatted by hand: 17 significant digits round-trip every double.
  auto numbers = [](std::span<const double> values) {
    std::vector<std::string> texts;
    for (double v : values) texts.push_back(json_number(v));
    return fmt::format("[{}]", fmt::join(texts, ","));
  };
  std::vector<std::string> cases, domains;
  for (const auto& values : r.case_values) cases.push_back(numbers(values));
  for (bool f : r.frequency_domain) domains.push_back(f ? "true" : "false");
  const std::string line =
      fmt::format("{{\"variant\":{},\"x\":{},\"cases\":[{}],\"frequency_domain\":[{}]}}\n",
                  nlohmann::json(r.variant).dump(), numbers(r.x), fmt::join(cases, ","),
                  fmt::join(domains, ","));
  std::lock_guard lock(mutex_);
  const auto [it, added] = records_.emplace(key(r.variant, r.x), r);
  if (!added) return;  // two searches met at one design: once is enough
  out_ << line << std::flush;
  if (!out_) throw RunError(fmt::format("journal {}: write failed", path_.string()));
}

std::vector<JournalRecord> EvaluationJournal::records() const {
  std::lock_guard lock(mutex_);
  std::vector<JournalRecord> all;
  all.reserve(records_.size());
  for (const auto& [key, record] : records_) all.push_back(record);
  return all;
}

void EvaluationJournal::mark_finished() {
  std::lock_guard lock(mutex_);
  out_ << kFinished << "\n" << std::flush;
  if (!out_) throw RunError(fmt::format("journal {}: write failed", path_.string()));
}

std::size_t EvaluationJournal::size() const {
  std::lock_guard lock(mutex_);
  return records_.size();
}

std::string study_fingerprint(const TuningStudy& study) {
  std::uint64_t hash = 1469598103934665603ULL;
  auto add = [&](const std::filesystem::path& path) {
    for (unsigned char c : read_all(path)) {
      hash ^= c;
      hash *= 1099511628211ULL;
    }
  };
  for (const auto& path : study_inputs(study)) add(path);
  return fmt::format("{:016x}", hash);
}

}  // namespace ridefit::optimisation
