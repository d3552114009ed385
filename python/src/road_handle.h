#pragma once

// A road for Python: any road::RoadInput (an excitation file or dict, or arrays), shared so that
// a simulation can hold it while Python drops its reference.

#include <memory>
#include <string>

#include "ridefit/road/road_input.h"

namespace ridefit::python {

struct RoadHandle {
  std::shared_ptr<const road::RoadInput> road;
  std::string name;  // the excitation file, the dict's name, or "<arrays>"
};

}  // namespace ridefit::python
