#include <yaml-cpp/yaml.h>

#include <fmt/core.h>

#include <cstdlib>
#include <fstream>
#include <system_error>

#include "dict_file.h"
#include "ridefit/common/errors.h"

namespace ridefit::python {

namespace py = pybind11;

namespace {

// Numbers are spelled exactly (fmt's shortest text that reads back to the same double), so the
// file reader sees the caller's values bit for bit.
YAML::Node yaml_of(const py::handle& value, const std::string& key) {
  if (py::isinstance<py::bool_>(value)) return YAML::Node(value.cast<bool>() ? "true" : "false");
  if (py::isinstance<py::int_>(value)) return YAML::Node(py::str(value).cast<std::string>());
  if (py::isinstance<py::float_>(value)) {
    return YAML::Node(fmt::format("{}", value.cast<double>()));
  }
  if (py::isinstance<py::str>(value)) return YAML::Node(value.cast<std::string>());
  if (py::isinstance<py::dict>(value)) {
    YAML::Node node(YAML::NodeType::Map);
    for (const auto& [k, v] : value.cast<py::dict>()) {
      if (!py::isinstance<py::str>(k)) {
        throw InputError(
            fmt::format("key '{}': keys must be strings", py::str(k).cast<std::string>()));
      }
      const std::string name = k.cast<std::string>();
      node[name] = yaml_of(v, key.empty() ? name : key + "." + name);
    }
    return node;
  }
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    YAML::Node node(YAML::NodeType::Sequence);
    for (const auto& item : value) node.push_back(yaml_of(item, key));
    return node;
  }
  // NumPy scalars and other numbers.
  if (py::hasattr(value, "__float__"))
    return yaml_of(py::float_(py::reinterpret_borrow<py::object>(value)), key);
  throw InputError(
      fmt::format("key '{}': a {} cannot be a value of a file (numbers, strings, "
                  "booleans, lists and dicts can)",
                  key, py::str(py::type::of(value).attr("__name__")).cast<std::string>()));
}

}  // namespace

DictFile::DictFile(const py::dict& mapping, std::string display_name)
    : display_name_(std::move(display_name)) {
  const YAML::Node root = yaml_of(mapping, "");
  std::string pattern = (std::filesystem::temp_directory_path() / "ridefit-dict-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) {
    throw RunError("cannot create a temporary directory for a dict given as a file");
  }
  directory_ = pattern;
  path_ = directory_ / "dict.yaml";
  YAML::Emitter emitter;
  emitter << root;
  std::ofstream out(path_);
  out << emitter.c_str() << "\n";
  if (!out) throw RunError(fmt::format("cannot write {}", path_.string()));
}

DictFile::~DictFile() {
  std::error_code ignored;
  std::filesystem::remove_all(directory_, ignored);
}

std::string DictFile::renamed(std::string message) const {
  const std::string temporary = path_.string();
  for (auto at = message.find(temporary); at != std::string::npos;
       at = message.find(temporary, at + display_name_.size())) {
    message.replace(at, temporary.size(), display_name_);
  }
  return message;
}

}  // namespace ridefit::python
