// Record k of a random road is another realisation; the scratch file does not outlive the call.
#include "ridefit/synthetic/road_realisation.h"

#include <gtest/gtest.h>

#include "support/passat.h"
#include "support/temp_dir.h"

namespace ridefit::synthetic {
namespace {

TEST(SyntheticRoadRealisation, RecordTwoIsAnotherSeedOfTheSameRoad) {
  testing::TempDir dir("ridefit_road_realisation");
  const std::filesystem::path excitation =
      testing::dataset("hidden/roads/iso8608_class_c_50kmh_30s.yaml");
  const auto scratch = dir.path() / ".road.yaml.tmp1";
  const auto first = load_road_realisation(excitation, 1, scratch);
  const auto again = load_road_realisation(excitation, 1, scratch);
  const auto second = load_road_realisation(excitation, 2, scratch);
  EXPECT_FALSE(std::filesystem::exists(scratch));
  EXPECT_EQ(first->at(12.3).elevation_m, again->at(12.3).elevation_m);
  EXPECT_NE(first->at(12.3).elevation_m, second->at(12.3).elevation_m);
  EXPECT_EQ(first->duration_s(), second->duration_s());
  // Seed 2 written into the file gives the same road as record 2.
  const auto seed2 = dir.write("seed2.yaml",
                               "type: iso8608\nclass: C\nspeed_km_per_h: 50\nduration_s: 30\n"
                               "seed: 2\n");
  const auto expected = load_road_realisation(seed2, 1, scratch);
  EXPECT_EQ(second->at(12.3).elevation_m, expected->at(12.3).elevation_m);
}

}  // namespace
}  // namespace ridefit::synthetic
