// NLopt damper tuning: the optimum against a fine grid, every algorithm, constraints held,
// infeasibility, common random numbers, and what ignoring friction costs.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "ridefit/optimisation/friction_cost.h"
#include "ridefit/optimisation/nlopt_tuner.h"
#include "ridefit/optimisation/tradeoff_curve.h"
#include "ridefit/optimisation/tuning_problem.h"
#include "support/passat.h"
#include "support/temp_dir.h"
#include "support/tuning_study_text.h"

namespace ridefit::optimisation {
namespace {

using testing::dataset;
using testing::half_car_study;

struct GridBest {
  double objective = std::numeric_limits<double>::infinity();
  std::vector<double> x;
};

// The best feasible point of an n × n grid, uniform in ln c.
GridBest grid_search(TuningProblem& problem, int n) {
  GridBest best;
  const auto& design = problem.study().design;
  const auto limits = problem.study_limits();
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      std::vector<double> x(2);
      for (int v = 0; v < 2; ++v) {
        const double u = (v == 0 ? i : j) / static_cast<double>(n - 1);
        x[static_cast<std::size_t>(v)] = design[static_cast<std::size_t>(v)].lower *
                                         std::pow(design[static_cast<std::size_t>(v)].upper /
                                                      design[static_cast<std::size_t>(v)].lower,
                                                  u);
      }
      const Evaluation e = problem.evaluate(FrictionVariant::kStudy, Accuracy::kSearch, x);
      if (problem.max_violation(e, limits) <= 0.0 && e.objective < best.objective) {
        best = {e.objective, x};
      }
    }
  }
  return best;
}

// Every algorithm in one test, so that the 61 × 61 grid (the slow part) is computed once.
TEST(DamperTuning, EveryAlgorithmMatchesAFineGridAndHoldsTheLimit) {
  testing::TempDir dir("ridefit_tuning");
  const std::string coarse = "evaluation: {frequency_points: 250}\n";
  TuningProblem grid_problem(load_tuning_study(dir.write("grid.yaml", half_car_study(coarse))));
  const GridBest grid = grid_search(grid_problem, 61);
  ASSERT_TRUE(std::isfinite(grid.objective));
  for (const std::string algorithm : {"cobyla", "bobyqa", "isres", "direct_l", "mlsl"}) {
    SCOPED_TRACE(algorithm);
    const bool local = algorithm == "cobyla" || algorithm == "bobyqa";
    const std::string settings = coarse + "optimiser: {algorithm: " + algorithm +
                                 ", x_tolerance: 1.0e-4" +
                                 (local ? "" : ", max_evaluations: 1500") + "}\n";
    TuningProblem problem(
        load_tuning_study(dir.write(algorithm + ".yaml", half_car_study(settings))));
    const OptimisationRun run = optimise(problem, FrictionVariant::kStudy, problem.study_limits(),
                                         study_start(problem.study()));
    ASSERT_TRUE(run.feasible);
    // Within 1 % of the grid's best, and no worse than it beyond the grid's own resolution.
    const Evaluation at_search = run.best;
    EXPECT_NEAR(at_search.objective, grid.objective, 0.01 * grid.objective);
    EXPECT_LE(at_search.objective, grid.objective * 1.002);
    for (const auto& m : run.margins) {
      EXPECT_TRUE(m.holds) << m.description;
      EXPECT_GE(m.relative_margin, -problem.study().optimiser.constraint_tolerance);
    }
    // The limit is active: the optimum sits on it, not inside.
    EXPECT_LT(run.margins.front().relative_margin, 0.01);
    // Far fewer evaluations than the 3721-point grid.
    EXPECT_LT(run.evaluations, 1600);
  }
}

TEST(DamperTuning, ImpossibleLimitsAreReportedInfeasible) {
  testing::TempDir dir("ridefit_tuning");
  TuningProblem problem(load_tuning_study(dir.write("study.yaml", half_car_study("", 0.01))));
  const OptimisationRun run = optimise(problem, FrictionVariant::kStudy, problem.study_limits(),
                                       study_start(problem.study()));
  EXPECT_FALSE(run.feasible);
  ASSERT_EQ(run.margins.size(), 1u);
  EXPECT_FALSE(run.margins.front().holds);
  // The least violating design: stiff front damping lowers the tyre load only so far.
  EXPECT_GT(run.margins.front().value, 0.05);
}

TEST(DamperTuning, MoreStartsNeverEndWorse) {
  testing::TempDir dir("ridefit_tuning");
  TuningProblem one(load_tuning_study(dir.write("one.yaml", half_car_study(""))));
  TuningProblem five(load_tuning_study(
      dir.write("five.yaml", half_car_study("optimiser: {starts: 5, seed: 3}\n"))));
  const auto a =
      optimise(one, FrictionVariant::kStudy, one.study_limits(), study_start(one.study()));
  const auto b =
      optimise(five, FrictionVariant::kStudy, five.study_limits(), study_start(five.study()));
  EXPECT_LE(b.best.objective, a.best.objective * (1.0 + 1e-9));
  EXPECT_GT(b.evaluations, a.evaluations);
  std::set<int> starts;
  for (const auto& step : b.history) starts.insert(step.start);
  EXPECT_EQ(starts.size(), 5u);
}

TEST(DamperTuning, TradeoffTightensMonotonically) {
  testing::TempDir dir("ridefit_tuning");
  TuningProblem problem(load_tuning_study(dir.write(
      "study.yaml", half_car_study("tradeoff: {metric: front_dynamic_load_ratio, limits: [0.15, "
                                   "0.16, 0.17, 0.185, 0.2]}\n"))));
  const auto points = tradeoff_curve(problem, study_start(problem.study()));
  ASSERT_EQ(points.size(), 5u);
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_TRUE(points[i].run.feasible) << points[i].limit;
    EXPECT_LE(points[i].achieved, points[i].limit * 1.001);
    if (i > 0) {
      EXPECT_GT(points[i].limit, points[i - 1].limit);
      // A looser road-holding limit never costs comfort.
      EXPECT_LE(points[i].run.verified.objective, points[i - 1].run.verified.objective);
    }
  }
  // 0.2 is looser than the unconstrained optimum's 0.199: the last point is the free optimum.
  EXPECT_LT(points.back().achieved, 0.2);
  EXPECT_LT(points.back().run.verified.objective, 0.97 * points.front().run.verified.objective);
}

// The Passat corner with its stick/slip strut on 20 s of two roads, simulated.
std::string passat_study(const std::string& extra) {
  return "model: " + dataset("vehicles/passat_b8_front.yaml") +
         "\ndesign:\n"
         "  - {parameter: damping_Ns_per_m, lower: 300, upper: 6000, scale: log}\n"
         "load_cases:\n"
         "  - {road: " +
         dataset("excitations/iso8608_class_a_50kmh.yaml") +
         "}\n"
         "  - {road: " +
         dataset("excitations/gravel_road_seed001.yaml") +
         ", speed_km_per_h: 30}\n"
         "objective: {metric: body_acc_wk_rms_m_per_s2}\n"
         "evaluation: {duration_s: 20}\n" +
         extra;
}

TEST(DamperTuning, ObjectiveIsSmoothInTheDesign) {
  // Common random numbers: each case keeps its road, so ±1 % steps in damping trace a smooth
  // curve; a new road realisation per evaluation would scatter it by several per cent.
  testing::TempDir dir("ridefit_tuning");
  TuningProblem problem(load_tuning_study(dir.write("study.yaml", passat_study(""))));
  std::vector<double> c, j;
  for (int k = -5; k <= 5; ++k) {
    const double value = 1500.0 * (1.0 + 0.002 * k);
    c.push_back(value);
    j.push_back(
        problem.evaluate(FrictionVariant::kStudy, Accuracy::kSearch, std::vector{value}).objective);
  }
  // Second differences against the curve's own scale: a smooth function has them tiny.
  double largest = 0.0;
  for (std::size_t k = 1; k + 1 < j.size(); ++k) {
    largest = std::max(largest, std::abs(j[k - 1] - 2 * j[k] + j[k + 1]));
  }
  const double span = std::abs(j.back() - j.front());
  EXPECT_GT(span, 1e-4 * j.front());  // the curve does move over ±1 %
  EXPECT_LT(largest, 0.1 * span);
  // The same design twice: the same number, from the cache.
  const Evaluation again =
      problem.evaluate(FrictionVariant::kStudy, Accuracy::kSearch, std::vector{c[3]});
  EXPECT_TRUE(again.reused);
  EXPECT_EQ(again.objective, j[3]);
}

TEST(DamperTuning, FrictionAwareOptimumBeatsTheBlindOneWithFriction) {
  testing::TempDir dir("ridefit_tuning");
  TuningProblem problem(load_tuning_study(dir.write(
      "study.yaml", passat_study("constraints: [{metric: dynamic_load_ratio, max: 0.18}]\n"))));
  ASSERT_TRUE(problem.study().friction_cost);
  const auto aware = optimise(problem, FrictionVariant::kStudy, problem.study_limits(),
                              study_start(problem.study()));
  ASSERT_TRUE(aware.feasible);
  const FrictionCost cost = friction_cost(problem, aware);
  // Friction damps the body too, so the blind tuning over-damps: it ends at more damping ...
  EXPECT_GT(cost.blind.best.x[0], 1.03 * aware.best.x[0]);
  // ... which, with the real (friction) model, rides worse than the aware optimum.
  EXPECT_GT(cost.blind_with_friction.objective, aware.verified.objective);
  EXPECT_GT(cost.comfort_loss_percent, 0.5);
  // And the blind model promised better comfort than the car delivers.
  EXPECT_LT(cost.blind.verified.objective, cost.blind_with_friction.objective);
}

}  // namespace
}  // namespace ridefit::optimisation

namespace ridefit::optimisation {
namespace {

TEST(DamperTuning, VerifiedOptimumAgreesWithTheSearch) {
  const TuningStudy study = load_tuning_study(dataset("studies/seed001_damper_tuning_linear.yaml"));
  TuningProblem problem(study);
  const OptimisationRun run =
      optimise(problem, FrictionVariant::kStudy, problem.study_limits(), study_start(study));
  EXPECT_TRUE(run.feasible);
  // Four times the frequency points change the figures by far less than a per mille.
  EXPECT_NEAR(run.verified.objective, run.best.objective, 1e-3 * run.best.objective);
  EXPECT_EQ(run.verified.x, run.best.x);
}

}  // namespace
}  // namespace ridefit::optimisation

namespace ridefit::optimisation {
namespace {

TEST(DamperTuning, SemiActiveGainsAreDesignVariablesToo) {
  // Skyhook on seed 001's half car: the gain and the damper's upper limit, simulated. The
  // clipping kinks the objective; COBYLA stops early here (0.382 against 0.379 m/s²), BOBYQA
  // inside AUGLAG reaches the bound on the upper limit.
  testing::TempDir dir("ridefit_tuning");
  TuningProblem problem(load_tuning_study(dir.write(
      "study.yaml",
      "model: " + dataset("vehicles/ajayi_half_car.yaml") +
          "\nset: {control.law: skyhook}\n"
          "design:\n"
          "  - {parameter: control.skyhook_damping_Ns_per_m, lower: 300, upper: 8000, scale: log}\n"
          "  - {parameter: control.max_damping_Ns_per_m, lower: 1500, upper: 6000}\n"
          "load_cases: [{road: " +
          dataset("excitations/gravel_road_seed001.yaml") +
          ", speed_km_per_h: 30}]\n"
          "objective: {metric: seat_acc_wk_rms_m_per_s2}\n"
          "constraints: [{metric: front_dynamic_load_ratio, max: 0.3}]\n"
          "evaluation: {duration_s: 10}\noptimiser: {algorithm: bobyqa}\n")));
  const auto start = study_start(problem.study());
  const Evaluation at_start = problem.evaluate(FrictionVariant::kStudy, Accuracy::kSearch, start);
  EXPECT_FALSE(at_start.frequency_domain[0]);  // semi-active: simulated
  const auto run = optimise(problem, FrictionVariant::kStudy, problem.study_limits(), start);
  ASSERT_TRUE(run.feasible);
  EXPECT_NE(run.best.x, start);
  // No feasible point of a 5 × 5 grid rides better.
  double grid_best = 1e9;
  for (double gain : {300.0, 800.0, 2000.0, 4000.0, 8000.0}) {
    for (double max : {1500.0, 2500.0, 3500.0, 4500.0, 6000.0}) {
      const Evaluation e =
          problem.evaluate(FrictionVariant::kStudy, Accuracy::kSearch, std::vector{gain, max});
      if (problem.feasible(e, problem.study_limits())) grid_best = std::min(grid_best, e.objective);
    }
  }
  EXPECT_LE(run.best.objective, grid_best * 1.001);
}

}  // namespace
}  // namespace ridefit::optimisation
