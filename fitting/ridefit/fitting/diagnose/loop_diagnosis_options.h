#pragma once

#include <map>
#include <string>
#include <vector>

#include "ridefit/fitting/diagnose/effect_selection.h"
#include "ridefit/fitting/diagnose/loop_disagreement.h"
#include "ridefit/simulate/strut_test_response.h"

namespace ridefit::fitting::diagnose {

// The uncertainty of a strut's data sheet, as a share of each value (one standard deviation):
// damping 12 %, top mount 15 %, Coulomb force 25 %, pre-sliding stiffness σ0 100 % (a sheet gives
// it to a factor of two at best, when it gives it at all).
std::map<std::string, double> strut_datasheet_tolerances();

// How a diagnosis of strut rig loops runs (loop_diagnosis.h). Plain fields with defaults, checked
// as a whole by validate().
struct LoopDiagnosisOptions {
  // The baseline's parameters every fit frees (fitting/strut_parameters.h names); empty = the
  // default: damping_Ns_per_m, force_offset_N (a load cell's zero is never known exactly), and
  // coulomb_force_N when the baseline has friction.
  std::vector<std::string> baseline_free;
  // The baseline's values an engineer is unsure of, each with the share of its value that is one
  // standard deviation of the sheet's uncertainty. Every fit, the baseline's and each effect's,
  // frees them too, within three of those of the sheet's value, symmetric in log:
  // [v/(1 + 3t), v·(1 + 3t)]. Dynamic loops determine the strut's σ0 and top mount well; held
  // wrong, the load cell's gain took their error up (a sheet 15 % soft on the mount and 2× on σ0:
  // a gain named on a record with nothing hidden). A value that is off (no friction, a rigid
  // mount at 1e9 N/m or more) is left out, and so is one `baseline_free` names (free within the
  // fit's own bounds). The default is strut_datasheet_tolerances(); empty:
  // the baseline's values are held but for those of `baseline_free` (levels known, as for a
  // calibrated strut: only then can a load cell's gain be told from them).
  std::map<std::string, double> baseline_tolerances = strut_datasheet_tolerances();
  std::vector<std::string> effects;  // ids to try; empty = the whole library
  int max_iterations = 50;           // per fit
  simulate::StrutTestSolverOptions solver;
  LoopDisagreementOptions map;
  SelectionOptions selection;  // significance, rounds, threads (gap_unit and refine set here)
  // A region of the final map counts as unexplained when its mean residual is at least this
  // share of the measured force's RMS.
  double unexplained_share = 0.03;

  // InputError naming the option for: a baseline parameter that is not a strut parameter or is
  // given twice, a tolerance of an unknown parameter or not in (0, 10], an unknown effect id, a
  // negative iteration limit, solver tolerances outside (0, 0.1] or a step limit not > 0, bad map
  // or selection options, a threshold not in (0, 1). Called by diagnose_loops().
  void validate() const;
};

}  // namespace ridefit::fitting::diagnose
