#include "ridefit/fitting/diagnose/residual_shape.h"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string_view>

#include "ridefit/common/errors.h"
#include "ridefit/fitting/diagnose/sparse_selection.h"

namespace ridefit::fitting::diagnose {
namespace {

// What one sample offers the basis: travel about mid-stroke and its scales.
struct Sample {
  double travel_m;  // about the training records' mid-stroke
  double velocity_m_per_s;
  double acceleration_m_per_s2;
  double model_force_N;
};

struct Scales {
  double half_stroke_m;
  double velocity_rms_m_per_s;
};

// A term of the basis: its value at a sample, the unit of its coefficient (SI, and as an engineer
// reads it), and what it says for either sign of its coefficient (a positive missing force is
// tension, as the records' force; travel is extension positive).
struct Term {
  std::string_view id;
  std::string_view unit;
  std::string_view shown_unit;
  double shown_per_si;
  double (*value)(const Sample&, const Scales&);
  std::string_view positive;
  std::string_view negative;
};

double sign(double v) { return v > 0.0 ? 1.0 : (v < 0.0 ? -1.0 : 0.0); }

double beyond(double travel_m, double knee_m) {
  return sign(travel_m) * std::max(std::abs(travel_m) - knee_m, 0.0);
}

// "{knee}" in a text is the knee's travel in mm.
constexpr std::array<Term, 13> kTerms{{
    {"travel", "N/m", "N/mm", 1e-3, [](const Sample& s, const Scales&) { return s.travel_m; },
     "a stiffness the model lacks: force rising with travel",
     "the model stiffer than the rig: less force with travel"},
    {"travel_progressive", "N/m^2", "N/mm²", 1e-6,
     [](const Sample& s, const Scales&) { return s.travel_m * std::abs(s.travel_m); },
     "a progressive spring: force against travel rising with its square either way",
     "a spring that softens with travel either way"},
    {"travel_squared", "N/m^2", "N/mm²", 1e-6,
     [](const Sample& s, const Scales&) { return s.travel_m * s.travel_m; },
     "an even force: a tension growing with the square of travel either way (a gas spring's "
     "curvature, a geometric nonlinearity)",
     "an even force: a compression growing with the square of travel either way (a gas "
     "spring's curvature, a geometric nonlinearity)"},
    {"travel_beyond_half_stroke", "N/m", "N/mm", 1e-3,
     [](const Sample& s, const Scales& k) { return beyond(s.travel_m, 0.5 * k.half_stroke_m); },
     "a stop: force rising with travel beyond ±{knee} mm from mid-stroke",
     "a spring that gives way beyond ±{knee} mm from mid-stroke"},
    {"travel_beyond_three_quarter_stroke", "N/m", "N/mm", 1e-3,
     [](const Sample& s, const Scales& k) { return beyond(s.travel_m, 0.75 * k.half_stroke_m); },
     "a stop: force rising with travel beyond ±{knee} mm from mid-stroke",
     "a spring that gives way beyond ±{knee} mm from mid-stroke"},
    {"velocity", "N*s/m", "N·s/m", 1.0,
     [](const Sample& s, const Scales&) { return s.velocity_m_per_s; },
     "damping the model lacks, in proportion to velocity",
     "less damping than the model's, in proportion to velocity"},
    {"velocity_squared", "N*s^2/m^2", "N·s²/m²", 1.0,
     [](const Sample& s, const Scales&) {
       return s.velocity_m_per_s * std::abs(s.velocity_m_per_s);
     },
     "damping that grows with speed (quadratic)",
     "damping that falls behind the model's at speed (digressive)"},
    {"velocity_root", "N*(s/m)^0.5", "N·(s/m)^½", 1.0,
     [](const Sample& s, const Scales&) {
       return sign(s.velocity_m_per_s) * std::sqrt(std::abs(s.velocity_m_per_s));
     },
     "a force against the motion that rises steeply at low speed and flattens (a bleed, a knee)",
     "less force than the model's at low speed, catching up at speed"},
    {"speed", "N*s/m", "N·s/m", 1.0,
     [](const Sample& s, const Scales&) { return std::abs(s.velocity_m_per_s); },
     "a tension growing with speed in both directions: rebound and compression differ",
     "a compression growing with speed in both directions: rebound and compression differ"},
    {"velocity_sign", "N", "N", 1.0,
     [](const Sample& s, const Scales& k) {
       return std::tanh(s.velocity_m_per_s / (0.05 * k.velocity_rms_m_per_s));
     },
     "a force of constant size against the motion: more friction than the model's",
     "less friction than the model's"},
    {"acceleration", "kg", "kg", 1.0,
     [](const Sample& s, const Scales&) { return s.acceleration_m_per_s2; },
     "a mass between the load cell and the damper whose inertia the record leaves in (the "
     "rig's moving_mass_kg)",
     "a force against the rig's acceleration (an inertia compensated twice, or a lag)"},
    {"model_force", "1", "× the model's force", 1.0,
     [](const Sample& s, const Scales&) { return s.model_force_N; },
     "the model's own force, scaled up (a gain above 1)",
     "the model's own force, scaled down (a gain below 1)"},
    {"travel_velocity", "N*s/m^2", "N·s/m per mm", 1e-3,
     [](const Sample& s, const Scales&) { return s.travel_m * s.velocity_m_per_s; },
     "damping that grows towards extension (travel-dependent damping)",
     "damping that grows towards compression (travel-dependent damping)"},
}};
constexpr int kTermCount = static_cast<int>(kTerms.size());

bool usable(const ShapeSamples& r, std::size_t k) {
  return std::isfinite(r.displacement_m[k]) && std::isfinite(r.velocity_m_per_s[k]) &&
         std::isfinite(r.acceleration_m_per_s2[k]) && std::isfinite(r.model_force_N[k]) &&
         std::isfinite(r.missing_force_N[k]);
}

SelectionRows rows_of(const std::vector<ShapeSamples>& records, double centre_m,
                      const Scales& scales) {
  std::size_t rows = 0;
  for (const auto& r : records) {
    for (std::size_t k = 0; k < r.missing_force_N.size(); ++k) rows += usable(r, k) ? 1 : 0;
  }
  SelectionRows d{Eigen::MatrixXd(rows, kTermCount), Eigen::VectorXd(rows), {}};
  Eigen::Index row = 0;
  for (const auto& r : records) {
    const Eigen::Index first = row;
    for (std::size_t k = 0; k < r.missing_force_N.size(); ++k) {
      if (!usable(r, k)) continue;
      const Sample s{r.displacement_m[k] - centre_m, r.velocity_m_per_s[k],
                     r.acceleration_m_per_s2[k], r.model_force_N[k]};
      for (int j = 0; j < kTermCount; ++j) d.basis(row, j) = kTerms[j].value(s, scales);
      d.target(row) = r.missing_force_N[k];
      ++row;
    }
    const Eigen::Index n = row - first;
    if (n == 0) continue;
    auto block = d.basis.middleRows(first, n);
    block.rowwise() -= block.colwise().mean();
    auto y = d.target.segment(first, n);
    y.array() -= y.mean();
    d.lengths.push_back(static_cast<std::size_t>(n));
  }
  return d;
}

void check(const std::vector<ShapeSamples>& records, std::string_view side) {
  if (records.empty()) {
    throw InputError(fmt::format("residual shape: no {} record", side));
  }
  for (std::size_t i = 0; i < records.size(); ++i) {
    const auto& r = records[i];
    const std::size_t n = r.missing_force_N.size();
    if (r.displacement_m.size() != n || r.velocity_m_per_s.size() != n ||
        r.acceleration_m_per_s2.size() != n || r.model_force_N.size() != n) {
      throw InputError(fmt::format(
          "residual shape: {} record {}: its columns differ in length (displacement {}, velocity "
          "{}, acceleration {}, model force {}, missing force {}); expected one length",
          side, i + 1, r.displacement_m.size(), r.velocity_m_per_s.size(),
          r.acceleration_m_per_s2.size(), r.model_force_N.size(), n));
    }
    if (n < 10) {
      throw InputError(fmt::format(
          "residual shape: {} record {} has {} samples; expected at least 10", side, i + 1, n));
    }
  }
}

const Term& term_of(std::string_view id) {
  for (const auto& t : kTerms) {
    if (t.id == id) return t;
  }
  throw std::logic_error("residual shape: unknown term");
}

std::string words_of(const Term& term, bool positive, double knee_m) {
  std::string text(positive ? term.positive : term.negative);
  const std::string mark = "{knee}";
  if (const auto at = text.find(mark); at != std::string::npos) {
    text.replace(at, mark.size(), fmt::format("{:.3g}", 1e3 * knee_m));
  }
  return text;
}

}  // namespace

ResidualShape residual_shape(const std::vector<ShapeSamples>& training,
                             const std::vector<ShapeSamples>& judging,
                             const SparseSelectionOptions& options) {
  options.validate();
  check(training, "training");
  check(judging, "judging");
  ResidualShape shape;
  double low = std::numeric_limits<double>::infinity(), high = -low, speed_squares = 0.0;
  std::size_t speeds = 0;
  for (const auto& r : training) {
    for (std::size_t k = 0; k < r.displacement_m.size(); ++k) {
      if (!usable(r, k)) continue;
      low = std::min(low, r.displacement_m[k]);
      high = std::max(high, r.displacement_m[k]);
      speed_squares += r.velocity_m_per_s[k] * r.velocity_m_per_s[k];
      ++speeds;
    }
  }
  if (speeds < 10) return shape;  // nothing finite to regress on
  shape.travel_centre_m = 0.5 * (low + high);
  shape.half_stroke_m = 0.5 * (high - low);
  const Scales scales{std::max(shape.half_stroke_m, 1e-12),
                      std::max(std::sqrt(speed_squares / static_cast<double>(speeds)), 1e-12)};
  const SelectionRows train = rows_of(training, shape.travel_centre_m, scales);
  const SelectionRows judge = rows_of(judging, shape.travel_centre_m, scales);
  const SparseSelection selection = select_columns(train, judge, options);
  shape.judged_share = selection.judged_share;
  shape.judged_sum_of_squares_N2 = judge.target.squaredNorm();
  shape.options = options;
  for (const auto& c : selection.columns) {
    const Term& term = kTerms[static_cast<std::size_t>(c.column)];
    ShapeTerm t;
    t.id = term.id;
    t.unit = term.unit;
    t.coefficient = c.coefficient;
    t.standard_error = c.standard_error;
    t.judged_share = c.judged_share;
    const double knee = term.id == "travel_beyond_half_stroke" ? 0.5 * scales.half_stroke_m
                        : term.id == "travel_beyond_three_quarter_stroke"
                            ? 0.75 * scales.half_stroke_m
                            : 0.0;
    t.words = words_of(term, t.coefficient >= 0.0, knee);
    shape.terms.push_back(t);
  }
  return shape;
}

std::string coefficient_text(const ShapeTerm& t) {
  const Term& term = term_of(t.id);
  return fmt::format("{:+.3g} ± {:.2g} {}", term.shown_per_si * t.coefficient,
                     term.shown_per_si * t.standard_error, term.shown_unit);
}

std::string describe(const ResidualShape& shape) {
  std::string text;
  for (const auto& t : shape.terms) {
    text += fmt::format("{}{} ({}, {:.0f} % of the judged residual)", text.empty() ? "" : "; ",
                        t.words, coefficient_text(t), 100.0 * t.judged_share);
  }
  return text;
}

}  // namespace ridefit::fitting::diagnose
