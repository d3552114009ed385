// The job file of `ridefit batch` (batch_jobs.h).
#include "batch_jobs.h"

#include <fmt/core.h>
#include <glob.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include "ridefit/common/errors.h"
#include "ridefit/io/output_paths.h"
#include "ridefit/io/path_type.h"
#include "ridefit/io/yaml_map.h"

namespace ridefit::cli {
namespace {

namespace fs = std::filesystem;

const std::set<std::string> kCommands = {"fit hysteresis", "fit psd", "diagnose"};

// Flags the batch sets itself: its output folder, its threads, its printing.
const std::set<std::string> kBatchFlags = {"output", "o", "plot",  "json",
                                           "quiet",  "q", "force", "threads"};

// One option of a job: the flag (dashes) and its values (none for a flag given as `true`);
// `false` leaves the flag out (also one `defaults:` gives).
struct JobOption {
  std::string flag;
  std::vector<std::string> values;
  bool given = true;
};

// Where a job's messages point: "FILE: job 3 (name): ".
struct JobPlace {
  fs::path file;
  std::size_t number = 0;
  std::string name;

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(fmt::format("{}: job {}{}: {}", file.string(), number,
                                 name.empty() ? "" : fmt::format(" ({})", name), what));
  }
  // Whether `path`, given under `key`, is a file; a path the system cannot look at (a name too
  // long, a folder that may not be searched) is refused here, naming the key.
  bool is_file(const fs::path& path, const std::string& key) const {
    try {
      return io::exists_as_file(path);
    } catch (const InputError& e) {
      fail(fmt::format("key '{}': {}", key, e.what()));
    }
  }
  // A message of the job file's reader (it begins with the file's name), placed in the job.
  [[noreturn]] void fail_with(const std::exception& e) const {
    std::string what = e.what();
    const std::string prefix = file.string() + ": ";
    if (what.rfind(prefix, 0) == 0) what = what.substr(prefix.size());
    fail(what);
  }
};

std::string dashed(std::string key) {
  std::replace(key.begin(), key.end(), '_', '-');
  return key;
}

// The options mapping: a value, a list (the flag repeated), true (a flag; false leaves it
// out), or a mapping (NAME=VALUE, the flag repeated).
std::vector<JobOption> read_options(const io::YamlMap& options) {
  std::vector<JobOption> result;
  for (const auto& key : options.keys()) {
    JobOption option{dashed(key), {}};
    if (options.is_mapping(key)) {
      const io::YamlMap entries = options.map(key);
      for (const auto& name : entries.keys())
        option.values.push_back(name + "=" + entries.text(name));
    } else if (options.list_length(key)) {
      option.values = options.texts(key);
    } else {
      const std::string value = options.text(key);
      option.given = value != "false";
      if (option.given && value != "true") option.values.push_back(value);
    }
    result.push_back(std::move(option));
  }
  return result;
}

// The keys a job shares with `defaults:`.
struct JobSettings {
  std::string command;
  fs::path model;
  std::vector<JobOption> options;
};

JobSettings read_settings(const io::YamlMap& map, JobSettings settings) {
  if (map.has("command")) settings.command = map.choice("command", kCommands);
  if (map.has("model")) settings.model = map.file("model").lexically_normal();
  if (map.has("options")) {
    for (auto& option : read_options(map.map("options"))) {
      auto same = std::find_if(settings.options.begin(), settings.options.end(),
                               [&](const JobOption& o) { return o.flag == option.flag; });
      if (same != settings.options.end()) {
        *same = std::move(option);
      } else {
        settings.options.push_back(std::move(option));
      }
    }
  }
  return settings;
}

// The files a glob pattern matches, sorted.
std::vector<fs::path> glob_files(const fs::path& pattern) {
  glob_t matches{};
  std::vector<fs::path> found;
  if (glob(pattern.c_str(), 0, nullptr, &matches) == 0) {
    for (std::size_t i = 0; i < matches.gl_pathc; ++i) found.emplace_back(matches.gl_pathv[i]);
  }
  globfree(&matches);  // before anything may throw
  std::vector<fs::path> files;
  for (auto& path : found) {
    if (io::exists_as_file(path)) files.push_back(std::move(path));
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The record lists of one entry of `jobs:`: one list for `record:`, one per matching file for
// `records:`.
std::vector<std::vector<fs::path>> read_records(const io::YamlMap& job, const JobPlace& place) {
  const fs::path dir = job.path().parent_path();
  if (job.has("record") == job.has("records")) {
    place.fail(
        "give `record:` (a file, or a list of files in one job) or `records:` (a glob such as "
        "lab/*.csv: one job per file), one of them");
  }
  std::vector<std::vector<fs::path>> jobs;
  if (job.has("record")) {
    std::vector<fs::path> records;
    for (const auto& text : job.texts("record")) {
      const fs::path path =
          (fs::path(text).is_relative() ? dir / text : fs::path(text)).lexically_normal();
      if (!place.is_file(path, "record")) {
        place.fail(fmt::format("key 'record': {}: no such file", path.string()));
      }
      records.push_back(path);
    }
    jobs.push_back(std::move(records));
    return jobs;
  }
  for (const auto& pattern : job.texts("records")) {
    const fs::path path =
        (fs::path(pattern).is_relative() ? dir / pattern : fs::path(pattern)).lexically_normal();
    const std::vector<fs::path> files = glob_files(path);
    if (files.empty()) place.fail(fmt::format("key 'records': {} matches no file", path.string()));
    for (const auto& file : files) jobs.push_back({file});
  }
  return jobs;
}

void check_name(const std::string& name, const JobPlace& place) {
  if (name.empty() || name == "." || name == ".." || name.front() == '.' ||
      name.find_first_of("/\\") != std::string::npos) {
    place.fail(fmt::format(
        "key 'name': '{}' cannot name a folder; give a plain name such as triangle_3mm", name));
  }
}

// The command's arguments: its inputs where its command line takes them, then the options.
std::vector<std::string> arguments_of(const JobSettings& settings,
                                      const std::vector<std::string>& records) {
  std::vector<std::string> arguments;
  if (settings.command == "diagnose") {
    arguments.push_back(settings.model.string());
    arguments.insert(arguments.end(), records.begin(), records.end());
  } else {
    arguments.insert(arguments.end(), records.begin(), records.end());
    arguments.push_back("--model");
    arguments.push_back(settings.model.string());
  }
  for (const auto& option : settings.options) {
    if (!option.given) continue;
    if (option.values.empty()) arguments.push_back(fmt::format("--{}", option.flag));
    for (const auto& value : option.values) {
      arguments.push_back(fmt::format("--{}", option.flag));
      arguments.push_back(value);
    }
  }
  return arguments;
}

// Checks a job's settings and makes its run, its inputs and the files it may write.
BatchJob make_job(JobSettings settings, const std::vector<fs::path>& records,
                  const JobPlace& place) {
  if (settings.command.empty()) {
    place.fail(
        "key 'command' is missing (here or under `defaults:`): fit hysteresis, fit psd "
        "or diagnose");
  }
  if (settings.model.empty()) place.fail("key 'model' is missing (here or under `defaults:`)");
  if (!place.is_file(settings.model, "model")) {
    place.fail(fmt::format("key 'model': {}: no such file", settings.model.string()));
  }
  BatchJob job;
  job.number = place.number;
  job.name = place.name;
  job.command = settings.command;
  job.inputs.push_back(settings.model);
  for (const auto& record : records) {
    job.records.push_back(record.string());
    job.inputs.push_back(record);
  }
  for (auto& option : settings.options) {
    if (kBatchFlags.count(option.flag) != 0 || option.flag == "model") {
      place.fail(fmt::format("key 'options.{}': set by the batch ({}); leave it out", option.flag,
                             option.flag == "model"
                                 ? "give `model:` beside `options:`"
                                 : "each job writes its files into -o DIR/<name>/"));
    }
    if (option.flag == "excitation") {  // a file: relative to the job file
      for (auto& value : option.values) {
        if (fs::path(value).is_relative()) {
          value = (place.file.parent_path() / value).lexically_normal().string();
        }
        job.inputs.emplace_back(value);
      }
    }
  }
  job.files = {"result.json", "model.yaml"};
  if (job.command == "diagnose") job.files.push_back("report.md");
  if (job.command == "fit hysteresis" && records.size() > 1) {
    for (const auto& r : records)
      job.files.push_back(io::output_for_input("model.yaml", r).string());
  }
  const std::vector<std::string> arguments = arguments_of(settings, job.records);
  try {
    if (job.command == "fit hysteresis") job.run = fit_hysteresis_job(arguments);
    if (job.command == "fit psd") job.run = fit_psd_job(arguments);
    if (job.command == "diagnose") job.run = diagnose_job(arguments);
  } catch (const CLI::ParseError& e) {
    place.fail(
        fmt::format("options: {} (options are `ridefit {} --help`'s flags without the "
                    "dashes)",
                    e.what(), job.command));
  } catch (const InputError& e) {
    place.fail(e.what());
  }
  return job;
}

}  // namespace

std::vector<BatchJob> load_batch_jobs(const fs::path& job_file) {
  const io::YamlMap root = io::YamlMap::load(job_file);
  JobSettings defaults;
  if (root.has("defaults")) {
    const io::YamlMap map = root.map("defaults");
    defaults = read_settings(map, {});
    map.finish();
  }
  std::vector<BatchJob> jobs;
  std::map<std::string, std::size_t> numbers;  // name -> job number
  const std::vector<io::YamlMap> entries = root.maps("jobs");
  root.finish();
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const io::YamlMap& entry = entries[i];
    JobPlace place{job_file, i + 1, ""};  // its `name:`, if any
    JobPlace shown = place;               // named in messages by its record without one
    try {
      if (entry.has("name")) {
        place.name = entry.text("name");
        shown.name = place.name;
        check_name(place.name, place);
      } else if (entry.has("record") && !entry.list_length("record")) {
        shown.name = fs::path(entry.text("record")).stem().string();
      }
      const JobSettings settings = read_settings(entry, defaults);
      const auto record_lists = read_records(entry, shown);
      entry.finish();
      const bool glob = entry.has("records");
      for (const auto& records : record_lists) {
        JobPlace job_place = place;
        const std::string stem = records.front().stem().string();
        if (place.name.empty() || glob) {
          job_place.name = place.name.empty() ? stem : fmt::format("{}_{}", place.name, stem);
        }
        check_name(job_place.name, job_place);
        const auto [other, added] = numbers.emplace(job_place.name, job_place.number);
        if (!added) {
          job_place.fail(fmt::format(
              "key 'name': '{}' is also job {}'s name; give each job its own `name:` (its "
              "folder is named after it)",
              job_place.name, other->second));
        }
        jobs.push_back(make_job(settings, records, job_place));
      }
    } catch (const InputError& e) {
      const std::string what = e.what();
      if (what.rfind(fmt::format("{}: job ", job_file.string()), 0) == 0) throw;
      shown.fail_with(e);
    }
  }
  return jobs;
}

}  // namespace ridefit::cli
