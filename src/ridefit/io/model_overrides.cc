#include "ridefit/io/model_overrides.h"

#include <fmt/core.h>

namespace ridefit::io {

ModelOverrides::ModelOverrides(std::initializer_list<std::pair<std::string, std::string>> texts)
    : keys(texts) {}

ModelOverrides::ModelOverrides(std::initializer_list<std::pair<std::string, double>> numbers) {
  for (const auto& [key, value] : numbers) set(key, value);
}

ModelOverrides& ModelOverrides::set(std::string key, std::string text) {
  keys.emplace_back(std::move(key), std::move(text));
  return *this;
}

ModelOverrides& ModelOverrides::set(std::string key, double value) {
  // fmt's "{}" is the shortest text that reads back to the same double (and "nan" or "inf",
  // which the readers refuse as numbers).
  return set(std::move(key), fmt::format("{}", value));
}

std::string with_override_named(const std::string& message, const ModelOverrides& overrides) {
  for (const auto& [key, value] : overrides.keys) {
    const auto dot = key.rfind('.');
    const std::string last = dot == std::string::npos ? key : key.substr(dot + 1);
    if (message.find("'" + key + "'") != std::string::npos ||
        (dot != std::string::npos && message.find(last) != std::string::npos)) {
      return fmt::format("{} ({} {}={})", message, overrides.origin, key, value);
    }
  }
  return message;
}

}  // namespace ridefit::io
