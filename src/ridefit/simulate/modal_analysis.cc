#include "ridefit/simulate/modal_analysis.h"

#include <fmt/format.h>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>

#include "ridefit/common/errors.h"

namespace ridefit::simulate {
namespace {

void validate(const Eigen::MatrixXd& a, const std::vector<MechanicalDof>& dofs) {
  if (a.rows() == 0 || a.rows() != a.cols()) {
    throw InputError(
        fmt::format("modal analysis: the state matrix is {}×{}; it must be square and non-empty",
                    a.rows(), a.cols()));
  }
  if (!a.allFinite()) {
    throw InputError(
        "modal analysis: the state matrix has a non-finite entry; every entry must be finite");
  }
  std::set<std::string> names;
  std::set<int> indices;
  for (const MechanicalDof& dof : dofs) {
    if (dof.name.empty()) {
      throw InputError("modal analysis: a degree of freedom has an empty name; name each one");
    }
    if (!names.insert(dof.name).second) {
      throw InputError(fmt::format(
          "modal analysis: degree of freedom '{}' is listed twice; names must be unique",
          dof.name));
    }
    if (!std::isfinite(dof.mass_kg) || dof.mass_kg <= 0.0) {
      throw InputError(fmt::format(
          "modal analysis: degree of freedom '{}' has mass {} kg; it must be positive and "
          "finite",
          dof.name, dof.mass_kg));
    }
    if (dof.position_index < 0 || dof.position_index >= a.rows()) {
      throw InputError(fmt::format(
          "modal analysis: degree of freedom '{}' has position index {}; it must be a state "
          "index in [0, {})",
          dof.name, dof.position_index, a.rows()));
    }
    if (!indices.insert(dof.position_index).second) {
      throw InputError(fmt::format(
          "modal analysis: degree of freedom '{}' shares position index {} with another; "
          "each DOF needs its own position state",
          dof.name, dof.position_index));
    }
  }
}

// Kinetic-energy shares of the DOFs in an eigenvector, and the dominant DOF's name.
void energy_shares(const Eigen::VectorXcd& shape, const std::vector<MechanicalDof>& dofs,
                   std::vector<double>& shares, std::string& dominant) {
  shares.assign(dofs.size(), 0.0);
  double total = 0.0;
  for (std::size_t i = 0; i < dofs.size(); ++i) {
    shares[i] = dofs[i].mass_kg * std::norm(shape(dofs[i].position_index));
    total += shares[i];
  }
  dominant.clear();
  if (!(total > 0.0)) {
    std::fill(shares.begin(), shares.end(), 0.0);
    return;
  }
  std::size_t best = 0;
  for (std::size_t i = 0; i < dofs.size(); ++i) {
    shares[i] /= total;
    if (shares[i] > shares[best]) best = i;
  }
  dominant = dofs[best].name;
}

}  // namespace

ModalAnalysis analyse_modes(const Eigen::MatrixXd& state_matrix,
                            const std::vector<MechanicalDof>& dofs) {
  validate(state_matrix, dofs);
  Eigen::EigenSolver<Eigen::MatrixXd> solver(state_matrix, /*computeEigenvectors=*/true);
  if (solver.info() != Eigen::Success) {
    throw RunError(
        fmt::format("modal analysis: the eigen solver did not converge for the {}×{} state matrix",
                    state_matrix.rows(), state_matrix.cols()));
  }
  const Eigen::VectorXcd eigenvalues = solver.eigenvalues();
  const Eigen::MatrixXcd eigenvectors = solver.eigenvectors();
  const double matrix_scale = state_matrix.cwiseAbs().rowwise().sum().maxCoeff();

  ModalAnalysis result;
  for (Eigen::Index j = 0; j < eigenvalues.size(); ++j) {
    const std::complex<double> lambda = eigenvalues(j);
    const double magnitude = std::abs(lambda);
    const bool is_real = std::abs(lambda.imag()) <= 1e-12 * std::max(magnitude, matrix_scale);
    if (is_real) {
      RealMode mode;
      mode.eigenvalue_per_s = lambda.real();
      mode.time_constant_s =
          lambda.real() == 0.0 ? std::numeric_limits<double>::infinity() : -1.0 / lambda.real();
      energy_shares(eigenvectors.col(j), dofs, mode.energy_share, mode.dominant_dof);
      result.real.push_back(std::move(mode));
    } else if (lambda.imag() > 0.0) {
      OscillatoryMode mode;
      mode.eigenvalue = lambda;
      mode.natural_frequency_Hz = magnitude / (2.0 * std::numbers::pi);
      mode.damped_frequency_Hz = lambda.imag() / (2.0 * std::numbers::pi);
      mode.damping_ratio = -lambda.real() / magnitude;
      energy_shares(eigenvectors.col(j), dofs, mode.energy_share, mode.dominant_dof);
      result.oscillatory.push_back(std::move(mode));
    }
  }
  std::sort(result.oscillatory.begin(), result.oscillatory.end(),
            [](const OscillatoryMode& a, const OscillatoryMode& b) {
              return a.natural_frequency_Hz < b.natural_frequency_Hz;
            });
  std::sort(result.real.begin(), result.real.end(), [](const RealMode& a, const RealMode& b) {
    return std::abs(a.eigenvalue_per_s) < std::abs(b.eigenvalue_per_s);
  });
  return result;
}

}  // namespace ridefit::simulate
