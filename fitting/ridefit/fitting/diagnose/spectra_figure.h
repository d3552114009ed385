#pragma once

#include "ridefit/fitting/diagnose/diagnosis.h"
#include "ridefit/io/gnuplot_figure.h"

namespace ridefit::fitting::diagnose {

// The figure of a diagnosis on vehicle spectra: per channel, a row of two panels, before | after,
// each the measured PSD of the held-out record with its confidence interval against the
// simulated one, the disagreement regions marked on the simulated curve.
io::Figure spectra_figure(const DiagnosisResult& result);

}  // namespace ridefit::fitting::diagnose
