// The optimiser's models edited in memory (edit_tuning_model) are the models the file reader
// builds from the same values (build_tuning_model), field for field, for every shipped tuning
// study, both friction variants, every load case, the start and both ends of every variable.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ridefit/model/half_car_parameter_table.h"
#include "ridefit/model/quarter_car_parameter_table.h"
#include "ridefit/optimisation/tuning_model.h"
#include "support/passat.h"
#include "support/throws_input_error.h"

namespace ridefit::optimisation {
namespace {

using testing::dataset;

void expect_same(const TuningModel& a, const TuningModel& b) {
  ASSERT_EQ(a.quarter.has_value(), b.quarter.has_value());
  if (a.quarter) {
    EXPECT_EQ(a.quarter->damper_state, b.quarter->damper_state);
    for (std::size_t i = 0; i < model::kQuarterCarParameters.size(); ++i) {
      EXPECT_EQ(model::quarter_car_parameter(a.quarter->parameters, i),
                model::quarter_car_parameter(b.quarter->parameters, i))
          << model::kQuarterCarParameters[i].key;
    }
    EXPECT_EQ(a.quarter->parameters.tyre_lift_off, b.quarter->parameters.tyre_lift_off);
    EXPECT_EQ(a.quarter->parameters.sensors.acc_sensor_order,
              b.quarter->parameters.sensors.acc_sensor_order);
    return;
  }
  auto pa = a.half->parameters, pb = b.half->parameters;
  auto ta = a.half->topology, tb = b.half->topology;
  std::vector<std::string> keys;
  for (const auto& row : model::kHalfCarBodyParameters) keys.emplace_back(row.key);
  for (const char* axle : {"front", "rear"}) {
    for (const auto i : model::half_car_axle_rows()) {
      keys.push_back(std::string(axle) + "." + std::string(model::kQuarterCarParameters[i].key));
    }
  }
  for (const char* mass : {"seat", "lower_body", "upper_body"}) {
    for (const auto& row : model::kSuspendedMassParameters) {
      keys.push_back(std::string(mass) + "." + std::string(row.key));
    }
  }
  for (const auto& row : model::kControlParameters)
    keys.push_back("control." + std::string(row.key));
  for (const auto& key : keys) {
    EXPECT_EQ(*model::half_car_field(pa, ta.control, key)->value,
              *model::half_car_field(pb, tb.control, key)->value)
        << key;
  }
  for (auto [x, y] : {std::pair{ta.front, tb.front}, {ta.rear, tb.rear}}) {
    EXPECT_EQ(x.suspension, y.suspension);
    EXPECT_EQ(x.damper_state, y.damper_state);
  }
  EXPECT_EQ(ta.control.law, tb.control.law);
  EXPECT_EQ(ta.upper_body_support, tb.upper_body_support);
}

class ShippedStudy : public ::testing::TestWithParam<std::string> {};

TEST_P(ShippedStudy, InMemoryModelsAreTheFileReadersModels) {
  const TuningStudy study = load_tuning_study(dataset("studies/" + GetParam()));
  const TuningModel base = load_base_model(study, "t");
  std::vector<std::vector<double>> points;
  std::vector<double> start;
  for (const auto& v : study.design) start.push_back(v.start);
  points.push_back(start);
  for (std::size_t v = 0; v < study.design.size(); ++v) {
    for (double value : {study.design[v].lower, study.design[v].upper}) {
      points.push_back(start);
      points.back()[v] = value;
    }
  }
  for (const auto variant : {FrictionVariant::kStudy, FrictionVariant::kBlind}) {
    for (const auto& load_case : study.load_cases) {
      for (const auto& x : points) {
        SCOPED_TRACE(load_case.name);
        expect_same(edit_tuning_model(base, study, variant, load_case, x, "t"),
                    build_tuning_model(study, variant, load_case, x, "t"));
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Studies, ShippedStudy,
                         ::testing::Values("passat_damper_tuning.yaml", "ajayi_damper_tuning.yaml",
                                           "seed001_damper_tuning_linear.yaml"));

TEST(InMemoryTuningModel, AValueTheModelRefusesNamesTheKeyAndWhereItCameFrom) {
  const TuningStudy study = load_tuning_study(dataset("studies/passat_damper_tuning.yaml"));
  const TuningModel base = load_base_model(study, "t");
  std::vector<double> x;
  for (const auto& v : study.design) x.push_back(v.start);
  x[0] = -5.0;  // outside the bounds the loader checked
  EXPECT_TRUE(testing::throws_input_error(
      [&] {
        edit_tuning_model(base, study, FrictionVariant::kStudy, study.load_cases[0], x,
                          "study.yaml: load case 'a'");
      },
      fmt::format("study.yaml: load case 'a': '{}' is -5, expected", study.design[0].keys[0])));
}

}  // namespace
}  // namespace ridefit::optimisation
