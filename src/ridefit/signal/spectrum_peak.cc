#include "ridefit/signal/spectrum_peak.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ridefit/common/errors.h"
#include "ridefit/signal/spectrum_check.h"

namespace ridefit::signal {

SpectrumPeak find_peak(std::span<const double> frequency_Hz, std::span<const double> psd,
                       double low_Hz, double high_Hz) {
  check_spectrum_band("spectrum peak", frequency_Hz, psd, low_Hz, high_Hz);
  const std::size_t n = psd.size();
  bool found = false;
  std::size_t best = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (frequency_Hz[k] < low_Hz || frequency_Hz[k] > high_Hz) continue;
    if (!found || psd[k] > psd[best]) best = k;
    found = true;
  }
  if (!found) {
    throw InputError(fmt::format(
        "spectrum peak: no frequency bin lies in the band [{}, {}] Hz; widen the band to at "
        "least the bin spacing ({} Hz here)",
        low_Hz, high_Hz, frequency_Hz[1] - frequency_Hz[0]));
  }

  SpectrumPeak peak{frequency_Hz[best], psd[best], best};
  if (best == 0 || best + 1 == n) return peak;
  const double p0 = psd[best - 1];
  const double p1 = psd[best];
  const double p2 = psd[best + 1];
  if (p0 <= 0.0 || p1 <= 0.0 || p2 <= 0.0 || p0 > p1 || p2 > p1) return peak;

  // Vertex of the parabola through (x_i, y_i) with x relative to the centre bin (so that
  // non-uniform spacing is handled too) and y = ln PSD.
  const double xa = frequency_Hz[best - 1] - frequency_Hz[best];
  const double xb = frequency_Hz[best + 1] - frequency_Hz[best];
  const double ya = std::log(p0) - std::log(p1);
  const double yb = std::log(p2) - std::log(p1);
  // y(x) = a x² + b x through (0,0), (xa,ya), (xb,yb).
  const double det = xa * xb * (xa - xb);
  const double a = (ya * xb - yb * xa) / det;
  const double b = (yb * xa * xa - ya * xb * xb) / det;
  if (!(a < 0.0)) return peak;  // flat top: no unique vertex
  const double x = std::clamp(-b / (2.0 * a), xa, xb);
  peak.frequency_Hz = frequency_Hz[best] + x;
  peak.psd = p1 * std::exp(a * x * x + b * x);
  return peak;
}

SpectrumPeak find_peak(const PowerSpectralDensity& spectrum, double low_Hz, double high_Hz) {
  return find_peak(spectrum.frequency_Hz, spectrum.psd, low_Hz, high_Hz);
}

}  // namespace ridefit::signal
