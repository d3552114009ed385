#pragma once

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "ridefit/model/parameter_info.h"

namespace ridefit::io {

// Strict, self-describing access to one YAML mapping of a user's file.
//
// Every read names the key it asked for, so that when the file is wrong the message says
// which file, which key, what was found and what is expected. Call finish() once all keys
// are read: any key nobody asked for is a typo and is rejected.
class YamlMap {
 public:
  // Loads `path` and wraps its top-level mapping.
  static YamlMap load(const std::filesystem::path& path);

  // Wraps a node that was found under `where` (e.g. "model.tyre") in file `path`.
  YamlMap(YAML::Node node, std::filesystem::path path, std::string where);

  const std::filesystem::path& path() const { return path_; }
  bool has(const std::string& key) const;
  // The same for a parameter row's key (model/*_parameter_table.h).
  bool has(const model::ParameterInfo& row) const { return has(row.key_string()); }

  // A required real number; `min_exclusive`/`min_inclusive` express range rules.
  double number(const std::string& key) const;
  double number(const model::ParameterInfo& row) const { return number(row.key_string()); }
  double positive(const std::string& key) const;      // > 0
  double non_negative(const std::string& key) const;  // >= 0
  // Physically plausible ranges: 0 < v <= hi, and 0 <= v <= hi.
  double positive_up_to(const std::string& key, double hi) const;
  // A model parameter within its table row's range (model/parameter_info.h), worded as
  // positive_up_to, non_negative_up_to or number_in.
  double parameter(const model::ParameterInfo& row) const;
  double non_negative_up_to(const std::string& key, double hi) const;
  double number_in(const std::string& key, double lo, double hi) const;  // lo <= v <= hi
  double number_or(const std::string& key, double fallback) const;
  long integer(const std::string& key) const;
  long integer_or(const std::string& key, long fallback) const;
  std::string text(const std::string& key) const;
  std::string text_or(const std::string& key, const std::string& fallback) const;
  // One of `choices`; the message lists them.
  std::string choice(const std::string& key, const std::set<std::string>& choices) const;
  // A nested mapping.
  YamlMap map(const std::string& key) const;
  // A non-empty list of finite numbers, e.g. `speeds_km_per_h: [20, 40]`.
  std::vector<double> numbers(const std::string& key) const;
  // A string, or a non-empty list of strings.
  std::vector<std::string> texts(const std::string& key) const;
  // A non-empty list of mappings, each wrapped for strict reading as "key[i]".
  std::vector<YamlMap> maps(const std::string& key) const;
  // What `key` holds, without reading it: a mapping, or a list and its length (none otherwise).
  bool is_mapping(const std::string& key) const;
  std::optional<std::size_t> list_length(const std::string& key) const;
  // The keys of a mapping in file order (e.g. names under `roads:`), all marked as read.
  std::vector<std::string> keys() const;
  // A path read relative to the directory of this file.
  std::filesystem::path file(const std::string& key) const;

  // Throws InputError naming every key that was present but never read.
  void finish() const;

  // "FILE: key 'a.b'" prefix for messages about `key`.
  std::string locate(const std::string& key) const;
  std::string locate(const model::ParameterInfo& row) const { return locate(row.key_string()); }

 private:
  YAML::Node required(const std::string& key) const;

  YAML::Node node_;
  std::filesystem::path path_;
  std::string where_;
  mutable std::set<std::string> used_;
};

}  // namespace ridefit::io
