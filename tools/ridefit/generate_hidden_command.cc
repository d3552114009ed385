// ridefit generate-hidden SPEC.yaml -o DIR [--seed N]
// Measurement records of a richer truth than the model the diagnosis is given: a model file plus
// effects switched on, simulated (CVODE) over a road or on the strut rig, measured through a
// sensor model, written as CSVs with a separate truth file the diagnosis never reads. The spec's
// keys: synthetic/hidden_dataset_spec.h; the records: synthetic/hidden_datasets.h.
#include <fmt/core.h>

#include <iostream>
#include <memory>

#include "command_options.h"
#include "ridefit/io/atomic_file.h"
#include "ridefit/io/output_paths.h"
#include "ridefit/io/staged_folder.h"
#include "ridefit/synthetic/hidden_datasets.h"
#include "subcommands.h"

namespace ridefit::cli {
namespace {

struct GenerateHiddenFlags {
  std::string spec_file;
  std::string output_dir;
  long seed_offset = 0;
  bool force = false;
};

void run(const GenerateHiddenFlags& flags) {
  const std::vector<synthetic::HiddenDataset> datasets =
      synthetic::read_hidden_spec(flags.spec_file);
  // Every file the run writes, each once; none an input.
  io::RunOutputs outputs({flags.spec_file});
  for (const auto& d : datasets) {
    outputs.add_input(d.model);
    if (!d.strut_rig) outputs.add_input(d.excitation);
  }
  const std::vector<std::string> files = synthetic::hidden_dataset_files(datasets);
  outputs.add_folder(flags.output_dir, "-o", files, flags.force, "--force");
  // Every model and excitation is checked before anything is simulated or written.
  std::vector<synthetic::HiddenTruthModel> truths;
  for (const auto& d : datasets) truths.push_back(synthetic::load_truth_model(d));
  io::prepare_output_directory(flags.output_dir, "-o");
  // Written into a staged copy of the folder, put in place as a whole; paths in the truth files
  // are relative to the folder itself.
  const std::filesystem::path dir = flags.output_dir;
  io::StagedFolder staged(dir, files);
  const auto progress = [](const std::filesystem::path& file, double end_s, double rate_Hz) {
    std::cerr << fmt::format("generate-hidden: {} ({:.0f} s at {:g} Hz)\n", file.string(), end_s,
                             rate_Hz);
  };
  for (std::size_t i = 0; i < datasets.size(); ++i) {
    synthetic::write_hidden_dataset(datasets[i], truths[i], dir, staged.path(), flags.seed_offset,
                                    progress);
  }
  staged.commit();
}

}  // namespace

void register_generate_hidden(CLI::App& app) {
  auto flags = std::make_shared<GenerateHiddenFlags>();
  CLI::App* command = app.add_subcommand(
      "generate-hidden",
      "Simulate measurement records of a model with hidden effects switched on (CSV) and their "
      "truth files, for testing `ridefit diagnose`");
  command->add_option("spec", flags->spec_file, "Datasets to generate (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("-o,--output", flags->output_dir, "Output folder")->required();
  command->add_option("--seed", flags->seed_offset, "Added to every dataset's noise seed")
      ->capture_default_str();
  add_force_flag(*command, flags->force);
  command->callback([flags] { run(*flags); });
}

}  // namespace ridefit::cli
