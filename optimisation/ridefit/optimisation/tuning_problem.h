#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "ridefit/optimisation/evaluation_journal.h"
#include "ridefit/optimisation/load_case_metrics.h"
#include "ridefit/optimisation/tuning_model.h"
#include "ridefit/optimisation/tuning_study.h"

namespace ridefit::optimisation {

// One design evaluated on every load case, and the study's objective and constraint metrics
// aggregated over the cases.
struct Evaluation {
  std::vector<double> x;                         // design values, physical units
  std::vector<std::vector<double>> case_values;  // [load case][metric_names(kind)]
  std::vector<bool> frequency_domain;            // per load case
  double objective = 0.0;
  std::vector<double> constraint_values;  // aggregated metric, one per constraint
  bool reused = false;                    // from the journal or an earlier call
};

// How one constraint stands at an evaluation. margin = limit − value for a max, value − limit
// for a min: positive (or zero) when it holds.
struct ConstraintMargin {
  std::string description;  // with the limit used
  double limit = 0.0;
  double value = 0.0;
  double margin = 0.0;
  double relative_margin = 0.0;  // margin / limit
  bool holds = false;            // relative_margin >= −constraint_tolerance
};

// The study made ready to evaluate: each load case's road generated once (common random
// numbers), evaluations cached in memory, load cases run in parallel. Independent searches run
// on branches (branch()): each sees the evaluations known when it was made and keeps its own
// new ones, so what a search finds, and what it counts as reused, does not depend on which
// other searches run beside it, on which thread or on which rank.
class TuningProblem {
 public:
  explicit TuningProblem(TuningStudy study, EvaluationJournal* journal = nullptr);

  const TuningStudy& study() const { return prepared_->study; }
  // The journal's evaluations become known (reused, not recomputed), and every evaluation
  // computed from now on, here or in a branch, is appended to it (may be null).
  void attach_journal(EvaluationJournal* journal);
  // Evaluations known from elsewhere (a journal read on another rank, a branch's results) are
  // reused, not recomputed; the first of one design is kept. Not thread-safe with evaluate().
  void learn(const std::vector<JournalRecord>& records);

  // A problem sharing the study, the model and the roads, knowing what this one knows now,
  // appending to the same journal, with load cases on `case_threads` threads (0: every core).
  TuningProblem branch(unsigned case_threads) const;
  // The evaluations this problem computed (not reused) since the last call, in order.
  std::vector<JournalRecord> take_computed();

  // Thread-safe (two concurrent calls for one new design may both compute it). A design
  // already evaluated, in this run or in the journal, is not recomputed. An InputError or
  // RunError of a case names the study, the case and the design.
  Evaluation evaluate(FrictionVariant variant, Accuracy accuracy, std::span<const double> x);

  // Constraint i's normalised value, ≤ 0 when it holds: (value − limit)/limit for a max,
  // (limit − value)/limit for a min. `limits` replace the study's (the trade-off sweep).
  double normalised_constraint(const Evaluation& e, std::size_t i,
                               std::span<const double> limits) const;
  double max_violation(const Evaluation& e, std::span<const double> limits) const;  // ≥ 0
  bool feasible(const Evaluation& e, std::span<const double> limits) const;
  std::vector<ConstraintMargin> margins(const Evaluation& e, std::span<const double> limits) const;
  std::vector<double> study_limits() const;

  // The aggregated value of metric `index` over the cases.
  double aggregate(const Evaluation& e, std::size_t metric, Aggregate how, bool upper) const;
  std::size_t metric_index(const std::string& name) const;

  // Evaluation `e` completed from a record's case values (objective, constraints).
  Evaluation finish(std::vector<double> x, std::vector<std::vector<double>> case_values,
                    std::vector<bool> frequency_domain, bool reused) const;

 private:
  // What every branch shares and none changes.
  struct Prepared {
    TuningStudy study;
    TuningModel base;  // the study's model, read once; evaluations edit copies in memory
    std::vector<LoadCaseRoad> roads;
  };
  TuningProblem(std::shared_ptr<const Prepared> prepared, EvaluationJournal* journal,
                std::map<std::string, Evaluation> memory, unsigned case_threads);

  std::shared_ptr<const Prepared> prepared_;
  EvaluationJournal* journal_;
  unsigned case_threads_;
  std::map<std::string, Evaluation> memory_;
  std::vector<JournalRecord> computed_;
  mutable std::mutex mutex_;
};

// "study/search", "blind/verify", …: the journal's name for a variant and an accuracy.
std::string variant_name(FrictionVariant variant, Accuracy accuracy);

}  // namespace ridefit::optimisation
