#include "ridefit/fitting/diagnose/residual_statistics.h"

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>

namespace ridefit::fitting::diagnose {
namespace {

constexpr int kWhitenessLags = 20;

}  // namespace

// Ljung–Box over lags 1..h of a residual: the largest |autocorrelation| and the p-value.
std::pair<double, double> residual_whiteness(const std::vector<double>& r) {
  const auto n = static_cast<double>(r.size());
  double mean = 0.0;
  for (double v : r) mean += v;
  mean /= n;
  double c0 = 0.0;
  for (double v : r) c0 += (v - mean) * (v - mean);
  if (!(c0 > 0.0)) return {0.0, 1.0};
  double q = 0.0, largest = 0.0;
  for (int lag = 1; lag <= kWhitenessLags; ++lag) {
    double c = 0.0;
    for (std::size_t k = static_cast<std::size_t>(lag); k < r.size(); ++k) {
      c += (r[k] - mean) * (r[k - static_cast<std::size_t>(lag)] - mean);
    }
    const double rho = c / c0;
    largest = std::max(largest, std::abs(rho));
    q += rho * rho / (n - lag);
  }
  q *= n * (n + 2.0);
  const boost::math::chi_squared chi2(kWhitenessLags);
  return {largest, boost::math::cdf(boost::math::complement(chi2, q))};
}

// Residual RMS where |measured| is in its top third over that in its bottom third.
double amplitude_dependence(const std::vector<double>& measured,
                            const std::vector<double>& simulated) {
  std::vector<double> magnitude(measured.size());
  for (std::size_t k = 0; k < magnitude.size(); ++k) magnitude[k] = std::abs(measured[k]);
  std::vector<double> sorted = magnitude;
  const std::size_t third = sorted.size() / 3;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(third),
                   sorted.end());
  const double low = sorted[third];
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(2 * third),
                   sorted.end());
  const double high = sorted[2 * third];
  double top = 0.0, bottom = 0.0;
  std::size_t n_top = 0, n_bottom = 0;
  for (std::size_t k = 0; k < magnitude.size(); ++k) {
    const double e = simulated[k] - measured[k];
    if (magnitude[k] >= high) {
      top += e * e;
      ++n_top;
    } else if (magnitude[k] <= low) {
      bottom += e * e;
      ++n_bottom;
    }
  }
  if (n_top == 0 || n_bottom == 0 || !(bottom > 0.0)) return 1.0;
  return std::sqrt((top / static_cast<double>(n_top)) / (bottom / static_cast<double>(n_bottom)));
}

}  // namespace ridefit::fitting::diagnose
