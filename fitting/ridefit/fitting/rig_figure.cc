#include "ridefit/fitting/rig_figure.h"

#include <algorithm>
#include <filesystem>

#include "ridefit/signal/periodicity.h"
#include "ridefit/signal/welch_psd.h"

namespace ridefit::fitting {

std::vector<io::PlotPanel> rig_record_panels(const HysteresisRecord& record,
                                             const std::vector<double>& model_force_N,
                                             const std::string& model_label) {
  const std::string name = std::filesystem::path(record.source).filename().string();
  const std::size_t n = std::min(record.time_s.size(), model_force_N.size());
  std::vector<io::PlotPanel> panels;
  if (n < 4) return panels;
  if (signal::looks_periodic(record.time_s, record.displacement_m)) {
    io::PlotPanel loop = io::xy_panel(name, "displacement [mm]", "force [N]");
    std::vector<double> x_mm;
    for (std::size_t k = 0; k < n; ++k) x_mm.push_back(1e3 * record.displacement_m[k]);
    loop.series.push_back({"measured", x_mm, record.force_N, {}, {}, io::SeriesStyle::kPoints});
    loop.series.push_back({model_label, x_mm, model_force_N, {}, {}, io::SeriesStyle::kLines});
    panels.push_back(std::move(loop));
    return panels;
  }
  // Force over velocity (central differences of the displacement).
  io::PlotPanel velocity =
      io::xy_panel(name + ": force over velocity", "velocity [mm/s]", "force [N]");
  std::vector<double> v_mm_s, measured, modelled;
  for (std::size_t k = 1; k + 1 < n; ++k) {
    v_mm_s.push_back(1e3 * (record.displacement_m[k + 1] - record.displacement_m[k - 1]) /
                     (record.time_s[k + 1] - record.time_s[k - 1]));
    measured.push_back(record.force_N[k]);
    modelled.push_back(model_force_N[k]);
  }
  velocity.series.push_back({"measured", v_mm_s, measured, {}, {}, io::SeriesStyle::kPoints});
  velocity.series.push_back({model_label, v_mm_s, modelled, {}, {}, io::SeriesStyle::kPoints});
  panels.push_back(std::move(velocity));
  // A time excerpt with the residual.
  const double duration = record.time_s[n - 1] - record.time_s[0];
  const double window = std::min(1.0, 0.2 * duration);
  const double middle = record.time_s[0] + 0.5 * duration;
  io::PlotPanel excerpt = io::time_panel(name + ": excerpt", "force [N]");
  std::vector<double> t, f_measured, f_model, residual;
  for (std::size_t k = 0; k < n; ++k) {
    if (std::abs(record.time_s[k] - middle) > 0.5 * window) continue;
    t.push_back(record.time_s[k]);
    f_measured.push_back(record.force_N[k]);
    f_model.push_back(model_force_N[k]);
    residual.push_back(model_force_N[k] - record.force_N[k]);
  }
  excerpt.series.push_back({"measured", t, f_measured, {}, {}, io::SeriesStyle::kLines});
  excerpt.series.push_back({model_label, t, f_model, {}, {}, io::SeriesStyle::kLines});
  excerpt.series.push_back({"residual", t, residual, {}, {}, io::SeriesStyle::kLines});
  panels.push_back(std::move(excerpt));
  // The residual's spectrum beside the force's.
  std::vector<double> all_residual(n);
  for (std::size_t k = 0; k < n; ++k) all_residual[k] = model_force_N[k] - record.force_N[k];
  const double rate = static_cast<double>(n - 1) / duration;
  signal::WelchOptions welch;
  welch.segment_length_s = std::min(1.0, 0.25 * duration);
  try {
    const auto force_psd =
        signal::welch_psd(std::span<const double>(record.force_N.data(), n), rate, welch);
    const auto residual_psd = signal::welch_psd(all_residual, rate, welch);
    io::PlotPanel spectrum = io::psd_panel(name + ": spectra", "PSD [N^2/Hz]");
    auto drop_dc = [](const std::vector<double>& v) {
      return std::vector<double>(v.begin() + 1, v.end());
    };
    spectrum.series.push_back({"measured force",
                               drop_dc(force_psd.frequency_Hz),
                               drop_dc(force_psd.psd),
                               {},
                               {},
                               io::SeriesStyle::kLines});
    spectrum.series.push_back({"residual",
                               drop_dc(residual_psd.frequency_Hz),
                               drop_dc(residual_psd.psd),
                               {},
                               {},
                               io::SeriesStyle::kLines});
    panels.push_back(std::move(spectrum));
  } catch (const std::exception&) {
    // Too short or non-uniform for a spectrum: the other panels stand.
  }
  return panels;
}

io::Figure rig_fit_figure(const std::vector<HysteresisRecord>& records,
                          const std::vector<std::vector<double>>& fitted_force_N) {
  io::Figure figure;
  figure.title = "measured and fitted rig force";
  for (std::size_t r = 0; r < records.size(); ++r) {
    for (auto& panel : rig_record_panels(records[r], fitted_force_N[r], "fitted")) {
      figure.panels.push_back(std::move(panel));
    }
  }
  return figure;
}

}  // namespace ridefit::fitting
