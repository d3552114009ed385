#include "ridefit/optimisation/tuning_problem.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "ridefit/common/errors.h"
#include "ridefit/common/parallel_for.h"

namespace ridefit::optimisation {

std::string variant_name(FrictionVariant variant, Accuracy accuracy) {
  return std::string(variant == FrictionVariant::kStudy ? "study" : "blind") + "/" +
         (accuracy == Accuracy::kSearch ? "search" : "verify");
}

namespace {

// A study built in memory is held to the file reader's rules.
TuningStudy checked(TuningStudy study) {
  study.optimiser.validate();
  study.evaluation.validate();
  return study;
}

// The study's road per load case, generated once for all evaluations.
std::vector<LoadCaseRoad> prepare_roads(const TuningStudy& study) {
  std::vector<LoadCaseRoad> roads(study.load_cases.size());
  common::parallel_for(roads.size(), study.evaluation.threads,
                       [&](std::size_t c) { roads[c] = prepare_load_case_road(study, c); });
  return roads;
}

std::string memory_key(const std::string& variant, std::span<const double> x) {
  std::string key = variant;
  for (double v : x) key += fmt::format("|{:.17g}", v);
  return key;
}

}  // namespace

TuningProblem::TuningProblem(TuningStudy study, EvaluationJournal* journal)
    : journal_(nullptr), case_threads_(0) {
  auto prepared = std::make_shared<Prepared>();
  prepared->study = checked(std::move(study));
  prepared->base =
      load_base_model(prepared->study, fmt::format("{}: set", prepared->study.study_file.string()));
  prepared->roads = prepare_roads(prepared->study);
  case_threads_ = prepared->study.evaluation.threads;
  prepared_ = std::move(prepared);
  attach_journal(journal);
}

TuningProblem::TuningProblem(std::shared_ptr<const Prepared> prepared, EvaluationJournal* journal,
                             std::map<std::string, Evaluation> memory, unsigned case_threads)
    : prepared_(std::move(prepared)),
      journal_(journal),
      case_threads_(case_threads),
      memory_(std::move(memory)) {}

void TuningProblem::attach_journal(EvaluationJournal* journal) {
  journal_ = journal;
  if (journal_) learn(journal_->records());
}

void TuningProblem::learn(const std::vector<JournalRecord>& records) {
  const std::size_t cases = study().load_cases.size();
  for (const auto& r : records) {
    if (r.case_values.size() != cases) {
      throw InputError(
          fmt::format("journal {}: an evaluation has {} load cases, the study {}",
                      journal_ ? journal_->path().string() : std::string("(from rank 0)"),
                      r.case_values.size(), cases));
    }
    const std::string key = memory_key(r.variant, r.x);
    std::lock_guard lock(mutex_);
    if (memory_.count(key) == 0) {
      memory_[key] = finish(r.x, r.case_values, r.frequency_domain, true);
    }
  }
}

TuningProblem TuningProblem::branch(unsigned case_threads) const {
  std::lock_guard lock(mutex_);
  return TuningProblem(prepared_, journal_, memory_, case_threads);
}

std::vector<JournalRecord> TuningProblem::take_computed() {
  std::lock_guard lock(mutex_);
  return std::exchange(computed_, {});
}

std::size_t TuningProblem::metric_index(const std::string& name) const {
  const auto& names = metric_names(study().kind);
  return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
}

double TuningProblem::aggregate(const Evaluation& e, std::size_t metric, Aggregate how,
                                bool upper) const {
  if (how == Aggregate::kWorstCase) {
    double worst = e.case_values.front()[metric];
    for (const auto& values : e.case_values) {
      worst = upper ? std::max(worst, values[metric]) : std::min(worst, values[metric]);
    }
    return worst;
  }
  double sum = 0.0, weights = 0.0;
  for (std::size_t c = 0; c < e.case_values.size(); ++c) {
    sum += study().load_cases[c].weight * e.case_values[c][metric];
    weights += study().load_cases[c].weight;
  }
  return sum / weights;
}

Evaluation TuningProblem::finish(std::vector<double> x,
                                 std::vector<std::vector<double>> case_values,
                                 std::vector<bool> frequency_domain, bool reused) const {
  Evaluation e;
  e.x = std::move(x);
  e.case_values = std::move(case_values);
  e.frequency_domain = std::move(frequency_domain);
  e.reused = reused;
  e.objective =
      aggregate(e, metric_index(study().objective.metric), study().objective.aggregate, true);
  for (const auto& c : study().constraints) {
    e.constraint_values.push_back(aggregate(e, metric_index(c.metric), c.aggregate, c.is_upper));
  }
  return e;
}

Evaluation TuningProblem::evaluate(FrictionVariant variant, Accuracy accuracy,
                                   std::span<const double> x) {
  const std::string name = variant_name(variant, accuracy);
  const std::string key = memory_key(name, x);
  {
    std::lock_guard lock(mutex_);
    if (const auto it = memory_.find(key); it != memory_.end()) {
      Evaluation e = it->second;
      e.reused = true;
      return e;
    }
  }
  const std::size_t cases = study().load_cases.size();
  std::vector<std::vector<double>> values(cases);
  std::vector<bool> frequency(cases);
  std::vector<LoadCaseMetrics> metrics(cases);
  common::parallel_for(cases, case_threads_, [&](std::size_t c) {
    std::string origin = fmt::format("{}: load case '{}' at", study().study_file.string(),
                                     study().load_cases[c].name);
    for (std::size_t v = 0; v < x.size(); ++v) {
      origin += fmt::format(" {}={:g}", study().design[v].name, x[v]);
    }
    const TuningModel model =
        edit_tuning_model(prepared_->base, study(), variant, study().load_cases[c], x, origin);
    try {
      metrics[c] = evaluate_load_case(study(), model, prepared_->roads[c], accuracy,
                                      variant == FrictionVariant::kStudy);
    } catch (const RunError& e) {
      throw RunError(fmt::format("{}: {}", origin, e.what()));
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: {}", origin, e.what()));
    }
  });
  for (std::size_t c = 0; c < cases; ++c) {
    values[c] = std::move(metrics[c].values);
    frequency[c] = metrics[c].frequency_domain;
  }
  Evaluation e = finish(std::vector<double>(x.begin(), x.end()), values, frequency, false);
  const JournalRecord record{name, e.x, e.case_values, e.frequency_domain};
  if (journal_) journal_->append(record);
  std::lock_guard lock(mutex_);
  memory_[key] = e;
  computed_.push_back(record);
  return e;
}

std::vector<double> TuningProblem::study_limits() const {
  std::vector<double> limits;
  for (const auto& c : study().constraints) limits.push_back(c.limit);
  return limits;
}

double TuningProblem::normalised_constraint(const Evaluation& e, std::size_t i,
                                            std::span<const double> limits) const {
  const double value = e.constraint_values[i];
  const double limit = limits[i];
  return study().constraints[i].is_upper ? (value - limit) / limit : (limit - value) / limit;
}

double TuningProblem::max_violation(const Evaluation& e, std::span<const double> limits) const {
  double worst = 0.0;
  for (std::size_t i = 0; i < study().constraints.size(); ++i) {
    worst = std::max(worst, normalised_constraint(e, i, limits));
  }
  return worst;
}

bool TuningProblem::feasible(const Evaluation& e, std::span<const double> limits) const {
  return max_violation(e, limits) <= study().optimiser.constraint_tolerance;
}

std::vector<ConstraintMargin> TuningProblem::margins(const Evaluation& e,
                                                     std::span<const double> limits) const {
  std::vector<ConstraintMargin> out;
  for (std::size_t i = 0; i < study().constraints.size(); ++i) {
    Constraint c = study().constraints[i];
    c.limit = limits[i];
    ConstraintMargin m;
    m.description = c.describe();
    m.limit = c.limit;
    m.value = e.constraint_values[i];
    m.margin = c.is_upper ? c.limit - m.value : m.value - c.limit;
    m.relative_margin = m.margin / c.limit;
    m.holds = m.relative_margin >= -study().optimiser.constraint_tolerance;  // within tolerance
    out.push_back(m);
  }
  return out;
}

}  // namespace ridefit::optimisation
