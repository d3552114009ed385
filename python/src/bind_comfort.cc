// ISO 2631-1: the frequency weightings (comfort/frequency_weighting.h, weighting_filter.h) and
// the metrics of a weighted acceleration (comfort/vibration_metrics.h).
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "bindings.h"
#include "numpy_arrays.h"
#include "ridefit/comfort/frequency_weighting.h"
#include "ridefit/comfort/vibration_metrics.h"
#include "ridefit/comfort/weighting_filter.h"

namespace ridefit::python {

namespace py = pybind11;

void bind_comfort(py::module_& m) {
  m.def(
      "weighting_magnitude",
      [](const std::string& weighting, const InputArray& frequency_Hz) {
        const comfort::Weighting w = comfort::parse_weighting(weighting);
        const auto f = as_span(frequency_Hz, "frequency_Hz");
        std::vector<double> magnitude(f.size());
        for (std::size_t i = 0; i < f.size(); ++i) {
          magnitude[i] = comfort::weighting_magnitude(w, f[i]);
        }
        return to_numpy(std::move(magnitude));
      },
      py::arg("weighting"), py::arg("frequency_Hz"),
      R"(|W(f)| of an ISO 2631-1 weighting ('Wk', 'Wd', 'Wf', 'Wc', 'We', 'Wj'), the analogue
filter of Annex A (Tables 3 and 4 tabulate it ×1000).)");
  m.def(
      "apply_weighting",
      [](const std::string& weighting, const InputArray& acceleration, double sample_rate_Hz) {
        const comfort::Weighting w = comfort::parse_weighting(weighting);
        const auto a = as_span(acceleration, "acceleration");
        std::vector<double> weighted;
        {
          py::gil_scoped_release unlocked;
          weighted = comfort::apply_weighting(w, a, sample_rate_Hz);
        }
        return to_numpy(std::move(weighted));
      },
      py::arg("weighting"), py::arg("acceleration"), py::arg("sample_rate_Hz"),
      R"(The weighted acceleration a_w (time domain, from rest); sample_rate_Hz at least
minimum_sample_rate_Hz(weighting).)");
  m.def(
      "minimum_sample_rate_Hz",
      [](const std::string& weighting) {
        return comfort::minimum_sample_rate_Hz(comfort::parse_weighting(weighting));
      },
      py::arg("weighting"), "The lowest sample rate apply_weighting accepts (5·f2)");
  m.def(
      "vibration_metrics",
      [](const InputArray& weighted, double sample_rate_Hz, double integration_time_s) {
        const auto a = as_span(weighted, "weighted");
        comfort::VibrationMetrics v;
        {
          py::gil_scoped_release unlocked;
          v = comfort::vibration_metrics(a, sample_rate_Hz, integration_time_s);
        }
        py::dict out;
        out["duration_s"] = v.duration_s;
        out["weighted_rms_m_per_s2"] = v.weighted_rms_m_per_s2;
        out["peak_m_per_s2"] = v.peak_m_per_s2;
        out["crest_factor"] = v.crest_factor;
        out["mtvv_m_per_s2"] = v.mtvv_m_per_s2;
        out["vdv_m_per_s1_75"] = v.vdv_m_per_s1_75;
        out["integration_time_s"] = v.integration_time_s;
        return out;
      },
      py::arg("weighted"), py::arg("sample_rate_Hz"), py::arg("integration_time_s") = 1.0,
      R"(ISO 2631-1 clause 6 values of an already weighted acceleration: weighted RMS, peak,
crest factor, MTVV (running RMS over integration_time_s) and VDV.)");
  m.def(
      "running_rms",
      [](const InputArray& weighted, double sample_rate_Hz, double integration_time_s) {
        return to_numpy(comfort::running_rms(as_span(weighted, "weighted"), sample_rate_Hz,
                                             integration_time_s));
      },
      py::arg("weighted"), py::arg("sample_rate_Hz"), py::arg("integration_time_s") = 1.0,
      "Running RMS (linear integration over the last integration_time_s), eq. (2)");
}

}  // namespace ridefit::python
