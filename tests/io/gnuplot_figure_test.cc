#include "ridefit/io/gnuplot_figure.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "ridefit/common/errors.h"

namespace ridefit::io {
namespace {

namespace fs = std::filesystem;

class GnuplotFigureTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("ridefit_gnuplot_" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static Figure two_panel_figure() {
    Figure figure;
    figure.title = "it's a test";
    PlotPanel psd = psd_panel("body", "PSD [(m/s^2)^2/Hz]");
    PlotSeries s{"meas_1", {0.0, 1.0, 2.0, 4.0}, {1.0, 1e-2, 1e-3, 1e-4}, {}, {}, {}};
    s.lower = {0.5, 5e-3, 5e-4, 5e-5};
    s.upper = {2.0, 2e-2, 2e-3, 2e-4};
    psd.series.push_back(s);
    figure.panels.push_back(psd);
    PlotPanel time = time_panel("time", "body_acc [m/s^2]");
    time.series.push_back({"sim", {0.0, 0.1, 0.2}, {0.0, 1.0, -1.0}, {}, {}, {}});
    figure.panels.push_back(time);
    return figure;
  }

  static std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  fs::path dir_;
};

TEST(GnuplotQuote, DoublesSingleQuotesAndFlattensNewlines) {
  EXPECT_EQ(gnuplot_quote("plain"), "'plain'");
  EXPECT_EQ(gnuplot_quote("it's"), "'it''s'");
  EXPECT_EQ(gnuplot_quote("a\nsystem('rm x')"), "'a system(''rm x'')'");
}

TEST_F(GnuplotFigureTest, DrawsPngAndSvgWithTheLabels) {
  ASSERT_TRUE(gnuplot_available());
  const fs::path png = dir_ / "figure.png";
  draw_figure(two_panel_figure(), png);
  const std::string bytes = read(png);
  ASSERT_GT(bytes.size(), 1000u);
  EXPECT_EQ(bytes.substr(1, 3), "PNG");
  const fs::path svg = dir_ / "figure.svg";
  draw_figure(two_panel_figure(), svg);
  const std::string text = read(svg);
  EXPECT_NE(text.find("<svg"), std::string::npos);
  EXPECT_NE(text.find("meas_1"), std::string::npos);  // underscores are not subscripts
  EXPECT_NE(text.find("it's a test"), std::string::npos);
  // Nothing but the figures is left behind.
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir_)) files += entry.is_regular_file();
  EXPECT_EQ(files, 2);
}

TEST_F(GnuplotFigureTest, FileNamesCannotInjectCommands) {
  const fs::path evil = dir_ / "a'; system('touch pwned'); '.png";
  draw_figure(two_panel_figure(), evil);
  EXPECT_TRUE(fs::exists(evil));
  EXPECT_FALSE(fs::exists(dir_ / "pwned"));
  EXPECT_FALSE(fs::exists("pwned"));
}

TEST_F(GnuplotFigureTest, PlotFileIsCheckedBeforeAnyWork) {
  EXPECT_THROW(check_plot_file(dir_ / "figure.pdf", {}, "--plot"), InputError);
  EXPECT_THROW(check_plot_file(dir_ / "missing" / "figure.png", {}, "--plot"), InputError);
  EXPECT_NO_THROW(check_plot_file(dir_ / "figure.PNG", {}, "--plot"));
  try {
    check_plot_file(dir_ / "figure.jpg", {}, "--plot");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(".png or .svg"), std::string::npos) << e.what();
  }
}

TEST_F(GnuplotFigureTest, MissingGnuplotIsAClearError) {
  const std::string saved = std::getenv("PATH") ? std::getenv("PATH") : "";
  setenv("PATH", dir_.c_str(), 1);
  const bool available = gnuplot_available();
  std::string check_message;
  try {
    check_plot_file(dir_ / "figure.png", {}, "--plot");
  } catch (const InputError& e) {
    check_message = e.what();
  }
  bool draw_failed = false;
  try {
    draw_figure(two_panel_figure(), dir_ / "figure.png");
  } catch (const RunError& e) {
    draw_failed = std::string(e.what()).find("gnuplot-nox") != std::string::npos;
  }
  setenv("PATH", saved.c_str(), 1);
  EXPECT_FALSE(available);
  EXPECT_NE(check_message.find("gnuplot is not on PATH"), std::string::npos) << check_message;
  EXPECT_TRUE(draw_failed);
  EXPECT_FALSE(fs::exists(dir_ / "figure.png"));
}

TEST_F(GnuplotFigureTest, MismatchedSeriesIsAProgrammingError) {
  Figure figure = two_panel_figure();
  figure.panels[1].series[0].y.pop_back();
  EXPECT_THROW(draw_figure(figure, dir_ / "figure.png"), std::invalid_argument);
  EXPECT_THROW(draw_figure(Figure{}, dir_ / "figure.png"), std::invalid_argument);
  EXPECT_FALSE(fs::exists(dir_ / "figure.png"));
}

}  // namespace
}  // namespace ridefit::io
