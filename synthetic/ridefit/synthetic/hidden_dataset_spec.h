#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "ridefit/study/sensor_model.h"

namespace ridefit::synthetic {

// One dataset of a hidden-effect spec: measurement records of a richer truth than the model a
// diagnosis is given (hidden_datasets.h writes them). Read from a spec file such as
// datasets/hidden/hidden_datasets.yaml, paths relative to it:
//
//   datasets:
//     - name: seed_top_mount_stiffening        # files NAME.csv, NAME_2.csv, NAME_truth.yaml
//       model: ../vehicles/passat_b8_front.yaml  # the truth's base
//       damper_state: stick_slip               # optional: replaces the model's
//       set: {top_mount_small_amplitude_stiffness_N_per_m: 707000}  # model keys changed
//       effects: [top_mount_amplitude_stiffening]  # effect library ids (or sensor_mount); truth
//                                                  # file only
//       excitation: ../excitations/iso8608_class_a_50kmh.yaml
//       duration_s: 60                         # default: the excitation's
//       sample_rate_Hz: 500                    # default 500
//       records: 2                             # default 2, at most 20; record k >= 2 drives
//                                              # another realisation of a random road (seed + k -
//                                              1) # with other noise
//       sensor: {noise: 0.005, high_pass_Hz: 0.1, low_pass_Hz: 100,
//                mount: {channel: body_acc, frequency_Hz: 12, damping_ratio: 0.05}}
//       seed: 11                               # noise seed (default 1)
//       baseline: {model: baselines/passat_slip.yaml, datasheet_seed: 7}  # optional: writes
//                 # NAME_baseline.yaml, that model with values off as a data sheet's are, drawn
//                 # (datasheet_values.h); or errors: {spring_stiffness_N_per_m: -0.07, ...},
//                 # each value times 1 + its share (vehicle and rig datasets: a rig
//                 # diagnosis puts that model's strut on the rig)
//     - name: rig_gas_force                    # a strut rig test instead
//       kind: strut_rig
//       model: ../vehicles/passat_b8_front.yaml  # its strut, put on the rig (strut_on_rig)
//       set: {gas_stiffness_N_per_m: 15000}    # strut-test keys (fitting/strut_parameters.h)
//       effects: [gas_force]
//       rig: {amplitudes_mm: [3, 1.5, 0.8], frequencies_Hz: [0.7, 2.3, 6.1]}  # a multisine;
//                                              # record k >= 2 takes seeded random phases
//       duration_s: 30                         # required
//       sample_rate_Hz: 1000                   # default 1000
//       noise_N: 0.6                           # Gaussian load-cell noise (default 0.6 N)
struct HiddenDataset {
  std::string name;
  bool strut_rig = false;
  std::filesystem::path model;
  std::string damper_state;  // "" keeps the model's
  std::map<std::string, double> set;
  std::vector<std::string> effects;
  long seed = 1;
  int records = 2;
  double duration_s = 0.0;  // 0: the excitation's (vehicle datasets)
  double sample_rate_Hz = 500.0;
  // A vehicle dataset: its road and its accelerometers.
  std::filesystem::path excitation;
  study::SensorModel sensor;
  std::string mount_channel;  // "body_acc" or "wheel_acc" with a sensor mount
  // A strut rig dataset: its multisine and load-cell noise.
  std::vector<double> rig_amplitudes_m, rig_frequencies_Hz;
  double noise_N = 0.6;
  // The baseline a diagnosis of it starts from, as an engineer's data sheet gives it (empty
  // model: none written): errors drawn with datasheet_seed, or the given shares.
  std::filesystem::path baseline_model;
  long baseline_datasheet_seed = 0;
  std::map<std::string, double> baseline_errors;
  // Where the dataset and its `set:` are in the spec ("FILE: key '...'"), for messages.
  std::string location;
  std::string set_location;
};

// Every dataset of `spec_file`. InputError naming the file and key for a missing, unknown or
// out-of-range key, an unknown effect (listing the known ones), a rig multisine with unequal
// lists or a frequency at or above Nyquist, a vehicle sensor band or log sweep reaching Nyquist,
// a rig dataset with a sensor, a baseline with neither or both of datasheet_seed
// and errors or an error share outside (-1, 10], no datasets, or two datasets of one name (their
// files would collide). Models and excitations are only named here; load_truth_model reads them.
std::vector<HiddenDataset> read_hidden_spec(const std::filesystem::path& spec_file);

// The file of record k (1-based): NAME.csv, NAME_2.csv, ...
std::string record_file_name(const HiddenDataset& d, int record);

// The data-sheet baseline's file, NAME_baseline.yaml.
std::string baseline_file_name(const HiddenDataset& d);

}  // namespace ridefit::synthetic
