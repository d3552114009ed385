#include "ridefit/study/recording_analysis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "support/input_error_message.h"

namespace ridefit::study {
namespace {

// 20 s of a 2 Hz body sine of `amplitude` and a constant `stuck` flag, at `rate_Hz`.
Recording sine_recording(const std::string& name, double amplitude, double rate_Hz = 1000.0) {
  std::vector<double> t, a, stuck;
  for (int i = 0; i < static_cast<int>(20.0 * rate_Hz); ++i) {
    t.push_back(i / rate_Hz);
    a.push_back(amplitude * std::sin(2.0 * std::numbers::pi * 2.0 * t.back()));
    stuck.push_back(0.0);
  }
  Recording r;
  r.source = name;
  r.table = io::CsvTable(name);
  r.table.add("time", "s", t);
  r.table.add("body_acc", "m/s^2", a);
  r.table.add("stuck", "1", stuck);
  r.sample_rate_Hz = rate_Hz;
  return r;
}

TEST(RecordingAnalysis, DefaultChannelsLeaveOutTimeAndStuckAndWeightBodyWithWk) {
  const std::vector<Recording> recordings = {sine_recording("a.csv", 1.0)};
  const RecordingAnalysis analysis = analyse_recordings(recordings, {});
  ASSERT_EQ(analysis.recordings[0].channels.size(), 1u);
  const ChannelMetrics& body = analysis.recordings[0].channels[0];
  ASSERT_TRUE(body.weighted.has_value());
  EXPECT_EQ(body.weighted->weighting, comfort::Weighting::kWk);
  // The band RMS over 0.5–30 Hz holds the whole 2 Hz sine: A/√2.
  EXPECT_NEAR(body.band_rms, 1.0 / std::sqrt(2.0), 0.01);
  RecordingAnalysisOptions unweighted;
  unweighted.weighting.by_channel_name = false;
  EXPECT_FALSE(analyse_recordings(recordings, unweighted).recordings[0].channels[0].weighted);
}

TEST(RecordingAnalysis, MissingChannelAndMixedRatesNameTheFile) {
  RecordingAnalysisOptions options;
  options.channels = {"seat_acc"};
  const std::vector<Recording> one = {sine_recording("a.csv", 1.0)};
  const std::string missing =
      testing::input_error_message([&] { analyse_recordings(one, options); });
  EXPECT_NE(missing.find("seat_acc"), std::string::npos) << missing;
  EXPECT_NE(missing.find("body_acc"), std::string::npos) << missing;  // what the file has
  const std::vector<Recording> mixed = {sine_recording("a.csv", 1.0),
                                        sine_recording("b.csv", 1.0, 800.0)};
  const std::string rates = testing::input_error_message([&] { analyse_recordings(mixed, {}); });
  EXPECT_NE(rates.find("b.csv"), std::string::npos) << rates;
}

TEST(RecordingAnalysis, CorrelationNeedsThreeLevelsAndSkipsConstantMetrics) {
  const std::vector<Recording> recordings = {
      sine_recording("a.csv", 1.0), sine_recording("b.csv", 2.0), sine_recording("c.csv", 4.0)};
  const RecordingAnalysis analysis = analyse_recordings(recordings, {});
  const std::vector<double> two_levels = {1.0, 1.0, 2.0};
  EXPECT_NE(testing::input_error_message([&] {
              correlate_with_levels(analysis, two_levels);
            }).find("at least 3"),
            std::string::npos);
  const std::vector<double> levels = {1.0, 2.0, 4.0};
  const auto rows = correlate_with_levels(analysis, levels);
  bool saw_rms = false;
  for (const auto& row : rows) {
    EXPECT_NE(row.metric, "crest_factor");  // √2 for every sine: no correlation to report
    if (row.metric == "rms") {
      saw_rms = true;
      EXPECT_NEAR(row.pearson_r, 1.0, 1e-12);
      EXPECT_NEAR(row.slope, 1.0 / std::sqrt(2.0), 1e-3);
      ASSERT_TRUE(row.relative_increase.has_value());
      EXPECT_NEAR(*row.relative_increase, 3.0, 1e-9);
    }
  }
  EXPECT_TRUE(saw_rms);
}

}  // namespace
}  // namespace ridefit::study
