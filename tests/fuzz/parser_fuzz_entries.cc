#include "fuzz/parser_fuzz_entries.h"

#include <unistd.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

#include "batch_jobs.h"  // the CLI's (tools/ridefit/)
#include "ridefit/common/errors.h"
#include "ridefit/fitting/hysteresis_record.h"
#include "ridefit/io/csv_table.h"
#include "ridefit/io/half_car_file.h"
#include "ridefit/io/model_kind.h"
#include "ridefit/io/quarter_car_file.h"
#include "ridefit/optimisation/evaluation_journal.h"
#include "ridefit/optimisation/tuning_study.h"
#include "ridefit/road/excitation_file.h"
#include "ridefit/road/opencrg_file.h"
#include "ridefit/study/half_car_sweep.h"

namespace ridefit::fuzz {
namespace {

namespace fs = std::filesystem;

// A scratch tree for this process, removed at exit:
//   vehicles/ excitations/ lab/  links to the shipped datasets' folders, so that a study's
//                                "../vehicles/x.yaml" resolves as it does in datasets/studies/;
//   studies/ roads/ data/ models/  where the inputs are written (roads/ also links every file
//                                of datasets/excitations, for "file: profile_example.csv").
class Scratch {
 public:
  Scratch() : root_(fs::temp_directory_path() / ("ridefit-fuzz-" + std::to_string(::getpid()))) {
    const fs::path datasets = fs::path(RIDEFIT_SOURCE_DIR) / "datasets";
    fs::remove_all(root_);
    for (const char* folder : {"studies", "roads", "data", "models"}) {
      fs::create_directories(root_ / folder);
    }
    for (const char* folder : {"vehicles", "excitations", "lab", "hidden"}) {
      fs::create_directory_symlink(datasets / folder, root_ / folder);
    }
    for (const auto& entry : fs::directory_iterator(datasets / "excitations")) {
      fs::create_symlink(entry.path(), root_ / "roads" / entry.path().filename());
    }
  }
  ~Scratch() {
    std::error_code ignored;
    fs::remove_all(root_, ignored);
  }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;

  // Writes `input` to <root>/<folder>/<name> and returns its path.
  fs::path write(const char* folder, const char* name, std::span<const std::uint8_t> input) const {
    const fs::path path = root_ / folder / name;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(input.data()),
              static_cast<std::streamsize>(input.size()));
    if (!out.flush()) throw std::runtime_error("fuzz scratch: cannot write " + path.string());
    return path;
  }

 private:
  fs::path root_;
};

const Scratch& scratch() {
  static const Scratch instance;
  return instance;
}

// Runs `parse`; an InputError is the parser refusing the input, which is its job.
template <typename Parse>
Outcome outcome_of(Parse&& parse) {
  try {
    parse();
    return Outcome::kAccepted;
  } catch (const InputError&) {
    return Outcome::kRefused;
  }
}

Outcome model_yaml(std::span<const std::uint8_t> input) {
  const fs::path path = scratch().write("models", "model.yaml", input);
  return outcome_of([&] {
    if (io::model_kind(path) == "half_car") {
      (void)io::load_half_car(path);
    } else {
      (void)io::load_quarter_car(path).make_model();
    }
  });
}

Outcome excitation_yaml(std::span<const std::uint8_t> input) {
  const fs::path path = scratch().write("roads", "input.yaml", input);
  return outcome_of([&] {
    const auto road = road::load_excitation(path);
    // The road must answer over its whole duration, as a simulation asks it.
    for (double share : {0.0, 0.5, 1.0}) (void)road->at(share * road->duration_s());
    (void)road::load_road_spectrum(path);
  });
}

Outcome tuning_study_yaml(std::span<const std::uint8_t> input) {
  const fs::path path = scratch().write("studies", "tuning.yaml", input);
  return outcome_of([&] {
    const auto study = optimisation::load_tuning_study(path);
    (void)optimisation::study_fingerprint(study);
  });
}

Outcome sweep_study_yaml(std::span<const std::uint8_t> input) {
  const fs::path path = scratch().write("studies", "sweep.yaml", input);
  return outcome_of([&] { (void)study::expand(study::load_half_car_sweep(path)); });
}

Outcome csv_with_units(std::span<const std::uint8_t> input) {
  const fs::path path = scratch().write("data", "record.csv", input);
  const Outcome table = outcome_of([&] { (void)io::CsvTable::read(path); });
  // The rig record reader adds its own checks (time, force, displacement, a command column).
  const Outcome record = outcome_of([&] { (void)fitting::load_hysteresis_record(path); });
  return table == Outcome::kAccepted || record == Outcome::kAccepted ? Outcome::kAccepted
                                                                     : Outcome::kRefused;
}

// A journal of a study with 2 design variables, 2 load cases and 3 metrics per case, whose
// fingerprint is "fuzz" (the corpus' first lines carry it, so mutations reach the records).
Outcome journal(std::span<const std::uint8_t> input) {
  const fs::path path = scratch().write("data", "journal.jsonl", input);
  return outcome_of([&] {
    const auto resumed = optimisation::EvaluationJournal::resume(path, "fuzz", {2, 2, 3});
    const std::array<double, 2> x{1000.0, 2000.0};
    (void)resumed.find("friction/search", x);
  });
}

// An OpenCRG road file (ASCII or binary); a grid that reads must also give a track.
Outcome opencrg_file(std::span<const std::uint8_t> input) {
  const fs::path path = scratch().write("roads", "input.crg", input);
  return outcome_of([&] {
    const road::CrgGrid grid = road::read_opencrg(path);
    (void)road::crg_track(grid, 0.5 * (grid.v_m.front() + grid.v_m.back()), path.string());
  });
}

// A `ridefit batch` job file in studies/, beside the linked lab/, vehicles/ and hidden/: every
// job's record list, model and options parsed by its command's own flags (nothing is run).
Outcome batch_jobs_yaml(std::span<const std::uint8_t> input) {
  const fs::path path = scratch().write("studies", "jobs.yaml", input);
  return outcome_of([&] { (void)cli::load_batch_jobs(path); });
}

constexpr std::array<Target, 8> kTargets{{
    {"model_yaml", &model_yaml},
    {"excitation_yaml", &excitation_yaml},
    {"tuning_study_yaml", &tuning_study_yaml},
    {"sweep_study_yaml", &sweep_study_yaml},
    {"csv_with_units", &csv_with_units},
    {"journal", &journal},
    {"opencrg_file", &opencrg_file},
    {"batch_jobs_yaml", &batch_jobs_yaml},
}};

}  // namespace

std::span<const Target> targets() { return kTargets; }

const Target& target(std::string_view name) {
  for (const Target& t : kTargets) {
    if (t.name == name) return t;
  }
  throw std::invalid_argument("no fuzz target named " + std::string(name));
}

}  // namespace ridefit::fuzz
