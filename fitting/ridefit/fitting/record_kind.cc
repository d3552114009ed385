#include "ridefit/fitting/record_kind.h"

#include <fstream>
#include <string>

#include "ridefit/io/measurement_file.h"

namespace ridefit::fitting {

bool is_rig_record(const std::filesystem::path& csv_file) {
  // A .mat file has no header line to look at: its channels are read (a bad file is an
  // InputError naming it, as the loader would give).
  if (io::is_mat_file(csv_file)) return io::read_measurement_table(csv_file).has("displacement");
  std::ifstream in(csv_file);
  std::string header;
  std::getline(in, header);
  return header.find("displacement") != std::string::npos;
}

}  // namespace ridefit::fitting
