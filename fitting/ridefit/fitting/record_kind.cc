#include "ridefit/fitting/record_kind.h"

#include <fstream>
#include <string>

namespace ridefit::fitting {

bool is_rig_record(const std::filesystem::path& csv_file) {
  std::ifstream in(csv_file);
  std::string header;
  std::getline(in, header);
  return header.find("displacement") != std::string::npos;
}

}  // namespace ridefit::fitting
