// welch_psd: Welch's PSD with its χ² confidence interval (signal/welch_psd.h, psd_confidence.h),
// as `ridefit analyse --psd` computes a channel's spectrum.
#include <pybind11/stl.h>

#include <fmt/core.h>

#include <string>

#include "bindings.h"
#include "numpy_arrays.h"
#include "ridefit/common/errors.h"
#include "ridefit/signal/detrend.h"
#include "ridefit/signal/psd_confidence.h"
#include "ridefit/signal/psd_smoothing.h"
#include "ridefit/signal/welch_psd.h"

namespace ridefit::python {

namespace py = pybind11;

namespace {

py::dict welch(const InputArray& signal_array, double sample_rate_Hz, double segment_s,
               std::size_t segment_samples, double overlap, const std::string& detrend,
               std::size_t smooth_bins, double confidence) {
  const auto samples = as_span(signal_array, "signal");
  signal::WelchOptions options;
  options.segment_length_s = segment_s;
  options.segment_length_samples = segment_samples;
  options.overlap_fraction = overlap;
  options.detrend = signal::parse_detrend(detrend);
  if (smooth_bins < 1 || smooth_bins % 2 == 0) {
    throw InputError(
        fmt::format("smooth_bins {}: expected an odd number of bins >= 1", smooth_bins));
  }
  signal::PowerSpectralDensity psd;
  signal::PsdConfidenceInterval interval;
  {
    py::gil_scoped_release unlocked;
    psd = signal::welch_psd(samples, sample_rate_Hz, options);
    if (smooth_bins > 1) psd = signal::smooth_psd(psd, smooth_bins);
    interval = signal::psd_confidence_interval(psd, confidence);
  }
  py::dict out;
  out["frequency_Hz"] = to_numpy(std::move(psd.frequency_Hz));
  out["psd"] = to_numpy(std::move(psd.psd));
  out["lower"] = to_numpy(std::move(interval.lower));
  out["upper"] = to_numpy(std::move(interval.upper));
  out["degrees_of_freedom"] = to_numpy(std::move(psd.degrees_of_freedom));
  out["confidence"] = interval.confidence;
  out["sample_rate_Hz"] = psd.sample_rate_Hz;
  out["frequency_resolution_Hz"] = psd.frequency_resolution_Hz;
  out["segment_length_samples"] = psd.segment_length_samples;
  out["segment_count"] = psd.segment_count;
  out["hop_samples"] = psd.hop_samples;
  out["smoothing_bins"] = psd.smoothing_bins;
  return out;
}

}  // namespace

void bind_signal(py::module_& m) {
  m.def("welch_psd", &welch, py::arg("signal"), py::arg("sample_rate_Hz"),
        py::arg("segment_s") = 0.0, py::arg("segment_samples") = 0, py::arg("overlap") = 0.5,
        py::arg("detrend") = "mean", py::arg("smooth_bins") = 1, py::arg("confidence") = 0.9,
        R"(One-sided Welch PSD of a uniformly sampled signal with its χ² confidence interval.

Periodic Hann window; segment length from segment_s or segment_samples (at most one; neither:
8 segments, MATLAB pwelch's default); overlap in [0, 1); detrend 'none', 'mean' or 'linear';
smooth_bins an odd centred moving average (1 = off); confidence in (0, 1).
Returns {'frequency_Hz', 'psd' ([unit]^2/Hz), 'lower', 'upper', 'degrees_of_freedom',
'confidence', 'sample_rate_Hz', 'frequency_resolution_Hz', 'segment_length_samples',
'segment_count', 'hop_samples', 'smoothing_bins'}; the arrays are float64.)");
}

}  // namespace ridefit::python
