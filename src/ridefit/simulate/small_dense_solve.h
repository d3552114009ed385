#pragma once

#include <Eigen/Core>
#include <cmath>
#include <utility>

namespace ridefit::simulate {

// Small dense solves for the tangent replay's G = I − γh·J (2–6 states, up to 24), written out
// because Eigen's general paths (PartialPivLU's inverse, dynamic-size blocking) cost more in
// dispatch than in arithmetic at these sizes.

// Solves a·x = b in place (b becomes x) by Gaussian elimination with partial pivoting on a copy
// of `a`. b's entries may be any scalar that a double multiplies (ceres::Jet, AutoDiffScalar):
// the elimination is done in doubles and applied to b, n³/3 + n² operations, where forming the
// inverse first (n³) and multiplying (n² in T) cost three times as much. False when a pivot is
// zero or not finite.
template <typename Matrix, typename T>
bool small_solve(Matrix a, T* b) {
  const Eigen::Index n = a.rows();
  for (Eigen::Index col = 0; col < n; ++col) {
    Eigen::Index pivot = col;
    double largest = std::abs(a(col, col));
    for (Eigen::Index r = col + 1; r < n; ++r) {
      if (std::abs(a(r, col)) > largest) {
        largest = std::abs(a(r, col));
        pivot = r;
      }
    }
    if (!(largest > 0.0) || !std::isfinite(largest)) return false;
    if (pivot != col) {
      for (Eigen::Index c = col; c < n; ++c) std::swap(a(col, c), a(pivot, c));
      std::swap(b[col], b[pivot]);
    }
    for (Eigen::Index r = col + 1; r < n; ++r) {
      const double factor = a(r, col) / a(col, col);
      if (factor == 0.0) continue;
      for (Eigen::Index c = col + 1; c < n; ++c) a(r, c) -= factor * a(col, c);
      b[r] -= factor * b[col];
    }
  }
  for (Eigen::Index r = n - 1; r >= 0; --r) {
    for (Eigen::Index c = r + 1; c < n; ++c) b[r] -= a(r, c) * b[c];
    b[r] /= a(r, r);
  }
  return true;
}

}  // namespace ridefit::simulate
