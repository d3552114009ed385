#include "model_handle.h"

#include <fmt/core.h>

#include <utility>

#include "ridefit/common/errors.h"
#include "ridefit/io/model_kind.h"

namespace ridefit::python {

namespace py = pybind11;

namespace {

// The CLI's --set: numbers are spelled exactly, text goes as typed (the reader checks both).
io::ModelOverrides overrides_of(const py::dict& overrides, const std::string& damper_state) {
  io::ModelOverrides result;
  result.origin = "given as an override";
  result.damper_state = damper_state;
  for (const auto& [key, value] : overrides) {
    const std::string name = py::str(key).cast<std::string>();
    if (py::isinstance<py::str>(value)) {
      result.set(name, value.cast<std::string>());
    } else if (py::isinstance<py::bool_>(value)) {
      result.set(name, value.cast<bool>() ? std::string("true") : std::string("false"));
    } else {
      result.set(name, py::float_(py::reinterpret_borrow<py::object>(value)).cast<double>());
    }
  }
  return result;
}

}  // namespace

template <typename Read>
auto ModelHandle::read(Read&& reader) const {
  if (!dict_) return reader();
  return read_renamed(*dict_, std::forward<Read>(reader));
}

ModelHandle ModelHandle::from_file(const std::filesystem::path& path, const py::dict& overrides,
                                   const std::string& damper_state) {
  ModelHandle handle;
  handle.path_ = path;
  handle.name_ = path.string();
  handle.overrides_ = overrides_of(overrides, damper_state);
  handle.load(damper_state);
  return handle;
}

ModelHandle ModelHandle::from_dict(const py::dict& mapping, const std::string& name,
                                   const py::dict& overrides, const std::string& damper_state) {
  ModelHandle handle;
  handle.dict_ = std::make_shared<const DictFile>(mapping, name);
  handle.path_ = handle.dict_->path();
  handle.name_ = name;
  handle.overrides_ = overrides_of(overrides, damper_state);
  handle.load(damper_state);
  return handle;
}

void ModelHandle::load(const std::string& damper_state) {
  kind_ = read([&] { return io::model_kind(path_); });
  if (kind_ == "half_car") {
    if (!damper_state.empty()) {
      throw InputError(
          "damper_state: a half car has a damper state per axle; use overrides "
          "{'front.damper_state': 'stick_slip'} (and front.suspension=strut)");
    }
    half_car_ = read([&] { return io::load_half_car(path_, overrides_); });
  } else {
    quarter_car_ = read([&] { return io::load_quarter_car(path_, overrides_); });
  }
}

const io::QuarterCarFile& ModelHandle::quarter_car(const std::string& what) const {
  if (!quarter_car_) {
    throw InputError(
        fmt::format("{}: {} is a half car; {} takes a quarter car", what, name_, what));
  }
  return *quarter_car_;
}

io::QuarterCarFile ModelHandle::quarter_car_in_state(const std::string& state,
                                                     const std::string& state_flag) const {
  quarter_car(state_flag);
  io::ModelOverrides overrides = overrides_;
  overrides.damper_state = state;
  return read([&] { return io::load_quarter_car(path_, overrides); });
}

const std::filesystem::path& ModelHandle::path() const { return path_; }

}  // namespace ridefit::python
