#pragma once

#include <optional>
#include <string>

namespace ridefit::road {

// Road elevation under one tyre and its rate, at a time.
// A record may also carry the command of a controlled damper (its coil current in A or valve
// voltage in V), which a car that follows it reads here; 0 where there is none.
struct RoadSample {
  double elevation_m = 0.0;
  double rate_m_per_s = 0.0;
  double command = 0.0;
};

// The road as one tyre sees it over time: h(t) and dh/dt, continuous in both, so that an
// adaptive integrator sees a smooth enough input (each implementation documents how).
class RoadInput {
 public:
  virtual ~RoadInput() = default;
  virtual RoadSample at(double time_s) const = 0;
  // The length of the excitation; simulations run from 0 to this time by default.
  virtual double duration_s() const = 0;
  // The longest step an adaptive integrator may take without stepping over a feature of
  // this road (an adaptive solver on a flat stretch would otherwise leap over a cleat):
  // the sample interval of a sampled road, a fraction of the shortest period of an
  // analytic one.
  virtual double max_step_s() const = 0;
  // The driving speed of a road driven over a profile; empty for roads given over time (a
  // sweep on a rig, a measured record), where a rear wheel's delay must come from elsewhere.
  virtual std::optional<double> speed_m_per_s() const { return std::nullopt; }
  // True when the samples carry a damper command (a measured record with a current or voltage
  // column).
  virtual bool has_command() const { return false; }
  // The command's unit, "A" or "V" ("" without a command).
  virtual std::string command_unit() const { return ""; }
};

}  // namespace ridefit::road
