#include "ridefit/io/model_values_file.h"

#include <yaml-cpp/yaml.h>

#include <sstream>

#include "ridefit/io/atomic_file.h"

namespace ridefit::io {

std::string model_with_values_text(const std::filesystem::path& model_file,
                                   const std::vector<std::pair<std::string, std::string>>& values,
                                   const std::string& comment) {
  YAML::Node root = YAML::LoadFile(model_file.string());
  // Not a structured binding: Clang 14 cannot capture one in the lambda below.
  for (const auto& entry : values) {
    const std::string& key = entry.first;
    const std::string& value = entry.second;
    std::vector<std::string> parts;
    std::size_t from = 0;
    for (std::size_t dot = key.find('.'); dot != std::string::npos; dot = key.find('.', from)) {
      parts.push_back(key.substr(from, dot - from));
      from = dot + 1;
    }
    const std::string last = key.substr(from);
    // yaml-cpp nodes are handles: walking by assignment would rebind, so recurse instead.
    auto set = [&](auto&& self, YAML::Node node, std::size_t depth) -> void {
      if (depth == parts.size()) {
        node[last] = value;
        return;
      }
      self(self, node[parts[depth]], depth + 1);
    };
    set(set, root, 0);
  }
  std::ostringstream out;
  out << "# " << comment << "\n" << root << "\n";
  return out.str();
}

std::string model_with_values_text(const std::filesystem::path& model_file,
                                   const std::vector<std::pair<std::string, double>>& values,
                                   const std::string& comment) {
  std::vector<std::pair<std::string, std::string>> texts;
  for (const auto& [key, value] : values) texts.emplace_back(key, YAML::Node(value).Scalar());
  return model_with_values_text(model_file, texts, comment);
}

void write_model_with_values(const std::filesystem::path& model_file,
                             const std::vector<std::pair<std::string, std::string>>& values,
                             const std::filesystem::path& output_file, const std::string& comment) {
  const std::string text = model_with_values_text(model_file, values, comment);
  write_atomically(output_file, [&](std::ostream& out) { out << text; });
}

void write_model_with_values(const std::filesystem::path& model_file,
                             const std::vector<std::pair<std::string, double>>& values,
                             const std::filesystem::path& output_file, const std::string& comment) {
  const std::string text = model_with_values_text(model_file, values, comment);
  write_atomically(output_file, [&](std::ostream& out) { out << text; });
}

}  // namespace ridefit::io
