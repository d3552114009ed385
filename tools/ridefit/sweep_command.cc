// ridefit sweep STUDY.yaml [-o results.csv] [--plot FILE.png|svg] [--json] [--threads N]
// A parametric study of the half car (seed 001's Figures 5–17) on all cores.
#include <fmt/core.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include "command_options.h"
#include "distributed_sweep.h"
#include "ridefit/common/errors.h"
#include "ridefit/distributed/mpi_session.h"
#include "ridefit/io/atomic_file.h"
#include "ridefit/io/gnuplot_figure.h"
#include "ridefit/io/output_paths.h"
#include "ridefit/study/half_car_sweep.h"
#include "subcommands.h"

namespace ridefit::cli {
namespace {

struct SweepFlags {
  std::string study_file;
  std::string output_file;
  std::string plot_file;
  unsigned threads = 0;
  bool json = false;
};

double speed_km_per_h(const study::SweepRow& row) { return row.point.speed_m_per_s * 3.6; }

// One CSV row per run: run, road, speed, method, the varied values, every metric; units in the
// headers. The road and the method are words, so this is a plain CSV, not a CsvTable.
void write_csv(const study::HalfCarSweep& sweep, const std::vector<study::SweepRow>& rows,
               const std::string& path) {
  io::write_atomically(path, [&](std::ostream& out) {
    out << "run[1],road,speed[m/s],method";
    for (const auto& axis : sweep.axes) {
      const auto [name, unit] = study::split_unit_suffix(axis.name);
      out << "," << name << "[" << unit << "]";
    }
    for (const auto& [metric, value] : study::HalfCarMetrics{}.named()) {
      const auto [name, unit] = study::split_unit_suffix(metric);
      out << "," << name << "[" << unit << "]";
    }
    out << "\n";
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const auto& row = rows[i];
      out << fmt::format("{},{},{:.10g},{}", i + 1, sweep.roads[row.point.road].first,
                         row.point.speed_m_per_s, row.frequency_domain ? "frequency" : "time");
      for (double v : row.point.values) out << fmt::format(",{:.10g}", v);
      for (const auto& [metric, value] : row.metrics.named()) out << fmt::format(",{:.8g}", value);
      out << "\n";
    }
  });
}

double dimension_value(const study::HalfCarSweep& sweep, const study::SweepRow& row,
                       const std::string& dimension) {
  if (dimension == "speed_km_per_h") return speed_km_per_h(row);
  if (dimension == "road") return static_cast<double>(row.point.road);
  for (std::size_t a = 0; a < sweep.axes.size(); ++a) {
    if (sweep.axes[a].name == dimension) return row.point.values[a];
  }
  return 0.0;
}

std::string series_label(const study::HalfCarSweep& sweep, const study::SweepRow& row,
                         const std::string& series) {
  if (series.empty()) return "";
  if (series == "road") return sweep.roads[row.point.road].first;
  if (series == "speed_km_per_h") return fmt::format("{:g} km/h", speed_km_per_h(row));
  return fmt::format("{} = {:g}", series, dimension_value(sweep, row, series));
}

io::Figure figure_of(const study::HalfCarSweep& sweep, const std::vector<study::SweepRow>& rows) {
  const study::SweepPlot& plot = *sweep.plot;
  io::Figure figure;
  figure.title = sweep.study_file.filename().string();
  const auto [x_name, x_unit] = study::split_unit_suffix(plot.x);
  for (const auto& y : plot.y) {
    const auto [y_name, y_unit] = study::split_unit_suffix(y);
    io::PlotPanel panel = io::xy_panel(y_name, fmt::format("{} [{}]", x_name, x_unit),
                                       fmt::format("{} [{}]", y_name, y_unit));
    std::map<std::string, std::size_t> series_index;
    for (const auto& row : rows) {
      const std::string label = series_label(sweep, row, plot.series);
      auto [it, added] = series_index.emplace(label, panel.series.size());
      if (added) {
        panel.series.push_back(
            {label.empty() ? y_name : label, {}, {}, {}, {}, io::SeriesStyle::kLinesPoints});
      }
      auto& s = panel.series[it->second];
      s.x.push_back(dimension_value(sweep, row, plot.x));
      for (const auto& [metric, value] : row.metrics.named()) {
        if (metric == y) s.y.push_back(value);
      }
    }
    figure.panels.push_back(std::move(panel));
  }
  figure.columns = static_cast<int>(std::min<std::size_t>(2, figure.panels.size()));
  return figure;
}

void run(const SweepFlags& flags) {
  const std::vector<std::filesystem::path> inputs = {flags.study_file};
  io::RunOutputs outputs(inputs);
  outputs.add_file(flags.output_file, "-o");
  outputs.add_plot(flags.plot_file, "--plot");
  const study::HalfCarSweep sweep = study::load_half_car_sweep(flags.study_file);
  if (!flags.plot_file.empty() && !sweep.plot) {
    throw InputError(fmt::format(
        "--plot: {} has no `plot:` entry saying what to draw (x, series, y)", flags.study_file));
  }
  const bool tty = isatty(fileno(stderr)) != 0;
  const auto start = std::chrono::steady_clock::now();
  double last_report = 0.0;
  const distributed::MpiSession& session = *distributed::MpiSession::current();
  distributed::TaskFarmStatistics farm;
  const auto rows = run_distributed_sweep(
      session, sweep, flags.threads,
      [&](std::size_t done, std::size_t total) {
        const double elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (elapsed < 1.0 || (elapsed - last_report < 0.5 && done < total)) return;
        last_report = elapsed;
        std::cerr << fmt::format("{}sweep: {}/{} runs, {:.1f} s{}", tty ? "\r" : "", done, total,
                                 elapsed, tty ? "" : "\n");
        if (tty && done == total) std::cerr << "\n";
      },
      &farm);
  const double elapsed_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!session.root()) return;  // rank 0 alone writes and reports
  if (!flags.output_file.empty()) write_csv(sweep, rows, flags.output_file);
  if (!flags.plot_file.empty()) io::draw_figure(figure_of(sweep, rows), flags.plot_file);
  if (flags.json) {
    nlohmann::json j = {{"study", flags.study_file},
                        {"runs", rows.size()},
                        {"wall_time_s", elapsed_s},
                        {"results", nlohmann::json::array()}};
    for (const auto& row : rows) {
      nlohmann::json r = {{"road", sweep.roads[row.point.road].first},
                          {"speed_m_per_s", row.point.speed_m_per_s},
                          {"method", row.frequency_domain ? "frequency" : "time"}};
      for (std::size_t a = 0; a < sweep.axes.size(); ++a) {
        r[sweep.axes[a].name] = row.point.values[a];
      }
      for (const auto& [metric, value] : row.metrics.named()) r[metric] = value;
      j["results"].push_back(r);
    }
    if (!flags.output_file.empty()) j["output"] = flags.output_file;
    if (!flags.plot_file.empty()) j["plot"] = flags.plot_file;
    if (session.size() > 1) {
      j["ranks"] = {{"count", session.size()},
                    {"runs_on_rank0", farm.tasks_on_rank0},
                    {"chunks_to_other_ranks", farm.chunks_handed_out},
                    {"bytes_received_by_rank0", farm.bytes_received},
                    {"bytes_sent_by_rank0", farm.bytes_sent}};
    }
    std::cout << j.dump(2) << "\n";
    return;
  }
  // A compact table: the varied values and the seat / body-segment comfort figures.
  std::cout << fmt::format("{}: {} runs in {:.2f} s{}\n", flags.study_file, rows.size(), elapsed_s,
                           session.size() > 1 ? fmt::format(" on {} ranks", session.size()) : "");
  std::cout << fmt::format("{:<10} {:>8}", "road", "km/h");
  for (const auto& axis : sweep.axes) std::cout << fmt::format(" {:>14.14}", axis.name);
  std::cout << fmt::format(" {:>9} {:>9} {:>9} {:>9} {:>10}\n", "seat_Wk", "lower_Wk", "upper_Wk",
                           "travel_f", "tyre_f/st");
  for (const auto& row : rows) {
    std::cout << fmt::format("{:<10} {:>8.1f}", sweep.roads[row.point.road].first,
                             speed_km_per_h(row));
    for (double v : row.point.values) std::cout << fmt::format(" {:>14.6g}", v);
    std::cout << fmt::format(
        " {:>9.4f} {:>9.4f} {:>9.4f} {:>9.5f} {:>10.4f}\n", row.metrics.seat_acc_wk_rms_m_per_s2,
        row.metrics.lower_body_acc_wk_rms_m_per_s2, row.metrics.upper_body_acc_wk_rms_m_per_s2,
        row.metrics.front_travel_rms_m, row.metrics.front_dynamic_load_ratio);
  }
  std::cout << "Wk-weighted RMS in m/s^2 (ISO 2631-1); travel_f: front travel RMS [m]; "
               "tyre_f/st: front dynamic tyre load RMS over static.\n";
  if (!flags.output_file.empty()) std::cout << "Results: " << flags.output_file << "\n";
  if (!flags.plot_file.empty()) std::cout << "Figure: " << flags.plot_file << "\n";
}

}  // namespace

void register_sweep(CLI::App& app) {
  auto flags = std::make_shared<SweepFlags>();
  CLI::App* command = app.add_subcommand(
      "sweep",
      "Parametric study of the half car: parameters × speeds × roads, in parallel (exact "
      "frequency domain when the car is linear)");
  command->add_option("study", flags->study_file, "Study file (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("-o,--output", flags->output_file, "Results CSV, one row per run");
  command->add_option("--plot", flags->plot_file, "Draw the study's `plot:` (.png or .svg)");
  command
      ->add_option("--threads", flags->threads,
                   "Threads (default: every core; under mpirun, each rank's share of its "
                   "machine's cores)")
      ->check(CLI::Range(1u, 256u));
  command->add_flag("--json", flags->json, "Print every run's results as JSON");
  command->callback([flags] { run(*flags); });
}

}  // namespace ridefit::cli
