#include "ridefit/io/yaml_map.h"

#include <fmt/core.h>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/io/path_type.h"

namespace ridefit::io {

namespace {

// Counts the documents of a YAML stream without building them. yaml-cpp 0.7's LoadAll() loops
// for ever, allocating, when a document starts with a token its parser does not consume (a
// ',' where a node should begin: ",", "- a\n,", "---\n,"; upstream issue #1040): each call of
// HandleNextDocument() then "finds" another empty document at the same place. Such a stall is
// reported as a syntax error at that place instead.
class DocumentCounter : public YAML::EventHandler {
 public:
  void OnDocumentStart(const YAML::Mark& mark) override { starts.push_back(mark); }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t,
                const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}

  std::vector<YAML::Mark> starts;
};

std::size_t count_documents(const std::string& text) {
  std::istringstream stream(text);
  YAML::Parser parser(stream);
  DocumentCounter counter;
  std::size_t documents = 0;
  while (parser.HandleNextDocument(counter)) {
    ++documents;
    const auto& starts = counter.starts;
    if (starts.size() >= 2 && starts[starts.size() - 1].pos == starts[starts.size() - 2].pos) {
      const YAML::Mark& at = starts.back();
      // yaml-cpp's positions do not count a UTF-8 byte-order mark.
      const std::size_t bom = text.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;
      const std::size_t index = static_cast<std::size_t>(std::max(at.pos, 0)) + bom;
      const char found = index < text.size() ? text[index] : ' ';
      throw YAML::ParserException(
          at, found == ','
                  ? std::string("a value cannot start with ','; quote it, or remove the comma")
                  : fmt::format("unexpected '{}'", found));
    }
  }
  return documents;
}

}  // namespace

YamlMap YamlMap::load(const std::filesystem::path& path) {
  if (!path_exists(path)) {
    throw InputError(fmt::format("{}: file not found", path.string()));
  }
  if (is_folder(path)) {
    throw InputError(fmt::format("{}: is a directory, expected a YAML file", path.string()));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot be read", path.string()));
  std::ostringstream content;
  content << in.rdbuf();  // an empty file sets content's failbit and leaves it empty: fine
  const std::string text = content.str();
  YAML::Node root;
  try {
    const std::size_t documents = count_documents(text);
    if (documents > 1) {
      throw InputError(
          fmt::format("{}: holds {} YAML documents (separated by ---); expected exactly one",
                      path.string(), documents));
    }
    if (documents == 1) root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InputError(fmt::format("{}:{}:{}: not valid YAML: {}", path.string(), e.mark.line + 1,
                                 e.mark.column + 1, e.msg));
  }
  if (!root.IsMap()) {
    throw InputError(fmt::format(
        "{}: expected a YAML mapping of `key: value` lines at the top level", path.string()));
  }
  return YamlMap(root, path, "");
}

YamlMap::YamlMap(YAML::Node node, std::filesystem::path path, std::string where)
    : node_(std::move(node)), path_(std::move(path)), where_(std::move(where)) {
  // yaml-cpp keeps duplicate keys and returns the first: a second value would be ignored.
  std::map<std::string, int> seen;
  for (const auto& entry : node_) {
    const int line = entry.first.Mark().line + 1;
    // A `? [a, b]` or `? ` (complex or empty) key names nothing ridefit reads.
    if (!entry.first.IsScalar()) {
      throw InputError(fmt::format("{}:{}: a key must be a name such as `mass_kg`, not a YAML {}",
                                   path_.string(), line,
                                   entry.first.IsNull()       ? "null (an empty or `~` key)"
                                   : entry.first.IsSequence() ? "sequence"
                                                              : "mapping"));
    }
    const std::string key = entry.first.Scalar();
    const auto [it, inserted] = seen.emplace(key, line);
    if (!inserted) {
      throw InputError(fmt::format("{}: duplicate key '{}' (lines {} and {}); give it once",
                                   path_.string(), key, it->second, line));
    }
  }
}

std::string YamlMap::locate(const std::string& key) const {
  const std::string full = where_.empty() ? key : where_ + "." + key;
  return fmt::format("{}: key '{}'", path_.string(), full);
}

bool YamlMap::has(const std::string& key) const { return static_cast<bool>(node_[key]); }

YAML::Node YamlMap::required(const std::string& key) const {
  used_.insert(key);
  const YAML::Node value = node_[key];
  if (value && value.IsNull()) {
    throw InputError(fmt::format("{} has no value", locate(key)));
  }
  if (!value) {
    // A key that differs only in case is a typo the user will not spot.
    for (const auto& entry : node_) {
      const std::string other = entry.first.Scalar();
      if (other.size() == key.size() &&
          std::equal(other.begin(), other.end(), key.begin(),
                     [](char a, char b) { return std::tolower(a) == std::tolower(b); })) {
        throw InputError(fmt::format("{} is missing; found '{}' instead (keys are case-sensitive)",
                                     locate(key), other));
      }
    }
    throw InputError(fmt::format("{} is missing (required)", locate(key)));
  }
  return value;
}

double YamlMap::number(const std::string& key) const {
  const YAML::Node value = required(key);
  if (!value.IsScalar()) {
    throw InputError(fmt::format("{} must be a number", locate(key)));
  }
  double result = 0.0;
  try {
    result = value.as<double>();
  } catch (const YAML::Exception&) {
    throw InputError(fmt::format("{} is '{}', expected a number", locate(key), value.Scalar()));
  }
  if (!std::isfinite(result)) {
    throw InputError(
        fmt::format("{} is '{}', expected a finite number", locate(key), value.Scalar()));
  }
  return result;
}

double YamlMap::positive(const std::string& key) const {
  const double v = number(key);
  if (!(v > 0.0)) {
    throw InputError(fmt::format("{} is {}, expected a value > 0", locate(key), v));
  }
  return v;
}

double YamlMap::non_negative(const std::string& key) const {
  const double v = number(key);
  if (v < 0.0) {
    throw InputError(fmt::format("{} is {}, expected a value >= 0", locate(key), v));
  }
  return v;
}

double YamlMap::positive_up_to(const std::string& key, double hi) const {
  const double v = number(key);
  if (!(v > 0.0) || v > hi) {
    throw InputError(fmt::format("{} is {}, expected a value > 0 and <= {:g}", locate(key), v, hi));
  }
  return v;
}

double YamlMap::parameter(const model::ParameterInfo& row) const {
  const std::string key(row.key);
  if (row.lower == 0.0 && row.lower_open) return positive_up_to(key, row.upper);
  if (row.lower == 0.0) return non_negative_up_to(key, row.upper);
  return number_in(key, row.lower, row.upper);
}

double YamlMap::non_negative_up_to(const std::string& key, double hi) const {
  const double v = number(key);
  if (v < 0.0 || v > hi) {
    throw InputError(fmt::format("{} is {}, expected a value in [0, {:g}]", locate(key), v, hi));
  }
  return v;
}

double YamlMap::number_in(const std::string& key, double lo, double hi) const {
  const double v = number(key);
  if (v < lo || v > hi) {
    throw InputError(fmt::format("{} is {}, expected a value in [{}, {}]", locate(key), v, lo, hi));
  }
  return v;
}

double YamlMap::number_or(const std::string& key, double fallback) const {
  used_.insert(key);
  return has(key) ? number(key) : fallback;
}

long YamlMap::integer(const std::string& key) const {
  const YAML::Node value = required(key);
  try {
    return value.as<long>();
  } catch (const YAML::Exception&) {
    throw InputError(fmt::format("{} is '{}', expected an integer", locate(key),
                                 value.IsScalar() ? value.Scalar() : std::string("a non-scalar")));
  }
}

long YamlMap::integer_or(const std::string& key, long fallback) const {
  used_.insert(key);
  return has(key) ? integer(key) : fallback;
}

std::string YamlMap::text(const std::string& key) const {
  const YAML::Node value = required(key);
  if (!value.IsScalar()) {
    throw InputError(fmt::format("{} must be a text value", locate(key)));
  }
  return value.Scalar();
}

std::string YamlMap::text_or(const std::string& key, const std::string& fallback) const {
  used_.insert(key);
  return has(key) ? text(key) : fallback;
}

std::string YamlMap::choice(const std::string& key, const std::set<std::string>& choices) const {
  const std::string v = text(key);
  if (choices.count(v) == 0) {
    std::string list;
    for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
    throw InputError(fmt::format("{} is '{}', expected one of: {}", locate(key), v, list));
  }
  return v;
}

bool YamlMap::is_mapping(const std::string& key) const { return required(key).IsMap(); }

std::optional<std::size_t> YamlMap::list_length(const std::string& key) const {
  const YAML::Node value = required(key);
  if (!value.IsSequence()) return std::nullopt;
  return value.size();
}

YamlMap YamlMap::map(const std::string& key) const {
  const YAML::Node value = required(key);
  if (!value.IsMap()) {
    throw InputError(fmt::format("{} must be a mapping of `key: value` entries", locate(key)));
  }
  return YamlMap(value, path_, where_.empty() ? key : where_ + "." + key);
}

std::vector<double> YamlMap::numbers(const std::string& key) const {
  const YAML::Node value = required(key);
  if (!value.IsSequence() || value.size() == 0) {
    throw InputError(
        fmt::format("{} must be a non-empty list of numbers, e.g. [20, 40, 60]", locate(key)));
  }
  std::vector<double> result;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const YAML::Node item = value[i];
    double v = 0.0;
    try {
      if (!item.IsScalar()) throw YAML::Exception(item.Mark(), "not a scalar");
      v = item.as<double>();
    } catch (const YAML::Exception&) {
      throw InputError(fmt::format("{}: item {} is not a number", locate(key), i + 1));
    }
    if (!std::isfinite(v)) {
      throw InputError(fmt::format("{}: item {} is {}, expected a finite number", locate(key),
                                   i + 1, item.Scalar()));
    }
    result.push_back(v);
  }
  return result;
}

std::vector<std::string> YamlMap::texts(const std::string& key) const {
  const YAML::Node value = required(key);
  if (value.IsScalar()) return {value.Scalar()};
  if (!value.IsSequence() || value.size() == 0) {
    throw InputError(fmt::format("{} must be a text or a non-empty list of texts", locate(key)));
  }
  std::vector<std::string> result;
  for (std::size_t i = 0; i < value.size(); ++i) {
    if (!value[i].IsScalar()) {
      throw InputError(fmt::format("{}: item {} is not a text", locate(key), i + 1));
    }
    result.push_back(value[i].Scalar());
  }
  return result;
}

std::vector<YamlMap> YamlMap::maps(const std::string& key) const {
  const YAML::Node value = required(key);
  if (!value.IsSequence() || value.size() == 0) {
    throw InputError(
        fmt::format("{} must be a non-empty list of `- key: value` entries", locate(key)));
  }
  std::vector<YamlMap> result;
  const std::string base = where_.empty() ? key : where_ + "." + key;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const std::string where = fmt::format("{}[{}]", base, i + 1);
    if (!value[i].IsMap()) {
      throw InputError(fmt::format("{}: key '{}' must be a mapping of `key: value` entries",
                                   path_.string(), where));
    }
    result.emplace_back(value[i], path_, where);
  }
  return result;
}

std::vector<std::string> YamlMap::keys() const {
  std::vector<std::string> result;
  for (const auto& entry : node_) {
    result.push_back(entry.first.Scalar());
    used_.insert(result.back());
  }
  return result;
}

std::filesystem::path YamlMap::file(const std::string& key) const {
  std::filesystem::path p = text(key);
  if (p.is_relative()) p = path_.parent_path() / p;
  return p;
}

void YamlMap::finish() const {
  std::vector<std::string> unknown;
  for (const auto& entry : node_) {
    const std::string key = entry.first.Scalar();  // a scalar: the constructor checked
    if (used_.count(key) == 0) unknown.push_back(key);
  }
  if (unknown.empty()) return;
  std::string list;
  for (const auto& k : unknown) list += (list.empty() ? "'" : ", '") + k + "'";
  std::string known;
  for (const auto& k : used_) known += (known.empty() ? "" : ", ") + k;
  throw InputError(fmt::format("{}: unknown key{} {}{}; the keys read here are: {}", path_.string(),
                               unknown.size() > 1 ? "s" : "", list,
                               where_.empty() ? "" : " under '" + where_ + "'", known));
}

}  // namespace ridefit::io
