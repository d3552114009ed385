#pragma once

namespace ridefit::simulate {

// ESDIRK3(2)4L[2]SA (Kennedy & Carpenter, NASA/TM-2016-219173, Table 16): four stages, the
// first explicit, three implicit stages sharing the diagonal γ; third order, an embedded
// second-order solution for the error estimate; L-stable and stiffly accurate (the last stage
// is the solution, so stiff components are damped exactly as backward Euler would, at any
// step), stage order 2. The numbers are SUNDIALS' table ARKODE_ESDIRK324L2SA_4_2_3 to the last
// digit (a test compares them).
//
// Why this pair: the models carry a stiff element (Dahl's σ0 beside the damper: c/σ0 is well
// below a millisecond) next to body and wheel modes that need accuracy, so the method must be
// L-stable and stiffly accurate. Their inputs are C2 at best (cubic splines of sampled roads) and
// the Dahl law has a kink at every reversal, so an order above three buys little; three
// implicit stages of one LU each keep a step cheap.
struct EsdirkTableau {
  static constexpr int kStages = 4;
  static constexpr int kOrder = 3;
  static constexpr int kEmbeddedOrder = 2;
  static constexpr double kGamma = 0.435866521508459;
  static constexpr double c[kStages] = {0.0, 0.87173304301691801, 0.59999999999999998, 1.0};
  static constexpr double a[kStages][kStages] = {
      {0.0, 0.0, 0.0, 0.0},
      {0.435866521508459, 0.435866521508459, 0.0, 0.0},
      {0.25764824606642722, -0.093514767574886248, 0.435866521508459, 0.0},
      {0.18764102434672381, -0.59529747357695484, 0.9717899277217722, 0.435866521508459}};
  // b = the last row of a (stiffly accurate); the embedded weights:
  static constexpr double b_embedded[kStages] = {0.10889661761586122, -0.91532581187071183,
                                                 1.2712735973021543, 0.53515559695269621};
};

}  // namespace ridefit::simulate
