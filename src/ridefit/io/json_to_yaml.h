#pragma once

#include <yaml-cpp/yaml.h>

#include <nlohmann/json.hpp>

namespace ridefit::io {

// The same tree as YAML, so a result file carries exactly what --json prints: objects become
// maps, arrays sequences; booleans, integers, numbers and strings stay what they are. The
// tree must hold no null (nlohmann::json::type_error).
YAML::Node to_yaml(const nlohmann::json& json);

}  // namespace ridefit::io
