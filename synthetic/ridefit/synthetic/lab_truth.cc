#include "ridefit/synthetic/lab_truth.h"

namespace ridefit::synthetic {

LoadCell lab_load_cell() { return {0.6, 10000.0 / 65536.0}; }

model::StrutTestParameters<double> lab_passat_strut(double coulomb_force_N) {
  auto p = model::dahl_strut_on_rig(5e6, coulomb_force_N, 1.0, 488000.0, 886.9);
  p.force_offset_N = kLabForceOffset_N;
  return p;
}

model::StrutTestParameters<double> lab_mr_strut() {
  auto p = model::dahl_strut_on_rig(3e6, 40.0, 1.0, 500000.0, 800.0);
  p.force_offset_N = kLabForceOffset_N;
  p.damping_per_command_Ns_per_m = 1500.0;
  p.coulomb_force_per_command_N = 180.0;
  p.command_lag_s = 0.012;
  return p;
}

model::QuarterCarParameters<double> lab_mr_car() {
  model::QuarterCarParameters<double> p{};
  p.sprung_mass_kg = 385.40;
  p.unsprung_mass_kg = 46.761;
  p.tyre_stiffness_N_per_m = 288180.0;
  p.tyre_damping_Ns_per_m = 100.0;
  p.spring_stiffness_N_per_m = 29000.0;
  p.top_mount_spring_path_stiffness_N_per_m = 800000.0;
  p.top_mount_stiffness_N_per_m = 488000.0;
  p.dahl_sigma0_N_per_m = 5.0e6;
  p.dahl_exponent = 1.0;
  p.damping_Ns_per_m = 600.0;
  p.damping_per_command_Ns_per_m = 1200.0;
  p.command_lag_s = 0.012;
  return p;
}

}  // namespace ridefit::synthetic
