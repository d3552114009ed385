#pragma once

#include <Eigen/Core>
#include <complex>

#include "ridefit/simulate/linear_state_space.h"

namespace ridefit::simulate {

// H(jω) = C·(jωI − A)⁻¹·B + D of a linear system at any frequency, fast enough for a sweep: A
// is diagonalised once, A = V·Λ·V⁻¹, so that H(jω) = (C·V)·diag(1/(jω − λ_i))·(V⁻¹·B) + D costs
// O(n·inputs·outputs) per frequency. When V is ill-conditioned (a defective or nearly defective
// A, cond₁(V) estimated above
// 1e8) the eigenbasis would lose digits, and each frequency is solved directly with
// a partial-pivoting LU of (jωI − A) instead.
class FrequencyResponse {
 public:
  explicit FrequencyResponse(const LinearStateSpace& system);

  // outputs × inputs at `frequency_Hz`.
  Eigen::MatrixXcd at(double frequency_Hz) const;
  // H(jω)·u, the outputs' response to one combination `u` of the inputs (e.g. two wheels' road
  // inputs with the rear's delay): O(n·(inputs + outputs)) in the eigenbasis, no matrix product.
  Eigen::VectorXcd at(double frequency_Hz, const Eigen::VectorXcd& u) const;
  bool uses_eigenbasis() const { return eigenbasis_; }

 private:
  LinearStateSpace system_;
  bool eigenbasis_ = false;
  Eigen::VectorXcd eigenvalues_;
  Eigen::MatrixXcd output_modes_;  // C·V
  Eigen::MatrixXcd modal_inputs_;  // V⁻¹·B
};

}  // namespace ridefit::simulate
