#pragma once

#include <span>
#include <vector>

namespace ridefit::comfort {

// Metrics of an already frequency-weighted acceleration a_w (m/s², or rad/s² for We) sampled
// uniformly at sample_rate_Hz, ISO 2631-1:1997 clause 6. Every function throws InputError for
// an empty record, an invalid rate or a non-finite sample (naming its index).

// Basic evaluation method, eq. (1): a_w = [ (1/T) ∫ a_w²(t) dt ]^½, by the rectangle rule.
double weighted_rms(std::span<const double> weighted, double sample_rate_Hz);

// Running RMS, eq. (2)–(3), with LINEAR (rectangular) integration over the last τ seconds:
//   a_w(t0) = [ (1/τ) ∫_{t0−τ}^{t0} a_w²(t) dt ]^½,
// evaluated at every sample t0 whose full window lies in the record: the window holds
// N = round(τ·fs) samples and the result has size − N + 1 values, element i covering samples
// i … i+N−1. Partial windows at the start are left out rather than padded, because padding with
// zeros would understate and dividing by the shorter length would overstate the running value.
// (ISO 2631-1 also allows exponential integration, eq. (3) note; not implemented.)
// τ = 1 s is the standard's recommendation for MTVV. Throws InputError for τ ≤ 0, a window
// under one sample, or a record shorter than τ.
std::vector<double> running_rms(std::span<const double> weighted, double sample_rate_Hz,
                                double integration_time_s = 1.0);

// Maximum transient vibration value, eq. (4): the largest running RMS (linear, τ).
double maximum_transient_vibration_value(std::span<const double> weighted, double sample_rate_Hz,
                                         double integration_time_s = 1.0);

// Fourth-power vibration dose value, eq. (5): VDV = [ ∫_0^T a_w⁴(t) dt ]^¼ in m/s^1.75,
// rectangle rule Σ a_w⁴ / fs (exact for a sine over whole periods with ≥ 5 samples a period).
double vibration_dose_value(std::span<const double> weighted, double sample_rate_Hz);

// Crest factor, clause 6.2.1: max |a_w| / a_w (dimensionless); 0 for an all-zero record.
double crest_factor(std::span<const double> weighted, double sample_rate_Hz);

// All of the above in one pass over a record (one finiteness check, one RMS).
struct VibrationMetrics {
  double duration_s = 0.0;             // T = size / fs
  double weighted_rms_m_per_s2 = 0.0;  // a_w
  double peak_m_per_s2 = 0.0;          // max |a_w|
  double crest_factor = 0.0;           // peak / a_w
  double mtvv_m_per_s2 = 0.0;          // max running RMS (τ)
  double vdv_m_per_s1_75 = 0.0;        // VDV
  double integration_time_s = 1.0;     // τ used for MTVV
};
VibrationMetrics vibration_metrics(std::span<const double> weighted, double sample_rate_Hz,
                                   double integration_time_s = 1.0);

}  // namespace ridefit::comfort
