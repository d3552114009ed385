// io::RunOutputs: the one check every command makes of its outputs before any work.
#include "ridefit/io/output_paths.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "ridefit/io/closest_names.h"
#include "ridefit/io/staged_folder.h"
#include "support/temp_dir.h"
#include "support/throws_input_error.h"

namespace ridefit::io {
namespace {

namespace fs = std::filesystem;
using testing::TempDir;
using testing::throws_input_error;

TEST(RunOutputs, TwoOutputsOfOnePathAreRefusedAlsoThroughALinkOrDotDot) {
  TempDir dir("ridefit_outputs");
  fs::create_directories(dir.path() / "x");
  RunOutputs outputs({});
  outputs.add_file(dir.path() / "a.csv", "-o");
  EXPECT_TRUE(
      throws_input_error([&] { outputs.add_file(dir.path() / "x" / ".." / "a.csv", "--plot"); },
                         "give each output its own path"));
  fs::create_directory_symlink(dir.path(), dir.path() / "link");
  EXPECT_TRUE(throws_input_error([&] { outputs.add_file(dir.path() / "link" / "a.csv", "--psd"); },
                                 "is also the -o output"));
  outputs.add_file(dir.path() / "b.csv", "--psd");  // another path is fine
}

TEST(RunOutputs, AnOutputIsNeverAnInputEvenThroughALinkThatDoesNotResolveYet) {
  TempDir dir("ridefit_outputs");
  const auto input = dir.write("model.yaml", "x: 1\n");
  fs::create_symlink(input, dir.path() / "alias.yaml");
  RunOutputs outputs({input});
  EXPECT_TRUE(throws_input_error([&] { outputs.add_file(dir.path() / "alias.yaml", "-o"); },
                                 "input of this run"));
}

TEST(RunOutputs, AFolderIsRefusedWhenItHoldsFilesRidefitDidNotWriteThere) {
  TempDir dir("ridefit_outputs");
  const auto out = dir.path() / "out";
  {
    RunOutputs outputs({});
    outputs.add_folder(out, "-o", {"report.md", "model.yaml"}, false, "--force");  // missing: fine
  }
  fs::create_directories(out);
  std::ofstream(out / "report.md") << "old";
  std::ofstream(out / ".report.md.tmp4194305") << "a temporary";  // ignored
  // Not listed in a manifest: someone else's file.
  EXPECT_TRUE(throws_input_error(
      [&] {
        RunOutputs({}).add_folder(out, "-o", {"report.md", "model.yaml"}, false, "--force");
      },
      "files ridefit did not write there (report.md); choose a new or empty folder, or give "
      "--force to write into it anyway"));
  RunOutputs({}).add_folder(out, "-o", {"report.md", "model.yaml"}, true, "--force");  // --force
  finish_output_folder(out, {"report.md"});
  RunOutputs({}).add_folder(out, "-o", {"report.md", "model.yaml"}, false, "--force");  // ours now
  // An input is never an output, not even with --force; nor are two names alike.
  EXPECT_TRUE(throws_input_error(
      [&] {
        RunOutputs({out / "model.yaml"}).add_folder(out, "-o", {"model.yaml"}, true, "--force");
      },
      "one of its inputs"));
  EXPECT_TRUE(throws_input_error(
      [&] {
        RunOutputs({}).add_folder(out, "-o", {"a.csv", "a.csv"}, true, "--force");
      },
      "twice"));
}

TEST(StagedFolder, CommitsAsAWholeKeepsOtherFilesAndLeavesNothingWhenNotCommitted) {
  TempDir dir("ridefit_outputs");
  const auto real = dir.path() / "real";
  fs::create_directories(real / "sub");
  std::ofstream(real / "a.txt") << "kept";
  std::ofstream(real / "report.md") << "old";
  std::ofstream(real / "sub" / "b.txt") << "deep";
  fs::create_directory_symlink(real, dir.path() / "alias");
  {
    StagedFolder staged(dir.path() / "alias", {"report.md"});
    EXPECT_NE(staged.path(), real);
    std::ofstream(staged.path() / "report.md") << "new";
    EXPECT_EQ(testing::text_of(real / "report.md"), "old");  // nothing visible yet
  }  // not committed: as it was, and no staging folder left
  EXPECT_EQ(testing::text_of(real / "report.md"), "old");
  std::size_t entries = 0;
  for (const auto& entry : fs::directory_iterator(dir.path())) entries += entry.exists() ? 1 : 0;
  EXPECT_EQ(entries, 2u);  // real and alias
  {
    StagedFolder staged(dir.path() / "alias", {"report.md"});
    std::ofstream(staged.path() / "report.md") << "new";
    staged.commit();
  }
  EXPECT_TRUE(fs::is_symlink(dir.path() / "alias"));
  EXPECT_EQ(testing::text_of(real / "report.md"), "new");
  EXPECT_EQ(testing::text_of(real / "a.txt"), "kept");
  EXPECT_EQ(testing::text_of(real / "sub" / "b.txt"), "deep");
  EXPECT_NE(testing::text_of(real / kOutputManifest).find("report.md"), std::string::npos);
}

TEST(ClosestNames, SuggestsTheNearestNamesAndNothingFarAway) {
  const std::vector<std::string> names = {"damping_Ns_per_m", "coulomb_force_N",
                                          "damping_above_knee_Ns_per_m"};
  EXPECT_EQ(closest_names("damping_Ns_per_mm", names).front(), "damping_Ns_per_m");
  EXPECT_TRUE(closest_names("xyz", names).empty());
  EXPECT_EQ(closest_names_text("coulomb_forc_N", names), "; closest: coulomb_force_N");
}

TEST(FirstRepeatedFile, NamesTheLaterOfTwoNamesForOneFile) {
  TempDir dir("ridefit_outputs");
  const std::filesystem::path a = dir.write("a.csv", "x\n");
  const std::filesystem::path b = dir.write("b.csv", "x\n");
  EXPECT_FALSE(first_repeated_file({a, b}).has_value());
  const auto repeated = first_repeated_file({a, b, dir.path() / "." / "a.csv"});
  ASSERT_TRUE(repeated.has_value());
  EXPECT_EQ(*repeated, dir.path() / "." / "a.csv");
}

TEST(OutputForInput, AppendsTheInputsStemInTheOutputsFolder) {
  EXPECT_EQ(output_for_input("out/fitted.yaml", "data/shim_2mm.csv"),
            std::filesystem::path("out/fitted_shim_2mm.yaml"));
  EXPECT_EQ(output_for_input("fitted", "a.csv"), std::filesystem::path("fitted_a"));
}

}  // namespace
}  // namespace ridefit::io
