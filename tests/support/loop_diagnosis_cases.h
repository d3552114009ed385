#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ridefit/fitting/diagnose/diagnosis.h"
#include "ridefit/fitting/strut_parameters.h"
#include "support/passat.h"

namespace ridefit::testing {

// The Passat strut on the rig with Fc = 60 N and a 2.5 N load-cell offset: the truth most loop
// diagnosis tests hide effects from.
inline model::StrutTestParameters<double> passat_rig_strut() {
  auto strut = fitting::strut_on_rig(passat_corner().parameters);
  strut.coulomb_force_N = 60.0;
  strut.force_offset_N = 2.5;
  return strut;
}

// The loop diagnosis' baseline for `strut` with its levels as `strut` has them (for a test whose
// premise is levels known, such as a load-cell gain, which trades against them), its offset
// unknown (0).
inline fitting::diagnose::DiagnosisModel loop_baseline_with_known_levels(
    const model::StrutTestParameters<double>& strut) {
  fitting::diagnose::DiagnosisModel m;
  m.kind = fitting::diagnose::DataKind::kStrutLoops;
  m.strut = strut;
  m.strut.force_offset_N = 0.0;
  return m;
}

// The loop diagnosis' baseline for `strut` as a data sheet gives it: the levels the baseline fit
// frees off the truth (damping +35 %, Coulomb force +40 %), its offset unknown (0).
inline fitting::diagnose::DiagnosisModel loop_baseline(
    const model::StrutTestParameters<double>& strut) {
  fitting::diagnose::DiagnosisModel m = loop_baseline_with_known_levels(strut);
  m.strut.damping_Ns_per_m *= 1.35;
  m.strut.coulomb_force_N *= 1.4;
  return m;
}

// A parameter of the diagnosis' final fit (a test failure when it was not fitted).
inline double final_value(const fitting::diagnose::DiagnosisResult& r, const std::string& name) {
  for (const auto& v : r.final_parameters) {
    if (v.name == name) return v.value;
  }
  ADD_FAILURE() << name << " was not fitted";
  return NAN;
}

}  // namespace ridefit::testing
