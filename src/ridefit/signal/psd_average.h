#pragma once

#include <span>
#include <string>

#include "ridefit/signal/welch_psd.h"

namespace ridefit::signal {

// Bartlett-style average of the PSDs of repeated runs (seed 000, §4.2: "the PSDs of single
// repetitions per configuration are averaged to reduce variance"). The records are independent,
// so the degrees of freedom add: ν[k] = Σ_r ν_r[k]. Each bin is the ν-weighted mean
//   P[k] = Σ_r ν_r[k]·P_r[k] / Σ_r ν_r[k],
// the minimum-variance combination, which makes the sum rule exact; for records of equal length
// (equal ν) it is the plain mean. segment_count becomes the total number of segments; the other
// fields are those of the first record.
//
// `names` (empty, or one per spectrum, e.g. the file names) label the records in messages;
// without them a record is "spectrum i" (0-based).
//
// Throws InputError for no spectra, a names list of the wrong length, a record without the
// statistics (see check_psd_statistics), or a record whose sample rate (relative tolerance
// 1e-9), segment length, hop (overlap) or smoothing width differs from the first record's; the
// message names the record and the differing quantity.
PowerSpectralDensity average_psd(std::span<const PowerSpectralDensity> spectra,
                                 std::span<const std::string> names = {});

}  // namespace ridefit::signal
