#include "ridefit/road/excitation_file.h"

#include <fmt/core.h>

#include <map>
#include <set>
#include <string>

#include "ridefit/common/errors.h"
#include "ridefit/io/yaml_map.h"
#include "ridefit/road/cleat.h"
#include "ridefit/road/iso8608.h"
#include "ridefit/road/log_sweep.h"
#include "ridefit/road/measured_road.h"
#include "ridefit/road/opencrg_road.h"
#include "ridefit/road/power_law_road.h"
#include "ridefit/road/profile_road.h"
#include "ridefit/road/road_limits.h"

namespace ridefit::road {
namespace {

// Exactly one of speed_m_per_s and speed_km_per_h, converted to m/s here and nowhere else.
double read_speed_m_per_s(const io::YamlMap& file) {
  const bool si = file.has("speed_m_per_s");
  const bool kmh = file.has("speed_km_per_h");
  if (si && kmh) {
    throw InputError(
        fmt::format("{}: keys 'speed_m_per_s' and 'speed_km_per_h' are both given; "
                    "give exactly one",
                    file.path().string()));
  }
  if (!si && !kmh) {
    throw InputError(fmt::format("{} is missing (required; or give speed_km_per_h)",
                                 file.locate("speed_m_per_s")));
  }
  const char* key = kmh ? "speed_km_per_h" : "speed_m_per_s";
  const double speed_m_per_s = kmh ? file.positive(key) / 3.6 : file.positive(key);
  check_speed_m_per_s(speed_m_per_s, key);  // names the key given
  return speed_m_per_s;
}

RandomRoadParameters read_random(const io::YamlMap& file) {
  RandomRoadParameters p;
  p.speed_m_per_s = read_speed_m_per_s(file);
  p.duration_s = file.positive("duration_s");
  const long seed = file.integer_or("seed", 1);
  if (seed < 0) {
    throw InputError(fmt::format("{} is {}, expected an integer >= 0", file.locate("seed"), seed));
  }
  p.seed = static_cast<std::uint64_t>(seed);
  p.band.low_cycles_per_m = file.number_or("band_low_cycles_per_m", p.band.low_cycles_per_m);
  p.band.high_cycles_per_m = file.number_or("band_high_cycles_per_m", p.band.high_cycles_per_m);
  p.sample_spacing_m = file.number_or("sample_spacing_m", p.sample_spacing_m);
  p.fade_in_m = file.number_or("fade_in_m", p.fade_in_m);
  return p;
}

std::unique_ptr<RoadInput> read_log_sweep(const io::YamlMap& file) {
  LogSweepParameters p;
  p.start_frequency_Hz = file.number_or("start_frequency_Hz", p.start_frequency_Hz);
  p.end_frequency_Hz = file.number_or("end_frequency_Hz", p.end_frequency_Hz);
  p.initial_amplitude_m = file.positive("initial_amplitude_m");
  p.end_amplitude_m = file.number_or("end_amplitude_m", p.initial_amplitude_m / 100.0);
  p.duration_s = file.number_or("duration_s", p.duration_s);
  file.finish();
  return std::make_unique<LogSweep>(p);
}

std::unique_ptr<RoadInput> read_iso8608(const io::YamlMap& file) {
  Iso8608RoadParameters p;
  p.road_class =
      parse_iso8608_class(file.choice("class", {"A", "B", "C", "D", "E", "F", "G", "H"}));
  p.random = read_random(file);
  file.finish();
  return std::make_unique<SpatialProfileRoad>(make_iso8608_road(p));
}

std::unique_ptr<RoadInput> read_power_law(const io::YamlMap& file) {
  PowerLawRoadParameters p;
  p.roughness_coefficient_m3 = file.positive("roughness_coefficient_m3");
  p.waviness = file.number("waviness");
  p.random = read_random(file);
  file.finish();
  return std::make_unique<SpatialProfileRoad>(make_power_law_road(p));
}

std::unique_ptr<RoadInput> read_cleat(const io::YamlMap& file) {
  CleatParameters p;
  p.shape = parse_cleat_shape(file.choice("shape", {"semicircular", "rectangular"}));
  p.height_m = file.positive("height_m");
  p.length_m = file.positive("length_m");
  p.start_distance_m = file.number_or("start_distance_m", p.start_distance_m);
  p.tyre_contact_length_m = file.number_or("tyre_contact_length_m", p.tyre_contact_length_m);
  p.speed_m_per_s = read_speed_m_per_s(file);
  if (file.has("duration_s")) p.duration_s = file.positive("duration_s");
  file.finish();
  return std::make_unique<SpatialProfileRoad>(make_cleat_road(p));
}

// Runs `load` on the data file named by key `file`; its errors (which name the data file)
// also name the YAML file and key that pointed there.
template <class Load>
auto with_data_file(const io::YamlMap& file, Load&& load) {
  try {
    return load();
  } catch (const InputError& e) {
    const std::string message = e.what();
    if (message.starts_with("key")) throw;  // about a YAML key, named by load_excitation
    throw InputError(fmt::format("{}: {}", file.locate("file"), message));
  }
}

std::unique_ptr<RoadInput> read_profile(const io::YamlMap& file) {
  const std::filesystem::path csv = file.file("file");
  ProfileRoadParameters p;
  p.speed_m_per_s = read_speed_m_per_s(file);
  p.offset_m = file.number_or("offset_m", p.offset_m);
  file.finish();
  return with_data_file(
      file, [&] { return std::make_unique<SpatialProfileRoad>(load_profile_road(csv, p)); });
}

std::unique_ptr<RoadInput> read_measured(const io::YamlMap& file) {
  const std::filesystem::path csv = file.file("file");
  const std::string channel = file.text_or("channel", "road");
  file.finish();
  return with_data_file(
      file, [&] { return std::make_unique<MeasuredRoad>(load_measured_road(csv, channel)); });
}

std::unique_ptr<RoadInput> read_opencrg_excitation(const io::YamlMap& file) {
  const std::filesystem::path crg = file.file("file");
  OpenCrgRoadParameters p;
  p.lateral_offset_m = file.number_or("lateral_offset_m", p.lateral_offset_m);
  p.speed_m_per_s = read_speed_m_per_s(file);
  p.offset_m = file.number_or("offset_m", p.offset_m);
  file.finish();
  return with_data_file(
      file, [&] { return std::make_unique<SpatialProfileRoad>(load_opencrg_road(crg, p)); });
}

}  // namespace

namespace {

using Reader = std::unique_ptr<RoadInput> (*)(const io::YamlMap&);

const std::map<std::string, Reader>& readers() {
  static const std::map<std::string, Reader> kReaders{
      {"log_sweep", read_log_sweep},       {"iso8608", read_iso8608},
      {"power_law", read_power_law},       {"cleat", read_cleat},
      {"profile", read_profile},           {"measured", read_measured},
      {"opencrg", read_opencrg_excitation}};
  return kReaders;
}

std::string read_type(const io::YamlMap& file) {
  std::set<std::string> types;
  for (const auto& entry : readers()) types.insert(entry.first);
  return file.choice("type", types);
}

// Runs `read` on the file; the parameter structs' own checks name the key ("key 'x' is …") but
// cannot know the file, so their messages gain it (YamlMap and CsvTable messages have it).
template <class Read>
auto naming_the_file(const std::filesystem::path& yaml_file, Read&& read) {
  try {
    return read();
  } catch (const InputError& e) {
    const std::string message = e.what();
    if (message.starts_with("key")) {
      throw InputError(fmt::format("{}: {}", yaml_file.string(), message));
    }
    throw;
  }
}

// The file's mapping with its speed replaced by `speed_m_per_s`.
io::YamlMap with_speed(const std::filesystem::path& yaml_file, double speed_m_per_s) {
  const io::YamlMap checked = io::YamlMap::load(yaml_file);
  if (!checked.has("speed_m_per_s") && !checked.has("speed_km_per_h")) {
    throw InputError(fmt::format(
        "{}: this excitation is not driven at a speed (no speed_m_per_s or speed_km_per_h), so "
        "a speed of {:.4g} km/h cannot be applied to it",
        yaml_file.string(), speed_m_per_s * 3.6));
  }
  YAML::Node root = YAML::Clone(YAML::LoadFile(yaml_file.string()));
  root.remove("speed_km_per_h");
  root["speed_m_per_s"] = speed_m_per_s;
  return io::YamlMap(root, yaml_file, "");
}

std::unique_ptr<RoadInput> read_excitation(const io::YamlMap& file) {
  const Reader read = readers().at(read_type(file));
  return naming_the_file(file.path(), [&] { return read(file); });
}

std::optional<RoadSpectrum> read_spectrum(const io::YamlMap& file) {
  const std::string type = read_type(file);
  if (type != "iso8608" && type != "power_law") return std::nullopt;
  return naming_the_file(file.path(), [&] {
    RoadSpectrum result;
    if (type == "iso8608") {
      result.spectrum = iso8608_spectrum(
          parse_iso8608_class(file.choice("class", {"A", "B", "C", "D", "E", "F", "G", "H"})));
    } else {
      PowerLawRoadParameters p;
      p.roughness_coefficient_m3 = file.positive("roughness_coefficient_m3");
      p.waviness = file.number("waviness");
      result.spectrum = p.spectrum();
    }
    const RandomRoadParameters random = read_random(file);
    file.finish();
    result.band = random.band;
    result.speed_m_per_s = random.speed_m_per_s;
    result.duration_s = random.duration_s;
    return std::optional<RoadSpectrum>(result);
  });
}

}  // namespace

std::unique_ptr<RoadInput> load_excitation(const std::filesystem::path& yaml_file) {
  return read_excitation(io::YamlMap::load(yaml_file));
}

std::unique_ptr<RoadInput> load_excitation(const std::filesystem::path& yaml_file,
                                           double speed_m_per_s) {
  return read_excitation(with_speed(yaml_file, speed_m_per_s));
}

std::optional<RoadSpectrum> load_road_spectrum(const std::filesystem::path& yaml_file,
                                               std::optional<double> speed_m_per_s) {
  // The full road is read first, so a spectrum is only ever given for a valid file.
  if (speed_m_per_s) {
    load_excitation(yaml_file, *speed_m_per_s);
    return read_spectrum(with_speed(yaml_file, *speed_m_per_s));
  }
  load_excitation(yaml_file);
  return read_spectrum(io::YamlMap::load(yaml_file));
}

}  // namespace ridefit::road
