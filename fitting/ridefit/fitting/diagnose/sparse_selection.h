#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

namespace ridefit::fitting::diagnose {

// Forward selection of a few columns of a basis that explain a target, judged on rows no fit saw:
// the core of a residual's shape in named terms (residual_shape.h for rig loops,
// spectral_shape.h for vehicle spectra).
//
// Each round fits every remaining column with the ones already kept to the training rows (least
// squares) and keeps the one that lowers the judging rows' sum of squares most, when it lowers it
// by at least min_share of where it started and its coefficient lies min_z standard errors from 0
// (widened by √τ, the training residual's correlation time over each part: residuals of a record
// or a spectrum are far from white). Columns that stand for each other enter one at a time, so
// the first names the shape best. The kept columns are then fitted on every row for their
// coefficients and standard errors.

// Rows of a basis and its target, in consecutive parts (records, channels) of `lengths`.
struct SelectionRows {
  Eigen::MatrixXd basis;
  Eigen::VectorXd target;
  std::vector<std::size_t> lengths;
};

struct SparseSelectionOptions {
  int max_terms = 3;
  double min_share = 0.05;
  double min_z = 4.0;

  // InputError naming the option: max_terms below 1, min_share outside (0, 1), min_z not a
  // finite value above 0.
  void validate() const;
};

struct SelectedColumn {
  int column = 0;
  double judged_share = 0.0;  // of the judging rows' sum of squares, removed as it entered
  double coefficient = 0.0;   // in the column's own units, from every row
  double standard_error = 0.0;
};

struct SparseSelection {
  std::vector<SelectedColumn> columns;  // in the order they entered
  double judged_share = 0.0;            // what they remove together on the judging rows
};

// The selection; columns that are zero on the training rows cannot enter. Empty when nothing
// passes, or when a side has fewer rows than 10. The coefficients are fitted on `all` when given
// (every row in its own order, where training and judging rows interleave, as a spectrum's even
// and odd bins do: its correlation time is measured along that order), else on the training rows
// followed by the judging rows.
SparseSelection select_columns(const SelectionRows& training, const SelectionRows& judging,
                               const SparseSelectionOptions& options,
                               const SelectionRows* all = nullptr);

}  // namespace ridefit::fitting::diagnose
