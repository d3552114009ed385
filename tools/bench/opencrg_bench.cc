// OpenCRG reading speed: a 10 m x 3.4 m grid at 1 cm (1001 rows x 341 long sections, KRBI,
// 1.37 MB), written once to a temporary file. Run with
//   opencrg_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// and record the medians in README's benchmark table (target: read <= 20 ms).
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <filesystem>
#include <random>
#include <string>

#include "ridefit/road/opencrg_file.h"
#include "ridefit/road/opencrg_road.h"

namespace {

namespace fs = std::filesystem;
using ridefit::road::CrgFormat;
using ridefit::road::CrgGrid;

// The grid's file, written on first use and removed at exit.
class GridFile {
 public:
  explicit GridFile(CrgFormat format) {
    path_ = fs::temp_directory_path() / ("ridefit_opencrg_bench_" + std::to_string(getpid()) + "_" +
                                         std::to_string(static_cast<int>(format)) + ".crg");
    CrgGrid grid;
    grid.u_increment_m = 0.01;
    for (int c = 0; c < 341; ++c) grid.v_m.push_back(-1.7 + 0.01 * c);
    std::mt19937_64 rng(1);
    std::normal_distribution<double> normal(0.0, 0.003);
    grid.z_m.resize(1001 * 341);
    for (double& z : grid.z_m) z = normal(rng);
    ridefit::road::write_opencrg(grid, path_, format);
  }
  ~GridFile() { fs::remove(path_); }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

const fs::path& krbi_file() {
  static const GridFile file(CrgFormat::kKrbi);
  return file.path();
}

void BM_OpenCrgReadKrbi341x1001(benchmark::State& state) {
  const fs::path& path = krbi_file();
  for (auto _ : state) {
    CrgGrid grid = ridefit::road::read_opencrg(path);
    benchmark::DoNotOptimize(grid.z_m.data());
  }
}
BENCHMARK(BM_OpenCrgReadKrbi341x1001)->Unit(benchmark::kMillisecond);

// The same grid as LRFI text (341 values a row, wrapped over 43 lines of 8).
void BM_OpenCrgReadLrfi341x1001(benchmark::State& state) {
  static const GridFile file(CrgFormat::kLrfi);
  for (auto _ : state) {
    CrgGrid grid = ridefit::road::read_opencrg(file.path());
    benchmark::DoNotOptimize(grid.z_m.data());
  }
}
BENCHMARK(BM_OpenCrgReadLrfi341x1001)->Unit(benchmark::kMillisecond);

// Reading plus the track between two sections and its spline: what `type: opencrg` does.
void BM_OpenCrgRoad341x1001(benchmark::State& state) {
  const fs::path& path = krbi_file();
  ridefit::road::OpenCrgRoadParameters p;
  p.lateral_offset_m = 0.345;
  for (auto _ : state) {
    auto road = ridefit::road::load_opencrg_road(path, p);
    benchmark::DoNotOptimize(road);
  }
}
BENCHMARK(BM_OpenCrgRoad341x1001)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
