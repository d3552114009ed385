#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "ridefit/optimisation/tuning_study.h"

namespace ridefit::optimisation {

// One finished evaluation: which model variant and accuracy (e.g. "friction/search"), the
// design values, and every metric of every load case (so objective and constraints, whatever
// their limits, follow from it).
struct JournalRecord {
  std::string variant;
  std::vector<double> x;
  std::vector<std::vector<double>> case_values;  // [load case][metric_names(kind)]
  std::vector<bool> frequency_domain;            // per load case
};

// An append-only journal of evaluations, one JSON object per line, written and flushed as
// each evaluation finishes, so a killed run loses at most the evaluations in flight. The
// first line names the journal format and the study's fingerprint. Resuming reads every
// complete line back; an optimiser replaying its (deterministic) path then finds the finished
// evaluations here instead of repeating them. x is written with 17 significant digits, which
// round-trips a double exactly, so a replayed point matches bit for bit.
class EvaluationJournal {
 public:
  // A new journal at `path`. The journal is locked (an advisory flock held until this object
  // goes away): a journal another process holds is an InputError naming that process. An
  // existing journal of a run that did not finish (evaluations after the last mark_finished())
  // is replaced only with `replace_evaluations`, else it is an InputError saying how many
  // evaluations it holds (nothing is touched).
  static EvaluationJournal create(const std::filesystem::path& path, const std::string& fingerprint,
                                  bool replace_evaluations = false);
  // What each line of this study's journal holds.
  struct Shape {
    std::size_t variables = 0;
    std::size_t cases = 0;
    std::size_t metrics = 0;
  };
  // Continues the journal at `path`, locked like create(). InputError when it is missing, not a
  // ridefit journal, or belongs to another study (fingerprint) — checked before anything is
  // written; then a torn last line (the run was killed while writing) is cut off, and any other
  // malformed line (not JSON, or x, cases or metrics of another size than `shape`, or a metric that
  // is not a finite number >= 0) is an InputError naming its line number.
  static EvaluationJournal resume(const std::filesystem::path& path, const std::string& fingerprint,
                                  const Shape& shape);

  EvaluationJournal(EvaluationJournal&& other) noexcept;
  EvaluationJournal& operator=(EvaluationJournal&&) = delete;
  ~EvaluationJournal();

  std::optional<JournalRecord> find(const std::string& variant, std::span<const double> x) const;
  // Every evaluation it holds (one per variant and design).
  std::vector<JournalRecord> records() const;
  // Thread-safe; a design the journal holds already (for the variant) is not written again.
  void append(const JournalRecord& record);
  // Marks the run finished (a line resume() skips): a later create() may replace the journal.
  void mark_finished();
  std::size_t size() const;
  const std::filesystem::path& path() const { return path_; }

 private:
  EvaluationJournal(std::filesystem::path path, std::ofstream out, int lock_fd);
  static std::string key(const std::string& variant, std::span<const double> x);

  std::filesystem::path path_;
  std::ofstream out_;
  int lock_fd_ = -1;  // holds the flock
  std::map<std::string, JournalRecord> records_;
  mutable std::mutex mutex_;
};

// A hash (FNV-1a, 64 bit, hex) of the study file, the model file, the fitted model and every
// road file: a journal only resumes the study it was written for.
std::string study_fingerprint(const TuningStudy& study);

}  // namespace ridefit::optimisation
