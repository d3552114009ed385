#pragma once

#include <filesystem>
#include <string>

namespace ridefit::io {

// The `model` key of a model file ("quarter_car", "half_car"), so a command can accept either;
// InputError when the file cannot be read or its `model` is missing or not one of those.
std::string model_kind(const std::filesystem::path& path);

}  // namespace ridefit::io
