#pragma once

#include <string>
#include <vector>

#include "ridefit/fitting/hysteresis_record.h"
#include "ridefit/io/gnuplot_figure.h"

namespace ridefit::fitting {

// The panels that show a rig record against a model's force. A periodic test
// (signal::looks_periodic) gets its force-displacement loop. A random test, whose loop is an
// unreadable cloud, gets instead: force over velocity (measured and model as points), a time
// excerpt (about 1 s from the middle, at most a fifth of the record) of the measured and model
// force with their residual, and the residual's spectrum beside the measured force's (Welch,
// 1 s Hann segments or a quarter of the record). `model_label` names the model's curves
// ("fitted", "baseline", …).
std::vector<io::PlotPanel> rig_record_panels(const HysteresisRecord& record,
                                             const std::vector<double>& model_force_N,
                                             const std::string& model_label);

// The figure of a hysteresis fit: every record's panels against its fitted force.
io::Figure rig_fit_figure(const std::vector<HysteresisRecord>& records,
                          const std::vector<std::vector<double>>& fitted_force_N);

}  // namespace ridefit::fitting
