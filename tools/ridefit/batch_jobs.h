#pragma once

// The job file of `ridefit batch` (batch_jobs.cc): independent fits and diagnoses of many
// records, each job's outputs in a folder of its own.
//
//   defaults:                  # optional, merged under every job (a job's own keys win)
//     command: fit hysteresis  # fit hysteresis | fit psd | diagnose
//     model: ../vehicles/passat_b8_front.yaml
//     options: {free: [dahl_sigma0_N_per_m, coulomb_force_N], interpolation: linear}
//   jobs:
//     - record: lab/triangle_3mm_1mmps.csv   # a path, or a list of paths fitted together
//       name: triangle                       # default: the (first) record's stem
//     - records: lab/shim_*.csv              # a glob (or a list of them): one job per file
//
// Paths are relative to the job file. `options` are the command's flags without the dashes
// (`max_nrmse` or `max-nrmse`): a value, a list (repeated flag: `free: [a, b]`), true for a
// flag, or a mapping for NAME=VALUE flags (`bounds: {coulomb_force_N: "10:200"}`).

#include <filesystem>
#include <string>
#include <vector>

#include "command_outcome.h"

namespace ridefit::cli {

struct BatchJob {
  std::size_t number = 0;  // of its entry under `jobs:`, from 1 (a glob's jobs share one)
  std::string name;        // its folder's name under the output folder; unique
  std::string command;     // "fit hysteresis", "fit psd" or "diagnose"
  std::vector<std::string> records;
  std::vector<std::filesystem::path> inputs;  // the model, the records, excitations
  std::vector<std::string> files;             // the names it may write into its folder
  CommandJob run;                             // the command's run, its arguments parsed
};

// The jobs of `job_file`, in file order (a glob's files sorted), each with its arguments parsed
// by its command's own options. InputError naming the file, the job (number from 1 and name)
// and the key: an unknown key or option, a record that matches no file, two jobs of one name.
std::vector<BatchJob> load_batch_jobs(const std::filesystem::path& job_file);

}  // namespace ridefit::cli
