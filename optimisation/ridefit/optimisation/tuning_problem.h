#pragma once

#include <atomic>
#include <map>
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
// numbers), evaluations cached in memory and in the journal, load cases run in parallel.
class TuningProblem {
 public:
  explicit TuningProblem(TuningStudy study, EvaluationJournal* journal = nullptr);

  const TuningStudy& study() const { return study_; }
  // Evaluations from now on are looked up in and appended to `journal` (may be null).
  void attach_journal(EvaluationJournal* journal) { journal_ = journal; }

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

  std::size_t computed_evaluations() const { return computed_; }
  std::size_t reused_evaluations() const { return reused_; }

 private:
  Evaluation finish(std::vector<double> x, std::vector<std::vector<double>> case_values,
                    std::vector<bool> frequency_domain, bool reused) const;

  TuningStudy study_;
  TuningModel base_;  // the study's model, read once; evaluations edit copies in memory
  EvaluationJournal* journal_;
  std::vector<LoadCaseRoad> roads_;
  std::map<std::string, Evaluation> memory_;
  std::mutex mutex_;
  std::atomic<std::size_t> computed_{0}, reused_{0};
};

// "study/search", "blind/verify", …: the journal's name for a variant and an accuracy.
std::string variant_name(FrictionVariant variant, Accuracy accuracy);

}  // namespace ridefit::optimisation
