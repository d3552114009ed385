#include "ridefit/study/half_car_sweep.h"

#include "ridefit/io/value_range.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>

#include "ridefit/common/errors.h"
#include "ridefit/common/parallel_for.h"
#include "ridefit/io/closest_names.h"
#include "ridefit/io/half_car_file.h"
#include "ridefit/io/yaml_map.h"
#include "ridefit/model/half_car_parameter_table.h"
#include "ridefit/road/excitation_file.h"
#include "ridefit/road/road_limits.h"
#include "ridefit/simulate/half_car_simulation.h"
#include "ridefit/study/load_case_evaluation.h"

namespace ridefit::study {
namespace {

constexpr std::size_t kMaxRuns = 100000;

SweepAxis read_axis(const io::YamlMap& entry, const std::filesystem::path& model) {
  SweepAxis axis;
  axis.keys = entry.texts("parameter");
  // A key of the file (a typo never adds a key nothing reads) and a number of the half car's
  // parameter table (a setting such as front.suspension is not swept).
  model::HalfCarParameters<double> parameters{};
  model::SemiActiveControl control;
  for (const auto& key : axis.keys) {
    if (io::half_car_has_key(model, key) && !model::half_car_field(parameters, control, key)) {
      throw InputError(fmt::format(
          "{}: '{}' is a setting of model {}, not a number to vary (give a numeric key such as "
          "front.damping_Ns_per_m; a setting is changed in the model file)",
          entry.locate("parameter"), key, model.string()));
    }
    if (!io::half_car_has_key(model, key)) {
      throw InputError(fmt::format(
          "{}: '{}' is not a key of model {} (give the dotted path of a numeric key, e.g. "
          "front.damping_Ns_per_m){}",
          entry.locate("parameter"), key, model.string(),
          io::closest_names_text(key, io::yaml_number_keys(model))));
    }
  }
  axis.name = entry.has("name") ? entry.text("name") : axis.keys.front();
  const bool values = entry.has("values");
  const bool range = entry.has("range");
  if (values == range) {
    throw InputError(fmt::format("{}: give exactly one of `values` (a list) and `range`",
                                 entry.locate("parameter")));
  }
  axis.values = values ? entry.numbers("values") : io::read_value_range(entry.map("range"));
  entry.finish();
  return axis;
}

std::vector<double> read_speeds(const io::YamlMap& file) {
  const bool kmh = file.has("speeds_km_per_h");
  const bool si = file.has("speeds_m_per_s");
  if (kmh && si) {
    throw InputError(
        fmt::format("{}: give speeds_km_per_h or speeds_m_per_s, not both", file.path().string()));
  }
  if (!kmh && !si) return {};
  const char* key = kmh ? "speeds_km_per_h" : "speeds_m_per_s";
  std::vector<double> speeds = file.numbers(key);
  for (double& v : speeds) {
    if (!(v > 0.0)) {
      throw InputError(
          fmt::format("{}: speed {} is not > 0; a car drives forward", file.locate(key), v));
    }
    if (kmh) v /= 3.6;
    if (v > road::kMaxSpeed_m_per_s) {
      throw InputError(fmt::format("{}: {:.4g} m/s is above the {} m/s this tool accepts",
                                   file.locate(key), v, road::kMaxSpeed_m_per_s));
    }
  }
  return speeds;
}

void check_plot(const HalfCarSweep& sweep, const io::YamlMap& plot) {
  const SweepPlot& p = *sweep.plot;
  std::set<std::string> dimensions = {"speed_km_per_h", "road"};
  for (const auto& axis : sweep.axes) dimensions.insert(axis.name);
  if (p.x == "road" || !dimensions.count(p.x)) {
    throw InputError(
        fmt::format("{} is '{}': expected speed_km_per_h or a `vary` name", plot.locate("x"), p.x));
  }
  if (!p.series.empty() && (p.series == p.x || !dimensions.count(p.series))) {
    throw InputError(
        fmt::format("{} is '{}': expected road, speed_km_per_h or a `vary` name other than x",
                    plot.locate("series"), p.series));
  }
  std::set<std::string> metrics;
  for (const auto& [name, value] : HalfCarMetrics{}.named()) metrics.insert(name);
  for (const auto& y : p.y) {
    if (!metrics.count(y)) {
      std::string list;
      for (const auto& m : metrics) list += (list.empty() ? "" : ", ") + m;
      throw InputError(
          fmt::format("{}: '{}' is not a metric; one of: {}", plot.locate("y"), y, list));
    }
  }
  // Every dimension that is neither x nor series must hold one value, or points would pile up.
  auto count = [&](const std::string& dimension) -> std::size_t {
    if (dimension == "road") return sweep.roads.size();
    if (dimension == "speed_km_per_h") return std::max<std::size_t>(1, sweep.speeds_m_per_s.size());
    for (const auto& axis : sweep.axes) {
      if (axis.name == dimension) return axis.values.size();
    }
    return 1;
  };
  for (const auto& dimension : dimensions) {
    const bool plotted = dimension == p.x || dimension == p.series ||
                         (sweep.zip && sweep.axes.size() > 1 && dimension != "road" &&
                          dimension != "speed_km_per_h" &&
                          (dimensions.count(p.x) && p.x != "road" && p.x != "speed_km_per_h"));
    if (!plotted && count(dimension) > 1) {
      throw InputError(fmt::format(
          "{}: the study varies {} too ({} values); make it the series or plot a study that "
          "holds it fixed",
          plot.locate("x"), dimension, count(dimension)));
    }
  }
}

// The study's car at one point: `base` with the point's values set in memory through the
// parameter table (no file is read per run) and checked by its validate().
io::HalfCarFile car_at(const io::HalfCarFile& base, const HalfCarSweep& sweep,
                       const SweepPoint& point) {
  io::HalfCarFile car = base;
  for (std::size_t a = 0; a < sweep.axes.size(); ++a) {
    for (const auto& key : sweep.axes[a].keys) {
      *model::half_car_field(car.parameters, car.topology.control, key)->value = point.values[a];
    }
  }
  if (const auto error = model::validate(car.parameters, car.topology)) {
    throw InputError(fmt::format("{}: vary: {}", sweep.study_file.string(), error->text()));
  }
  return car;
}

}  // namespace

std::pair<std::string, std::string> split_unit_suffix(const std::string& name) {
  static const std::vector<std::pair<std::string, std::string>> kSuffixes = {
      {"_Ns_per_m", "Ns/m"},
      {"_N_per_m", "N/m"},
      {"_m_per_s2", "m/s^2"},
      {"_rad_per_s2", "rad/s^2"},
      {"_m_per_s", "m/s"},
      {"_km_per_h", "km/h"},
      {"_kg_m2", "kg*m^2"},
      {"_kg", "kg"},
      {"_N", "N"},
      {"_m", "m"},
      {"_s", "s"},
      {"_Hz", "Hz"}};
  for (const auto& [suffix, unit] : kSuffixes) {
    if (name.size() > suffix.size() && name.ends_with(suffix)) {
      return {name.substr(0, name.size() - suffix.size()), unit};
    }
  }
  return {name, "1"};
}

HalfCarSweep load_half_car_sweep(const std::filesystem::path& study_file) {
  const io::YamlMap file = io::YamlMap::load(study_file);
  HalfCarSweep sweep;
  sweep.study_file = study_file;
  sweep.model_file = file.file("model");
  io::load_half_car(sweep.model_file);  // the model's own errors first
  const io::YamlMap roads = file.map("roads");
  for (const auto& name : roads.keys()) {
    sweep.roads.emplace_back(name, roads.file(name));
    road::load_excitation(sweep.roads.back().second);  // each road's own errors
  }
  if (sweep.roads.empty()) {
    throw InputError(
        fmt::format("{} lists no road; give at least one name: file", file.locate("roads")));
  }
  sweep.speeds_m_per_s = read_speeds(file);
  if (file.has("vary")) {
    std::set<std::string> names;
    for (const auto& entry : file.maps("vary")) {
      sweep.axes.push_back(read_axis(entry, sweep.model_file));
      if (!names.insert(sweep.axes.back().name).second) {
        throw InputError(fmt::format("{}: '{}' is varied twice", entry.locate("parameter"),
                                     sweep.axes.back().name));
      }
    }
  }
  sweep.zip = file.has("combine") && file.choice("combine", {"grid", "zip"}) == "zip";
  if (sweep.zip) {
    for (const auto& axis : sweep.axes) {
      if (axis.values.size() != sweep.axes.front().values.size()) {
        throw InputError(
            fmt::format("{}: zip needs axes of one length; '{}' has {} values, '{}' {}",
                        file.locate("combine"), sweep.axes.front().name,
                        sweep.axes.front().values.size(), axis.name, axis.values.size()));
      }
    }
  }
  if (file.has("method")) {
    const std::string method = file.choice("method", {"auto", "frequency", "time"});
    sweep.method = method == "frequency" ? EvaluationMethod::kFrequency
                   : method == "time"    ? EvaluationMethod::kTime
                                         : EvaluationMethod::kAuto;
  }
  if (file.has("time")) {
    const io::YamlMap time = file.map("time");
    if (time.has("output_rate_Hz"))
      sweep.output_rate_Hz = time.positive_up_to("output_rate_Hz", 1e5);
    if (time.has("settle_s")) sweep.settle_s = time.non_negative_up_to("settle_s", 1e4);
    if (time.has("duration_s")) sweep.duration_s = time.positive_up_to("duration_s", 1e5);
    if (sweep.duration_s > 0.0 && sweep.settle_s >= sweep.duration_s) {
      throw InputError(fmt::format(
          "{} is {:g} s, not below time.duration_s ({:g} s): nothing would be left to evaluate; "
          "give a settle_s below the duration",
          time.locate("settle_s"), sweep.settle_s, sweep.duration_s));
    }
    time.finish();
  }
  std::size_t runs = sweep.roads.size() * std::max<std::size_t>(1, sweep.speeds_m_per_s.size());
  if (!sweep.axes.empty()) {
    std::size_t grid = sweep.zip ? sweep.axes.front().values.size() : 1;
    if (!sweep.zip) {
      for (const auto& axis : sweep.axes) {
        grid *= axis.values.size();
        if (grid > kMaxRuns) break;
      }
    }
    runs *= grid;
  }
  if (runs > kMaxRuns) {
    throw InputError(fmt::format("{}: the study has more than {} runs; split it",
                                 study_file.string(), kMaxRuns));
  }
  if (file.has("plot")) {
    const io::YamlMap plot = file.map("plot");
    SweepPlot p;
    p.x = plot.text("x");
    p.series = plot.text_or("series", "");
    p.y = plot.texts("y");
    plot.finish();
    sweep.plot = p;
    check_plot(sweep, plot);
  }
  file.finish();
  return sweep;
}

std::vector<SweepPoint> expand(const HalfCarSweep& sweep) {
  std::vector<std::vector<double>> combinations;
  if (sweep.axes.empty()) {
    combinations.push_back({});
  } else if (sweep.zip) {
    for (std::size_t i = 0; i < sweep.axes.front().values.size(); ++i) {
      std::vector<double> values;
      for (const auto& axis : sweep.axes) values.push_back(axis.values[i]);
      combinations.push_back(values);
    }
  } else {
    combinations.push_back({});
    for (const auto& axis : sweep.axes) {
      std::vector<std::vector<double>> next;
      for (const auto& prefix : combinations) {
        for (double v : axis.values) {
          next.push_back(prefix);
          next.back().push_back(v);
        }
      }
      combinations = std::move(next);
    }
  }
  std::vector<SweepPoint> points;
  const std::vector<double> own_speed = {0.0};  // 0: the road's own speed
  const auto& speeds = sweep.speeds_m_per_s.empty() ? own_speed : sweep.speeds_m_per_s;
  for (std::size_t r = 0; r < sweep.roads.size(); ++r) {
    for (double speed : speeds) {
      for (const auto& values : combinations) points.push_back({r, speed, values});
    }
  }
  return points;
}

namespace {

struct RoadCase {
  LoadCaseRoad road;
  LoadCaseSettings settings;  // method kFrequency or kTime, decided once for every run
};

}  // namespace

struct PreparedSweep::State {
  std::filesystem::path study_file;
  std::vector<SweepPoint> points;
  std::vector<io::HalfCarFile> models;
  std::map<std::pair<std::size_t, double>, RoadCase> roads;
};

PreparedSweep::PreparedSweep(const HalfCarSweep& sweep, unsigned threads)
    : state_(std::make_unique<State>()) {
  state_->study_file = sweep.study_file;
  std::vector<SweepPoint>& points = state_->points;
  points = expand(sweep);
  // Every model first, so a value the model rejects stops the study before it runs.
  const io::HalfCarFile base = io::load_half_car(sweep.model_file);
  std::vector<io::HalfCarFile>& models = state_->models;
  models.resize(points.size());
  common::parallel_for(points.size(), threads, [&](std::size_t i) {
    try {
      models[i] = car_at(base, sweep, points[i]);
    } catch (const InputError& e) {
      throw InputError(fmt::format("run {} of {}: {}", i + 1, points.size(), e.what()));
    }
  });
  // Roads: a spectrum (frequency domain) or a generated profile (time domain) per road and
  // speed, made once and shared by the runs.
  // Every run's car, not only the first: a study may vary what makes a car nonlinear (the
  // control law, a damper state, a damper's compression_to_rebound_ratio).
  const bool linear = std::all_of(models.begin(), models.end(), [](const io::HalfCarFile& m) {
    return m.make_model().is_linear();
  });
  auto& roads = state_->roads;
  for (auto& point : points) {
    const auto key = std::make_pair(point.road, point.speed_m_per_s);
    if (roads.count(key)) continue;
    const auto& path = sweep.roads[point.road].second;
    const std::optional<double> speed =
        point.speed_m_per_s > 0.0 ? std::optional(point.speed_m_per_s) : std::nullopt;
    RoadCase c;
    c.road.spectrum = road::load_road_spectrum(path, speed);
    c.settings.method = sweep.method;
    c.settings.output_rate_Hz = sweep.output_rate_Hz;
    c.settings.settle_s = sweep.settle_s;
    c.settings.duration_s = sweep.duration_s;
    const bool frequency = in_frequency_domain(
        linear, c.road, c.settings,
        fmt::format("{}: road '{}'", sweep.study_file.string(), sweep.roads[point.road].first));
    c.settings.method = frequency ? EvaluationMethod::kFrequency : EvaluationMethod::kTime;
    if (!frequency) {
      c.road.input = speed ? road::load_excitation(path, *speed) : road::load_excitation(path);
      const double used_s = sweep.duration_s > 0.0 ? sweep.duration_s : c.road.input->duration_s();
      if (sweep.settle_s >= used_s) {
        throw InputError(fmt::format(
            "{}: time.settle_s is {:g} s, not below the {:g} s of road '{}'{}: nothing would be "
            "left to evaluate; give a shorter settle_s or a longer road",
            sweep.study_file.string(), sweep.settle_s, used_s, sweep.roads[point.road].first,
            sweep.duration_s > 0.0 ? " (time.duration_s)" : ""));
      }
    }
    roads[key] = std::move(c);
  }
  for (auto& point : points) {
    if (point.speed_m_per_s > 0.0) continue;
    const RoadCase& c = roads.at({point.road, 0.0});
    const std::optional<double> own = c.road.spectrum
                                          ? std::optional(c.road.spectrum->speed_m_per_s)
                                          : c.road.input->speed_m_per_s();
    if (!own) {
      throw InputError(fmt::format("{}: road '{}' is not driven at a speed; give speeds_km_per_h",
                                   sweep.study_file.string(), sweep.roads[point.road].first));
    }
  }
}

PreparedSweep::~PreparedSweep() = default;

std::size_t PreparedSweep::runs() const { return state_->points.size(); }

SweepRow PreparedSweep::run(std::size_t i) const {
  const SweepPoint& point = state_->points.at(i);
  const RoadCase& c = state_->roads.at({point.road, point.speed_m_per_s});
  const auto evaluation = evaluate_on_load_case(state_->models[i].make_model(), c.road, c.settings,
                                                state_->study_file.string());
  SweepRow row;
  row.point = point;
  row.frequency_domain = evaluation.frequency_domain;
  row.metrics = evaluation.metrics;
  row.point.speed_m_per_s = evaluation.frequency_domain
                                ? c.road.spectrum->speed_m_per_s
                                : c.road.input->speed_m_per_s().value_or(0.0);
  return row;
}

std::vector<SweepRow> run_half_car_sweep(
    const HalfCarSweep& sweep, unsigned threads,
    const std::function<void(std::size_t, std::size_t)>& progress) {
  const PreparedSweep prepared(sweep, threads);
  std::vector<SweepRow> rows(prepared.runs());
  std::size_t done = 0;
  common::parallel_for(
      rows.size(), threads, [&](std::size_t i) { rows[i] = prepared.run(i); },
      [&](std::size_t) {
        ++done;
        if (progress) progress(done, rows.size());
      });
  return rows;
}

}  // namespace ridefit::study
