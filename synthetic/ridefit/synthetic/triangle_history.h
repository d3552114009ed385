#pragma once

namespace ridefit::synthetic {

// A quasi-static triangle displacement 0 → A → 0 → −A → 0 at a constant stroke speed v (period
// 4A/v), as in seed 000's calibration test (Section 2.2: 3 mm at 1 mm/s, 12 s a cycle). Straight
// between corners: a fit should interpolate its samples linearly (a spline would overshoot).
class TriangleHistory {
 public:
  // InputError unless both are finite and > 0.
  TriangleHistory(double amplitude_m, double speed_m_per_s);

  double operator()(double time_s) const;
  double period_s() const { return period_s_; }

 private:
  double amplitude_m_;
  double period_s_;
};

}  // namespace ridefit::synthetic
