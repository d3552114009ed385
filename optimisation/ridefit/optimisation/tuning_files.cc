#include "ridefit/optimisation/tuning_files.h"

namespace ridefit::optimisation {
namespace {

std::filesystem::path sibling(const std::filesystem::path& path, const std::string& suffix) {
  return path.parent_path() / (path.stem().string() + suffix);
}

}  // namespace

std::vector<std::filesystem::path> study_inputs(const TuningStudy& study) {
  std::vector<std::filesystem::path> inputs = {study.study_file, study.model_file};
  if (!study.fitted_model.empty()) inputs.push_back(study.fitted_model);
  for (const auto& c : study.load_cases) inputs.push_back(c.road_file);
  return inputs;
}

TuningFiles tuning_files(const TuningStudy& study, const std::string& result,
                         const std::filesystem::path& journal) {
  TuningFiles files;
  files.result = result;
  if (!result.empty()) {
    files.model = sibling(result, "_model.yaml").string();
    if (study.tradeoff) files.tradeoff_csv = sibling(result, "_tradeoff.csv").string();
  }
  files.journal = !journal.empty() ? journal
                  : !result.empty()
                      ? sibling(result, ".journal")
                      : std::filesystem::path(study.study_file.stem().string() + ".journal");
  return files;
}

}  // namespace ridefit::optimisation
