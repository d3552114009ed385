#pragma once

#include <string>
#include <vector>

#include "ridefit/fitting/hysteresis_record.h"

namespace ridefit::fitting::diagnose {

// Where a strut model's loops and the rig's disagree: the loop-shape counterpart of the spectral
// disagreement map (disagreement_map.h). Residual = simulated − measured force.

struct LoopDisagreementOptions {
  int bins = 12;  // quantile bins of velocity and of displacement per record (half each side of 0)
  // A region must also move the force by at least this share of the measured force's RMS
  // (about its mean) on average.
  double min_region_share = 0.02;
  double significance_sigmas = 3.0;  // |mean residual| of a bin against its standard error

  // InputError naming the option for: fewer than 2 bins, a share outside [0, 1), sigmas not > 0.
  void validate() const;
};

// A run of adjacent velocity or displacement bins whose mean residual has the same sign and is
// significant in each: e.g. the model's force too low just after reversals (small |velocity|)
// or too low in compression (negative displacement).
struct LoopRegion {
  std::string record;
  std::string quantity;  // "velocity" (m/s) or "displacement" (m)
  double low = 0.0;
  double high = 0.0;
  double mean_residual_N = 0.0;  // simulated − measured, over the region's samples
  double share = 0.0;            // mean_residual_N over the measured force's RMS about its mean
};

struct LoopRecordDisagreement {
  std::string record;
  double nrmse_percent = 0.0;  // 100·RMS(residual)/RMS(measured − its mean)
  double residual_rms_N = 0.0;
  double residual_max_autocorrelation = 0.0;
  double residual_whiteness_p = 0.0;  // residual_statistics.h
  double amplitude_dependence = 0.0;  // of the force (residual_statistics.h)
};

struct LoopDisagreementMap {
  std::vector<LoopRecordDisagreement> records;
  std::vector<LoopRegion> regions;
  // The loop gap: NRMSE in % over all records, 100·sqrt(Σ residual² / Σ (measured − record
  // mean)²); 0 when simulation and measurement agree exactly.
  double gap_percent = 0.0;
};

// The rig's velocity, m/s: its measured velocity where the record has one, else central
// differences of the displacement (one-sided at the ends).
std::vector<double> rig_velocity_m_per_s(const HysteresisRecord& record);

// The loop gap alone (LoopDisagreementMap::gap_percent), without the map's regions: what the
// selection scores every trial with. Same preconditions as map_loop_disagreement.
double force_nrmse_percent(const std::vector<HysteresisRecord>& records,
                           const std::vector<std::vector<double>>& simulated_force_N);

// The map of each record's measured force against `simulated_force_N` (one per record, same
// length). InputError when counts or lengths differ or a simulated value is not finite.
LoopDisagreementMap map_loop_disagreement(const std::vector<HysteresisRecord>& records,
                                          const std::vector<std::vector<double>>& simulated_force_N,
                                          const LoopDisagreementOptions& options = {});

}  // namespace ridefit::fitting::diagnose
