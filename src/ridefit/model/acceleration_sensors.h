#pragma once

namespace ridefit::model {

// The accelerometers' measuring chain of a vehicle record: what the sensors make of the true
// body and wheel accelerations. Not physics (the quarter car's motion never depends on it): the
// spectral comparisons (fitting/psd_fit.h, the diagnosis' disagreement map) show the simulated
// PSD of a channel as the sensor would,
//   P_shown(f) = g²·|H(f)|²·P_sim(f)  (+ the channel's white noise floor N),
// with g the channel's gain (calibration, amplifier) and H a low-pass shared by both channels
// (an anti-alias filter, the sensor's own band):
//   |H(f)|² = (1 + (f/f_c)²)^(−n),   n = 1: first order; n = 2: two first-order stages in series
//   (critically damped second order); f_c = 0: none.
// A delay cannot be part of it: |e^(−iωτ)| = 1, an auto-spectrum does not change (it needs a
// comparison in time or a cross-spectrum with the road).
//
// Templated like QuarterCarParameters, so a PSD fit frees the gains and the cutoff as Jets.
template <typename T>
struct AccelerationSensors {
  T body_acc_gain{1.0};         // measured body_acc over true, dimensionless (1 = ideal)
  T wheel_acc_gain{1.0};        // measured wheel_acc over true
  T acc_sensor_cutoff_Hz{0.0};  // f_c of the low-pass [Hz]; 0 = none
  int acc_sensor_order = 1;     // n: 1 or 2

  template <typename U>
  AccelerationSensors<U> cast() const {
    return {U(body_acc_gain), U(wheel_acc_gain), U(acc_sensor_cutoff_Hz), acc_sensor_order};
  }

  // |H(f)|² of the low-pass (1 without one).
  T low_pass_power(double frequency_Hz) const {
    if (!(acc_sensor_cutoff_Hz > 0.0)) return T(1.0);
    const T x = frequency_Hz / acc_sensor_cutoff_Hz;
    const T stage = T(1.0) / (T(1.0) + x * x);
    return acc_sensor_order == 2 ? stage * stage : stage;
  }
  // g²·|H(f)|²: the factor on each channel's simulated PSD.
  T body_power_gain(double frequency_Hz) const {
    return body_acc_gain * body_acc_gain * low_pass_power(frequency_Hz);
  }
  T wheel_power_gain(double frequency_Hz) const {
    return wheel_acc_gain * wheel_acc_gain * low_pass_power(frequency_Hz);
  }
  // True when the chain changes nothing (every gain 1, no low-pass).
  bool ideal() const {
    return body_acc_gain == 1.0 && wheel_acc_gain == 1.0 && !(acc_sensor_cutoff_Hz > 0.0);
  }
};

}  // namespace ridefit::model
