// Rig test files (io/rig_test_file.h): each waveform's keys, the rig's limits from the file or
// its own file, and messages that name the file and key.
#include "ridefit/io/rig_test_file.h"

#include <gtest/gtest.h>

#include <string>

#include "support/temp_dir.h"
#include "support/throws_input_error.h"

namespace ridefit::io {
namespace {

using testing::throws_input_error;

TEST(RigTestFile, ReadsEachWaveformAndTheRigsLimits) {
  testing::TempDir dir("rig_test_file");
  const RigTestFile sine = load_rig_test(dir.write(
      "sine.yaml",
      "waveform: sine\namplitude_m: 0.01\nfrequency_Hz: 2\nduration_s: 5\nsample_rate_Hz: 500\n"));
  EXPECT_EQ(sine.test.waveform, road::RigWaveform::kSine);
  EXPECT_DOUBLE_EQ(sine.test.amplitude_m, 0.01);
  EXPECT_DOUBLE_EQ(sine.test.frequency_Hz, 2.0);
  EXPECT_DOUBLE_EQ(sine.test.sample_rate_Hz, 500.0);
  EXPECT_DOUBLE_EQ(sine.limits.stroke_m, 0.05);  // the default rig
  const RigTestFile triangle = load_rig_test(
      dir.write("triangle.yaml",
                "waveform: triangle\namplitude_m: 0.003\nspeed_m_per_s: 0.001\nduration_s: 12\n"
                "rig: {stroke_m: 0.1, force_N: 5000}\n"));
  EXPECT_EQ(triangle.test.waveform, road::RigWaveform::kTriangle);
  EXPECT_DOUBLE_EQ(triangle.test.speed_m_per_s, 0.001);
  EXPECT_DOUBLE_EQ(triangle.test.sample_rate_Hz, 1000.0);  // the default rate
  EXPECT_DOUBLE_EQ(triangle.limits.stroke_m, 0.1);
  EXPECT_DOUBLE_EQ(triangle.limits.force_N, 5000.0);
  EXPECT_DOUBLE_EQ(triangle.limits.velocity_m_per_s, 1.5);
  const RigTestFile random = load_rig_test(
      dir.write("random.yaml",
                "waveform: random\nrms_m: 0.002\nband_Hz: [0.5, 20]\nseed: 7\nduration_s: 20\n"));
  EXPECT_EQ(random.test.waveform, road::RigWaveform::kRandom);
  EXPECT_DOUBLE_EQ(random.test.band_low_Hz, 0.5);
  EXPECT_DOUBLE_EQ(random.test.band_high_Hz, 20.0);
  EXPECT_EQ(random.test.seed, 7u);
  // A rig file: its keys at the top level, or a model's `rig:` block.
  const road::RigLimits own =
      load_rig_limits(dir.write("rig.yaml", "stroke_m: 0.075\nfrequency_Hz: 50\n"));
  EXPECT_DOUBLE_EQ(own.stroke_m, 0.075);
  EXPECT_DOUBLE_EQ(own.frequency_Hz, 50.0);
  EXPECT_DOUBLE_EQ(own.force_N, 20e3);
  EXPECT_DOUBLE_EQ(load_rig_limits(dir.write("block.yaml", "rig:\n  force_N: 8000\n")).force_N,
                   8000.0);
  // The limits given to the reader hold unless the file has its own.
  road::RigLimits short_rig;
  short_rig.stroke_m = 0.005;
  EXPECT_TRUE(throws_input_error(
      [&] { load_rig_test(dir.path() / "sine.yaml", short_rig); },
      "sine.yaml: amplitude_m: the test reaches ±10 mm, beyond the rig's stroke (±5 mm"));
}

TEST(RigTestFile, BadFilesNameTheFileAndKey) {
  testing::TempDir dir("rig_test_file_bad");
  const struct {
    std::string text;
    std::string words;
  } cases[] = {
      {"waveform: square\nduration_s: 5\n", "key 'waveform' is 'square', expected one of"},
      {"waveform: sine\nfrequency_Hz: 2\nduration_s: 5\n", "amplitude_m"},
      {"waveform: sine\namplitude_m: 0.01\nfrequency_Hz: 2\nduration_s: 5\nspeed_m_per_s: 1\n",
       "unknown key 'speed_m_per_s'"},
      {"waveform: random\nrms_m: 0.002\nband_Hz: [1, 2, 3]\nduration_s: 5\n",
       "holds 3 numbers; give two, [low, high] in Hz"},
      {"waveform: random\nrms_m: 0.002\nband_Hz: [1, 5]\nseed: -4\nduration_s: 5\n",
       "give a whole number from 0 to 4294967295"},
      {"waveform: sine\namplitude_m: 0.01\nfrequency_Hz: 2\nduration_s: 5\nrig: {force_N: -5}\n",
       "rig.force_N: -5 is not a positive finite number"},
      {"waveform: sine\namplitude_m: 0.01\nfrequency_Hz: 2\nduration_s: 5\nrig: {torque: 5}\n",
       "unknown key 'torque'"},
      {"waveform: sine\namplitude_m: 0.001\nfrequency_Hz: 50\nduration_s: 5\n",
       "frequency_Hz: the test's motion reaches 50 Hz, above the 30 Hz the rig follows"},
  };
  int i = 0;
  for (const auto& c : cases) {
    const std::string name = "bad" + std::to_string(i++) + ".yaml";
    const auto path = dir.write(name, c.text);
    EXPECT_TRUE(throws_input_error([&] { load_rig_test(path); }, c.words)) << c.text;
    EXPECT_TRUE(throws_input_error([&] { load_rig_test(path); }, name)) << c.text;
  }
}

}  // namespace
}  // namespace ridefit::io
