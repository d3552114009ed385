#pragma once

#include <Eigen/Core>

#include <complex>
#include <string>
#include <vector>

namespace ridefit::simulate {

// A mechanical degree of freedom of a first-order model x' = A x: its name ("body",
// "wheel", "seat", …), its mass (or rotational inertia, kg·m²) and the state index of its
// position.
struct MechanicalDof {
  std::string name;
  double mass_kg = 0.0;
  int position_index = 0;
};

// An underdamped mode, from the eigenvalue pair λ, λ̄ of A (the one with Im λ > 0 is kept):
//   natural_frequency_Hz = |λ| / 2π
//   damped_frequency_Hz  = Im λ / 2π
//   damping_ratio        = −Re λ / |λ|   (negative for an unstable mode)
// For a second-order system λ = −ζωn ± iωn·sqrt(1 − ζ²), so these are the textbook ωn/2π,
// ωd/2π and ζ.
//
// energy_share[i] = m_i·|φ_i|² / Σ_j m_j·|φ_j|², with φ_i the eigenvector's component at DOF
// i's position. A mode's velocities are λ·φ, so this is each DOF's share of the mode's
// kinetic energy (the common factor |λ|² cancels). dominant_dof names the largest share.
// When the mode moves no listed position at all (e.g. a mode of internal states only) the
// shares are all 0 and dominant_dof is empty.
struct OscillatoryMode {
  std::complex<double> eigenvalue;  // 1/s
  double natural_frequency_Hz = 0.0;
  double damped_frequency_Hz = 0.0;
  double damping_ratio = 0.0;
  std::string dominant_dof;
  std::vector<double> energy_share;  // one per MechanicalDof, in the order given
};

// A real eigenvalue λ: a first-order (e.g. Maxwell element, friction state) or overdamped
// motion, x ∝ exp(λ t).
//   time_constant_s = −1/λ   (> 0 decays; < 0 grows; +∞ for λ = 0, a free rigid-body or
//                            integrating state)
// energy_share and dominant_dof as for OscillatoryMode (shares of m_i·φ_i²).
struct RealMode {
  double eigenvalue_per_s = 0.0;
  double time_constant_s = 0.0;
  std::string dominant_dof;
  std::vector<double> energy_share;
};

struct ModalAnalysis {
  std::vector<OscillatoryMode> oscillatory;  // by natural frequency, lowest first
  std::vector<RealMode> real;                // by |λ|, slowest first
};

// Eigen-decomposition of the state matrix A (n×n, x' = A x) with Eigen::EigenSolver.
// An eigenvalue counts as real when |Im λ| ≤ 1e-12·max(|λ|, ‖A‖) (the solver returns
// conjugate pairs for 2×2 Schur blocks, exact zeros for 1×1 blocks; the slack absorbs
// rounding around a critically damped pair).
//
// Throws InputError when A is empty, not square or not finite, or a DOF has an empty or
// repeated name, a mass that is not positive and finite, or a position index outside
// [0, n) or shared with another DOF. Throws RunError if the eigen solver fails.
ModalAnalysis analyse_modes(const Eigen::MatrixXd& state_matrix,
                            const std::vector<MechanicalDof>& dofs);

}  // namespace ridefit::simulate
