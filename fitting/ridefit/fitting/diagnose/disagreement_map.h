#pragma once

#include <functional>
#include <string>
#include <vector>

#include "ridefit/fitting/diagnose/peak_shift.h"

namespace ridefit::fitting::diagnose {

// One channel of a record, measured and simulated on the same time base (same length, same
// sample rate), e.g. "wheel_acc" in m/s², or "force" in N for a strut-rig loop.
struct ChannelPair {
  std::string name;
  std::vector<double> measured;
  std::vector<double> simulated;
  // The measured channel's white sensor-noise floor, one-sided PSD [unit²/Hz]: added to the
  // simulated PSD before the comparison (the model as the sensor would show it), so bins where
  // the measurement is noise do not read as the model missing something.
  double noise_psd = 0.0;
  // The measuring chain's factor on the simulated PSD at a frequency [Hz] (a gain squared times a
  // low-pass' |H|², model/acceleration_sensors.h), applied before the floor is added:
  // P_shown = chain_power(f)·P_sim + N. Empty = 1 (an ideal sensor).
  std::function<double(double frequency_Hz)> chain_power{};
};

struct DisagreementOptions {
  double band_low_Hz = 0.5;  // the comparison band (the road's excitation band)
  double band_high_Hz = 30.0;
  double above_band_high_Hz = 0.0;  // > band_high_Hz: also compare (band_high, above_band_high]
                                    // for energy nonlinear effects put above the road's band;
                                    // 0 = twice band_high_Hz, at most a quarter of the
                                    // sample rate
  double segment_s = 4.0;           // Welch segments: periodic Hann, 50 % overlap
  double confidence = 0.99;         // of the measured PSD's χ² interval (signal/psd_confidence.h)
  double min_region_dB = 1.0;       // a region must also differ by at least this much on average
  int min_region_bins = 2;          // and span at least this many bins
  // Band tests (pooled_bands.h): windows of 2, 4, 8, … bins up to this width, each tested at
  // the family-wise rate 1 − confidence; 0 = single bins only.
  double pooled_max_width_Hz = 8.0;
  // The smallest per-bin scatter of the log ratio the band tests assume (pooled_bands.h
  // log_ratio_variance), in dB (RMS).
  double pooled_min_scatter_dB = 0.25;
  // Peak frequencies (peak_shift.h): measured against simulated per channel, at the rate
  // 1 − confidence shared over the channels.
  bool compare_peaks = true;

  // InputError naming the option for: a band not 0 < low < high, above_band_high_Hz neither 0
  // nor above the band, a segment not > 0, a confidence outside (0, 1), a negative region size
  // or width, fewer than 1 bin, a scatter not > 0.
  void validate() const;
};

// What made a region significant.
enum class RegionEvidence {
  kBins,        // single bins outside the F(ν, ν) interval
  kPooledBand,  // only windows of pooled bins (the mean ratio outside its interval)
  kPeakShift,   // the channel's measured and simulated peaks lie further apart than they resolve
};

// A band where simulation and measurement differ significantly: contiguous bins where the ratio
// P_sim/P_meas lies outside the two-sided F(ν, ν) interval, or that lie in a significant pooled
// window (pooled_bands.h), on the same side (two Welch estimates with ν degrees of freedom each;
// gaps of one bin bridged), whose mean difference is at least min_region_dB. Or a peak shift:
// the band between the measured and the simulated peak of a channel whose peaks differ by more
// than they resolve (peak_shift.h), whatever its size in dB.
struct DisagreementRegion {
  std::string channel;
  double low_Hz = 0.0;
  double high_Hz = 0.0;
  double size_dB = 0.0;  // mean of 10·log10(P_sim / P_meas) over the region's bins (signed)
  double measured_peak_Hz = 0.0;   // where the measured PSD is largest inside the region
  double simulated_peak_Hz = 0.0;  // where the simulated PSD is largest inside the region
  bool above_band = false;         // lies above the excitation band
  RegionEvidence evidence = RegionEvidence::kBins;
  double resolution_Hz = 0.0;  // a peak shift: the shift that counts (PeakComparison)
};

struct ChannelDisagreement {
  std::string channel;
  std::vector<double> frequency_Hz;  // bins of the band and of the above-band range
  std::vector<double> measured_psd, simulated_psd;
  std::vector<double> measured_lower, measured_upper;  // the measured PSD's interval
  std::vector<double> ratio_dB;                        // 10·log10(P_sim / P_meas) per bin
  std::vector<bool> significant;                       // ratio outside the F interval
  // The spectral gap: RMS over the band's bins of ratio_dB [dB]; 0 when they agree exactly.
  double gap_dB = 0.0;
  // Peak of each PSD over the band (after 3-bin smoothing so one noisy bin cannot win).
  double measured_peak_Hz = 0.0;
  double simulated_peak_Hz = 0.0;
  // The peaks located by their half-power parabola, with standard errors, and whether they
  // differ by more than they resolve (peak_shift.h); set when options.compare_peaks.
  PeakComparison peak;
  // Time domain: RMS of (simulated − measured), and that over the RMS of the measured signal.
  double residual_rms = 0.0;
  double nrmse = 0.0;
  // Whiteness of the residual: largest |autocorrelation| over lags 1..20 samples of the
  // residual, and the Ljung-Box p-value over those lags (small p: structure left).
  double residual_max_autocorrelation = 0.0;
  double residual_whiteness_p = 0.0;
  // Amplitude dependence: the residual RMS where |measured| is in its top third over that
  // where it is in its bottom third. About 1 for an additive error; a pure gain error gives the
  // ratio of |measured| itself (about 6 for Gaussian samples); far above that, the error grows
  // faster than the signal (a nonlinearity). 1 when the bottom third has no residual.
  double amplitude_dependence = 0.0;
  // Power above the band over power in the band, measured and simulated.
  double measured_above_band_share = 0.0;
  double simulated_above_band_share = 0.0;
};

struct DisagreementMap {
  std::vector<ChannelDisagreement> channels;
  std::vector<DisagreementRegion> regions;  // all channels, largest |size_dB| first
  // RMS of the channels' gap_dB (the gap the diagnosis reports before and after).
  double gap_dB = 0.0;
};

// Compares measurement and simulation channel by channel. InputError (naming the channel) for
// series of different lengths, too short for one segment, or non-finite samples.
DisagreementMap map_disagreement(const std::vector<ChannelPair>& channels, double sample_rate_Hz,
                                 const DisagreementOptions& options = {});

}  // namespace ridefit::fitting::diagnose
