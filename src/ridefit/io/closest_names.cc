#include "ridefit/io/closest_names.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <set>

namespace ridefit::io {

namespace {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

void number_keys(const YAML::Node& node, const std::string& prefix, std::vector<std::string>& out) {
  if (!node.IsMap()) return;
  for (const auto& item : node) {
    if (!item.first.IsScalar()) continue;  // not a name that could be meant
    const std::string key = prefix + item.first.Scalar();
    if (item.second.IsMap()) {
      number_keys(item.second, key + ".", out);
    } else if (item.second.IsScalar()) {
      try {
        item.second.as<double>();
        out.push_back(key);
      } catch (const YAML::Exception&) {
      }
    }
  }
}

}  // namespace

std::vector<std::string> yaml_number_keys(const std::filesystem::path& yaml_file) {
  std::vector<std::string> keys;
  try {
    number_keys(YAML::LoadFile(yaml_file.string()), "", keys);
  } catch (const YAML::Exception&) {
  }
  return keys;
}

std::vector<std::string> closest_names(const std::string& name,
                                       const std::vector<std::string>& candidates,
                                       std::size_t count) {
  std::vector<std::pair<std::size_t, std::size_t>> scored;  // (distance, index)
  std::set<std::string> seen;
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    if (!seen.insert(candidates[k]).second) continue;
    const std::size_t d = edit_distance(name, candidates[k]);
    if (2 * d <= std::max(name.size(), candidates[k].size())) scored.emplace_back(d, k);
  }
  std::stable_sort(scored.begin(), scored.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> names;
  for (std::size_t k = 0; k < scored.size() && k < count; ++k) {
    names.push_back(candidates[scored[k].second]);
  }
  return names;
}

std::string closest_names_text(const std::string& name, const std::vector<std::string>& candidates,
                               std::size_t count) {
  const auto names = closest_names(name, candidates, count);
  std::string text;
  for (const auto& n : names) text += (text.empty() ? "; closest: " : ", ") + n;
  return text;
}

}  // namespace ridefit::io
