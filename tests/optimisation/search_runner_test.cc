// Searches side by side: a tuning's outcome does not depend on how its searches are spread
// (threads here; ranks in tests/mpi/optimise_ranks_test.sh), branches see what their parent
// knew and keep their own evaluations, and runs travel between ranks as bytes exactly.
#include "ridefit/optimisation/search_runner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "ridefit/optimisation/nlopt_tuner.h"
#include "ridefit/optimisation/run_bytes.h"
#include "ridefit/optimisation/tuning_outcome.h"
#include "support/temp_dir.h"
#include "support/tuning_study_text.h"

namespace ridefit::optimisation {
namespace {

// testing::half_car_study with `starts` starts of `algorithm` and a trade-off of two points.
std::string study_text(const std::string& algorithm, int starts) {
  return testing::half_car_study(
      "optimiser: {algorithm: " + algorithm + ", starts: " + std::to_string(starts) +
      ", max_evaluations: 60, seed: 7}\n"
      "evaluation: {frequency_points: 250}\n"
      "tradeoff: {metric: front_dynamic_load_ratio, limits: [0.16, 0.2]}\n");
}

// Runs the searches last first, one at a time: another order than any thread pool's, as a
// rank layout could give.
class BackwardsRunner final : public SearchRunner {
 public:
  std::vector<OptimisationRun> run(TuningProblem& problem,
                                   const std::vector<SearchTask>& tasks) override {
    std::vector<OptimisationRun> runs(tasks.size());
    std::vector<std::vector<JournalRecord>> computed(tasks.size());
    for (std::size_t k = tasks.size(); k-- > 0;) {
      TuningProblem branch = problem.branch(1);
      runs[k] = tasks[k](branch);
      computed[k] = branch.take_computed();
    }
    for (const auto& records : computed) problem.learn(records);
    return runs;
  }
};

void expect_same_evaluation(const Evaluation& a, const Evaluation& b) {
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.case_values, b.case_values);
  EXPECT_EQ(a.frequency_domain, b.frequency_domain);
  EXPECT_EQ(a.objective, b.objective);
  EXPECT_EQ(a.constraint_values, b.constraint_values);
  EXPECT_EQ(a.reused, b.reused);
}

void expect_same_run(const OptimisationRun& a, const OptimisationRun& b) {
  EXPECT_EQ(a.variant, b.variant);
  EXPECT_EQ(a.limits, b.limits);
  expect_same_evaluation(a.best, b.best);
  expect_same_evaluation(a.verified, b.verified);
  EXPECT_EQ(a.feasible, b.feasible);
  ASSERT_EQ(a.margins.size(), b.margins.size());
  for (std::size_t i = 0; i < a.margins.size(); ++i) {
    EXPECT_EQ(a.margins[i].description, b.margins[i].description);
    EXPECT_EQ(a.margins[i].margin, b.margins[i].margin);
    EXPECT_EQ(a.margins[i].holds, b.margins[i].holds);
  }
  EXPECT_EQ(a.nlopt_result, b.nlopt_result);
  EXPECT_EQ(a.evaluations, b.evaluations);
  EXPECT_EQ(a.computed, b.computed);
  ASSERT_EQ(a.history.size(), b.history.size());
  for (std::size_t i = 0; i < a.history.size(); ++i) {
    EXPECT_EQ(a.history[i].start, b.history[i].start);
    EXPECT_EQ(a.history[i].objective, b.history[i].objective);
    EXPECT_EQ(a.history[i].max_violation, b.history[i].max_violation);
    EXPECT_EQ(a.history[i].reused, b.history[i].reused);
  }
}

void expect_same_outcome(const TuningOutcome& a, const TuningOutcome& b) {
  expect_same_run(a.aware, b.aware);
  ASSERT_EQ(a.friction.has_value(), b.friction.has_value());
  if (a.friction) {
    expect_same_run(a.friction->blind, b.friction->blind);
    EXPECT_EQ(a.friction->comfort_loss, b.friction->comfort_loss);
  }
  ASSERT_EQ(a.tradeoff.size(), b.tradeoff.size());
  for (std::size_t i = 0; i < a.tradeoff.size(); ++i) {
    EXPECT_EQ(a.tradeoff[i].limit, b.tradeoff[i].limit);
    EXPECT_EQ(a.tradeoff[i].achieved, b.tradeoff[i].achieved);
    expect_same_run(a.tradeoff[i].run, b.tradeoff[i].run);
  }
}

// COBYLA (deterministic) and ISRES (NLopt's seeded generator, which must not be shared between
// searches on different threads), each from several starts.
TEST(SearchRunner, TheOutcomeDoesNotDependOnHowTheSearchesAreSpread) {
  testing::TempDir dir("ridefit_search_runner");
  for (const auto& [algorithm, starts] :
       std::vector<std::pair<std::string, int>>{{"cobyla", 4}, {"isres", 3}}) {
    SCOPED_TRACE(algorithm);
    const auto file = dir.write(algorithm + ".yaml", study_text(algorithm, starts));
    TuningProblem one(load_tuning_study(file));
    LocalSearchRunner one_thread(1);
    const TuningOutcome reference = run_tuning_study(one, {}, &one_thread);
    ASSERT_TRUE(reference.aware.feasible);
    ASSERT_EQ(reference.tradeoff.size(), 2u);
    std::set<int> used;
    for (const auto& step : reference.aware.history) used.insert(step.start);
    EXPECT_EQ(used.size(), static_cast<std::size_t>(starts));

    TuningProblem three(load_tuning_study(file));
    LocalSearchRunner three_threads(3);
    expect_same_outcome(reference, run_tuning_study(three, {}, &three_threads));

    TuningProblem backwards(load_tuning_study(file));
    BackwardsRunner backwards_runner;
    expect_same_outcome(reference, run_tuning_study(backwards, {}, &backwards_runner));
  }
}

TEST(SearchRunner, BranchesSeeWhatTheParentKnewAndKeepTheirOwn) {
  testing::TempDir dir("ridefit_search_runner");
  TuningProblem parent(load_tuning_study(dir.write("s.yaml", study_text("cobyla", 1))));
  const std::vector<double> known{1000.0, 1200.0};
  const std::vector<double> fresh{1500.0, 900.0};
  EXPECT_FALSE(parent.evaluate(FrictionVariant::kStudy, Accuracy::kSearch, known).reused);
  EXPECT_EQ(parent.take_computed().size(), 1u);

  TuningProblem branch = parent.branch(1);
  EXPECT_TRUE(branch.evaluate(FrictionVariant::kStudy, Accuracy::kSearch, known).reused);
  const Evaluation e = branch.evaluate(FrictionVariant::kStudy, Accuracy::kSearch, fresh);
  EXPECT_FALSE(e.reused);
  // Another accuracy is another evaluation.
  EXPECT_FALSE(branch.evaluate(FrictionVariant::kStudy, Accuracy::kVerify, known).reused);
  const std::vector<JournalRecord> computed = branch.take_computed();
  ASSERT_EQ(computed.size(), 2u);
  EXPECT_EQ(computed[0].variant, "study/search");
  EXPECT_EQ(computed[0].x, fresh);
  EXPECT_TRUE(branch.take_computed().empty());

  // A sibling does not see its sibling's evaluations; the parent, once told, does.
  TuningProblem sibling = parent.branch(1);
  EXPECT_FALSE(sibling.evaluate(FrictionVariant::kStudy, Accuracy::kSearch, fresh).reused);
  parent.learn(computed);
  const Evaluation learnt = parent.evaluate(FrictionVariant::kStudy, Accuracy::kSearch, fresh);
  EXPECT_TRUE(learnt.reused);
  EXPECT_EQ(learnt.objective, e.objective);
  EXPECT_EQ(learnt.case_values, e.case_values);
  EXPECT_TRUE(parent.take_computed().empty());
}

TEST(SearchRunner, RunsTravelAsBytesExactly) {
  testing::TempDir dir("ridefit_search_runner");
  TuningProblem problem(load_tuning_study(dir.write("s.yaml", study_text("cobyla", 2))));
  const OptimisationRun run = optimise(problem, FrictionVariant::kStudy, problem.study_limits(),
                                       study_start(problem.study()));
  ASSERT_GT(run.history.size(), 5u);
  ASSERT_FALSE(run.margins.empty());
  std::vector<JournalRecord> records = {
      {"blind/verify", {1.0 / 3.0, 2e-300}, {{0.1, 0.2}, {0.3, 1e300}}, {true, false}}};
  const std::string bytes = run_to_bytes(run, records);
  const auto [back, back_records] = run_from_bytes(bytes);
  expect_same_run(run, back);
  ASSERT_EQ(back_records.size(), 1u);
  EXPECT_EQ(back_records[0].variant, records[0].variant);
  EXPECT_EQ(back_records[0].x, records[0].x);
  EXPECT_EQ(back_records[0].case_values, records[0].case_values);
  EXPECT_EQ(back_records[0].frequency_domain, records[0].frequency_domain);
  const auto only_records = records_from_bytes(records_to_bytes(records));
  ASSERT_EQ(only_records.size(), 1u);
  EXPECT_EQ(only_records[0].x, records[0].x);
  // Cut short or with bytes left over: an error, never a run made up.
  EXPECT_THROW(run_from_bytes(bytes.substr(0, bytes.size() - 3)), std::out_of_range);
  EXPECT_THROW(run_from_bytes(bytes + "x"), std::logic_error);
}

}  // namespace
}  // namespace ridefit::optimisation
