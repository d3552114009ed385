#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace ridefit::io {

// Writes `model_file` again with keys replaced, each by its dotted path
// ("front.damping_Ns_per_m"; a quarter car's keys have no dot), atomically, with `comment` as
// a first line. Everything else of the file (keys, order, other values) stays as it was, so
// the result loads wherever the input did. Values are written as plain YAML scalars (a number
// as its text, e.g. "878.55", reads back as that number). A key the file does not have is added
// where its path says (the caller has checked it against the model).
void write_model_with_values(const std::filesystem::path& model_file,
                             const std::vector<std::pair<std::string, std::string>>& values,
                             const std::filesystem::path& output_file, const std::string& comment);

// The text write_model_with_values writes, in memory (for a run that writes it elsewhere, or
// sends it to another process first).
std::string model_with_values_text(const std::filesystem::path& model_file,
                                   const std::vector<std::pair<std::string, std::string>>& values,
                                   const std::string& comment);
std::string model_with_values_text(const std::filesystem::path& model_file,
                                   const std::vector<std::pair<std::string, double>>& values,
                                   const std::string& comment);

// The same with numbers, each written as yaml-cpp writes a double (17 significant digits; .nan,
// .inf), so it reads back as the same value.
void write_model_with_values(const std::filesystem::path& model_file,
                             const std::vector<std::pair<std::string, double>>& values,
                             const std::filesystem::path& output_file, const std::string& comment);

}  // namespace ridefit::io
