#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "ridefit/model/quarter_car.h"
#include "ridefit/road/road_input.h"
#include "ridefit/simulate/quarter_car_simulation.h"

namespace ridefit::study {

// The friction study of seed 000, Section 3.2: one stick/slip quarter car run over one
// excitation at several Coulomb forces, each summarised by what the seed reads off its
// Figures 9–11 (PSD peak frequencies of body and wheel, acceleration levels, stick share).
struct FrictionStudyOptions {
  std::vector<double> coulomb_forces_N = {0.0, 12.0, 30.0, 60.0, 120.0};
  simulate::SimulationOptions simulation;  // output rate 1 kHz, CVODE by default
  double psd_segment_s = 10.0;             // Welch, Hann, 50 % overlap: 0.1 Hz bins
  double body_band_low_Hz = 0.5, body_band_high_Hz = 6.0;
  double wheel_band_low_Hz = 8.0, wheel_band_high_Hz = 30.0;
  // The body's slip band around the slip model's body mode (1.3 Hz for the Passat) and its
  // stick band around the stick model's body mode (3.4 Hz).
  double slip_band_low_Hz = 1.0, slip_band_high_Hz = 1.6;
  double stick_band_low_Hz = 2.8, stick_band_high_Hz = 4.2;
  unsigned threads = 0;  // 0 = all cores
};

struct FrictionCase {
  double coulomb_force_N = 0.0;
  double body_peak_Hz = 0.0;   // highest body-acceleration PSD in the body band
  double wheel_peak_Hz = 0.0;  // highest wheel-acceleration PSD in the wheel band
  double body_acc_rms_m_per_s2 = 0.0;
  double wheel_acc_rms_m_per_s2 = 0.0;
  // ISO 2631-1 Wk-weighted RMS and VDV of the body acceleration (the seat-rail comfort value);
  // empty when the output rate is below what the Wk filter needs (weighting_filter.h).
  std::optional<double> body_acc_wk_rms_m_per_s2;
  std::optional<double> body_acc_wk_vdv_m_per_s1_75;
  double body_slip_band_rms_m_per_s2 = 0.0;   // from the PSD over the slip band
  double body_stick_band_rms_m_per_s2 = 0.0;  // from the PSD over the stick band
  double stuck_share = 0.0;                   // share of samples with stuck = 1
  std::vector<double> body_psd;               // (m/s^2)^2/Hz on frequency_Hz
  std::vector<double> wheel_psd;
  simulate::SolverStatistics statistics;
};

struct FrictionStudyResult {
  std::vector<double> frequency_Hz;
  std::vector<FrictionCase> cases;  // in the order of coulomb_forces_N
};

// Runs the cases in parallel. `progress` (may be empty) is called after each case.
FrictionStudyResult run_friction_study(
    const model::QuarterCarParameters<double>& parameters, const road::RoadInput& road,
    const FrictionStudyOptions& options,
    const std::function<void(const FrictionCase&)>& progress = {});

}  // namespace ridefit::study
