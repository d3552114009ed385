#pragma once

#include <string>
#include <vector>

#include "ridefit/fitting/diagnose/sparse_selection.h"

namespace ridefit::fitting::diagnose {

// What a disagreement looks like that no effect of the library explains: the force the model
// lacks on the rig (measured − simulated) regressed on a small basis of physically named terms of
// the rig's travel, velocity and acceleration and of the model's own force (a stiffness, a
// progressive spring or an even force in travel, a stop beyond part of the stroke, damping that
// grows or flattens with speed or differs between compression and rebound, a friction level, a
// mass, a gain). A suggestion for a new effect in words, never a named library effect.
//
// The terms are chosen by forward selection fitted on the training records and judged on the
// held-out ones (sparse_selection.h), each record's mean removed (a load-cell offset is no shape).

// One record's samples (all of one length).
struct ShapeSamples {
  std::vector<double> displacement_m;
  std::vector<double> velocity_m_per_s;
  std::vector<double> acceleration_m_per_s2;
  std::vector<double> model_force_N;    // the model's force, as the load cell would read it
  std::vector<double> missing_force_N;  // measured − simulated
};

struct ShapeTerm {
  std::string id;     // "travel_squared", ...
  std::string words;  // what the term says, for its sign: "a force of one sign growing with …"
  std::string unit;   // of the coefficient
  double coefficient = 0.0;     // fitted on the training and judging records together
  double standard_error = 0.0;  // widened by the residual's correlation time
  // Of the judging records' missing force's sum of squares, the share the term removed as it
  // entered (fitted on the training records).
  double judged_share = 0.0;
};

struct ResidualShape {
  std::vector<ShapeTerm> terms;  // in the order they entered; none: the basis says nothing
  double judged_share = 0.0;     // what the terms remove together on the judging records
  // The judging records' missing force's sum of squares that judged_share is a share of (each
  // record's mean removed) [N²].
  double judged_sum_of_squares_N2 = 0.0;
  // Travel terms are taken about the training records' mid-stroke, over their half stroke.
  double travel_centre_m = 0.0;
  double half_stroke_m = 0.0;
  SparseSelectionOptions options;  // the thresholds the terms passed
};

// The shape of `training`'s and `judging`'s missing force. InputError for bad options, no
// records on either side, or a record whose columns differ in length or hold fewer than 10 samples.
// Samples that are not finite are left out.
ResidualShape residual_shape(const std::vector<ShapeSamples>& training,
                             const std::vector<ShapeSamples>& judging,
                             const SparseSelectionOptions& options = {});

// A term's coefficient and standard error as an engineer reads them: "+4.02 ± 0.05 N/mm²".
std::string coefficient_text(const ShapeTerm& term);

// The terms in words with their coefficients, "; " between them ("" for none): "an even force: a
// tension growing with the square of travel either way (…) (+4.02 ± 0.05 N/mm², 91 % of the
// judged residual)".
std::string describe(const ResidualShape& shape);

}  // namespace ridefit::fitting::diagnose
