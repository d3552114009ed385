#include "distributed_sweep.h"

#include <cstdint>
#include <cstring>
#include <string>
#include <utility>

namespace ridefit::cli {
namespace {

// A row as raw doubles: exact, so rank 0 writes the same bytes as one process.
void put(std::string& out, double v) { out.append(reinterpret_cast<const char*>(&v), sizeof v); }
double take(const std::string& in, std::size_t& at) {
  double v = 0.0;
  std::memcpy(&v, in.data() + at, sizeof v);
  at += sizeof v;
  return v;
}

// Every field of the metrics (a field left out here would read 0 after a multi-rank run, which
// the rank tests' byte comparison with the one-process run catches).
constexpr double study::HalfCarMetrics::*kMetricFields[] = {
    &study::HalfCarMetrics::seat_acc_wk_rms_m_per_s2,
    &study::HalfCarMetrics::lower_body_acc_wk_rms_m_per_s2,
    &study::HalfCarMetrics::upper_body_acc_wk_rms_m_per_s2,
    &study::HalfCarMetrics::pitch_acc_we_rms_rad_per_s2,
    &study::HalfCarMetrics::seat_acc_rms_m_per_s2,
    &study::HalfCarMetrics::lower_body_acc_rms_m_per_s2,
    &study::HalfCarMetrics::upper_body_acc_rms_m_per_s2,
    &study::HalfCarMetrics::body_acc_rms_m_per_s2,
    &study::HalfCarMetrics::pitch_acc_rms_rad_per_s2,
    &study::HalfCarMetrics::front_travel_rms_m,
    &study::HalfCarMetrics::rear_travel_rms_m,
    &study::HalfCarMetrics::front_tyre_force_rms_N,
    &study::HalfCarMetrics::rear_tyre_force_rms_N,
    &study::HalfCarMetrics::front_dynamic_load_ratio,
    &study::HalfCarMetrics::rear_dynamic_load_ratio,
};

std::string encode(const study::SweepRow& row) {
  std::string out;
  put(out, row.frequency_domain ? 1.0 : 0.0);
  put(out, row.point.speed_m_per_s);
  for (const auto field : kMetricFields) put(out, row.metrics.*field);
  return out;
}

study::SweepRow decode(const std::string& bytes, study::SweepPoint point) {
  study::SweepRow row;
  std::size_t at = 0;
  row.frequency_domain = take(bytes, at) != 0.0;
  point.speed_m_per_s = take(bytes, at);
  row.point = std::move(point);
  for (const auto field : kMetricFields) row.metrics.*field = take(bytes, at);
  return row;
}

}  // namespace

std::vector<study::SweepRow> run_distributed_sweep(
    const distributed::MpiSession& session, const study::HalfCarSweep& sweep, unsigned threads,
    const std::function<void(std::size_t, std::size_t)>& progress,
    distributed::TaskFarmStatistics* statistics) {
  const unsigned rank_threads =
      threads > 0 ? threads : distributed::default_threads_per_rank(session);
  // Every rank prepares the whole study (cheap beside the runs), so a task is only its index.
  const study::PreparedSweep prepared(sweep, rank_threads);
  distributed::TaskFarmOptions options;
  options.threads = rank_threads;
  options.progress = progress;
  options.statistics = statistics;
  const std::vector<std::string> results = distributed::run_task_farm(
      session, prepared.runs(), [&](std::size_t i) { return encode(prepared.run(i)); }, options);
  if (!session.root()) return {};
  const std::vector<study::SweepPoint> points = study::expand(sweep);
  std::vector<study::SweepRow> rows;
  rows.reserve(results.size());
  for (std::size_t i = 0; i < results.size(); ++i) rows.push_back(decode(results[i], points[i]));
  return rows;
}

}  // namespace ridefit::cli
