#pragma once

#include "ridefit/common/errors.h"

namespace ridefit::cli {

// A failed run that every rank of the session throws alike (the ranks agreed on it, e.g. by
// distributed::broadcast_from_root): main() ends every rank with exit 1, rank 0 printing the
// message, without ending the job through MPI_Abort. Without MPI, a RunError like any other.
class CollectiveRunError : public RunError {
 public:
  using RunError::RunError;
};

}  // namespace ridefit::cli
