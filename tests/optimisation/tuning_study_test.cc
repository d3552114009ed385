// The study file: defaults, friction from a fitted model, study-wide settings.
#include "ridefit/optimisation/tuning_study.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "ridefit/optimisation/tuning_model.h"
#include "support/passat.h"
#include "support/temp_dir.h"
#include "support/throws_input_error.h"

namespace ridefit::optimisation {
namespace {

using testing::dataset;

std::string cases() {
  return "load_cases: [{road: " + dataset("excitations/iso8608_class_a_50kmh.yaml") +
         ", speed_km_per_h: 30, weight: 3, set: {sprung_mass_kg: 445.4}}]\n"
         "objective: {metric: body_acc_wk_rms_m_per_s2, aggregate: worst_case}\n";
}

TEST(TuningStudy, DefaultsComeFromTheModel) {
  testing::TempDir dir("ridefit_study");
  const auto study = load_tuning_study(dir.write(
      "s.yaml", "model: " + dataset("vehicles/passat_b8_front.yaml") +
                    "\ndesign:\n  - {parameter: damping_Ns_per_m, lower: 300, upper: 6000}\n"
                    "  - {parameter: compression_to_rebound_ratio, lower: 0.3, upper: 1}\n" +
                    cases()));
  ASSERT_EQ(study.design.size(), 2u);
  EXPECT_DOUBLE_EQ(study.design[0].start, 886.9);  // the file's value
  EXPECT_DOUBLE_EQ(study.design[1].start, 1.0);    // the key's own default
  EXPECT_FALSE(study.design[0].log_scale);
  ASSERT_EQ(study.load_cases.size(), 1u);
  EXPECT_NEAR(*study.load_cases[0].speed_m_per_s, 30.0 / 3.6, 1e-12);
  EXPECT_EQ(study.load_cases[0].weight, 3.0);
  EXPECT_EQ(study.objective.aggregate, Aggregate::kWorstCase);
  EXPECT_TRUE(study.model_has_friction);  // Fc = 60 N in stick/slip
  EXPECT_TRUE(study.friction_cost);       // so the blind comparison runs by default
  EXPECT_EQ(study.optimiser.algorithm, Algorithm::kCobyla);
  // The case's laden mass reaches the model.
  const TuningModel model = build_tuning_model(study, FrictionVariant::kStudy, study.load_cases[0],
                                               std::vector{1000.0, 0.5}, "t");
  EXPECT_DOUBLE_EQ(model.quarter->parameters.sprung_mass_kg, 445.4);
  EXPECT_DOUBLE_EQ(model.quarter->parameters.damping_Ns_per_m, 1000.0);
  EXPECT_DOUBLE_EQ(model.quarter->parameters.compression_to_rebound_ratio, 0.5);
  // The blind variant drops the Dahl element and keeps everything else.
  const TuningModel blind = build_tuning_model(study, FrictionVariant::kBlind, study.load_cases[0],
                                               std::vector{1000.0, 0.5}, "t");
  EXPECT_EQ(blind.quarter->damper_state, model::DamperState::kSlip);
  EXPECT_DOUBLE_EQ(blind.quarter->parameters.damping_Ns_per_m, 1000.0);
}

TEST(TuningStudy, FrictionFromAFittedModel) {
  testing::TempDir dir("ridefit_study");
  std::ifstream in(dataset("vehicles/passat_b8_front.yaml"));
  std::stringstream text;
  text << in.rdbuf();
  std::string fitted = text.str();
  fitted.replace(fitted.find("coulomb_force_N: 60"), 19, "coulomb_force_N: 42.5");
  dir.write("fitted.yaml", fitted);
  const auto study = load_tuning_study(
      dir.write("s.yaml", "model: " + dataset("vehicles/passat_b8_front.yaml") +
                              "\nfriction: {fitted_model: fitted.yaml}\n"
                              "design: [{parameter: damping_Ns_per_m, lower: 300, upper: 6000}]\n" +
                              cases()));
  const TuningModel model = build_tuning_model(study, FrictionVariant::kStudy, study.load_cases[0],
                                               std::vector{900.0}, "t");
  EXPECT_DOUBLE_EQ(model.quarter->parameters.coulomb_force_N, 42.5);
  EXPECT_EQ(study.fitted_model.filename(), "fitted.yaml");
}

TEST(TuningStudy, HalfCarFrictionGoesToTheStrutAxleOnly) {
  testing::TempDir dir("ridefit_study");
  const auto study = load_tuning_study(dir.write(
      "s.yaml", "model: " + dataset("vehicles/ajayi_half_car.yaml") +
                    "\nset: {front.suspension: strut}\nfriction: {coulomb_force_N: 25}\n"
                    "design: [{parameter: [front.damping_Ns_per_m, rear.damping_Ns_per_m], "
                    "lower: 300, upper: 5000, name: damping_Ns_per_m}]\n"
                    "load_cases: [{road: " +
                    dataset("excitations/smooth_road_seed001.yaml") +
                    "}]\nobjective: {metric: seat_acc_wk_rms_m_per_s2}\n"));
  ASSERT_EQ(study.friction_values.size(), 1u);
  EXPECT_EQ(study.friction_values[0].first, "front.coulomb_force_N");
  const TuningModel model = build_tuning_model(study, FrictionVariant::kStudy, study.load_cases[0],
                                               std::vector{1234.0}, "t");
  EXPECT_EQ(model.half->topology.front.suspension, model::AxleSuspension::kStrut);
  EXPECT_DOUBLE_EQ(model.half->parameters.front.coulomb_force_N, 25.0);
  // One variable sets both axles.
  EXPECT_DOUBLE_EQ(model.half->parameters.front.damping_Ns_per_m, 1234.0);
  EXPECT_DOUBLE_EQ(model.half->parameters.rear.damping_Ns_per_m, 1234.0);
  EXPECT_TRUE(study.friction_cost);
}

TEST(TuningStudy, NoFrictionMeansNoFrictionCost) {
  testing::TempDir dir("ridefit_study");
  const std::string base = "model: " + dataset("vehicles/ajayi_half_car.yaml") +
                           "\ndesign: [{parameter: front.damping_Ns_per_m, lower: 300, upper: "
                           "5000}]\nload_cases: [{road: " +
                           dataset("excitations/smooth_road_seed001.yaml") +
                           "}]\nobjective: {metric: seat_acc_wk_rms_m_per_s2}\n";
  EXPECT_FALSE(load_tuning_study(dir.write("a.yaml", base)).friction_cost);
  EXPECT_TRUE(testing::throws_input_error(
      [&] { load_tuning_study(dir.write("b.yaml", base + "friction_cost: true\n")); },
      "nothing to ignore"));
}

}  // namespace
}  // namespace ridefit::optimisation
