#pragma once

#include "ridefit/fitting/diagnose/diagnosis.h"
#include "ridefit/fitting/diagnose/loop_diagnosis.h"
#include "ridefit/io/gnuplot_figure.h"

namespace ridefit::fitting::diagnose {

// The figure of a diagnosis on strut rig loops, for the first two judging records: the loops
// (force over displacement) before | after, and below them the force residual over velocity
// before | after, the loop-shape regions marked on each.
io::Figure loop_figure(const DiagnosisResult& result, const LoopDiagnosisData& data);

}  // namespace ridefit::fitting::diagnose
