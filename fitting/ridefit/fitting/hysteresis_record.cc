#include "ridefit/fitting/hysteresis_record.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "ridefit/common/errors.h"
#include "ridefit/fitting/quantised_displacement.h"
#include "ridefit/io/command_column.h"
#include "ridefit/io/csv_table.h"
#include "ridefit/io/measurement_file.h"
#include "ridefit/signal/signal_presence.h"

namespace ridefit::fitting {
namespace {

// The record's channels from its table (all rows), checked for units; no length check yet.
HysteresisRecord record_from_table(const io::CsvTable& table, const std::string& source) {
  HysteresisRecord record;
  record.source = source;
  record.time_s = table.time_s();
  const io::CsvColumn& displacement = table.column("displacement");
  const io::CsvColumn& force = table.column("force");
  if (displacement.unit != "m") {
    throw InputError(fmt::format("{}: column displacement is in {}, expected a length (m, mm)",
                                 source, displacement.unit));
  }
  if (force.unit != "N") {
    throw InputError(
        fmt::format("{}: column force is in {}, expected a force (N, kN)", source, force.unit));
  }
  record.displacement_m = displacement.values;
  record.force_N = force.values;
  if (auto command = io::read_command_column(table, source)) {
    record.command = std::move(command->values);
    record.command_unit = command->unit;
  }
  if (table.has("velocity")) {
    const io::CsvColumn& velocity = table.column("velocity");
    if (velocity.unit != "m/s") {
      throw InputError(fmt::format("{}: column velocity is in {}, expected a speed (m/s, mm/s)",
                                   source, velocity.unit));
    }
    record.velocity_m_per_s = velocity.values;
  }
  return record;
}

// At least 20 samples, a displacement that moves and a force that changes.
void require_fittable(const HysteresisRecord& record) {
  if (record.time_s.size() < 20) {
    throw InputError(fmt::format("{}: {} samples; a hysteresis fit needs at least 20",
                                 record.source, record.time_s.size()));
  }
  // A rig that did not move, or a load cell that read nothing, gives a fit of round-off.
  signal::require_signal(record.displacement_m, record.source, "displacement", "m");
  signal::require_signal(record.force_N, record.source, "force", "N");
}

// How many times x crosses its mid-stroke (with a dead band of 5 % of the stroke, so that
// quantisation noise at a turning point does not count).
int mid_stroke_crossings(const std::vector<double>& x) {
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  const double mid = 0.5 * (*lo + *hi), band = 0.05 * (*hi - *lo);
  int side = 0, crossings = 0;
  for (double v : x) {
    const int now = v > mid + band ? 1 : (v < mid - band ? -1 : 0);
    if (now != 0 && side != 0 && now != side) ++crossings;
    if (now != 0) side = now;
  }
  return crossings;
}

// At least one whole cycle: two crossings of mid-stroke, or one for a record that starts and
// ends near mid-stroke (0 → +A → −A → 0, a sine or triangle started at its zero).
bool holds_a_cycle(const std::vector<double>& x) {
  const int crossings = mid_stroke_crossings(x);
  if (crossings >= 2) return true;
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  const double mid = 0.5 * (*lo + *hi), near = 0.25 * (*hi - *lo);
  return crossings == 1 && std::abs(x.front() - mid) <= near && std::abs(x.back() - mid) <= near;
}

}  // namespace

HysteresisRecord rows_of(const HysteresisRecord& r, std::size_t first, std::size_t last,
                         std::string source) {
  auto part = [&](const std::vector<double>& v) {
    return v.empty() ? std::vector<double>()
                     : std::vector<double>(v.begin() + static_cast<std::ptrdiff_t>(first),
                                           v.begin() + static_cast<std::ptrdiff_t>(last));
  };
  HysteresisRecord out;
  out.source = std::move(source);
  out.time_s = part(r.time_s);
  out.displacement_m = part(r.displacement_m);
  out.force_N = part(r.force_N);
  out.command = part(r.command);
  out.command_unit = r.command_unit;
  out.velocity_m_per_s = part(r.velocity_m_per_s);
  // Rows of an examined record keep its displacement as it was treated.
  out.displacement_low_pass = r.displacement_low_pass;
  out.displacement_low_passed = r.displacement_low_passed;
  return out;
}

HysteresisRecord load_hysteresis_record(const std::filesystem::path& csv_file) {
  HysteresisRecord record =
      record_from_table(io::read_measurement_table(csv_file), csv_file.string());
  require_fittable(record);
  examine_quantised_displacement(record);
  return record;
}

std::pair<std::size_t, std::size_t> moving_rows(const HysteresisRecord& record) {
  const auto& x = record.displacement_m;
  const std::size_t n = x.size();
  if (n < 3) return {0, n};
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  const double stroke = *hi - *lo;
  // Motion: 1 % of the stroke away from the rest position. The motion starts where the
  // displacement last sat within a few quantisation steps (the smallest step seen) of rest.
  double step = stroke;
  for (std::size_t k = 1; k < n; ++k) {
    const double d = std::abs(x[k] - x[k - 1]);
    if (d > 1e-6 * stroke) step = std::min(step, d);
  }
  const double moved = 0.01 * stroke, still = std::max(2.5 * step, 1e-4 * stroke);
  std::size_t first = 0;
  while (first < n && std::abs(x[first] - x.front()) <= moved) ++first;
  while (first > 0 && std::abs(x[first - 1] - x.front()) > still) --first;
  std::size_t last = n;
  while (last > first && std::abs(x[last - 1] - x.back()) <= moved) --last;
  while (last < n && std::abs(x[last] - x.back()) > still) ++last;
  // A sample of rest on each side: the model starts from rest at the first one.
  first = first > 0 ? first - 1 : 0;
  last = std::min(n, last + 1);
  if (last <= first + 2) return {0, n};
  return {first, last};
}

std::vector<HysteresisRecord> load_hysteresis_tests(const std::filesystem::path& file) {
  const io::CsvTable table = io::read_measurement_table(file);
  HysteresisRecord whole = record_from_table(table, file.string());
  const std::string segment_name =
      table.has("segment") ? "segment" : (table.has("test") ? "test" : "");
  if (segment_name.empty()) {
    require_fittable(whole);
    if (!holds_a_cycle(whole.displacement_m)) {
      throw InputError(fmt::format(
          "{}: the test (rows 2-{}) moves through less than one cycle (its displacement crosses "
          "mid-stroke {} time(s)); a loop needs at least one whole cycle",
          file.string(), whole.time_s.size() + 1, mid_stroke_crossings(whole.displacement_m)));
    }
    examine_quantised_displacement(whole);
    return {whole};
  }
  // Rows of each test, in the order the tests appear; a test's rows must be contiguous.
  const std::vector<double>& number = table.column(segment_name).values;
  std::vector<std::pair<long, std::pair<std::size_t, std::size_t>>> tests;
  for (std::size_t k = 0; k < number.size(); ++k) {
    const double v = number[k];
    if (v != std::floor(v) || std::abs(v) > 1e9) {
      throw InputError(fmt::format(
          "{}: row {}, column '{}': {} is not a whole number; it numbers the tests in the file "
          "(1, 2, 3, ...)",
          file.string(), k + 2, segment_name, v));
    }
    const long id = static_cast<long>(v);
    if (tests.empty() || tests.back().first != id) {
      for (const auto& t : tests) {
        if (t.first == id) {
          throw InputError(fmt::format(
              "{}: row {}, column '{}': test {} appears again after another test (rows {}-{}); "
              "each test's rows must follow each other",
              file.string(), k + 2, segment_name, id, t.second.first + 2, t.second.second + 1));
        }
      }
      tests.push_back({id, {k, k + 1}});
    } else {
      tests.back().second.second = k + 1;
    }
  }
  std::vector<HysteresisRecord> out;
  for (const auto& [id, rows] : tests) {
    const std::string label = fmt::format("{} ({} {})", file.string(), segment_name, id);
    HysteresisRecord test = rows_of(whole, rows.first, rows.second, label);
    require_fittable(test);
    const auto [first, last] = moving_rows(test);
    test = rows_of(test, first, last, label);
    if (!holds_a_cycle(test.displacement_m)) {
      throw InputError(fmt::format(
          "{}: {} {} (rows {}-{}) moves through less than one cycle (its displacement crosses "
          "mid-stroke {} time(s)); a loop needs at least one whole cycle",
          file.string(), segment_name, id, rows.first + 2, rows.second + 1,
          mid_stroke_crossings(test.displacement_m)));
    }
    require_fittable(test);
    examine_quantised_displacement(test);
    out.push_back(std::move(test));
  }
  return out;
}

std::vector<HysteresisRecord> load_rig_files(const std::vector<std::filesystem::path>& files,
                                             const std::string& per_file_option) {
  std::vector<HysteresisRecord> records;
  for (const auto& file : files) {
    std::vector<HysteresisRecord> tests = load_hysteresis_tests(file);
    if (!per_file_option.empty() && tests.size() > 1) {
      throw InputError(fmt::format(
          "{}: {} holds {} tests (a segment column), and per-file values are written one model "
          "per file; fit the tests with shared parameters (a command column gives each its own "
          "level through the command law), or split the file",
          per_file_option, file.string(), tests.size()));
    }
    for (auto& test : tests) records.push_back(std::move(test));
  }
  return records;
}

}  // namespace ridefit::fitting
