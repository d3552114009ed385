#include "ridefit/optimisation/tuning_settings.h"

#include <fmt/core.h>

#include <cmath>
#include <string>

#include "ridefit/common/errors.h"

namespace ridefit::optimisation {
namespace {

using common::SettingError;

// The wording of the file readers (io/yaml_map.h): "is 0, expected a value > 0 and <= 0.5".
std::optional<SettingError> positive_up_to(const char* key, double v, double hi) {
  if (v > 0.0 && v <= hi) return std::nullopt;
  return SettingError{key, fmt::format("is {}, expected a value > 0 and <= {:g}", v, hi)};
}

std::optional<SettingError> non_negative_up_to(const char* key, double v, double hi) {
  if (v >= 0.0 && v <= hi) return std::nullopt;
  return SettingError{key, fmt::format("is {}, expected a value in [0, {:g}]", v, hi)};
}

std::optional<SettingError> number_in(const char* key, double v, double lo, double hi) {
  if (v >= lo && v <= hi) return std::nullopt;
  return SettingError{key, fmt::format("is {}, expected a value in [{}, {}]", v, lo, hi)};
}

std::optional<SettingError> integer_in(const char* key, long v, long lo, long hi,
                                       const char* note = "") {
  if (v >= lo && v <= hi) return std::nullopt;
  return SettingError{key, fmt::format("is {}, expected {}{} … {}", v, lo, note, hi)};
}

template <typename... Checks>
std::optional<SettingError> first(const Checks&... checks) {
  std::optional<SettingError> found;
  ((found = found ? found : checks), ...);
  return found;
}

void throw_if(const std::optional<SettingError>& e, const char* section) {
  if (e) throw InputError(fmt::format("{} setting '{}' {}", section, e->key, e->message));
}

}  // namespace

std::optional<SettingError> OptimiserSettings::error() const {
  if (auto e = first(integer_in("starts", starts, 1, kMaxStarts),
                     integer_in("max_evaluations", max_evaluations, 1, kMaxEvaluations),
                     positive_up_to("x_tolerance", x_tolerance, 0.5),
                     non_negative_up_to("f_tolerance", f_tolerance, 0.5),
                     non_negative_up_to("max_time_s", max_time_s, 1e7),
                     positive_up_to("initial_step", initial_step, 1.0),
                     non_negative_up_to("constraint_tolerance", constraint_tolerance, 0.01))) {
    return e;
  }
  if (algorithm == Algorithm::kDirectL && starts > 1) {
    return SettingError{"starts", fmt::format("is {}, but DIRECT-L does not use a start point, so "
                                              "more starts only repeat it; give starts: 1",
                                              starts)};
  }
  return std::nullopt;
}

void OptimiserSettings::validate() const { throw_if(error(), "optimiser"); }

std::optional<SettingError> EvaluationSettings::error() const {
  return first(positive_up_to("output_rate_Hz", output_rate_Hz, 1e5),
               non_negative_up_to("settle_s", settle_s, 1e4),
               non_negative_up_to("duration_s", duration_s, 1e5),
               number_in("relative_tolerance", relative_tolerance, 1e-12, 1e-2),
               number_in("verify_relative_tolerance", verify_relative_tolerance, 1e-12, 1e-2),
               integer_in("frequency_points", frequency_points, 50, 100000),
               integer_in("threads", threads, 0, 1024, " (every core)"));
}

void EvaluationSettings::validate() const { throw_if(error(), "evaluation"); }

}  // namespace ridefit::optimisation
