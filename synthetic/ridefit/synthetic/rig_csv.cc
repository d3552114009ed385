#include "ridefit/synthetic/rig_csv.h"

#include <fmt/core.h>

#include <ostream>

#include "ridefit/io/atomic_file.h"

namespace ridefit::synthetic {

void write_rig_csv(const std::filesystem::path& path, const fitting::HysteresisRecord& record,
                   RigCsvDigits digits) {
  const bool fixed = digits == RigCsvDigits::kFixed;
  const bool commanded = !record.command.empty();
  io::write_atomically(path, [&](std::ostream& out) {
    out << "time[s],displacement[mm],force[N]";
    if (commanded) out << (record.command_unit == "V" ? ",voltage[V]" : ",current[A]");
    out << "\n";
    for (std::size_t k = 0; k < record.time_s.size(); ++k) {
      const double t = record.time_s[k], x_mm = 1e3 * record.displacement_m[k];
      const double f = record.force_N[k];
      out << (fixed ? fmt::format("{:.4f},{:.6f},{:.3f}", t, x_mm, f)
                    : fmt::format("{:.6g},{:.6g},{:.6g}", t, x_mm, f));
      if (commanded) {
        out << (fixed ? fmt::format(",{:.5f}", record.command[k])
                      : fmt::format(",{:.6g}", record.command[k]));
      }
      out << "\n";
    }
  });
}

}  // namespace ridefit::synthetic
