// A reference rig record written as a rig CSV reads back as the same record.
#include "ridefit/synthetic/rig_csv.h"

#include <gtest/gtest.h>

#include <cmath>

#include "ridefit/synthetic/multisine.h"
#include "ridefit/synthetic/reference_rig_record.h"
#include "ridefit/synthetic/switching_command.h"
#include "support/temp_dir.h"

namespace ridefit::synthetic {
namespace {

TEST(SyntheticRigCsv, ReferenceRecordReadsBackAtThePrintedResolution) {
  const auto strut = model::dahl_strut_on_rig(5e6, 60.0, 1.0, 488000.0, 886.9);
  std::mt19937_64 rng(1);
  const SwitchingCommand current(2.0, 2.0, rng);
  const Multisine x = lab_three_sines();
  const auto record = reference_rig_record(sample_times(401, 200.0), x, strut, current, "rig");
  ASSERT_EQ(record.time_s.size(), 401u);
  EXPECT_EQ(record.time_s.back(), 2.0);
  EXPECT_EQ(record.displacement_m[37], x(37 / 200.0));
  EXPECT_EQ(record.command[37], current(37 / 200.0));
  testing::TempDir dir("ridefit_rig_csv");
  for (const auto digits : {RigCsvDigits::kFixed, RigCsvDigits::kSixSignificant}) {
    write_rig_csv(dir.path() / "rig.csv", record, digits);
    const auto back = fitting::load_hysteresis_record(dir.path() / "rig.csv");
    ASSERT_EQ(back.force_N.size(), record.force_N.size());
    EXPECT_EQ(back.command_unit, "A");
    for (std::size_t k = 0; k < record.time_s.size(); ++k) {
      EXPECT_NEAR(back.time_s[k], record.time_s[k], 5e-5);
      EXPECT_NEAR(back.displacement_m[k], record.displacement_m[k], 6e-9);
      EXPECT_NEAR(back.force_N[k], record.force_N[k], 5e-4 * (1.0 + std::abs(record.force_N[k])));
      EXPECT_NEAR(back.command[k], record.command[k], 6e-6);
    }
  }
  const std::string text = testing::text_of(dir.path() / "rig.csv");
  EXPECT_EQ(text.substr(0, text.find('\n')), "time[s],displacement[mm],force[N],current[A]");
}

}  // namespace
}  // namespace ridefit::synthetic
