// The summary of `ridefit batch` (batch_summary.h).
#include "batch_summary.h"

#include <fmt/core.h>

#include <ostream>
#include <tuple>

#include "ridefit/io/atomic_file.h"

namespace ridefit::cli {
namespace {

// A field of the summary's row from the command's --json summary (null when absent).
nlohmann::json field(const nlohmann::json& summary, const char* key) {
  return summary.is_object() && summary.contains(key) ? summary[key] : nlohmann::json();
}

// The row's key values: a fit's parameters (name, value, standard error; the file for a
// per-file one), a diagnosis' named effects and its gap before and after.
void add_key_values(nlohmann::json& row, const nlohmann::json& summary) {
  row["parameters"] = nlohmann::json::array();
  for (const auto& p : field(summary, "parameters")) {
    nlohmann::json value = {{"name", p.at("name")},
                            {"value", p.at("value")},
                            {"standard_error", p.at("standard_error")}};
    if (p.contains("file") && p["file"].is_string() && !p["file"].get<std::string>().empty()) {
      value["file"] = p["file"];
    }
    row["parameters"].push_back(value);
  }
  row["nrmse_percent"] = field(summary, "nrmse_percent");
  const nlohmann::json named = field(summary, "named");
  row["top_effect"] = named.is_array() && !named.empty() ? named[0] : nlohmann::json();
  row["named_effects"] = named.is_array() ? named : nlohmann::json::array();
  for (const auto& [unit, before, after] :
       {std::tuple{"dB", "gap_before_dB", "gap_after_dB"},
        std::tuple{"%", "gap_before_nrmse_percent", "gap_after_nrmse_percent"}}) {
    if (field(summary, before).is_null()) continue;
    row["gap_before"] = field(summary, before);
    row["gap_after"] = field(summary, after);
    row["gap_unit"] = unit;
  }
}

// A CSV field: quoted when it holds a comma, a quote or a line break.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  quoted += '"';
  return quoted;
}

std::string number_text(const nlohmann::json& value) {
  return value.is_number() ? fmt::format("{:.10g}", value.get<double>()) : "";
}

std::string text_of(const nlohmann::json& value) {
  return value.is_string() ? value.get<std::string>() : "";
}

void write_csv(std::ostream& out, const nlohmann::json& summary) {
  out << "job[1],name,command,records,status,parameters,nrmse[%],top_effect,gap_before,"
         "gap_after,gap_unit,wall_time[s],message\n";
  for (const auto& row : summary.at("jobs")) {
    std::string records;
    for (const auto& r : row.at("records")) {
      if (!records.empty()) records += ';';
      records += text_of(r);
    }
    std::string values;
    for (const auto& p : row.at("parameters")) {
      values += fmt::format("{}{}{}={}", values.empty() ? "" : "; ", text_of(p.at("name")),
                            p.contains("file") ? fmt::format("[{}]", text_of(p["file"])) : "",
                            number_text(p.at("value")));
      if (p.at("standard_error").is_number()) {
        values += fmt::format("±{:.3g}", p["standard_error"].get<double>());
      }
    }
    const auto get = [&](const char* key) {
      return row.contains(key) ? row[key] : nlohmann::json();
    };
    out << fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{}\n", row.at("job").get<int>(),
                       csv_field(text_of(row.at("name"))), csv_field(text_of(row.at("command"))),
                       csv_field(records), text_of(row.at("status")), csv_field(values),
                       number_text(get("nrmse_percent")), csv_field(text_of(get("top_effect"))),
                       number_text(get("gap_before")), number_text(get("gap_after")),
                       text_of(get("gap_unit")), number_text(get("wall_time_s")),
                       csv_field(text_of(get("message"))));
  }
}

}  // namespace

nlohmann::json batch_summary_json(const std::filesystem::path& job_file,
                                  const std::vector<BatchJob>& jobs,
                                  const std::vector<BatchJobResult>& results) {
  nlohmann::json summary = {{"job_file", job_file.string()},
                            {"jobs", nlohmann::json::array()},
                            {"ok", 0},
                            {"failed", 0},
                            {"not_run", 0}};
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    const BatchJobResult& result = results[i];
    nlohmann::json row = {{"job", i + 1},
                          {"name", jobs[i].name},
                          {"command", jobs[i].command},
                          {"records", jobs[i].records},
                          {"status", result.status}};
    add_key_values(row, result.summary);
    if (result.status != "not run") row["wall_time_s"] = result.wall_time_s;
    if (!result.message.empty()) row["message"] = result.message;
    const std::string count = result.status == "not run" ? "not_run" : result.status;
    summary[count] = summary[count].get<int>() + 1;
    summary["jobs"].push_back(std::move(row));
  }
  return summary;
}

void write_batch_summary(const std::filesystem::path& dir, const nlohmann::json& summary) {
  io::write_atomically(dir / "summary.json", [&](std::ostream& out) {
    out << summary.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  });
  io::write_atomically(dir / "summary.csv", [&](std::ostream& out) { write_csv(out, summary); });
}

}  // namespace ridefit::cli
