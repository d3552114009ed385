// One job of `ridefit batch` run, and its bytes (batch_job_result.h).
#include "batch_job_result.h"

#include <chrono>
#include <exception>

#include "ridefit/common/errors.h"

namespace ridefit::cli {

BatchJobResult run_batch_job(const BatchJob& job) {
  const auto start = std::chrono::steady_clock::now();
  BatchJobResult result;
  try {
    const CommandOutcome outcome = job.run();
    result.status = outcome.failure.empty() ? "ok" : "failed";
    result.message = outcome.failure;
    result.summary = outcome.summary;
    result.files.push_back({"result.json", outcome.summary.dump(2) + "\n"});
    result.files.insert(result.files.end(), outcome.files.begin(), outcome.files.end());
  } catch (const InputError& e) {
    result.status = "failed";
    result.message = std::string("bad input: ") + e.what();
  } catch (const std::exception& e) {  // RunError and anything else: this job only
    result.status = "failed";
    result.message = e.what();
  }
  result.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

std::string encode(const BatchJobResult& result) {
  nlohmann::json j = {{"status", result.status},
                      {"message", result.message},
                      {"summary", result.summary},
                      {"files", nlohmann::json::array()},
                      {"wall_time_s", result.wall_time_s}};
  for (const auto& file : result.files) j["files"].push_back({file.name, file.text});
  // A message may quote a file that is not UTF-8: its bad bytes become U+FFFD.
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

BatchJobResult decode_batch_job_result(const std::string& bytes) {
  const nlohmann::json j = nlohmann::json::parse(bytes);
  BatchJobResult result;
  result.status = j.at("status").get<std::string>();
  result.message = j.at("message").get<std::string>();
  result.summary = j.at("summary");
  for (const auto& file : j.at("files")) {
    result.files.push_back({file.at(0).get<std::string>(), file.at(1).get<std::string>()});
  }
  result.wall_time_s = j.at("wall_time_s").get<double>();
  return result;
}

}  // namespace ridefit::cli
