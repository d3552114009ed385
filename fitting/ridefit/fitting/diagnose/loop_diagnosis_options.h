#pragma once

#include <string>
#include <vector>

#include "ridefit/fitting/diagnose/effect_selection.h"
#include "ridefit/fitting/diagnose/loop_disagreement.h"
#include "ridefit/simulate/strut_test_response.h"

namespace ridefit::fitting::diagnose {

// How a diagnosis of strut rig loops runs (loop_diagnosis.h). Plain fields with defaults, checked
// as a whole by validate().
struct LoopDiagnosisOptions {
  // The baseline's parameters every fit frees (fitting/strut_parameters.h names); empty = the
  // default: damping_Ns_per_m, force_offset_N (a load cell's zero is never known exactly), and
  // coulomb_force_N when the baseline has friction.
  std::vector<std::string> baseline_free;
  std::vector<std::string> effects;  // ids to try; empty = the whole library
  int max_iterations = 50;           // per fit
  simulate::StrutTestSolverOptions solver;
  LoopDisagreementOptions map;
  SelectionOptions selection;  // significance, rounds, threads (gap_unit and refine set here)
  // A region of the final map counts as unexplained when its mean residual is at least this
  // share of the measured force's RMS.
  double unexplained_share = 0.03;

  // InputError naming the option for: a baseline parameter that is not a strut parameter or is
  // given twice, an unknown effect id, a negative iteration limit, solver tolerances outside
  // (0, 0.1] or a step limit not > 0, bad map or selection options, a threshold not in (0, 1).
  // Called by diagnose_loops().
  void validate() const;
};

}  // namespace ridefit::fitting::diagnose
