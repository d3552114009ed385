#include "ridefit/optimisation/tuning_files.h"

#include <gtest/gtest.h>

namespace ridefit::optimisation {
namespace {

TuningStudy study_with_tradeoff(bool tradeoff) {
  TuningStudy study;
  study.study_file = "studies/passat.yaml";
  study.model_file = "vehicles/passat.yaml";
  study.load_cases.push_back({});
  study.load_cases.back().road_file = "roads/smooth.yaml";
  if (tradeoff) study.tradeoff = Tradeoff{0, {0.2, 0.3}};
  return study;
}

TEST(TuningFiles, ModelTradeoffAndJournalGoBesideTheResult) {
  const TuningFiles files = tuning_files(study_with_tradeoff(true), "out/result.yaml", "");
  EXPECT_EQ(files.model, "out/result_model.yaml");
  EXPECT_EQ(files.tradeoff_csv, "out/result_tradeoff.csv");
  EXPECT_EQ(files.journal, "out/result.journal");
}

TEST(TuningFiles, WithoutAResultOnlyTheJournalIsWritten) {
  const TuningFiles files = tuning_files(study_with_tradeoff(true), "", "");
  EXPECT_EQ(files.model, "");
  EXPECT_EQ(files.tradeoff_csv, "");
  // In the working directory, named after the study.
  EXPECT_EQ(files.journal, "passat.journal");
  EXPECT_EQ(tuning_files(study_with_tradeoff(false), "", "my.journal").journal, "my.journal");
  EXPECT_EQ(tuning_files(study_with_tradeoff(false), "r.yaml", "").tradeoff_csv, "");
}

TEST(TuningFiles, StudyInputsAreEveryFileTheStudyReads) {
  TuningStudy study = study_with_tradeoff(false);
  study.fitted_model = "fits/strut.yaml";
  const std::vector<std::filesystem::path> expected = {
      "studies/passat.yaml", "vehicles/passat.yaml", "fits/strut.yaml", "roads/smooth.yaml"};
  EXPECT_EQ(study_inputs(study), expected);
}

}  // namespace
}  // namespace ridefit::optimisation
