#include "ridefit/io/json_to_yaml.h"

#include <gtest/gtest.h>

#include <sstream>

namespace ridefit::io {
namespace {

// A result file is the --json tree as YAML: it must read back as the same values and types.
TEST(JsonToYaml, KeepsTheTreeAndItsTypes) {
  const nlohmann::json j = {{"status", "optimum"},
                            {"evaluations", 42},
                            {"value", 0.318125},
                            {"feasible", true},
                            {"variables", {{"damping_Ns_per_m", 1234.5}}},
                            {"points", {1.5, 2.5}}};
  std::stringstream text;
  text << to_yaml(j);
  const YAML::Node back = YAML::Load(text.str());
  EXPECT_EQ(back["status"].as<std::string>(), "optimum");
  EXPECT_EQ(back["evaluations"].as<int>(), 42);
  EXPECT_DOUBLE_EQ(back["value"].as<double>(), 0.318125);
  EXPECT_TRUE(back["feasible"].as<bool>());
  EXPECT_DOUBLE_EQ(back["variables"]["damping_Ns_per_m"].as<double>(), 1234.5);
  ASSERT_TRUE(back["points"].IsSequence());
  EXPECT_DOUBLE_EQ(back["points"][1].as<double>(), 2.5);
}

}  // namespace
}  // namespace ridefit::io
