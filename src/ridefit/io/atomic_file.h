#pragma once

#include <filesystem>
#include <functional>
#include <iosfwd>

namespace ridefit::io {

// Writes a file through a temporary file in the same directory and renames it into place,
// so a failed run never leaves a half-written file nor overwrites a good one.
// `write` fills the stream; if it throws, the temporary file is removed and the error
// propagates. An unwritable destination is an InputError naming the path.
void write_atomically(const std::filesystem::path& path,
                      const std::function<void(std::ostream&)>& write);

}  // namespace ridefit::io
