// ridefit generate-lab OUT_DIR [--seed N]
// Synthetic strut rig tests with known truth (datasets/lab/ comes from here): the test set of
// synthetic/lab_test_set.h, written into a staged copy of the folder and put in place as a whole.
#include <iostream>
#include <memory>

#include "ridefit/io/atomic_file.h"
#include "ridefit/io/output_paths.h"
#include "ridefit/io/staged_folder.h"
#include "ridefit/synthetic/lab_test_set.h"
#include "subcommands.h"

namespace ridefit::cli {
namespace {

struct GenerateLabFlags {
  std::string output_dir;
  bool force = false;
  unsigned seed = 1;
};

void run(const GenerateLabFlags& flags) {
  const std::vector<std::string> files = synthetic::lab_test_files();
  io::RunOutputs({}).add_folder(flags.output_dir, "DIR", files, flags.force, "--force");
  io::prepare_output_directory(flags.output_dir, "DIR");
  io::StagedFolder staged(flags.output_dir, files);
  synthetic::write_lab_tests(staged.path(), flags.seed);
  staged.commit();
  std::cout << "Rig tests written to " << flags.output_dir << "\n";
}

}  // namespace

void register_generate_lab(CLI::App& app) {
  auto flags = std::make_shared<GenerateLabFlags>();
  CLI::App* command = app.add_subcommand(
      "generate-lab", "Write synthetic strut rig tests with known truth (CSV + truth.yaml)");
  command->add_option("directory", flags->output_dir, "Output directory (created if missing)")
      ->required();
  command->add_option("--seed", flags->seed, "Seed of the force noise")->capture_default_str();
  command->add_flag("--force", flags->force,
                    "Write into an existing folder that holds files ridefit did not write there "
                    "(files of the same name are replaced)");
  command->callback([flags] { run(*flags); });
}

}  // namespace ridefit::cli
