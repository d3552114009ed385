// The study's optimiser and evaluation settings check themselves (error(), validate()) with the
// rule and wording the study file reader reports at the key's file and line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "ridefit/optimisation/tuning_problem.h"
#include "ridefit/optimisation/tuning_settings.h"
#include "ridefit/optimisation/tuning_study.h"
#include "support/throws_input_error.h"

namespace ridefit::optimisation {
namespace {

using testing::throws_input_error;

TEST(TuningSettings, DefaultsHoldAndEachRuleNamesItsKey) {
  EXPECT_FALSE(OptimiserSettings{}.error());
  EXPECT_FALSE(EvaluationSettings{}.error());
  auto key_of = [](const auto& s) { return s.error() ? s.error()->key : std::string("none"); };

  OptimiserSettings o;
  o.starts = 0;
  EXPECT_EQ(key_of(o), "starts");
  EXPECT_EQ(o.error()->message, "is 0, expected 1 … 1000");
  o = {};
  o.x_tolerance = 0.0;
  EXPECT_EQ(key_of(o), "x_tolerance");
  o = {};
  o.f_tolerance = -1e-9;
  EXPECT_EQ(key_of(o), "f_tolerance");
  o = {};
  o.max_evaluations = 0;
  EXPECT_EQ(key_of(o), "max_evaluations");
  o = {};
  o.initial_step = 1.5;
  EXPECT_EQ(key_of(o), "initial_step");
  o = {};
  o.constraint_tolerance = 0.02;
  EXPECT_EQ(key_of(o), "constraint_tolerance");
  o = {};
  o.max_time_s = -1.0;
  EXPECT_EQ(key_of(o), "max_time_s");
  o = {};
  o.algorithm = Algorithm::kDirectL;
  o.starts = 3;
  EXPECT_EQ(key_of(o), "starts");
  EXPECT_TRUE(throws_input_error([&] { o.validate(); },
                                 "optimiser setting 'starts' is 3, but DIRECT-L does not use"));

  EvaluationSettings e;
  e.output_rate_Hz = 0.0;
  EXPECT_EQ(key_of(e), "output_rate_Hz");
  e = {};
  e.settle_s = -1.0;
  EXPECT_EQ(key_of(e), "settle_s");
  e = {};
  e.duration_s = 2e5;
  EXPECT_EQ(key_of(e), "duration_s");
  e = {};
  e.relative_tolerance = 0.1;
  EXPECT_EQ(key_of(e), "relative_tolerance");
  e = {};
  e.verify_relative_tolerance = 0.0;
  EXPECT_EQ(key_of(e), "verify_relative_tolerance");
  e = {};
  e.frequency_points = 10;
  EXPECT_EQ(key_of(e), "frequency_points");
  e = {};
  e.threads = 2000;
  EXPECT_TRUE(throws_input_error([&] { e.validate(); },
                                 "evaluation setting 'threads' is 2000, expected 0 (every core)"));
  e = {};
  e.duration_s = std::nan("");
  EXPECT_EQ(key_of(e), "duration_s");  // NaN breaks every rule
}

std::filesystem::path study_with(const std::string& section) {
  const auto dir = std::filesystem::temp_directory_path() / "ridefit_tuning_settings_test";
  std::filesystem::create_directories(dir);
  const auto path = dir / "study.yaml";
  std::ofstream(path) << "model: " << RIDEFIT_SOURCE_DIR
                      << "/datasets/vehicles/passat_b8_front.yaml\n"
                         "design:\n  - {parameter: damping_Ns_per_m, lower: 300, upper: 6000}\n"
                         "load_cases:\n  - {road: "
                      << RIDEFIT_SOURCE_DIR
                      << "/datasets/excitations/iso8608_class_a_50kmh.yaml}\n"
                         "objective: {metric: body_acc_wk_rms_m_per_s2}\n"
                      << section;
  return path;
}

TEST(TuningSettings, TheStudyReaderReportsTheSameRuleAtTheKeysLine) {
  const auto path = study_with("optimiser: {starts: 0}\n");
  EXPECT_TRUE(throws_input_error([&] { load_tuning_study(path); },
                                 "key 'optimiser.starts' is 0, expected 1 … 1000"));
  const auto huge = study_with("optimiser: {max_evaluations: 99999999999}\n");
  EXPECT_TRUE(throws_input_error([&] { load_tuning_study(huge); },
                                 "key 'optimiser.max_evaluations' is 99999999999"));
  const auto zero = study_with("evaluation: {duration_s: 0}\n");  // 0 = the road's own length
  EXPECT_EQ(load_tuning_study(zero).evaluation.duration_s, 0.0);
}

TEST(TuningSettings, AStudyBuiltInMemoryIsHeldToTheSameRules) {
  TuningStudy study = load_tuning_study(study_with(""));
  study.evaluation.frequency_points = 3;
  EXPECT_TRUE(throws_input_error([&] { TuningProblem problem(study); },
                                 "evaluation setting 'frequency_points' is 3"));
}

}  // namespace
}  // namespace ridefit::optimisation
