#include "ridefit/io/json_to_yaml.h"

namespace ridefit::io {

YAML::Node to_yaml(const nlohmann::json& json) {
  if (json.is_object()) {
    YAML::Node node(YAML::NodeType::Map);
    for (const auto& [key, value] : json.items()) node[key] = to_yaml(value);
    return node;
  }
  if (json.is_array()) {
    YAML::Node node(YAML::NodeType::Sequence);
    for (const auto& value : json) node.push_back(to_yaml(value));
    return node;
  }
  if (json.is_boolean()) return YAML::Node(json.get<bool>());
  if (json.is_number_integer()) return YAML::Node(json.get<long>());
  if (json.is_number()) return YAML::Node(json.get<double>());
  return YAML::Node(json.get<std::string>());
}

}  // namespace ridefit::io
