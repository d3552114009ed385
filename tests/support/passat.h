#pragma once

#include <string>

#include "ridefit/io/quarter_car_file.h"

namespace ridefit::testing {

inline std::string dataset(const std::string& relative) {
  return std::string(RIDEFIT_SOURCE_DIR) + "/datasets/" + relative;
}

inline io::QuarterCarFile passat_corner() {
  return io::load_quarter_car(dataset("vehicles/passat_b8_front.yaml"));
}

}  // namespace ridefit::testing
