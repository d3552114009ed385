#include "ridefit/synthetic/lab_test_set.h"

#include <fmt/core.h>

#include <ostream>
#include <random>

#include "ridefit/io/atomic_file.h"
#include "ridefit/synthetic/lab_truth.h"
#include "ridefit/synthetic/load_cell.h"
#include "ridefit/synthetic/multisine.h"
#include "ridefit/synthetic/reference_rig_record.h"
#include "ridefit/synthetic/rig_csv.h"
#include "ridefit/synthetic/semi_active_drive.h"
#include "ridefit/synthetic/switching_command.h"
#include "ridefit/synthetic/triangle_history.h"

namespace ridefit::synthetic {
namespace {

// The 1 kHz histories' grid is k · 1 ms (not k / 1000, which differs in the last bit), as the
// shipped files were made.
std::vector<double> millisecond_times(std::size_t samples) {
  std::vector<double> t(samples);
  for (std::size_t k = 0; k < samples; ++k) t[k] = static_cast<double>(k) * 1e-3;
  return t;
}

// The reference record of `strut` read through the lab's load cell, written as the lab's CSV.
void write_lab_record(const std::filesystem::path& path, std::vector<double> time_s,
                      const std::function<double(double)>& displacement_m,
                      const model::StrutTestParameters<double>& strut, std::mt19937_64& rng,
                      const std::function<double(double)>& current = {}) {
  fitting::HysteresisRecord r =
      reference_rig_record(std::move(time_s), displacement_m, strut, current);
  r.force_N = read_load_cell(r.force_N, lab_load_cell(), rng);
  write_rig_csv(path, r, RigCsvDigits::kFixed);
}

void write_truth(const std::filesystem::path& path, unsigned seed) {
  io::write_atomically(path, [&](std::ostream& out) {
    out << fmt::format(
        "# The truth behind the synthetic rig tests of this folder (ridefit generate-lab, seed "
        "{}).\n# Strut: seed 000's Passat strut; the shim files differ only in Fc.\n"
        "dahl_sigma0_N_per_m: 5.0e6\ndahl_exponent: 1\ntop_mount_stiffness_N_per_m: 488000\n"
        "damping_Ns_per_m: 886.9\nforce_offset_N: {}\nforce_noise_std_N: {}\n"
        "force_quantum_N: {:.6f}\ncoulomb_force_N:\n  triangle_3mm_1mmps.csv: 60\n"
        "  dynamic_60s.csv: 60\n  shim_0mm.csv: 40\n  shim_2mm.csv: 50\n  shim_4mm.csv: 60\n"
        "# Fc = 40 N + 5 N/mm · spring compression (seed 000 Figure 4's kind of relation)\n"
        "semi_active_random.csv:  # an MR-like strut, its current in the file\n"
        "  dahl_sigma0_N_per_m: 3.0e6\n  coulomb_force_N: 40\n  dahl_exponent: 1\n"
        "  top_mount_stiffness_N_per_m: 500000\n  damping_Ns_per_m: 800\n"
        "  damping_per_command_Ns_per_m: 1500\n  coulomb_force_per_command_N: 180\n"
        "  command_lag_s: 0.012\n"
        "semi_active_drive.csv:  # the MR-like damper in the Passat corner (slip), on the road\n"
        "  damper_state: slip\n  damping_Ns_per_m: 600\n  damping_per_command_Ns_per_m: 1200\n"
        "  command_lag_s: 0.012\n  accelerometer_noise_share_of_rms: 0.01\n",
        seed, kLabForceOffset_N, lab_load_cell().noise_N, lab_load_cell().quantum_N);
  });
}

}  // namespace

std::vector<std::string> lab_test_files() {
  return {"triangle_3mm_1mmps.csv", "dynamic_60s.csv", "shim_0mm.csv",
          "shim_2mm.csv",           "shim_4mm.csv",    "semi_active_random.csv",
          "semi_active_drive.csv",  "truth.yaml"};
}

void write_lab_tests(const std::filesystem::path& dir, unsigned seed) {
  std::mt19937_64 rng(seed);
  const TriangleHistory triangle(0.003, 0.001);
  write_lab_record(dir / "triangle_3mm_1mmps.csv", sample_times(10 * 12 * 200 + 1, 200.0), triangle,
                   lab_passat_strut(60.0), rng);
  write_lab_record(dir / "dynamic_60s.csv", millisecond_times(60001), lab_three_sines(),
                   lab_passat_strut(60.0), rng);
  for (int shim_mm : {0, 2, 4}) {
    write_lab_record(dir / fmt::format("shim_{}mm.csv", shim_mm),
                     sample_times(3 * 12 * 200 + 1, 200.0), triangle,
                     lab_passat_strut(40.0 + 5.0 * shim_mm), rng);
  }
  // 30 s: the random motion's phases, then the current, from the same generator.
  const Multisine motion = random_rig_motion(rng);
  const SwitchingCommand current(30.0, 2.0, rng);
  write_lab_record(dir / "semi_active_random.csv", millisecond_times(30001), motion, lab_mr_strut(),
                   rng, current);
  write_semi_active_drive(dir / "semi_active_drive.csv", rng);
  write_truth(dir / "truth.yaml", seed);
}

}  // namespace ridefit::synthetic
