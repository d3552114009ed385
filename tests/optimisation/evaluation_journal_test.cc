// The evaluation journal: exact round trip, torn lines, foreign journals, fingerprints.
#include "ridefit/optimisation/evaluation_journal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "ridefit/common/errors.h"
#include "ridefit/optimisation/tuning_study.h"
#include "support/passat.h"
#include "support/temp_dir.h"
#include "support/throws_input_error.h"

namespace ridefit::optimisation {
namespace {

const EvaluationJournal::Shape kShape{2, 2, 2};

JournalRecord record(double x) {
  return {"study/search",
          {x, 1.0 / 3.0},
          {{0.1 + x, 2.0 / 7.0}, {std::nextafter(1.0, 2.0), 5e-300}},
          {false, true}};
}

TEST(EvaluationJournal, ResumeFindsEveryRecordBitForBit) {
  testing::TempDir dir("ridefit_journal");
  const auto path = dir.path() / "run.journal";
  {
    auto journal = EvaluationJournal::create(path, "abc");
    journal.append(record(1234.5678901234567));
    journal.append(record(std::nextafter(887.0, 900.0)));
  }
  const auto journal = EvaluationJournal::resume(path, "abc", kShape);
  EXPECT_EQ(journal.size(), 2u);
  const auto found =
      journal.find("study/search", std::vector{std::nextafter(887.0, 900.0), 1.0 / 3.0});
  ASSERT_TRUE(found.has_value());
  EXPECT_EQ(found->case_values, record(std::nextafter(887.0, 900.0)).case_values);
  EXPECT_EQ(found->frequency_domain, (std::vector<bool>{false, true}));
  // One ulp away is another design; another variant is another model.
  EXPECT_FALSE(journal.find("study/search", std::vector{887.0, 1.0 / 3.0}).has_value());
  EXPECT_FALSE(journal.find("blind/search", std::vector{std::nextafter(887.0, 900.0), 1.0 / 3.0})
                   .has_value());
}

TEST(EvaluationJournal, ADesignMetTwiceIsWrittenOnce) {
  // Searches side by side (threads, ranks) can meet at one design; the journal keeps it once.
  testing::TempDir dir("ridefit_journal");
  const auto path = dir.path() / "run.journal";
  {
    auto journal = EvaluationJournal::create(path, "abc");
    journal.append(record(2.0));
    journal.append(record(2.0));
    journal.append(record(3.0));
    EXPECT_EQ(journal.size(), 2u);
    EXPECT_EQ(journal.records().size(), 2u);
  }
  std::ifstream in(path);
  std::size_t lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  EXPECT_EQ(lines, 3u);  // the header and two evaluations
}

TEST(EvaluationJournal, TornLastLineIsCutAndAppendingContinues) {
  testing::TempDir dir("ridefit_journal");
  const auto path = dir.path() / "run.journal";
  {
    auto journal = EvaluationJournal::create(path, "abc");
    journal.append(record(1.0));
  }
  std::ofstream(path, std::ios::app) << "{\"variant\":\"study/search\",\"x\":[2.0,";  // killed
  {
    auto journal = EvaluationJournal::resume(path, "abc", kShape);
    EXPECT_EQ(journal.size(), 1u);
    journal.append(record(3.0));
  }
  const auto journal = EvaluationJournal::resume(path, "abc", kShape);
  EXPECT_EQ(journal.size(), 2u);
  EXPECT_TRUE(journal.find("study/search", std::vector{3.0, 1.0 / 3.0}).has_value());
}

TEST(EvaluationJournal, ForeignOrBrokenJournalsAreInputErrors) {
  testing::TempDir dir("ridefit_journal");
  const auto path = dir.path() / "run.journal";
  { EvaluationJournal::create(path, "abc").append(record(1.0)); }
  EXPECT_TRUE(testing::throws_input_error([&] { EvaluationJournal::resume(path, "def", kShape); },
                                          "another study"));
  EXPECT_TRUE(testing::throws_input_error(
      [&] { EvaluationJournal::resume(dir.path() / "missing", "abc", kShape); },
      "no such journal"));
  const auto csv = dir.write("data.csv", "time[s],x[m]\n0,1\n");
  EXPECT_TRUE(testing::throws_input_error([&] { EvaluationJournal::resume(csv, "abc", kShape); },
                                          "line 1"));
  const auto middle =
      dir.write("broken.journal",
                "{\"format\":\"ridefit-optimise-journal-1\",\"study\":\"abc\"}\n{\"variant\":1}\n");
  EXPECT_TRUE(testing::throws_input_error([&] { EvaluationJournal::resume(middle, "abc", kShape); },
                                          "line 2"));
}

TEST(EvaluationJournal, WrongShapesAreInputErrorsAndOtherFilesAreNeverTouched) {
  testing::TempDir dir("ridefit_journal");
  const auto path = dir.path() / "run.journal";
  { EvaluationJournal::create(path, "abc").append(record(1.0)); }
  EXPECT_TRUE(testing::throws_input_error(
      [&] {
        EvaluationJournal::resume(path, "abc", {3, 2, 2});
      },
      "line 2"));
  EXPECT_TRUE(testing::throws_input_error(
      [&] {
        EvaluationJournal::resume(path, "abc", {2, 1, 2});
      },
      "2 load cases, the study has 1"));
  EXPECT_TRUE(testing::throws_input_error(
      [&] {
        EvaluationJournal::resume(path, "abc", {2, 2, 8});
      },
      "metrics per case"));
  // A file that is not a journal, without a final newline, stays as it was.
  const auto text = dir.write("notes.txt", "hello world");
  EXPECT_TRUE(testing::throws_input_error([&] { EvaluationJournal::resume(text, "abc", kShape); },
                                          "empty"));
  EXPECT_EQ(std::filesystem::file_size(text), 11u);
  EXPECT_TRUE(testing::throws_input_error(
      [&] { EvaluationJournal::resume(dir.path(), "abc", kShape); }, "is a directory"));
}

TEST(EvaluationJournal, IsLockedWhileARunHoldsIt) {
  testing::TempDir dir("ridefit_journal");
  const auto path = dir.path() / "run.journal";
  auto journal = EvaluationJournal::create(path, "abc");
  journal.append(record(1.0));
  // A second writer (here in the same process: a flock belongs to an open file) is refused and
  // the journal is left as it was.
  const auto size = std::filesystem::file_size(path);
  EXPECT_TRUE(testing::throws_input_error([&] { EvaluationJournal::create(path, "abc", true); },
                                          "in use by"));
  EXPECT_TRUE(testing::throws_input_error([&] { EvaluationJournal::resume(path, "abc", kShape); },
                                          "in use by"));
  EXPECT_EQ(std::filesystem::file_size(path), size);
}

TEST(EvaluationJournal, AJournalOfAnUnfinishedRunIsReplacedOnlyWhenAskedTo) {
  testing::TempDir dir("ridefit_journal");
  const auto path = dir.path() / "run.journal";
  {
    auto journal = EvaluationJournal::create(path, "abc");
    journal.append(record(1.0));
    journal.append(record(2.0));
  }
  const auto size = std::filesystem::file_size(path);
  EXPECT_TRUE(testing::throws_input_error([&] { EvaluationJournal::create(path, "abc"); },
                                          "holds 2 evaluations"));
  EXPECT_EQ(std::filesystem::file_size(path), size);
  {
    // Resumed and finished: the finished mark is skipped by resume, and a new run may replace it.
    auto journal = EvaluationJournal::resume(path, "abc", kShape);
    EXPECT_EQ(journal.size(), 2u);
    journal.mark_finished();
  }
  EXPECT_EQ(EvaluationJournal::resume(path, "abc", kShape).size(), 2u);
  { EvaluationJournal::create(path, "abc"); }
  EXPECT_EQ(EvaluationJournal::resume(path, "abc", kShape).size(), 0u);
  {
    auto journal = EvaluationJournal::create(path, "abc");
    journal.append(record(3.0));
  }
  { EvaluationJournal::create(path, "abc", true); }  // --force
  EXPECT_EQ(EvaluationJournal::resume(path, "abc", kShape).size(), 0u);
}

TEST(StudyFingerprint, ChangesWithTheModelFile) {
  testing::TempDir dir("ridefit_journal");
  std::ifstream in(testing::dataset("vehicles/passat_b8_front.yaml"));
  std::stringstream model;
  model << in.rdbuf();
  dir.write("car.yaml", model.str());
  const auto study = dir.write(
      "study.yaml",
      "model: car.yaml\ndesign: [{parameter: damping_Ns_per_m, lower: 300, upper: 5000}]\n"
      "load_cases: [{road: " +
          testing::dataset("excitations/iso8608_class_a_50kmh.yaml") +
          "}]\nobjective: {metric: body_acc_wk_rms_m_per_s2}\n");
  const std::string before = study_fingerprint(load_tuning_study(study));
  EXPECT_EQ(before, study_fingerprint(load_tuning_study(study)));
  dir.write("car.yaml", model.str() + "\n# edited\n");
  EXPECT_NE(before, study_fingerprint(load_tuning_study(study)));
}

}  // namespace
}  // namespace ridefit::optimisation
