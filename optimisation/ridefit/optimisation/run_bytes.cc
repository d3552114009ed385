#include "ridefit/optimisation/run_bytes.h"

#include <cstdint>
#include <stdexcept>

#include "ridefit/common/byte_buffer.h"

namespace ridefit::optimisation {
namespace {

using common::ByteReader;
using common::ByteWriter;

void put_count(ByteWriter& out, std::size_t n) { out.put(static_cast<std::uint64_t>(n)); }
std::size_t get_count(ByteReader& in) { return static_cast<std::size_t>(in.get<std::uint64_t>()); }

void put_flags(ByteWriter& out, const std::vector<bool>& flags) {
  put_count(out, flags.size());
  for (bool f : flags) out.put(static_cast<std::uint8_t>(f));
}
std::vector<bool> get_flags(ByteReader& in) {
  std::vector<bool> flags(get_count(in));
  for (std::size_t i = 0; i < flags.size(); ++i) flags[i] = in.get<std::uint8_t>() != 0;
  return flags;
}

void put_table(ByteWriter& out, const std::vector<std::vector<double>>& rows) {
  put_count(out, rows.size());
  for (const auto& row : rows) out.put(row);
}
std::vector<std::vector<double>> get_table(ByteReader& in) {
  std::vector<std::vector<double>> rows(get_count(in));
  for (auto& row : rows) row = in.get_doubles();
  return rows;
}

void put_evaluation(ByteWriter& out, const Evaluation& e) {
  out.put(e.x);
  put_table(out, e.case_values);
  put_flags(out, e.frequency_domain);
  out.put(e.objective);
  out.put(e.constraint_values);
  out.put(static_cast<std::uint8_t>(e.reused));
}
Evaluation get_evaluation(ByteReader& in) {
  Evaluation e;
  e.x = in.get_doubles();
  e.case_values = get_table(in);
  e.frequency_domain = get_flags(in);
  e.objective = in.get<double>();
  e.constraint_values = in.get_doubles();
  e.reused = in.get<std::uint8_t>() != 0;
  return e;
}

void put_records(ByteWriter& out, const std::vector<JournalRecord>& records) {
  put_count(out, records.size());
  for (const auto& r : records) {
    out.put(r.variant);
    out.put(r.x);
    put_table(out, r.case_values);
    put_flags(out, r.frequency_domain);
  }
}
std::vector<JournalRecord> get_records(ByteReader& in) {
  std::vector<JournalRecord> records(get_count(in));
  for (auto& r : records) {
    r.variant = in.get_string();
    r.x = in.get_doubles();
    r.case_values = get_table(in);
    r.frequency_domain = get_flags(in);
  }
  return records;
}

void expect_end(const ByteReader& in) {
  if (!in.done()) throw std::logic_error("run_bytes: bytes left over");
}

}  // namespace

std::string run_to_bytes(const OptimisationRun& run, const std::vector<JournalRecord>& computed) {
  ByteWriter out;
  out.put(static_cast<std::uint8_t>(run.variant == FrictionVariant::kBlind));
  out.put(run.limits);
  put_evaluation(out, run.best);
  put_evaluation(out, run.verified);
  out.put(static_cast<std::uint8_t>(run.feasible));
  put_count(out, run.margins.size());
  for (const auto& m : run.margins) {
    out.put(m.description);
    for (double v : {m.limit, m.value, m.margin, m.relative_margin}) out.put(v);
    out.put(static_cast<std::uint8_t>(m.holds));
  }
  out.put(run.nlopt_result);
  out.put(static_cast<std::int64_t>(run.evaluations));
  out.put(static_cast<std::int64_t>(run.computed));
  put_count(out, run.history.size());
  for (const auto& step : run.history) {
    out.put(static_cast<std::int64_t>(step.start));
    out.put(step.objective);
    out.put(step.max_violation);
    out.put(static_cast<std::uint8_t>(step.reused));
  }
  put_records(out, computed);
  return out.take();
}

std::pair<OptimisationRun, std::vector<JournalRecord>> run_from_bytes(const std::string& bytes) {
  ByteReader in(bytes);
  OptimisationRun run;
  run.variant = in.get<std::uint8_t>() ? FrictionVariant::kBlind : FrictionVariant::kStudy;
  run.limits = in.get_doubles();
  run.best = get_evaluation(in);
  run.verified = get_evaluation(in);
  run.feasible = in.get<std::uint8_t>() != 0;
  run.margins.resize(get_count(in));
  for (auto& m : run.margins) {
    m.description = in.get_string();
    m.limit = in.get<double>();
    m.value = in.get<double>();
    m.margin = in.get<double>();
    m.relative_margin = in.get<double>();
    m.holds = in.get<std::uint8_t>() != 0;
  }
  run.nlopt_result = in.get_string();
  run.evaluations = static_cast<int>(in.get<std::int64_t>());
  run.computed = static_cast<int>(in.get<std::int64_t>());
  run.history.resize(get_count(in));
  for (auto& step : run.history) {
    step.start = static_cast<int>(in.get<std::int64_t>());
    step.objective = in.get<double>();
    step.max_violation = in.get<double>();
    step.reused = in.get<std::uint8_t>() != 0;
  }
  std::vector<JournalRecord> computed = get_records(in);
  expect_end(in);
  return {std::move(run), std::move(computed)};
}

std::string records_to_bytes(const std::vector<JournalRecord>& records) {
  ByteWriter out;
  put_records(out, records);
  return out.take();
}

std::vector<JournalRecord> records_from_bytes(const std::string& bytes) {
  ByteReader in(bytes);
  std::vector<JournalRecord> records = get_records(in);
  expect_end(in);
  return records;
}

}  // namespace ridefit::optimisation
