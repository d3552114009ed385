#include "ridefit/io/gnuplot_figure.h"

#include <fcntl.h>
#include <fmt/core.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "ridefit/common/errors.h"
#include "ridefit/io/atomic_file.h"
#include "ridefit/io/temporary_files.h"

namespace ridefit::io {
namespace {

namespace fs = std::filesystem;

// Okabe-Ito colours: distinguishable with the common colour-vision deficiencies.
constexpr const char* kPalette[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                    "#E69F00", "#56B4E9", "#000000", "#F0E442"};

std::string lowercase_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

bool shown(double x, double y, const PlotPanel& panel) {
  if (!std::isfinite(x) || !std::isfinite(y)) return false;
  if (panel.x_scale == AxisScale::kLog && x <= 0.0) return false;
  if (panel.y_scale == AxisScale::kLog && y <= 0.0) return false;
  return true;
}

void check_series(const PlotSeries& s) {
  if (s.x.size() != s.y.size()) {
    throw std::invalid_argument("draw_figure: series '" + s.label +
                                "' has x and y of different lengths");
  }
  const bool band = !s.lower.empty() || !s.upper.empty();
  if (band && (s.lower.size() != s.x.size() || s.upper.size() != s.x.size())) {
    throw std::invalid_argument("draw_figure: series '" + s.label +
                                "' has a band of the wrong length");
  }
}

// `$d<panel>_<series>` data blocks; a band block holds x, lower, upper.
void write_data_blocks(std::ostream& out, const Figure& figure) {
  for (std::size_t p = 0; p < figure.panels.size(); ++p) {
    const PlotPanel& panel = figure.panels[p];
    for (std::size_t s = 0; s < panel.series.size(); ++s) {
      const PlotSeries& series = panel.series[s];
      check_series(series);
      out << fmt::format("$d{}_{} << EOD\n", p, s);
      for (std::size_t i = 0; i < series.x.size(); ++i) {
        if (shown(series.x[i], series.y[i], panel)) {
          out << fmt::format("{:.10g} {:.10g}\n", series.x[i], series.y[i]);
        }
      }
      out << "EOD\n";
      if (series.lower.empty()) continue;
      out << fmt::format("$b{}_{} << EOD\n", p, s);
      for (std::size_t i = 0; i < series.x.size(); ++i) {
        if (shown(series.x[i], series.lower[i], panel) &&
            shown(series.x[i], series.upper[i], panel)) {
          out << fmt::format("{:.10g} {:.10g} {:.10g}\n", series.x[i], series.lower[i],
                             series.upper[i]);
        }
      }
      out << "EOD\n";
    }
  }
}

std::string range(const std::optional<std::pair<double, double>>& r) {
  if (!r) return "[*:*]";
  return fmt::format("[{:.10g}:{:.10g}]", r->first, r->second);
}

void write_panel(std::ostream& out, const PlotPanel& panel, std::size_t p) {
  out << "reset\n";  // a panel does not inherit the previous one's axes
  out << "set grid xtics ytics mxtics mytics lc rgb '#dddddd'\n";
  // The position is one of gnuplot's own word pairs, never user text.
  static const std::set<std::string> kWords = {"top",    "bottom",  "left",  "right", "center",
                                               "inside", "outside", "above", "below"};
  std::stringstream words(panel.key_position);
  bool known_position = true;
  for (std::string word; words >> word;) known_position = known_position && kWords.count(word);
  out << "set key " << (known_position ? panel.key_position : "top right") << " opaque font ',9'\n";
  out << "set title " << gnuplot_quote(panel.title) << "\n";
  out << "set xlabel " << gnuplot_quote(panel.x_label) << "\n";
  out << "set ylabel " << gnuplot_quote(panel.y_label) << "\n";
  out << (panel.x_scale == AxisScale::kLog ? "set logscale x\n" : "unset logscale x\n");
  out << (panel.y_scale == AxisScale::kLog ? "set logscale y\nset format y '%.0e'\n"
                                           : "unset logscale y\n");
  // Keep points off the frame on linear axes (log axes start where the data do).
  if (panel.x_scale == AxisScale::kLinear && panel.y_scale == AxisScale::kLinear) {
    out << "set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05\n";
  }
  out << "set xrange " << range(panel.x_range) << "\n";
  out << "set yrange " << range(panel.y_range) << "\n";
  std::vector<std::string> items;
  for (std::size_t s = 0; s < panel.series.size(); ++s) {
    if (panel.series[s].lower.empty()) continue;
    items.push_back(fmt::format(
        "$b{}_{} using 1:2:3 with filledcurves fc rgb '{}' fs transparent solid 0.2 noborder "
        "notitle",
        p, s, kPalette[s % std::size(kPalette)]));
  }
  for (std::size_t s = 0; s < panel.series.size(); ++s) {
    const PlotSeries& series = panel.series[s];
    const char* style = series.style == SeriesStyle::kLines    ? "lines lw 1.5"
                        : series.style == SeriesStyle::kPoints ? "points pt 7 ps 0.8"
                                                               : "linespoints lw 1.5 pt 7 ps 0.8";
    items.push_back(fmt::format("$d{}_{} using 1:2 with {} lc rgb '{}' title {}", p, s, style,
                                kPalette[s % std::size(kPalette)], gnuplot_quote(series.label)));
  }
  if (items.empty()) {
    // An empty panel still takes its place in the grid.
    out << "set xrange [0:1]\nset yrange [0:1]\nplot NaN notitle\n";
    return;
  }
  out << "plot ";
  for (std::size_t i = 0; i < items.size(); ++i) out << (i ? ", \\\n     " : "") << items[i];
  out << "\n";
}

std::string script_for(const Figure& figure, const fs::path& output, bool svg) {
  const std::size_t n = figure.panels.size();
  const int columns =
      figure.columns > 0 ? figure.columns : static_cast<int>(std::min<std::size_t>(n, 3));
  const int rows = static_cast<int>((n + static_cast<std::size_t>(columns) - 1) /
                                    static_cast<std::size_t>(columns));
  const int title_px = figure.title.empty() ? 0 : 30;
  std::ostringstream out;
  out << fmt::format("set terminal {} size {},{} noenhanced font ',10'{}\n",
                     svg ? "svg" : "pngcairo", columns * figure.panel_width_px,
                     rows * figure.panel_height_px + title_px, svg ? " background '#ffffff'" : "");
  out << "set output " << gnuplot_quote(output.string()) << "\n";
  write_data_blocks(out, figure);
  out << fmt::format("set multiplot layout {},{} title {}\n", rows, columns,
                     gnuplot_quote(figure.title));
  for (std::size_t p = 0; p < n; ++p) write_panel(out, figure.panels[p], p);
  out << "unset multiplot\nset output\n";
  return out.str();
}

std::string read_all(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Runs `gnuplot script` without a shell; returns its exit status and stderr.
// The gnuplot executable on PATH, or "" when there is none.
std::string gnuplot_path() {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return "";
  std::stringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    // An empty PATH entry means the current directory.
    const fs::path base = dir.empty() ? fs::current_path() : fs::path(dir);
    if (access((base / "gnuplot").c_str(), X_OK) == 0) return (base / "gnuplot").string();
  }
  return "";
}

std::pair<int, std::string> run_gnuplot(const fs::path& script, const fs::path& log) {
  // Everything the child needs is prepared before fork: between fork and exec it only calls
  // async-signal-safe functions. The child dies with its parent (PR_SET_PDEATHSIG), so a
  // killed run never leaves gnuplot behind.
  std::string program = gnuplot_path();
  if (program.empty()) {
    throw RunError(
        "gnuplot could not be started; install it (tools/setup installs the Debian package "
        "gnuplot-nox) or draw no figure");
  }
  std::string script_arg = script.string();
  const std::string log_path = log.string();
  char* argv[] = {program.data(), script_arg.data(), nullptr};
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) throw RunError("gnuplot could not be started: fork failed");
  if (pid == 0) {
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(127);  // the parent died before prctl
    const int in = open("/dev/null", O_RDONLY);
    const int out = open("/dev/null", O_WRONLY);
    const int err = open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (in < 0 || out < 0 || err < 0) _exit(127);
    dup2(in, STDIN_FILENO);
    dup2(out, STDOUT_FILENO);
    dup2(err, STDERR_FILENO);
    execv(program.c_str(), argv);
    _exit(127);
  }
  const ChildProcess child(pid);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw RunError("waiting for gnuplot failed");
  }
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128;
  return {code, read_all(log)};
}

}  // namespace

std::string gnuplot_quote(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) {
    if (c == '\'') {
      quoted += "''";
    } else if (c == '\n' || c == '\r') {
      quoted += ' ';
    } else {
      quoted += c;
    }
  }
  return quoted + "'";
}

PlotPanel psd_panel(std::string title, std::string y_label) {
  PlotPanel panel;
  panel.title = std::move(title);
  panel.x_label = "frequency [Hz]";
  panel.y_label = std::move(y_label);
  panel.x_scale = AxisScale::kLog;
  panel.y_scale = AxisScale::kLog;
  return panel;
}

PlotPanel time_panel(std::string title, std::string y_label) {
  PlotPanel panel;
  panel.title = std::move(title);
  panel.x_label = "time [s]";
  panel.y_label = std::move(y_label);
  return panel;
}

PlotPanel xy_panel(std::string title, std::string x_label, std::string y_label) {
  PlotPanel panel;
  panel.key_position = "top left";  // curves of a study mostly rise to the right
  panel.title = std::move(title);
  panel.x_label = std::move(x_label);
  panel.y_label = std::move(y_label);
  return panel;
}

bool gnuplot_available() { return !gnuplot_path().empty(); }

void check_plot_file(const fs::path& path, const std::vector<fs::path>& inputs,
                     const std::string& flag) {
  const std::string ext = lowercase_extension(path);
  if (ext != ".png" && ext != ".svg") {
    throw InputError(fmt::format("{} {}: the figure's type follows its extension; use .png or .svg",
                                 flag, path.string()));
  }
  check_output_file(path, inputs, flag);
  if (!gnuplot_available()) {
    throw InputError(fmt::format(
        "{} {}: gnuplot is not on PATH; install it (tools/setup installs the Debian package "
        "gnuplot-nox) or leave out {}",
        flag, path.string(), flag));
  }
}

void draw_figure(const Figure& figure, const fs::path& path) {
  if (figure.panels.empty()) throw std::invalid_argument("draw_figure: a figure needs a panel");
  const bool svg = lowercase_extension(path) == ".svg";
  const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
  const std::string stem = fmt::format(".{}.{}", path.filename().string(), getpid());
  const fs::path script = dir / (stem + ".gp");
  const fs::path log = dir / (stem + ".log");
  const fs::path tmp_output = dir / (stem + (svg ? ".svg" : ".png"));
  remove_stale_temporaries(dir, path.filename().string());
  const TemporaryFile registered_script(script), registered_log(log), registered_output(tmp_output);
  auto cleanup = [&] {
    std::error_code ignored;
    fs::remove(script, ignored);
    fs::remove(log, ignored);
    fs::remove(tmp_output, ignored);
  };
  try {
    {
      std::ofstream out(script);
      if (!out) throw InputError(fmt::format("{}: cannot write next to it", path.string()));
      out << script_for(figure, tmp_output, svg);
      if (!out) throw InputError(fmt::format("{}: cannot write next to it", path.string()));
    }
    const auto [code, messages] = run_gnuplot(script, log);
    if (code != 0 || !fs::exists(tmp_output) || fs::file_size(tmp_output) == 0) {
      throw RunError(fmt::format("gnuplot failed to draw {} (exit {}): {}", path.string(), code,
                                 messages.empty() ? "no message" : messages));
    }
    fs::rename(tmp_output, path);
  } catch (...) {
    cleanup();
    throw;
  }
  cleanup();
}

}  // namespace ridefit::io
