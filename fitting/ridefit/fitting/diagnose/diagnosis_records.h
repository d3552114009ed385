#pragma once

#include <filesystem>
#include <vector>

#include "ridefit/fitting/diagnose/diagnosis.h"

namespace ridefit::fitting::diagnose {

// The data of a diagnosis on vehicle spectra, read from one record (its first half is fitted,
// its second half judges: split_record) or two (the first is fitted, the second judges), each
// driven by a road column or by an excitation file: `excitations` holds none, one for all
// records, or one per record (std::invalid_argument otherwise: the caller checks the counts).
// InputError naming the files for an excitation much longer than its record (a road for another
// record: it must cover the record and not be much longer) and for two records that hold
// different channels (the judging record must show what the fitted one shows); the loader's
// own InputErrors otherwise.
DiagnosisData load_diagnosis_data(const std::vector<std::filesystem::path>& records,
                                  const std::vector<std::filesystem::path>& excitations);

}  // namespace ridefit::fitting::diagnose
