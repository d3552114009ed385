#include "ridefit/model/half_car_parameter_table.h"

#include <fmt/core.h>

#include "ridefit/model/quarter_car_parameter_table.h"

namespace ridefit::model {
namespace {

namespace qc = quarter_car_rows;

constexpr std::size_t row_of(const ParameterInfo& row) { return quarter_car_row_index(row); }

// The axle's own rows before the strut's (kStrutRows).
constexpr std::size_t kAxleOwnRows = 4;

// HalfCarAxle's fields in the order of half_car_axle_rows().
double* axle_field(HalfCarAxle<double>& a, std::size_t i) {
  double* const own[] = {&a.unsprung_mass_kg, &a.tyre_stiffness_N_per_m, &a.tyre_damping_Ns_per_m,
                         &a.spring_stiffness_N_per_m};
  static_assert(std::size(own) == kAxleOwnRows);
  return i < kAxleOwnRows ? own[i] : &strut_field(a.strut(), i - kAxleOwnRows);
}

double* body_field(HalfCarParameters<double>& p, std::size_t i) {
  double* const fields[] = {&p.body_mass_kg, &p.pitch_inertia_kg_m2, &p.front_axle_distance_m,
                            &p.rear_axle_distance_m, &p.seat_distance_m};
  static_assert(std::size(fields) == kHalfCarBodyParameters.size());
  return fields[i];
}

double* mass_field(SuspendedMass<double>& m, std::size_t i) {
  double* const fields[] = {&m.mass_kg, &m.stiffness_N_per_m, &m.damping_Ns_per_m};
  static_assert(std::size(fields) == kSuspendedMassParameters.size());
  return fields[i];
}

double* control_field(SemiActiveControl& c, std::size_t i) {
  double* const fields[] = {&c.min_damping_Ns_per_m, &c.max_damping_Ns_per_m,
                            &c.skyhook_damping_Ns_per_m, &c.groundhook_damping_Ns_per_m,
                            &c.skyhook_share};
  static_assert(std::size(fields) == kControlParameters.size());
  return fields[i];
}

template <std::size_t N>
std::optional<std::size_t> find(const std::array<ParameterInfo, N>& rows, std::string_view key) {
  for (std::size_t i = 0; i < N; ++i) {
    if (rows[i].key == key) return i;
  }
  return std::nullopt;
}

std::optional<ParameterError> check_axle(const HalfCarAxle<double>& a, const AxleTopology& t,
                                         std::string_view name) {
  const auto& rows = half_car_axle_rows();
  for (std::size_t i = 0; i < kAxleOwnRows; ++i) {
    const ParameterInfo& row = kQuarterCarParameters[rows[i]];
    const double v = *axle_field(const_cast<HalfCarAxle<double>&>(a), i);
    if (auto error = check_range(row, v, fmt::format("{}.{}", name, row.key))) return error;
  }
  // A passive axle's damper may be 0 (a strut's rate divides by it).
  return validate_strut(a, fmt::format("{}.", name), t.suspension == AxleSuspension::kPassive);
}

}  // namespace

const std::array<std::size_t, kHalfCarAxleRows>& half_car_axle_rows() {
  static constexpr std::array<std::size_t, kHalfCarAxleRows> rows = [] {
    std::array<std::size_t, kHalfCarAxleRows> r{
        row_of(qc::unsprung_mass_kg), row_of(qc::tyre_stiffness_N_per_m),
        row_of(qc::tyre_damping_Ns_per_m), row_of(qc::spring_stiffness_N_per_m)};
    for (std::size_t i = 0; i < kStrutRows.size(); ++i) r[kAxleOwnRows + i] = kStrutRows[i];
    return r;
  }();
  return rows;
}

std::optional<HalfCarField> half_car_field(HalfCarParameters<double>& p, SemiActiveControl& control,
                                           std::string_view key) {
  const auto dot = key.find('.');
  if (dot == std::string_view::npos) {
    if (const auto i = find(kHalfCarBodyParameters, key)) {
      return HalfCarField{body_field(p, *i), &kHalfCarBodyParameters[*i]};
    }
    return std::nullopt;
  }
  const std::string_view group = key.substr(0, dot);
  const std::string_view leaf = key.substr(dot + 1);
  if (group == "front" || group == "rear") {
    HalfCarAxle<double>& axle = group == "front" ? p.front : p.rear;
    const auto& rows = half_car_axle_rows();
    for (std::size_t i = 0; i < rows.size(); ++i) {
      if (kQuarterCarParameters[rows[i]].key == leaf) {
        return HalfCarField{axle_field(axle, i), &kQuarterCarParameters[rows[i]]};
      }
    }
    return std::nullopt;
  }
  SuspendedMass<double>* mass = group == "seat"         ? &p.seat
                                : group == "lower_body" ? &p.lower_body
                                : group == "upper_body" ? &p.upper_body
                                                        : nullptr;
  if (mass) {
    if (const auto i = find(kSuspendedMassParameters, leaf)) {
      return HalfCarField{mass_field(*mass, *i), &kSuspendedMassParameters[*i]};
    }
    return std::nullopt;
  }
  if (group == "control") {
    if (const auto i = find(kControlParameters, leaf)) {
      return HalfCarField{control_field(control, *i), &kControlParameters[*i]};
    }
  }
  return std::nullopt;
}

std::optional<ParameterError> validate(const HalfCarParameters<double>& p,
                                       const HalfCarTopology& topology) {
  auto& q = const_cast<HalfCarParameters<double>&>(p);
  for (std::size_t i = 0; i < kHalfCarBodyParameters.size(); ++i) {
    if (auto error = check_range(kHalfCarBodyParameters[i], *body_field(q, i))) return error;
  }
  if (auto error = check_axle(p.front, topology.front, "front")) return error;
  if (auto error = check_axle(p.rear, topology.rear, "rear")) return error;
  for (auto [name, mass] :
       {std::pair{"seat", &q.seat}, {"lower_body", &q.lower_body}, {"upper_body", &q.upper_body}}) {
    for (std::size_t i = 0; i < kSuspendedMassParameters.size(); ++i) {
      const ParameterInfo& row = kSuspendedMassParameters[i];
      if (auto error = check_range(row, *mass_field(*mass, i), fmt::format("{}.{}", name, row.key)))
        return error;
    }
  }
  auto control = topology.control;
  for (std::size_t i = 0; i < kControlParameters.size(); ++i) {
    const ParameterInfo& row = kControlParameters[i];
    if (auto error =
            check_range(row, *control_field(control, i), fmt::format("control.{}", row.key)))
      return error;
  }
  if (control.min_damping_Ns_per_m > control.max_damping_Ns_per_m) {
    return ParameterError{
        fmt::format("control.{}", control_rows::min_damping_Ns_per_m.key),
        fmt::format("is {} Ns/m, above {} {} Ns/m; a damper's limits need c_min <= c_max",
                    control.min_damping_Ns_per_m, control_rows::max_damping_Ns_per_m.key,
                    control.max_damping_Ns_per_m)};
  }
  if (control.law != ControlLaw::kPassive) {
    if (!(control.max_damping_Ns_per_m > 0.0)) {
      return ParameterError{fmt::format("control.{}", control_rows::max_damping_Ns_per_m.key),
                            "must be > 0 under a control law"};
    }
    for (auto [name, axle] : {std::pair{"front", &p.front}, {"rear", &p.rear}}) {
      if (axle->commanded() && axle->damping_per_command_Ns_per_m == 0.0) {
        return ParameterError{
            fmt::format("{}.{}", name, qc::coulomb_force_per_command_N.key),
            fmt::format("needs {}.{} != 0: the control law sets the damping through the "
                        "command, u = (c_law - c)/c_b",
                        name, qc::damping_per_command_Ns_per_m.key)};
      }
    }
  }
  return std::nullopt;
}

}  // namespace ridefit::model
