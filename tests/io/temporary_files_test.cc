// Temporary files and gnuplot children of an interrupted or killed run (io/temporary_files.h).
#include "ridefit/io/temporary_files.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>

#include "ridefit/io/atomic_file.h"
#include "ridefit/io/gnuplot_figure.h"
#include "support/temp_dir.h"

namespace ridefit::io {
namespace {

namespace fs = std::filesystem;
using testing::TempDir;

// The id of a process that has ended (and been reaped).
pid_t dead_pid() {
  const pid_t pid = fork();
  if (pid == 0) _exit(0);
  waitpid(pid, nullptr, 0);
  return pid;
}

bool gone(pid_t pid) {
  if (kill(pid, 0) != 0) return true;
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string ignored, state;
  stat >> ignored >> ignored >> state;
  return state == "Z";  // a zombie waiting for init has died
}

TEST(TemporaryFiles, SigtermRemovesTheRegisteredFilesAndTheProcessDiesOfIt) {
  TempDir dir("ridefit_temporaries");
  const fs::path temporary = dir.path() / ".out.csv.tmp1";
  const pid_t child = fork();
  if (child == 0) {
    install_temporary_cleanup();
    std::ofstream(temporary) << "half";
    const TemporaryFile registered(temporary);
    raise(SIGTERM);
    _exit(0);  // not reached
  }
  int status = 0;
  waitpid(child, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM);
  EXPECT_FALSE(fs::exists(temporary));
}

TEST(TemporaryFiles, TheNextWriteRemovesWhatAKilledRunLeftButNotALiveRunsFiles) {
  TempDir dir("ridefit_temporaries");
  const std::string dead = std::to_string(dead_pid());
  const std::string live = std::to_string(getppid());
  for (const std::string& name : {".out.csv.tmp" + dead, ".out.csv.tmp" + live,
                                  ".fig.png." + dead + ".gp", ".fig.png." + dead + ".log"}) {
    std::ofstream(dir.path() / name) << "x";
  }
  write_atomically(dir.path() / "out.csv", [](std::ostream& out) { out << "time[s]\n0\n"; });
  EXPECT_FALSE(fs::exists(dir.path() / (".out.csv.tmp" + dead)));
  EXPECT_TRUE(fs::exists(dir.path() / (".out.csv.tmp" + live)));
  // Only the target's own temporaries: the figure's wait for a figure to be drawn there.
  EXPECT_TRUE(fs::exists(dir.path() / (".fig.png." + dead + ".gp")));
  remove_stale_temporaries(dir.path());
  EXPECT_FALSE(fs::exists(dir.path() / (".fig.png." + dead + ".gp")));
  EXPECT_FALSE(fs::exists(dir.path() / (".fig.png." + dead + ".log")));
  EXPECT_EQ(temporary_owner(".out.csv.tmp" + live), std::stol(live));
  EXPECT_EQ(temporary_owner("out.csv"), 0);
}

TEST(TemporaryFiles, GnuplotDiesWithItsParent) {
  TempDir dir("ridefit_temporaries");
  // A stand-in gnuplot that records its pid and hangs.
  const fs::path bin = dir.path() / "bin";
  fs::create_directories(bin);
  const fs::path pid_file = dir.path() / "gnuplot.pid";
  std::ofstream(bin / "gnuplot") << "#!/bin/sh\necho $$ > " << pid_file.string()
                                 << "\nexec /bin/sleep 60\n";
  fs::permissions(bin / "gnuplot", fs::perms::owner_all);
  if (access((bin / "gnuplot").c_str(), X_OK) != 0) {
    GTEST_SKIP() << "the temporary directory does not allow executing the stand-in gnuplot";
  }
  const pid_t child = fork();
  if (child == 0) {
    setenv("PATH", bin.c_str(), 1);
    Figure figure;
    figure.panels.push_back(psd_panel("p", "PSD"));
    figure.panels.back().series.push_back(
        {"s", {1.0, 2.0}, {1.0, 2.0}, {}, {}, SeriesStyle::kLines});
    try {
      draw_figure(figure, dir.path() / "f.png");
    } catch (...) {
    }
    _exit(0);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (!fs::exists(pid_file) || fs::file_size(pid_file) == 0) {
    ASSERT_LT(std::chrono::steady_clock::now(), deadline) << "the stand-in gnuplot never ran";
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  pid_t gnuplot = 0;
  std::ifstream(pid_file) >> gnuplot;
  ASSERT_GT(gnuplot, 0);
  kill(child, SIGKILL);  // no chance to tidy up
  waitpid(child, nullptr, 0);
  while (!gone(gnuplot) && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  EXPECT_TRUE(gone(gnuplot)) << "gnuplot " << gnuplot << " outlived its parent";
  if (!gone(gnuplot)) kill(gnuplot, SIGKILL);
}

}  // namespace
}  // namespace ridefit::io
