#include "ridefit/fitting/diagnose/spectral_shape.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <complex>

#include "ridefit/common/errors.h"

namespace ridefit::fitting::diagnose {
namespace {

constexpr double kResonanceDamping = 0.1;
constexpr int kGridPerOctave = 6;

enum class Kind { kLevel, kTilt, kResonance, kLowPass, kShift };

// One column of the dictionary: a shape on one channel's bins.
struct Column {
  Kind kind;
  std::size_t channel;
  double frequency_Hz;  // f₀ or f_c; 0 for the others
};

// A channel's bins in the band whose ratio is finite.
struct Bins {
  std::vector<double> frequency_Hz;
  std::vector<double> missing_dB;  // 10·log10(P_meas/P_sim)
  std::vector<double> slope_dB;    // d(10·log10 P_sim)/d ln f, smoothed over five bins
};

Bins bins_of(const ChannelDisagreement& c, double low_Hz, double high_Hz) {
  Bins b;
  std::vector<double> log_f, level;
  for (std::size_t k = 0; k < c.frequency_Hz.size(); ++k) {
    const double f = c.frequency_Hz[k];
    if (f < low_Hz || f > high_Hz || !(f > 0.0) || !std::isfinite(c.ratio_dB[k]) ||
        !(c.simulated_psd[k] > 0.0)) {
      continue;
    }
    b.frequency_Hz.push_back(f);
    b.missing_dB.push_back(-c.ratio_dB[k]);
    log_f.push_back(std::log(f));
    level.push_back(10.0 * std::log10(c.simulated_psd[k]));
  }
  // The simulated spectrum's slope along ln f: a least-squares line through five neighbours (a
  // Welch estimate scatters bin to bin).
  const std::size_t n = log_f.size();
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t lo = k >= 2 ? k - 2 : 0, hi = std::min(k + 2, n - 1);
    double mx = 0.0, my = 0.0;
    for (std::size_t j = lo; j <= hi; ++j) {
      mx += log_f[j];
      my += level[j];
    }
    const double m = static_cast<double>(hi - lo + 1);
    mx /= m;
    my /= m;
    double sxy = 0.0, sxx = 0.0;
    for (std::size_t j = lo; j <= hi; ++j) {
      sxy += (log_f[j] - mx) * (level[j] - my);
      sxx += (log_f[j] - mx) * (log_f[j] - mx);
    }
    b.slope_dB.push_back(sxx > 0.0 ? sxy / sxx : 0.0);
  }
  return b;
}

double value(const Column& c, const Bins& b, std::size_t k, double centre_Hz) {
  const double f = b.frequency_Hz[k];
  switch (c.kind) {
    case Kind::kLevel:
      return 1.0;
    case Kind::kTilt:
      return std::log10(f / centre_Hz);
    case Kind::kResonance: {
      const double r = f / c.frequency_Hz;
      const std::complex<double> damping(0.0, 2.0 * kResonanceDamping * r);
      return 10.0 * std::log10(std::norm((1.0 + damping) / (1.0 - r * r + damping)));
    }
    case Kind::kLowPass: {
      const double r = f / c.frequency_Hz;
      return -10.0 * std::log10(1.0 + r * r);
    }
    case Kind::kShift:
      return -b.slope_dB[k];
  }
  return 0.0;
}

std::string words_of(const Column& c, const std::string& channel, double coefficient) {
  const bool up = coefficient >= 0.0;
  switch (c.kind) {
    case Kind::kLevel:
      return fmt::format("{} {} than the model over the band (a sensor's gain, the road's level)",
                         channel, up ? "higher" : "lower");
    case Kind::kTilt:
      return fmt::format(
          "{} {} with frequency against the model (the road's waviness, the damping of the higher "
          "frequencies)",
          channel, up ? "rising" : "falling");
    case Kind::kResonance:
      return up ? fmt::format(
                      "{} carried through a resonance near {:.3g} Hz (a sensor on a panel, a mode "
                      "the model lacks)",
                      channel, c.frequency_Hz)
                : fmt::format(
                      "{} short of the model near {:.3g} Hz, as through an antiresonance (an "
                      "absorber, a mode the model has and the car does not)",
                      channel, c.frequency_Hz);
    case Kind::kLowPass:
      return up ? fmt::format(
                      "{} falling above {:.3g} Hz as through a low-pass (a sensor's band, a "
                      "filter, a mount)",
                      channel, c.frequency_Hz)
                : fmt::format(
                      "{} rising above {:.3g} Hz against the model (the model filters "
                      "more than the car)",
                      channel, c.frequency_Hz);
    case Kind::kShift:
      return fmt::format(
          "{}: the measured response sits {} in frequency than the model's (modes {}: a "
          "stiffness or a mass off)",
          channel, up ? "higher" : "lower", up ? "too low in the model" : "too high in the model");
  }
  return "";
}

std::string_view id_of(Kind k) {
  switch (k) {
    case Kind::kLevel:
      return "level";
    case Kind::kTilt:
      return "tilt";
    case Kind::kResonance:
      return "resonance";
    case Kind::kLowPass:
      return "low_pass";
    case Kind::kShift:
      return "frequency_shift";
  }
  return "";
}

std::string_view unit_of(Kind k) {
  switch (k) {
    case Kind::kLevel:
      return "dB";
    case Kind::kTilt:
      return "dB/decade";
    case Kind::kShift:
      return "share";
    default:
      return "1";
  }
}

}  // namespace

SpectralShape spectral_shape(const DisagreementMap& map, double band_low_Hz, double band_high_Hz,
                             const SparseSelectionOptions& options) {
  options.validate();
  if (!(band_low_Hz > 0.0) || !(band_low_Hz < band_high_Hz)) {
    throw InputError(fmt::format("spectral shape: band {}…{} Hz: expected 0 < low < high",
                                 band_low_Hz, band_high_Hz));
  }
  std::vector<Bins> channels;
  for (const auto& c : map.channels) channels.push_back(bins_of(c, band_low_Hz, band_high_Hz));
  const double centre_Hz = std::sqrt(band_low_Hz * band_high_Hz);
  std::vector<Column> columns;
  for (std::size_t ch = 0; ch < channels.size(); ++ch) {
    if (channels[ch].frequency_Hz.size() < 10) continue;
    columns.push_back({Kind::kLevel, ch, 0.0});
    columns.push_back({Kind::kTilt, ch, 0.0});
    columns.push_back({Kind::kShift, ch, 0.0});
    for (double f = band_low_Hz; f <= band_high_Hz; f *= std::exp2(1.0 / kGridPerOctave)) {
      columns.push_back({Kind::kResonance, ch, f});
      columns.push_back({Kind::kLowPass, ch, f});
    }
  }
  SpectralShape shape;
  if (columns.empty()) return shape;
  // Even bins fit, odd bins judge, each channel a part of its own; the reported coefficients
  // from every bin in order (neighbouring bins correlate: their correlation time is taken along
  // the spectrum).
  auto rows_of = [&](int parity) {  // 0 even, 1 odd, -1 every bin
    SelectionRows side;
    std::size_t rows = 0;
    for (const auto& b : channels) {
      if (b.frequency_Hz.size() < 10) continue;
      const std::size_t n =
          parity < 0 ? b.frequency_Hz.size()
                     : (b.frequency_Hz.size() + 1 - static_cast<std::size_t>(parity)) / 2;
      side.lengths.push_back(n);
      rows += n;
    }
    side.basis = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows),
                                       static_cast<Eigen::Index>(columns.size()));
    side.target.resize(static_cast<Eigen::Index>(rows));
    Eigen::Index row = 0;
    const std::size_t first = parity < 0 ? 0 : static_cast<std::size_t>(parity);
    const std::size_t stride = parity < 0 ? 1 : 2;
    for (std::size_t ch = 0; ch < channels.size(); ++ch) {
      const Bins& b = channels[ch];
      if (b.frequency_Hz.size() < 10) continue;
      for (std::size_t k = first; k < b.frequency_Hz.size(); k += stride, ++row) {
        side.target(row) = b.missing_dB[k];
        for (std::size_t j = 0; j < columns.size(); ++j) {
          if (columns[j].channel == ch) {
            side.basis(row, static_cast<Eigen::Index>(j)) = value(columns[j], b, k, centre_Hz);
          }
        }
      }
    }
    return side;
  };
  const SelectionRows fit = rows_of(0), judge = rows_of(1), every = rows_of(-1);
  const SparseSelection selection = select_columns(fit, judge, options, &every);
  shape.judged_share = selection.judged_share;
  shape.options = options;
  for (const auto& s : selection.columns) {
    const Column& c = columns[static_cast<std::size_t>(s.column)];
    SpectralShapeTerm t;
    t.id = id_of(c.kind);
    t.channel = map.channels[c.channel].channel;
    t.frequency_Hz = c.frequency_Hz;
    t.unit = unit_of(c.kind);
    t.coefficient = s.coefficient;
    t.standard_error = s.standard_error;
    t.judged_share = s.judged_share;
    t.words = words_of(c, t.channel, s.coefficient);
    shape.terms.push_back(t);
  }
  return shape;
}

std::string coefficient_text(const SpectralShapeTerm& t) {
  if (t.id == "frequency_shift") {
    return fmt::format("{:+.3g} ± {:.2g} %", 100.0 * t.coefficient, 100.0 * t.standard_error);
  }
  return fmt::format("{:+.3g} ± {:.2g} {}", t.coefficient, t.standard_error,
                     t.unit == "1" ? "× the named shape" : t.unit);
}

std::string describe(const SpectralShape& shape) {
  std::string text;
  for (const auto& t : shape.terms) {
    text += fmt::format("{}{} ({}, {:.0f} % of the judged ratio)", text.empty() ? "" : "; ",
                        t.words, coefficient_text(t), 100.0 * t.judged_share);
  }
  return text;
}

}  // namespace ridefit::fitting::diagnose
