#pragma once

#include <filesystem>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace ridefit::io {

// Writes a file through a temporary file in the same directory and renames it into place,
// so a failed run never leaves a half-written file nor overwrites a good one.
// `write` fills the stream; if it throws, the temporary file is removed and the error
// propagates. An unwritable destination is an InputError naming the path.
void write_atomically(const std::filesystem::path& path,
                      const std::function<void(std::ostream&)>& write);

// The same for a writer that needs a file name rather than a stream (a C library such as
// matio): `write` creates `temporary` (in the destination's directory), which is renamed to
// `path` when it returns and removed when it throws.
void write_file_atomically(
    const std::filesystem::path& path,
    const std::function<void(const std::filesystem::path& temporary)>& write);

// Checks, before any work is done, that `path` can take an output file: its directory exists,
// it is not a directory or a device, and it is none of `inputs` (a run must not overwrite
// its own input). `flag` names the option in messages (e.g. "-o"). Throws InputError.
void check_output_file(const std::filesystem::path& path,
                       const std::vector<std::filesystem::path>& inputs, const std::string& flag);

// The same for an output directory: it is created if missing; an existing non-directory is
// an InputError.
void prepare_output_directory(const std::filesystem::path& path, const std::string& flag);

}  // namespace ridefit::io
