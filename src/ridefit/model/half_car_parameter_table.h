#pragma once

#include <array>
#include <optional>
#include <string_view>

#include "ridefit/model/half_car.h"
#include "ridefit/model/parameter_info.h"

namespace ridefit::model {

// The half car's parameter rows (parameter_info.h). The body's own rows are here; each axle
// (front., rear.) has the quarter-car rows of the keys it shares (quarter_car_parameter_table.h);
// the seat and the two body segments (seat., lower_body., upper_body.) share the suspended-mass
// rows; the control law's numbers are under control. Keys of a whole model are dotted:
// "front.damping_Ns_per_m", "seat.mass_kg", "control.skyhook_damping_Ns_per_m".
inline constexpr std::array<ParameterInfo, 5> kHalfCarBodyParameters{{
    {"body_mass_kg", "kg", 0.0, 1e5, true, false, "body mass"},
    {"pitch_inertia_kg_m2", "kg*m^2", 0.0, 1e6, true, false,
     "body pitch inertia about the centre of gravity"},
    {"front_axle_distance_m", "m", 0.0, 20.0, true, false,
     "a1, front axle ahead of the centre of gravity"},
    {"rear_axle_distance_m", "m", 0.0, 20.0, true, false, "a2, rear axle behind it"},
    {"seat_distance_m", "m", -20.0, 20.0, false, false, "a3, seat ahead of it (negative: behind)"},
}};

// The body's rows by name (as quarter_car_rows).
namespace half_car_body_rows {
inline constexpr const ParameterInfo& body_mass_kg = kHalfCarBodyParameters[0];
inline constexpr const ParameterInfo& pitch_inertia_kg_m2 = kHalfCarBodyParameters[1];
inline constexpr const ParameterInfo& front_axle_distance_m = kHalfCarBodyParameters[2];
inline constexpr const ParameterInfo& rear_axle_distance_m = kHalfCarBodyParameters[3];
inline constexpr const ParameterInfo& seat_distance_m = kHalfCarBodyParameters[4];
}  // namespace half_car_body_rows

inline constexpr std::array<ParameterInfo, 3> kSuspendedMassParameters{{
    {"mass_kg", "kg", 0.0, 1e5, true, false, "mass of the seat or the body segment"},
    {"stiffness_N_per_m", "N/m", 0.0, 1e10, true, false, "its support's stiffness"},
    {"damping_Ns_per_m", "N*s/m", 0.0, 1e7, false, false, "its support's damping"},
}};

// The seat's and the body segments' rows by name.
namespace suspended_mass_rows {
inline constexpr const ParameterInfo& mass_kg = kSuspendedMassParameters[0];
inline constexpr const ParameterInfo& stiffness_N_per_m = kSuspendedMassParameters[1];
inline constexpr const ParameterInfo& damping_Ns_per_m = kSuspendedMassParameters[2];
}  // namespace suspended_mass_rows

inline constexpr std::array<ParameterInfo, 5> kControlParameters{{
    {"min_damping_Ns_per_m", "N*s/m", 0.0, 1e7, false, false, "the damper's lowest coefficient"},
    {"max_damping_Ns_per_m", "N*s/m", 0.0, 1e7, false, false, "its highest (> 0 under a law)"},
    {"skyhook_damping_Ns_per_m", "N*s/m", 0.0, 1e7, false, false, "skyhook and hybrid laws"},
    {"groundhook_damping_Ns_per_m", "N*s/m", 0.0, 1e7, false, false, "groundhook and hybrid laws"},
    {"skyhook_share", "1", 0.0, 1.0, false, false, "hybrid law's share of skyhook, alpha"},
}};

// The control law's rows by name.
namespace control_rows {
inline constexpr const ParameterInfo& min_damping_Ns_per_m = kControlParameters[0];
inline constexpr const ParameterInfo& max_damping_Ns_per_m = kControlParameters[1];
inline constexpr const ParameterInfo& skyhook_damping_Ns_per_m = kControlParameters[2];
inline constexpr const ParameterInfo& groundhook_damping_Ns_per_m = kControlParameters[3];
inline constexpr const ParameterInfo& skyhook_share = kControlParameters[4];
}  // namespace control_rows

// The quarter-car row indices an axle has, in HalfCarAxle's order: its wheel, tyre and coil
// spring, then the strut's (kStrutRows).
inline constexpr std::size_t kHalfCarAxleRows = 24;
const std::array<std::size_t, kHalfCarAxleRows>& half_car_axle_rows();

// The field of `p` (or of `control`) of a dotted key, with its row; none for a key the half car
// does not have.
struct HalfCarField {
  double* value;
  const ParameterInfo* row;
};
std::optional<HalfCarField> half_car_field(HalfCarParameters<double>& p, SemiActiveControl& control,
                                           std::string_view key);

// Every row's range and the rules between values that the file reader enforces (a strut's
// damping > 0, c_min <= c_max, a law's c_max > 0, a commanded friction slope under a law needs
// a damping slope): the first violation, or none. For a model edited in memory.
std::optional<ParameterError> validate(const HalfCarParameters<double>& p,
                                       const HalfCarTopology& topology);

}  // namespace ridefit::model
