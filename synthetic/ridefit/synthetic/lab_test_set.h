#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace ridefit::synthetic {

// Synthetic strut rig tests with known truth (datasets/lab/ is this set at seed 1): seed 000's
// calibration test (quasi-static triangle, 3 mm at 1 mm/s, 10 cycles at 200 Hz), a 60 s dynamic
// history (lab_three_sines at 1 kHz), three shim settings whose friction grows with the spring's
// compression (its Figure 4: Fc = 40 N + 5 N/mm, 3 cycles each), an MR-like strut under a random
// rig motion with a switching coil current (semi_active_random.csv, with a current[A] column),
// the same kind of damper in a car on the road (semi_active_drive.cc) and truth.yaml. Forces are
// the strut-test model at the truth (lab_truth.h) by CVODE at rtol 1e-10 on the exact
// displacement, read through the lab's load cell.

// The names of the files write_lab_tests writes.
std::vector<std::string> lab_test_files();

// Writes the set into the existing folder `dir`; all randomness from one generator seeded with
// `seed`, used in the order of lab_test_files(). RunError when an integrator fails.
void write_lab_tests(const std::filesystem::path& dir, unsigned seed);

}  // namespace ridefit::synthetic
