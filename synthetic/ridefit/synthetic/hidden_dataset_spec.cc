#include "ridefit/synthetic/hidden_dataset_spec.h"

#include <fmt/core.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <set>

#include "ridefit/common/errors.h"
#include "ridefit/fitting/diagnose/effect.h"
#include "ridefit/io/yaml_map.h"
#include "ridefit/model/quarter_car_parameter_table.h"
#include "ridefit/road/log_sweep.h"

namespace ridefit::synthetic {
namespace {

std::vector<std::string> read_effects(const io::YamlMap& d) {
  std::set<std::string> known{"sensor_mount"};
  for (const auto& e : fitting::diagnose::effect_library()) known.emplace(e->id());
  std::vector<std::string> effects;
  if (!d.has("effects")) return effects;
  for (const auto& id : d.texts("effects")) {
    if (!known.count(id)) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      throw InputError(
          fmt::format("{}: unknown effect '{}'; one of: {}", d.locate("effects"), id, list));
    }
    effects.push_back(id);
  }
  return effects;
}

// `rig:`, duration, rate and noise of a strut rig dataset.
void read_rig(const io::YamlMap& d, HiddenDataset& out) {
  const io::YamlMap rig = d.map("rig");
  for (double a : rig.numbers("amplitudes_mm")) out.rig_amplitudes_m.push_back(1e-3 * a);
  out.rig_frequencies_Hz = rig.numbers("frequencies_Hz");
  if (out.rig_amplitudes_m.empty() ||
      out.rig_amplitudes_m.size() != out.rig_frequencies_Hz.size()) {
    throw InputError(fmt::format("{}: give as many amplitudes_mm as frequencies_Hz, at least one",
                                 d.locate("rig")));
  }
  for (double f : out.rig_frequencies_Hz) {
    if (!(f > 0.0) || !std::isfinite(f)) {
      throw InputError(
          fmt::format("{}: frequencies must be finite and > 0 Hz", rig.locate("frequencies_Hz")));
    }
  }
  out.duration_s = d.positive("duration_s");
  out.sample_rate_Hz = d.has("sample_rate_Hz") ? d.positive_up_to("sample_rate_Hz", 1e5) : 1000.0;
  for (double f : out.rig_frequencies_Hz) {
    if (!(f < 0.5 * out.sample_rate_Hz)) {
      throw InputError(fmt::format(
          "{}: {:g} Hz is at or above the Nyquist frequency ({:g} Hz at sample_rate_Hz {:g}); "
          "the record would show an alias. Give frequencies below {:g} Hz or a sample rate "
          "above {:g} Hz",
          rig.locate("frequencies_Hz"), f, 0.5 * out.sample_rate_Hz, out.sample_rate_Hz,
          0.5 * out.sample_rate_Hz, 2.0 * f));
    }
  }
  rig.finish();
  out.noise_N = d.has("noise_N") ? d.non_negative("noise_N") : 0.6;
}

// Excitation, duration and rate of a vehicle dataset.
void read_road(const io::YamlMap& d, HiddenDataset& out) {
  out.excitation = d.file("excitation");
  out.duration_s = d.has("duration_s") ? d.positive("duration_s") : 0.0;
  out.sample_rate_Hz = d.has("sample_rate_Hz") ? d.positive_up_to("sample_rate_Hz", 1e5) : 500.0;
  // A sweep up to a frequency the records cannot hold would alias into the band.
  YAML::Node excitation;
  try {
    excitation = YAML::LoadFile(out.excitation.string());
  } catch (const YAML::Exception&) {
    // Malformed: the excitation's loader names what is wrong, later.
  }
  if (excitation.IsMap() && excitation["type"] &&
      excitation["type"].as<std::string>() == "log_sweep" &&
      (!excitation["end_frequency_Hz"] || excitation["end_frequency_Hz"].IsScalar())) {
    const double end_Hz = excitation["end_frequency_Hz"]
                              ? excitation["end_frequency_Hz"].as<double>()
                              : road::LogSweepParameters{}.end_frequency_Hz;
    if (end_Hz >= 0.5 * out.sample_rate_Hz) {
      throw InputError(fmt::format(
          "{}: the excitation {} sweeps up to {:g} Hz, at or above the Nyquist frequency "
          "({:g} Hz at sample_rate_Hz {:g}); give a sample rate above {:g} Hz",
          d.locate("excitation"), out.excitation.string(), end_Hz, 0.5 * out.sample_rate_Hz,
          out.sample_rate_Hz, 2.0 * end_Hz));
    }
  }
}

// `sensor:` of a vehicle dataset: every corner frequency below Nyquist.
void read_sensor(const io::YamlMap& d, HiddenDataset& out) {
  const io::YamlMap s = d.map("sensor");
  out.sensor.noise_fraction = s.has("noise") ? s.non_negative_up_to("noise", 1.0) : 0.005;
  out.sensor.high_pass_Hz = s.has("high_pass_Hz") ? s.non_negative("high_pass_Hz") : 0.1;
  out.sensor.low_pass_Hz = s.has("low_pass_Hz") ? s.positive("low_pass_Hz") : 0.0;
  const double nyquist_Hz = 0.5 * out.sample_rate_Hz;
  auto below_nyquist = [&](const io::YamlMap& map, const std::string& key, double f) {
    if (f >= nyquist_Hz) {
      throw InputError(fmt::format(
          "{} is {:g} Hz, at or above the Nyquist frequency ({:g} Hz at sample_rate_Hz {:g}); "
          "give a frequency below {:g} Hz or a higher sample rate",
          map.locate(key), f, nyquist_Hz, out.sample_rate_Hz, nyquist_Hz));
    }
  };
  below_nyquist(s, "high_pass_Hz", out.sensor.high_pass_Hz);
  below_nyquist(s, "low_pass_Hz", out.sensor.low_pass_Hz);
  if (s.has("mount")) {
    const io::YamlMap m = s.map("mount");
    out.mount_channel = m.choice("channel", {"body_acc", "wheel_acc"});
    out.sensor.mount = study::SensorMount{m.positive("frequency_Hz"), m.positive("damping_ratio")};
    below_nyquist(m, "frequency_Hz", out.sensor.mount->frequency_Hz);
    m.finish();
  }
  s.finish();
}

// `baseline:` of a dataset: its model and how its values are off (a rig dataset's: the model
// whose strut a rig diagnosis puts on the rig, with the strut's sheet values freed).
void read_baseline(const io::YamlMap& d, HiddenDataset& out) {
  const io::YamlMap b = d.map("baseline");
  out.baseline_model = b.file("model");
  if (b.has("datasheet_seed") == b.has("errors")) {
    throw InputError(fmt::format(
        "{}: give either datasheet_seed (errors drawn from the data-sheet tolerances) or errors "
        "(a share per key)",
        d.locate("baseline")));
  }
  if (b.has("datasheet_seed")) out.baseline_datasheet_seed = b.integer("datasheet_seed");
  if (b.has("errors")) {
    const io::YamlMap errors = b.map("errors");
    for (const auto& key : errors.keys()) {
      if (!model::quarter_car_parameter_index(key)) {
        throw InputError(
            fmt::format("{}: '{}' is not a quarter-car parameter", errors.locate(key), key));
      }
      const double share = errors.number(key);
      if (!(share > -1.0 && share <= 10.0)) {
        throw InputError(fmt::format("{} is {}, expected a share in (-1, 10] of the value",
                                     errors.locate(key), share));
      }
      out.baseline_errors[key] = share;
    }
    errors.finish();
  }
  b.finish();
}

HiddenDataset read_dataset(const io::YamlMap& d) {
  HiddenDataset out;
  out.name = d.text("name");
  if (out.name.empty() || out.name.find_first_of("/\\ ") != std::string::npos) {
    throw InputError(fmt::format("{}: a file stem without spaces or slashes", d.locate("name")));
  }
  out.strut_rig = d.has("kind") && d.choice("kind", {"vehicle", "strut_rig"}) == "strut_rig";
  out.model = d.file("model");
  out.damper_state = out.strut_rig ? "" : d.text_or("damper_state", "");
  out.location = d.locate("name");
  if (d.has("set")) {
    out.set_location = d.locate("set");
    const io::YamlMap set = d.map("set");
    for (const auto& key : set.keys()) out.set[key] = set.number(key);
    set.finish();
  }
  out.effects = read_effects(d);
  if (out.strut_rig) {
    read_rig(d, out);
  } else {
    read_road(d, out);
  }
  out.records = static_cast<int>(d.has("records") ? d.integer("records") : 2);
  if (out.records < 1 || out.records > 20) {
    throw InputError(fmt::format("{} is {}, expected 1 to 20", d.locate("records"), out.records));
  }
  out.seed = d.integer_or("seed", 1);
  if (d.has("sensor") && out.strut_rig) {
    throw InputError(
        fmt::format("{}: a strut rig dataset takes noise_N, not a sensor", d.locate("sensor")));
  }
  if (d.has("sensor")) read_sensor(d, out);
  if (d.has("baseline")) read_baseline(d, out);
  d.finish();
  return out;
}

}  // namespace

std::vector<HiddenDataset> read_hidden_spec(const std::filesystem::path& spec_file) {
  const io::YamlMap spec = io::YamlMap::load(spec_file);
  std::vector<HiddenDataset> datasets;
  for (const auto& d : spec.maps("datasets")) datasets.push_back(read_dataset(d));
  spec.finish();
  if (datasets.empty()) throw InputError(fmt::format("{}: no datasets", spec_file.string()));
  for (std::size_t i = 0; i < datasets.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (datasets[j].name == datasets[i].name) {
        throw InputError(fmt::format(
            "{}: dataset name '{}' is also the name of dataset {} ({}); each dataset's files are "
            "named after it, so give each its own name",
            datasets[i].location, datasets[i].name, j + 1, datasets[j].location));
      }
    }
  }
  return datasets;
}

std::string baseline_file_name(const HiddenDataset& d) { return d.name + "_baseline.yaml"; }

std::string record_file_name(const HiddenDataset& d, int record) {
  return record == 1 ? d.name + ".csv" : fmt::format("{}_{}.csv", d.name, record);
}

}  // namespace ridefit::synthetic
