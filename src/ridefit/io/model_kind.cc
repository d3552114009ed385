#include "ridefit/io/model_kind.h"

#include "ridefit/io/yaml_map.h"

namespace ridefit::io {

std::string model_kind(const std::filesystem::path& path) {
  return YamlMap::load(path).choice("model", {"quarter_car", "half_car"});
}

}  // namespace ridefit::io
