#pragma once

#include <filesystem>
#include <random>

namespace ridefit::synthetic {

// The MR-like damper in a car on the road (lab_truth.h's lab_mr_car, slip): 120 s over an
// ISO 8608 class B road at 50 km/h with a coil current switching like the rig test's
// (switching_command.h, 0–2 A), by CVODE at rtol 1e-10, at 200 Hz; the accelerometers read with
// Gaussian noise of 1 % of each channel's RMS. Written as
// `time[s],road[mm],body_acc[m/s^2],wheel_acc[m/s^2],current[A]`. From `rng`, in this order: the
// road's seed, the current, the noise (body and wheel interleaved per sample).
void write_semi_active_drive(const std::filesystem::path& path, std::mt19937_64& rng);

}  // namespace ridefit::synthetic
