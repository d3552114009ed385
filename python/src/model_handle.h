#pragma once

// A model file loaded for Python: a quarter car or a half car (io::model_kind picks), from a YAML
// file or a dict, with the overrides it was loaded with. The file is read once; `modes` reads it
// again with another damper state, as `ridefit modes --state` does.

#include <pybind11/pybind11.h>

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "dict_file.h"
#include "ridefit/io/half_car_file.h"
#include "ridefit/io/model_overrides.h"
#include "ridefit/io/quarter_car_file.h"

namespace ridefit::python {

class ModelHandle {
 public:
  // `overrides`: key → number or text (the CLI's --set); `damper_state`: "" or slip, stick,
  // stick_slip (the CLI's --damper-state, quarter car only).
  static ModelHandle from_file(const std::filesystem::path& path, const pybind11::dict& overrides,
                               const std::string& damper_state);
  static ModelHandle from_dict(const pybind11::dict& mapping, const std::string& name,
                               const pybind11::dict& overrides, const std::string& damper_state);

  const std::string& kind() const { return kind_; }  // "quarter_car" or "half_car"
  const std::string& name() const { return name_; }  // the file, or the dict's name
  bool is_quarter_car() const { return quarter_car_.has_value(); }
  // InputError naming `what` (the function) for the other kind of model.
  const io::QuarterCarFile& quarter_car(const std::string& what) const;
  const io::HalfCarFile& half_car() const { return *half_car_; }

  // The quarter car read again with another damper state (messages name the dict's name).
  io::QuarterCarFile quarter_car_in_state(const std::string& state,
                                          const std::string& state_flag) const;
  const std::filesystem::path& path() const;

 private:
  void load(const std::string& damper_state);
  // Runs a read of path(), renaming the temporary file of a dict in its messages.
  template <typename Read>
  auto read(Read&& reader) const;

  std::string kind_;
  std::string name_;
  std::filesystem::path path_;
  std::shared_ptr<const DictFile> dict_;  // kept while a model from a dict lives
  io::ModelOverrides overrides_;
  std::optional<io::QuarterCarFile> quarter_car_;
  std::optional<io::HalfCarFile> half_car_;
};

}  // namespace ridefit::python
