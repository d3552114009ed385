#include "ridefit/optimisation/tuning_problem.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

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

}  // namespace

TuningProblem::TuningProblem(TuningStudy study, EvaluationJournal* journal)
    : study_(checked(std::move(study))),
      base_(load_base_model(study_, fmt::format("{}: set", study_.study_file.string()))),
      journal_(journal) {
  roads_.resize(study_.load_cases.size());
  common::parallel_for(roads_.size(), study_.evaluation.threads,
                       [&](std::size_t c) { roads_[c] = prepare_load_case_road(study_, c); });
}

std::size_t TuningProblem::metric_index(const std::string& name) const {
  const auto& names = metric_names(study_.kind);
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
    sum += study_.load_cases[c].weight * e.case_values[c][metric];
    weights += study_.load_cases[c].weight;
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
      aggregate(e, metric_index(study_.objective.metric), study_.objective.aggregate, true);
  for (const auto& c : study_.constraints) {
    e.constraint_values.push_back(aggregate(e, metric_index(c.metric), c.aggregate, c.is_upper));
  }
  return e;
}

Evaluation TuningProblem::evaluate(FrictionVariant variant, Accuracy accuracy,
                                   std::span<const double> x) {
  const std::string name = variant_name(variant, accuracy);
  std::string key = name;
  for (double v : x) key += fmt::format("|{:.17g}", v);
  {
    std::lock_guard lock(mutex_);
    if (const auto it = memory_.find(key); it != memory_.end()) {
      ++reused_;
      Evaluation e = it->second;
      e.reused = true;
      return e;
    }
  }
  if (journal_) {
    if (auto record = journal_->find(name, x)) {
      if (record->case_values.size() != study_.load_cases.size()) {
        throw InputError(fmt::format("journal {}: an evaluation has {} load cases, the study {}",
                                     journal_->path().string(), record->case_values.size(),
                                     study_.load_cases.size()));
      }
      Evaluation e = finish(record->x, record->case_values, record->frequency_domain, true);
      std::lock_guard lock(mutex_);
      memory_[key] = e;
      ++reused_;
      return e;
    }
  }
  const std::size_t cases = study_.load_cases.size();
  std::vector<std::vector<double>> values(cases);
  std::vector<bool> frequency(cases);
  std::vector<LoadCaseMetrics> metrics(cases);
  common::parallel_for(cases, study_.evaluation.threads, [&](std::size_t c) {
    std::string origin =
        fmt::format("{}: load case '{}' at", study_.study_file.string(), study_.load_cases[c].name);
    for (std::size_t v = 0; v < x.size(); ++v) {
      origin += fmt::format(" {}={:g}", study_.design[v].name, x[v]);
    }
    const TuningModel model =
        edit_tuning_model(base_, study_, variant, study_.load_cases[c], x, origin);
    try {
      metrics[c] = evaluate_load_case(study_, model, roads_[c], accuracy,
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
  if (journal_) journal_->append({name, e.x, e.case_values, e.frequency_domain});
  std::lock_guard lock(mutex_);
  memory_[key] = e;
  ++computed_;
  return e;
}

std::vector<double> TuningProblem::study_limits() const {
  std::vector<double> limits;
  for (const auto& c : study_.constraints) limits.push_back(c.limit);
  return limits;
}

double TuningProblem::normalised_constraint(const Evaluation& e, std::size_t i,
                                            std::span<const double> limits) const {
  const double value = e.constraint_values[i];
  const double limit = limits[i];
  return study_.constraints[i].is_upper ? (value - limit) / limit : (limit - value) / limit;
}

double TuningProblem::max_violation(const Evaluation& e, std::span<const double> limits) const {
  double worst = 0.0;
  for (std::size_t i = 0; i < study_.constraints.size(); ++i) {
    worst = std::max(worst, normalised_constraint(e, i, limits));
  }
  return worst;
}

bool TuningProblem::feasible(const Evaluation& e, std::span<const double> limits) const {
  return max_violation(e, limits) <= study_.optimiser.constraint_tolerance;
}

std::vector<ConstraintMargin> TuningProblem::margins(const Evaluation& e,
                                                     std::span<const double> limits) const {
  std::vector<ConstraintMargin> out;
  for (std::size_t i = 0; i < study_.constraints.size(); ++i) {
    Constraint c = study_.constraints[i];
    c.limit = limits[i];
    ConstraintMargin m;
    m.description = c.describe();
    m.limit = c.limit;
    m.value = e.constraint_values[i];
    m.margin = c.is_upper ? c.limit - m.value : m.value - c.limit;
    m.relative_margin = m.margin / c.limit;
    m.holds = m.relative_margin >= -study_.optimiser.constraint_tolerance;  // within tolerance
    out.push_back(m);
  }
  return out;
}

}  // namespace ridefit::optimisation
