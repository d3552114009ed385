#pragma once

#include <filesystem>

namespace ridefit::io {

// What a path a user gave (an input or an output) names, asked without std::filesystem's
// throwing calls: file_type::not_found when nothing is there (or a parent is not a folder), or
// an InputError naming the path and the system's reason when the system cannot tell (a name too
// long, a folder that may not be searched): never a raw filesystem_error.
std::filesystem::file_type path_type(const std::filesystem::path& path);

inline bool is_folder(const std::filesystem::path& path) {
  return path_type(path) == std::filesystem::file_type::directory;
}
inline bool exists_as_file(const std::filesystem::path& path) {
  return path_type(path) == std::filesystem::file_type::regular;
}
inline bool path_exists(const std::filesystem::path& path) {
  return path_type(path) != std::filesystem::file_type::not_found;
}

}  // namespace ridefit::io
