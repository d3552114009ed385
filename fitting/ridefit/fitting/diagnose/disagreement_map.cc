#include "ridefit/fitting/diagnose/disagreement_map.h"

#include <fmt/core.h>

#include <algorithm>
#include <boost/math/distributions/fisher_f.hpp>
#include <cmath>
#include <span>

#include "ridefit/common/errors.h"
#include "ridefit/fitting/diagnose/pooled_bands.h"
#include "ridefit/fitting/diagnose/residual_statistics.h"
#include "ridefit/signal/equivalent_dof.h"
#include "ridefit/signal/hann_window.h"
#include "ridefit/signal/psd_confidence.h"
#include "ridefit/signal/statistics.h"
#include "ridefit/signal/welch_psd.h"

namespace ridefit::fitting::diagnose {
namespace {

void check(const std::vector<ChannelPair>& channels, double fs, const DisagreementOptions& o) {
  if (channels.empty()) throw InputError("the disagreement map needs at least one channel");
  if (!(fs > 0.0) || !std::isfinite(fs)) {
    throw InputError(fmt::format("sample rate {} Hz: expected a finite value > 0", fs));
  }
  o.validate();
  if (!(o.band_high_Hz < 0.5 * fs)) {
    throw InputError(fmt::format("band {}–{} Hz: the top is not below the Nyquist frequency {} Hz",
                                 o.band_low_Hz, o.band_high_Hz, 0.5 * fs));
  }
  for (const auto& c : channels) {
    if (c.measured.size() != c.simulated.size()) {
      throw InputError(fmt::format("channel {}: {} measured against {} simulated samples", c.name,
                                   c.measured.size(), c.simulated.size()));
    }
    if (static_cast<double>(c.measured.size()) < o.segment_s * fs) {
      throw InputError(fmt::format("channel {}: {} samples, fewer than one {} s segment", c.name,
                                   c.measured.size(), o.segment_s));
    }
    for (const auto* series : {&c.measured, &c.simulated}) {
      for (std::size_t k = 0; k < series->size(); ++k) {
        if (!std::isfinite((*series)[k])) {
          throw InputError(fmt::format("channel {}: sample {} of the {} series is not finite",
                                       c.name, k,
                                       series == &c.measured ? "measured" : "simulated"));
        }
      }
    }
  }
}

double smoothed_peak(const std::vector<double>& f, const std::vector<double>& p,
                     std::size_t count) {
  double best = -1.0, at = 0.0;
  for (std::size_t k = 0; k < count; ++k) {
    const double left = p[k > 0 ? k - 1 : k], right = p[k + 1 < count ? k + 1 : k];
    const double s = (left + p[k] + right) / 3.0;
    if (s > best) {
      best = s;
      at = f[k];
    }
  }
  return at;
}

// Each bin's flagged side inside [first, last): the sign of its ratio where the bin alone is
// significant, else the sign of the mean of the strongest significant pooled window covering it
// whose mean is at least min_region_dB, else 0.
std::vector<int> flagged_sides(const ChannelDisagreement& d, std::size_t first, std::size_t last,
                               double nu, const std::vector<double>& bin_correlation,
                               std::size_t max_width_bins, double alpha, double min_scatter_dB,
                               double min_region_dB) {
  std::vector<int> side(d.frequency_Hz.size(), 0);
  if (last > first && max_width_bins >= 2) {
    std::vector<double> log_ratio;
    for (std::size_t k = first; k < last; ++k) {
      log_ratio.push_back(std::log(d.simulated_psd[k] / d.measured_psd[k]));
    }
    const double floor = min_scatter_dB * std::log(10.0) / 10.0;
    const double variance = log_ratio_variance(log_ratio, nu, bin_correlation, floor * floor);
    auto bands =
        significant_pooled_bands(log_ratio, variance, bin_correlation, alpha, max_width_bins);
    std::stable_sort(bands.begin(), bands.end(), [](const PooledBand& a, const PooledBand& b) {
      return std::abs(a.z) < std::abs(b.z);
    });
    for (const auto& band : bands) {  // weakest first: the strongest window has the last word
      // Only windows that also differ by min_region_dB on average: the union of significant
      // windows must not dilute a region with the weak bins a wide window takes in.
      if (std::abs(band.mean_log_ratio) * 10.0 / std::log(10.0) < min_region_dB) continue;
      for (std::size_t k = band.first; k < band.last; ++k) side[first + k] = band.z > 0 ? 1 : -1;
    }
  }
  for (std::size_t k = first; k < last; ++k) {
    if (d.significant[k]) side[k] = d.ratio_dB[k] > 0.0 ? 1 : -1;
  }
  return side;
}

// Runs of flagged bins of one side (single-bin gaps bridged) inside [first, last).
void find_regions(const ChannelDisagreement& d, const std::vector<int>& side, std::size_t first,
                  std::size_t last, bool above_band, const DisagreementOptions& o,
                  std::vector<DisagreementRegion>& out) {
  std::size_t k = first;
  while (k < last) {
    if (side[k] == 0) {
      ++k;
      continue;
    }
    const int high = side[k];
    std::size_t end = k + 1;  // one past the region's last flagged bin
    for (std::size_t j = k + 1; j < last; ++j) {
      const bool same = side[j] == high;
      if (same) {
        end = j + 1;
      } else if (j > end) {
        break;  // a gap of two bins ends it
      }
    }
    const std::size_t bins = end - k;
    double mean = 0.0;
    std::size_t measured_peak = k, simulated_peak = k;
    bool single_bins = false;
    for (std::size_t j = k; j < end; ++j) {
      mean += d.ratio_dB[j];
      single_bins = single_bins || d.significant[j];
      if (d.measured_psd[j] > d.measured_psd[measured_peak]) measured_peak = j;
      if (d.simulated_psd[j] > d.simulated_psd[simulated_peak]) simulated_peak = j;
    }
    mean /= static_cast<double>(bins);
    if (bins >= static_cast<std::size_t>(o.min_region_bins) && std::abs(mean) >= o.min_region_dB) {
      out.push_back({d.channel, d.frequency_Hz[k], d.frequency_Hz[end - 1], mean,
                     d.frequency_Hz[measured_peak], d.frequency_Hz[simulated_peak], above_band,
                     single_bins ? RegionEvidence::kBins : RegionEvidence::kPooledBand, 0.0});
    }
    k = end;
  }
}

}  // namespace

void DisagreementOptions::validate() const {
  if (!(band_low_Hz >= 0.0) || !(band_low_Hz < band_high_Hz) || !std::isfinite(band_high_Hz)) {
    throw InputError(fmt::format("band {}–{} Hz: expected 0 <= low < high, both finite",
                                 band_low_Hz, band_high_Hz));
  }
  if (!(above_band_high_Hz == 0.0 ||
        (above_band_high_Hz > band_high_Hz && std::isfinite(above_band_high_Hz)))) {
    throw InputError(fmt::format(
        "band above {} Hz: expected 0 (automatic) or a finite top above the band's {} Hz",
        above_band_high_Hz, band_high_Hz));
  }
  if (!(segment_s > 0.0) || !std::isfinite(segment_s)) {
    throw InputError(fmt::format("segment {} s: expected a length > 0", segment_s));
  }
  if (!(confidence > 0.0 && confidence < 1.0)) {
    throw InputError(fmt::format("confidence {}: expected a value in (0, 1)", confidence));
  }
  if (!(min_region_dB >= 0.0) || !std::isfinite(min_region_dB)) {
    throw InputError(
        fmt::format("smallest region {} dB: expected a finite value >= 0", min_region_dB));
  }
  if (min_region_bins < 1) {
    throw InputError(fmt::format("smallest region {} bins: expected at least 1", min_region_bins));
  }
  if (!(pooled_max_width_Hz >= 0.0) || !std::isfinite(pooled_max_width_Hz)) {
    throw InputError(fmt::format("pooled band width {} Hz: expected a finite value >= 0 (0: none)",
                                 pooled_max_width_Hz));
  }
  if (!(pooled_min_scatter_dB > 0.0) || !std::isfinite(pooled_min_scatter_dB)) {
    throw InputError(
        fmt::format("pooled scatter {} dB: expected a finite value > 0", pooled_min_scatter_dB));
  }
}

DisagreementMap map_disagreement(const std::vector<ChannelPair>& channels, double sample_rate_Hz,
                                 const DisagreementOptions& options) {
  check(channels, sample_rate_Hz, options);
  const double above_high = options.above_band_high_Hz > options.band_high_Hz
                                ? std::min(options.above_band_high_Hz, 0.5 * sample_rate_Hz)
                                : std::min(2.0 * options.band_high_Hz, 0.25 * sample_rate_Hz);
  signal::WelchOptions welch;
  welch.segment_length_s = options.segment_s;
  DisagreementMap map;
  double gap_power = 0.0;
  for (const auto& c : channels) {
    const auto measured = signal::welch_psd(c.measured, sample_rate_Hz, welch);
    const auto simulated = signal::welch_psd(c.simulated, sample_rate_Hz, welch);
    const auto interval = signal::psd_confidence_interval(measured, options.confidence);
    ChannelDisagreement d;
    d.channel = c.name;
    std::size_t band_bins = 0;
    double in_band_measured = 0.0, in_band_simulated = 0.0, above_measured = 0.0,
           above_simulated = 0.0, sum_squares = 0.0;
    for (std::size_t k = 0; k < measured.frequency_Hz.size(); ++k) {
      const double f = measured.frequency_Hz[k];
      const bool in_band = f >= options.band_low_Hz && f <= options.band_high_Hz;
      const bool above = f > options.band_high_Hz && f <= above_high;
      if (!in_band && !above) continue;
      const double pm = std::max(measured.psd[k], 1e-300);
      const double chain = c.chain_power ? c.chain_power(f) : 1.0;
      const double ps = std::max(chain * simulated.psd[k] + c.noise_psd, 1e-300);
      const double ratio = 10.0 * std::log10(ps / pm);
      d.frequency_Hz.push_back(f);
      d.measured_psd.push_back(pm);
      d.simulated_psd.push_back(ps);
      d.measured_lower.push_back(interval.lower[k]);
      d.measured_upper.push_back(interval.upper[k]);
      d.ratio_dB.push_back(ratio);
      // Both sides are Welch estimates with ν degrees of freedom each (the simulation scatters as
      // the measurement does), so their ratio is judged against F(ν, ν), not against the measured
      // side's χ² interval alone (which flags ~8 % of bins of two realisations of one process).
      const double nu = measured.degrees_of_freedom[k];
      const boost::math::fisher_f f_ratio(nu, nu);
      const double alpha = 1.0 - options.confidence;
      const double r = ps / pm;
      d.significant.push_back(r < boost::math::quantile(f_ratio, 0.5 * alpha) ||
                              r > boost::math::quantile(f_ratio, 1.0 - 0.5 * alpha));
      if (in_band) {
        ++band_bins;
        sum_squares += ratio * ratio;
        in_band_measured += pm;
        in_band_simulated += ps;
      } else {
        above_measured += pm;
        above_simulated += ps;
      }
    }
    // The band's bins come first (frequencies ascend and the band lies below the rest).
    d.gap_dB = band_bins > 0 ? std::sqrt(sum_squares / static_cast<double>(band_bins)) : 0.0;
    d.measured_peak_Hz = smoothed_peak(d.frequency_Hz, d.measured_psd, band_bins);
    d.simulated_peak_Hz = smoothed_peak(d.frequency_Hz, d.simulated_psd, band_bins);
    d.measured_above_band_share = in_band_measured > 0.0 ? above_measured / in_band_measured : 0.0;
    d.simulated_above_band_share =
        in_band_simulated > 0.0 ? above_simulated / in_band_simulated : 0.0;
    std::vector<double> residual(c.measured.size());
    for (std::size_t k = 0; k < residual.size(); ++k) residual[k] = c.simulated[k] - c.measured[k];
    d.residual_rms = signal::rms(residual);
    const double measured_rms = signal::rms(c.measured);
    d.nrmse = measured_rms > 0.0 ? d.residual_rms / measured_rms : 0.0;
    std::tie(d.residual_max_autocorrelation, d.residual_whiteness_p) = residual_whiteness(residual);
    d.amplitude_dependence = amplitude_dependence(c.measured, c.simulated);
    // The band's and the above-band range's bins are pooled (and Bonferroni-counted) apart.
    const std::vector<double> bin_correlation =
        signal::welch_bin_correlation(signal::periodic_hann_window(measured.segment_length_samples),
                                      measured.hop_samples, measured.segment_count, 3);
    const double nu = measured.degrees_of_freedom[measured.degrees_of_freedom.size() / 2];
    const auto max_width = static_cast<std::size_t>(
        std::max(0.0, std::floor(options.pooled_max_width_Hz / measured.frequency_resolution_Hz)));
    const double alpha = 1.0 - options.confidence;
    const std::size_t all = d.frequency_Hz.size();
    std::vector<int> side = flagged_sides(d, 0, band_bins, nu, bin_correlation, max_width, alpha,
                                          options.pooled_min_scatter_dB, options.min_region_dB);
    const std::vector<int> above_side =
        flagged_sides(d, band_bins, all, nu, bin_correlation, max_width, alpha,
                      options.pooled_min_scatter_dB, options.min_region_dB);
    std::copy(above_side.begin() + static_cast<std::ptrdiff_t>(band_bins), above_side.end(),
              side.begin() + static_cast<std::ptrdiff_t>(band_bins));
    find_regions(d, side, 0, band_bins, false, options, map.regions);
    find_regions(d, side, band_bins, all, true, options, map.regions);
    if (options.compare_peaks && band_bins > 0) {
      const std::span<const double> f(d.frequency_Hz.data(), band_bins);
      d.peak = compare_peaks(
          estimate_peak(f, std::span<const double>(d.measured_psd.data(), band_bins), nu,
                        bin_correlation),
          estimate_peak(f, std::span<const double>(d.simulated_psd.data(), band_bins), nu,
                        bin_correlation),
          measured.frequency_resolution_Hz, alpha / static_cast<double>(channels.size()));
      if (d.peak.significant) {
        const double low = std::min(d.peak.measured.frequency_Hz, d.peak.simulated.frequency_Hz);
        const double high = std::max(d.peak.measured.frequency_Hz, d.peak.simulated.frequency_Hz);
        double mean = 0.0;
        std::size_t bins = 0;
        for (std::size_t k = 0; k < band_bins; ++k) {
          if (d.frequency_Hz[k] >= low && d.frequency_Hz[k] <= high) {
            mean += d.ratio_dB[k];
            ++bins;
          }
        }
        map.regions.push_back({d.channel, low, high,
                               bins > 0 ? mean / static_cast<double>(bins) : 0.0,
                               d.peak.measured.frequency_Hz, d.peak.simulated.frequency_Hz, false,
                               RegionEvidence::kPeakShift, d.peak.threshold_Hz});
      }
    }
    gap_power += d.gap_dB * d.gap_dB;
    map.channels.push_back(std::move(d));
  }
  map.gap_dB = std::sqrt(gap_power / static_cast<double>(channels.size()));
  std::stable_sort(map.regions.begin(), map.regions.end(),
                   [](const DisagreementRegion& a, const DisagreementRegion& b) {
                     return std::abs(a.size_dB) > std::abs(b.size_dB);
                   });
  return map;
}

}  // namespace ridefit::fitting::diagnose
