#pragma once

#include "ridefit/model/quarter_car.h"
#include "ridefit/model/strut_test.h"
#include "ridefit/synthetic/load_cell.h"

namespace ridefit::synthetic {

// The known truth behind the lab-like rig tests (lab_test_set.h), written to their truth.yaml.

// The rig's load cell: 0.6 N noise (1 % of Fc = 60 N), 16 bit over ±5 kN; its zero error is
// kLabForceOffset_N, in every strut below.
inline constexpr double kLabForceOffset_N = 2.5;
LoadCell lab_load_cell();

// Seed 000's Passat strut: σ0 = 5e6 N/m (well above the 488 N/mm top mount), d = 1,
// c = 886.9 N·s/m, at the Coulomb force of the test (it grows with the spring's compression).
model::StrutTestParameters<double> lab_passat_strut(double coulomb_force_N);

// An MR-like controlled strut: passive c = 800 N·s/m and Fc = 40 N, rising by 1500 N·s/m and
// 180 N per ampere of coil current after a 12 ms lag.
model::StrutTestParameters<double> lab_mr_strut();

// The MR-like damper in a car: datasets/vehicles/passat_b8_front.yaml's corner (slip), its damper
// replaced by c = 600 + 1200·ū N·s/m, ū lagging the coil current by 12 ms.
model::QuarterCarParameters<double> lab_mr_car();

}  // namespace ridefit::synthetic
