// How a fit evaluates a record's Jacobian (hysteresis_fit.cc): many free values in two halves of
// Jet lanes on two threads, the same residuals and derivatives as one pass of Jets and the
// derivatives of the residuals the cost reports (central differences on the frozen steps); and
// the steps of the last run in doubles replayed for a Jacobian at the same point, never at
// another.
#include <ceres/cost_function.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "ridefit/fitting/hysteresis_fit.h"
#include "ridefit/fitting/strut_parameters.h"
#include "support/controlled_damper_record.h"

namespace ridefit::fitting {
namespace {

// An MR strut's fit as on the real random record: command law with its shape and lag, a
// blow-off knee, gas rate, offset and the load cell's moving mass (11 free values).
const std::vector<std::string> kFree = {"damping_Ns_per_m",
                                        "dahl_sigma0_N_per_m",
                                        "force_offset_N",
                                        "gas_stiffness_N_per_m",
                                        "damping_per_command_Ns_per_m",
                                        "coulomb_force_per_command_N",
                                        "command_lag_s",
                                        "command_exponent",
                                        "damper_knee_velocity_m_per_s",
                                        "damping_above_knee_Ns_per_m",
                                        "moving_mass_kg"};

model::StrutTestParameters<double> evaluated_at() {
  auto p = testing::mr_strut();
  p.command_exponent = 0.8;
  p.damper_knee_velocity_m_per_s = 0.05;
  p.damping_above_knee_Ns_per_m = 400.0;
  p.gas_stiffness_N_per_m = 2000.0;
  p.force_offset_N = 20.0;
  p.moving_mass_kg = 2.5;
  return p;
}

HysteresisRecord controlled_record() {
  // CVODE at rtol 1e-10 under a random motion and a switching command (not the ESDIRK the cost
  // runs; any record would do for the derivatives, a realistic one keeps every lane busy).
  return testing::cvode_controlled_record(testing::mr_strut(), testing::random_rig_motion(7),
                                          testing::switching_command(3, 2.0, 2.0), 2.0, 1000.0);
}

struct Evaluation {
  std::vector<double> residuals;
  std::vector<std::vector<double>> jacobian;  // per free value, per residual
};

Evaluation evaluate(ceres::CostFunction& cost, std::vector<double> values, bool with_jacobian) {
  const std::size_t m = static_cast<std::size_t>(cost.num_residuals());
  Evaluation e{std::vector<double>(m),
               std::vector<std::vector<double>>(values.size(), std::vector<double>(m, 0.0))};
  std::vector<const double*> blocks;
  for (double& v : values) blocks.push_back(&v);
  std::vector<double*> columns;
  for (auto& c : e.jacobian) columns.push_back(c.data());
  EXPECT_TRUE(
      cost.Evaluate(blocks.data(), e.residuals.data(), with_jacobian ? columns.data() : nullptr));
  return e;
}

std::vector<double> values_of(const model::StrutTestParameters<double>& p) {
  std::vector<double> v;
  for (const auto& name : kFree) v.push_back(strut_parameter(p, strut_parameter_index(name)));
  return v;
}

void expect_same(const Evaluation& a, const Evaluation& b, const std::string& what) {
  for (std::size_t k = 0; k < a.residuals.size(); ++k) {
    ASSERT_NEAR(a.residuals[k], b.residuals[k], 1e-9 * (1.0 + std::abs(b.residuals[k])))
        << what << ", residual " << k;
  }
  for (std::size_t j = 0; j < a.jacobian.size(); ++j) {
    double scale = 0.0, worst = 0.0;
    for (std::size_t k = 0; k < a.residuals.size(); ++k) {
      scale = std::max(scale, std::abs(b.jacobian[j][k]));
      worst = std::max(worst, std::abs(a.jacobian[j][k] - b.jacobian[j][k]));
    }
    EXPECT_GT(scale, 0.0) << what << ": " << kFree[j];
    EXPECT_LE(worst, 1e-10 * scale) << what << ": " << kFree[j];
  }
}

TEST(JacobianPasses, SplitJacobianIsTheOnePassJacobian) {
  const auto record = controlled_record();
  const auto at = evaluated_at();
  std::unique_ptr<ceres::CostFunction> split(
      make_hysteresis_cost(record, at, kFree, {}, {JacobianPasses::kSplitAcrossTwoCores}));
  std::unique_ptr<ceres::CostFunction> one(
      make_hysteresis_cost(record, at, kFree, {}, {JacobianPasses::kOnePass}));
  const auto a = evaluate(*split, values_of(at), true);
  expect_same(a, evaluate(*one, values_of(at), true), "split against one pass");
  // The residuals without a Jacobian are the run's own (not a replay): within its tolerance.
  const auto plain = evaluate(*split, values_of(at), false);
  double spread = 0.0, worst = 0.0;
  for (std::size_t k = 0; k < plain.residuals.size(); ++k) {
    spread = std::max(spread, std::abs(record.force_N[k]));
    worst = std::max(worst, std::abs(plain.residuals[k] - a.residuals[k]));
  }
  EXPECT_LT(worst, 1e-3 * spread);
}

// Central differences of the discrete map the split Jacobian belongs to (the steps frozen).
TEST(JacobianPasses, SplitJacobianMatchesCentralDifferencesOnFrozenSteps) {
  const auto record = controlled_record();
  const auto at = evaluated_at();
  simulate::StrutTestSolverOptions solver;
  const auto steps = simulate::strut_test_steps(record.time_s, record.displacement_m, at, solver,
                                                record.command, record.velocity_m_per_s);
  solver.frozen_steps = &steps;
  std::unique_ptr<ceres::CostFunction> cost(
      make_hysteresis_cost(record, at, kFree, solver, {JacobianPasses::kSplitAcrossTwoCores}));
  const std::vector<double> values = values_of(at);
  const auto exact = evaluate(*cost, values, true);
  for (std::size_t j = 0; j < kFree.size(); ++j) {
    const double step = 1e-6 * std::max(std::abs(values[j]), 1e-3);
    auto up = values, down = values;
    up[j] += step;
    down[j] -= step;
    const auto plus = evaluate(*cost, up, false);
    const auto minus = evaluate(*cost, down, false);
    double scale = 0.0, worst = 0.0;
    for (std::size_t k = 0; k < exact.residuals.size(); ++k) {
      const double numeric = (plus.residuals[k] - minus.residuals[k]) / (2.0 * step);
      scale = std::max(scale, std::abs(exact.jacobian[j][k]));
      worst = std::max(worst, std::abs(numeric - exact.jacobian[j][k]));
    }
    EXPECT_GT(scale, 0.0) << kFree[j];
    EXPECT_LT(worst, 1e-5 * scale) << kFree[j];
  }
}

// Both passes, each with and without kept steps, against a cost that runs afresh every time.
TEST(JacobianPasses, KeptStepsServeTheJacobianAtTheirPointOnly) {
  const auto record = controlled_record();
  const auto at = evaluated_at();
  auto elsewhere = at;
  elsewhere.damping_Ns_per_m *= 1.2;
  elsewhere.command_lag_s *= 0.7;
  for (const auto passes : {JacobianPasses::kSplitAcrossTwoCores, JacobianPasses::kOnePass}) {
    const std::string name =
        passes == JacobianPasses::kOnePass ? "one pass" : "split across two cores";
    std::unique_ptr<ceres::CostFunction> fresh(
        make_hysteresis_cost(record, at, kFree, {}, {passes, false}));
    std::unique_ptr<ceres::CostFunction> kept(
        make_hysteresis_cost(record, at, kFree, {}, {passes, true}));
    // The residuals at a point, then the Jacobian there: the kept steps are replayed.
    const auto trial = evaluate(*kept, values_of(at), false);
    const auto jacobian = evaluate(*kept, values_of(at), true);
    expect_same(jacobian, evaluate(*fresh, values_of(at), true), name + ", at the kept point");
    // (the replay takes one Newton step from each recorded stage, converged to 1e-5 of the
    // tolerance): measured 4e-9 of the largest force, against the integration's own 3e-5 at
    // rtol 1e-6 (strut_test_response.h)
    double spread = 0.0, worst = 0.0;
    for (std::size_t k = 0; k < trial.residuals.size(); ++k) {
      spread = std::max(spread, std::abs(record.force_N[k]));
      worst = std::max(worst, std::abs(trial.residuals[k] - jacobian.residuals[k]));
    }
    EXPECT_LT(worst, 1e-7 * spread) << name << ": the replay reproduces the run it follows";
    // The residuals at one point, the Jacobian at another: the steps are not reused.
    evaluate(*kept, values_of(at), false);
    expect_same(evaluate(*kept, values_of(elsewhere), true),
                evaluate(*fresh, values_of(elsewhere), true), name + ", elsewhere");
  }
}

}  // namespace
}  // namespace ridefit::fitting
