#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ridefit::io {

enum class AxisScale { kLinear, kLog };
enum class SeriesStyle { kLines, kPoints, kLinesPoints };

// One curve. `lower`/`upper`, when given (both, each as long as x), draw a shaded band behind
// the curve, e.g. a PSD's confidence interval.
struct PlotSeries {
  std::string label;
  std::vector<double> x;
  std::vector<double> y;
  std::vector<double> lower;
  std::vector<double> upper;
  SeriesStyle style = SeriesStyle::kLines;
};

struct PlotPanel {
  std::string title;
  std::string x_label;  // with its unit, e.g. "frequency [Hz]"
  std::string y_label;
  AxisScale x_scale = AxisScale::kLinear;
  AxisScale y_scale = AxisScale::kLinear;
  std::optional<std::pair<double, double>> x_range;  // unset: gnuplot's autoscale
  std::optional<std::pair<double, double>> y_range;
  std::vector<PlotSeries> series;
  std::string key_position = "top right";  // gnuplot's words: top left, bottom right, …
};

// Panels in a grid of `columns` (0: all in one row up to three, then three per row).
struct Figure {
  std::string title;
  std::vector<PlotPanel> panels;
  int columns = 0;
  int panel_width_px = 600;
  int panel_height_px = 450;
};

// The three kinds of panel the commands draw.
PlotPanel psd_panel(std::string title, std::string y_label);   // log-log over frequency [Hz]
PlotPanel time_panel(std::string title, std::string y_label);  // linear over time [s]
PlotPanel xy_panel(std::string title, std::string x_label, std::string y_label);

// Checks, before any work is done, that a --plot target is usable: extension .png or .svg
// (the terminal follows from it), a writable place (check_output_file), and gnuplot on PATH.
// Throws InputError naming `flag` and what would be right.
void check_plot_file(const std::filesystem::path& path,
                     const std::vector<std::filesystem::path>& inputs, const std::string& flag);

// True when a `gnuplot` executable is on PATH.
bool gnuplot_available();

// Draws the figure with gnuplot into `path` (.png: pngcairo; .svg: svg). The data travel inside
// the script as gnuplot data blocks and gnuplot is started directly (posix_spawn, no shell);
// every string reaching the script (titles, labels, the output path) is quoted as a gnuplot
// single-quoted string, so no file name or label can inject commands. Points that a log axis
// cannot show (<= 0) and non-finite points are left out. gnuplot writes to a temporary file
// that is renamed into place only when it succeeds. A missing gnuplot or a failing gnuplot is
// a RunError with gnuplot's own message; an empty figure or a series with mismatched lengths
// is std::invalid_argument (a programming error).
void draw_figure(const Figure& figure, const std::filesystem::path& path);

// `text` as a gnuplot single-quoted string: '...' with every ' doubled. Newlines (which end a
// gnuplot command) become spaces. Exposed for the test.
std::string gnuplot_quote(const std::string& text);

}  // namespace ridefit::io
