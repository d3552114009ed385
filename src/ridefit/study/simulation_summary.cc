#include "ridefit/study/simulation_summary.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "ridefit/signal/statistics.h"
#include "ridefit/simulate/solver_statistics_json.h"

namespace ridefit::study {
namespace {

// The share of samples in which the Dahl element is on its pre-sliding branch.
double stuck_share(const simulate::QuarterCarResponse& response) {
  double share = 0.0;
  for (double s : response.stuck) share += s;
  return share / static_cast<double>(response.stuck.size());
}

std::string written_to(const SimulationRun& run) {
  return run.output_file.empty() ? "" : ", written to " + run.output_file;
}

}  // namespace

std::string summary_text(const SimulationRun& run, const model::QuarterCar& car,
                         const simulate::QuarterCarResponse& response) {
  return fmt::format(
      "{} over {}: {} samples, {} steps ({}), body_acc RMS {:.4g} m/s^2, wheel_acc RMS "
      "{:.4g} m/s^2, stuck {:.1f} % of the time{}\n",
      model::to_string(car.damper_state()), run.excitation_file, response.time_s.size(),
      response.statistics.steps, response.statistics.method,
      signal::rms(response.body_acc_m_per_s2), signal::rms(response.wheel_acc_m_per_s2),
      100.0 * stuck_share(response), written_to(run));
}

nlohmann::json summary_json(const SimulationRun& run, const model::QuarterCar& car,
                            const simulate::QuarterCarResponse& response) {
  double travel_peak = 0.0;
  for (double t : response.travel_m) travel_peak = std::max(travel_peak, std::abs(t));
  return {{"model", run.model_file},
          {"excitation", run.excitation_file},
          {"damper_state", model::to_string(car.damper_state())},
          {"output", run.output_file},
          {"duration_s", response.time_s.back()},
          {"samples", response.time_s.size()},
          {"output_rate_Hz", run.output_rate_Hz},
          {"wall_time_s", run.wall_time_s},
          {"solver", simulate::to_json(response.statistics)},
          {"rms",
           {{"body_acc_m_per_s2", signal::rms(response.body_acc_m_per_s2)},
            {"wheel_acc_m_per_s2", signal::rms(response.wheel_acc_m_per_s2)},
            {"travel_m", signal::rms(response.travel_m)},
            {"tyre_force_N", signal::rms(response.tyre_force_N)},
            {"friction_force_N", signal::rms(response.friction_force_N)}}},
          {"travel_peak_m", travel_peak},
          {"stuck_share", stuck_share(response)}};
}

std::string summary_text(const SimulationRun& run, const simulate::HalfCarResponse& response,
                         const std::optional<HalfCarMetrics>& metrics) {
  std::string text =
      fmt::format("half car over {}: {} samples, {} steps ({}), rear delay {:.4g} s{}\n",
                  run.excitation_file, response.time_s.size(), response.statistics.steps,
                  response.statistics.method, response.rear_delay_s, written_to(run));
  if (metrics) {
    text += fmt::format(
        "  Wk-weighted RMS: seat {:.4g}, lower body {:.4g}, upper body {:.4g} m/s^2; We pitch "
        "{:.4g} rad/s^2\n  travel RMS front {:.4g} m, rear {:.4g} m; dynamic tyre load RMS "
        "front {:.3f}, rear {:.3f} of static\n",
        metrics->seat_acc_wk_rms_m_per_s2, metrics->lower_body_acc_wk_rms_m_per_s2,
        metrics->upper_body_acc_wk_rms_m_per_s2, metrics->pitch_acc_we_rms_rad_per_s2,
        metrics->front_travel_rms_m, metrics->rear_travel_rms_m, metrics->front_dynamic_load_ratio,
        metrics->rear_dynamic_load_ratio);
  }
  return text;
}

nlohmann::json summary_json(const SimulationRun& run, const simulate::HalfCarResponse& response,
                            const std::optional<HalfCarMetrics>& metrics) {
  nlohmann::json summary = {{"model", run.model_file},
                            {"excitation", run.excitation_file},
                            {"output", run.output_file},
                            {"samples", response.time_s.size()},
                            {"rear_delay_s", response.rear_delay_s},
                            {"wall_time_s", run.wall_time_s},
                            {"solver", simulate::to_json(response.statistics)}};
  if (metrics) {
    for (const auto& [name, value] : metrics->named()) summary["metrics"][name] = value;
  }
  return summary;
}

}  // namespace ridefit::study
