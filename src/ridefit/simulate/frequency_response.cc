#include "ridefit/simulate/frequency_response.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <numbers>
#include <stdexcept>

namespace ridefit::simulate {

FrequencyResponse::FrequencyResponse(const LinearStateSpace& system) : system_(system) {
  const auto n = system.A.rows();
  if (system.A.cols() != n || system.B.rows() != n || system.C.cols() != n ||
      system.D.rows() != system.C.rows() || system.D.cols() != system.B.cols()) {
    throw std::invalid_argument("FrequencyResponse: A, B, C, D have inconsistent sizes");
  }
  const Eigen::EigenSolver<Eigen::MatrixXd> eigen(system.A);
  if (eigen.info() != Eigen::Success) return;  // the LU path still works
  const Eigen::MatrixXcd v = eigen.eigenvectors();
  // An estimate of 1/cond₁(V) from the LU the modal inputs need anyway (an SVD of V for the
  // 2-norm condition took about 8 % of a half car's frequency-domain evaluation).
  const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(v);
  const double rcond = lu.rcond();
  if (!(rcond > 1e-8)) return;
  eigenvalues_ = eigen.eigenvalues();
  output_modes_ = system.C.cast<std::complex<double>>() * v;
  modal_inputs_ = lu.solve(system.B.cast<std::complex<double>>());
  eigenbasis_ = true;
}

Eigen::MatrixXcd FrequencyResponse::at(double frequency_Hz) const {
  const std::complex<double> s(0.0, 2.0 * std::numbers::pi * frequency_Hz);
  if (eigenbasis_) {
    const Eigen::VectorXcd resolvent = (s - eigenvalues_.array()).inverse().matrix();
    return output_modes_ * resolvent.asDiagonal() * modal_inputs_ +
           system_.D.cast<std::complex<double>>();
  }
  const auto n = system_.A.rows();
  const Eigen::MatrixXcd shifted =
      s * Eigen::MatrixXcd::Identity(n, n) - system_.A.cast<std::complex<double>>();
  return system_.C.cast<std::complex<double>>() *
             shifted.partialPivLu().solve(system_.B.cast<std::complex<double>>()) +
         system_.D.cast<std::complex<double>>();
}

Eigen::VectorXcd FrequencyResponse::at(double frequency_Hz, const Eigen::VectorXcd& u) const {
  if (u.size() != system_.B.cols()) {
    throw std::invalid_argument("FrequencyResponse::at: u needs one entry per input");
  }
  const std::complex<double> s(0.0, 2.0 * std::numbers::pi * frequency_Hz);
  if (eigenbasis_) {
    const Eigen::VectorXcd modal =
        (modal_inputs_ * u).cwiseQuotient((s - eigenvalues_.array()).matrix());
    return output_modes_ * modal + system_.D.cast<std::complex<double>>() * u;
  }
  const auto n = system_.A.rows();
  const Eigen::MatrixXcd shifted =
      s * Eigen::MatrixXcd::Identity(n, n) - system_.A.cast<std::complex<double>>();
  return system_.C.cast<std::complex<double>>() *
             shifted.partialPivLu().solve(system_.B.cast<std::complex<double>>() * u) +
         system_.D.cast<std::complex<double>>() * u;
}

}  // namespace ridefit::simulate
