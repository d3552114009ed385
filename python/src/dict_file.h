#pragma once

// A Python dict given where the library reads a YAML file (a model, an excitation): the dict is
// written as YAML to a private temporary file, so the file readers check it with the very same
// rules. Messages name `display_name` (e.g. "<dict>") instead of the temporary path.

#include <pybind11/pybind11.h>

#include <filesystem>
#include <string>

#include "ridefit/common/errors.h"

namespace ridefit::python {

class DictFile {
 public:
  // `mapping`: a dict of str keys to numbers, strings, bools, lists and nested dicts.
  DictFile(const pybind11::dict& mapping, std::string display_name);
  ~DictFile();
  DictFile(const DictFile&) = delete;
  DictFile& operator=(const DictFile&) = delete;

  const std::filesystem::path& path() const { return path_; }
  const std::string& display_name() const { return display_name_; }

  // `message` with the temporary path replaced by the display name.
  std::string renamed(std::string message) const;

 private:
  std::filesystem::path directory_;
  std::filesystem::path path_;
  std::string display_name_;
};

// Runs `read` (a library call that reads `file`) and rethrows its InputError with `file`'s
// temporary path replaced by its display name.
template <typename Read>
auto read_renamed(const DictFile& file, Read&& read) -> decltype(read()) {
  try {
    return read();
  } catch (const InputError& e) {
    throw InputError(file.renamed(e.what()));
  }
}

}  // namespace ridefit::python
