#include "ridefit/synthetic/road_realisation.h"

#include <yaml-cpp/yaml.h>

#include <fstream>
#include <string>

#include "ridefit/io/temporary_files.h"
#include "ridefit/road/excitation_file.h"

namespace ridefit::synthetic {

std::unique_ptr<road::RoadInput> load_road_realisation(const std::filesystem::path& excitation,
                                                       int record,
                                                       const std::filesystem::path& scratch) {
  YAML::Node node = YAML::LoadFile(excitation.string());
  const std::string type = node["type"] ? node["type"].as<std::string>() : "";
  if (record == 1 || (type != "iso8608" && type != "power_law")) {
    return road::load_excitation(excitation);
  }
  const long seed = node["seed"] ? node["seed"].as<long>() : 1;
  node["seed"] = seed + record - 1;
  const io::TemporaryFile registered(scratch);  // removed if the run is interrupted
  {
    std::ofstream out(scratch);
    out << node << "\n";
  }
  auto road = road::load_excitation(scratch);
  std::filesystem::remove(scratch);
  return road;
}

}  // namespace ridefit::synthetic
