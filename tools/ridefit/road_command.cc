// ridefit road PROFILE.csv|ROAD.crg|RECORD.csv [--lateral-offset M] [--speed V --channel C]
//              [--segment M] [--psd-segment M] [--psd out.csv] [--plot FIG.png|svg] [--json]
// The ISO 8608 class and the IRI (ASTM E1926) of a measured longitudinal road profile: a
// profile over distance, an OpenCRG track, or the road channel of a vehicle record over time
// driven at a known speed.
#include <fmt/core.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <regex>
#include <string>
#include <system_error>

#include "ridefit/common/errors.h"
#include "ridefit/io/csv_table.h"
#include "ridefit/io/gnuplot_figure.h"
#include "ridefit/io/measurement_file.h"
#include "ridefit/io/output_paths.h"
#include "ridefit/road/international_roughness_index.h"
#include "ridefit/road/iso8608_classification.h"
#include "ridefit/road/road_profile.h"
#include "ridefit/road/road_profile_file.h"
#include "ridefit/study/road_profile_figure.h"
#include "subcommands.h"

namespace ridefit::cli {
namespace {

struct RoadFlags {
  std::string profile_file;
  std::optional<double> lateral_offset_m;
  std::string speed;  // with its unit: 50km/h, 13.9m/s; empty = not given
  std::string channel;
  double segment_m = 0.0;      // 0 = 100 m, or the whole profile when it is shorter
  double psd_segment_m = 0.0;  // 0 = min(100 m, length/4)
  std::string psd_file;
  std::string plot_file;
  bool json = false;
};

// The spectrum as a CSV (or .mat) that reads back (CsvTable units); written atomically.
void write_psd(const std::string& file, const road::Iso8608Classification& result) {
  io::CsvTable table;
  table.add("spatial_frequency", "cycles/m", result.spatial_frequency_cycles_per_m);
  table.add("psd", "m^3", result.psd_m3);
  table.add("psd_lower", "m^3", result.psd_lower_m3);
  table.add("psd_upper", "m^3", result.psd_upper_m3);
  io::write_measurement_table(table, file);
}

// `--speed 50km/h` or `--speed 13.9m/s` in m/s; a bare number is refused, since both units are
// common.
std::optional<double> speed_m_per_s(const std::string& text) {
  if (text.empty()) return std::nullopt;
  static const std::regex pattern(R"(\s*([-+0-9.eE]+)\s*(m/s|km/h)\s*)");
  std::smatch match;
  double value = 0.0;
  if (std::regex_match(text, match, pattern)) {
    const std::string number = match[1].str();
    const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
    if (error == std::errc() && end == number.data() + number.size()) {
      return match[2].str() == "km/h" ? value / 3.6 : value;
    }
  }
  throw InputError(fmt::format(
      "--speed {}: expected a speed with its unit, e.g. --speed 50km/h or --speed 13.9m/s", text));
}

void run(const RoadFlags& flags) {
  io::RunOutputs outputs({flags.profile_file});
  outputs.add_file(flags.psd_file, "--psd");
  outputs.add_plot(flags.plot_file, "--plot");
  if (flags.segment_m < 0.0 || !std::isfinite(flags.segment_m)) {
    throw InputError(fmt::format("--segment {}: expected a length > 0 in m", flags.segment_m));
  }
  road::RoadProfile profile;
  try {
    profile = road::load_road_profile(
        flags.profile_file, {flags.lateral_offset_m, speed_m_per_s(flags.speed), flags.channel});
  } catch (const road::MissingDrivingSpeed& e) {
    throw InputError(fmt::format("{}: give it with --speed, e.g. --speed 50km/h", e.what()));
  }
  road::Iso8608ClassificationOptions psd_options;
  psd_options.segment_length_m = flags.psd_segment_m;
  road::IriOptions iri_options;
  iri_options.segment_length_m = flags.segment_m > 0.0 ? flags.segment_m
                                                       : std::min(iri_options.segment_length_m,
                                                                  road::profile_length_m(profile));
  road::Iso8608Classification iso;
  road::InternationalRoughnessIndex iri;
  try {
    iso = road::classify_iso8608(profile, psd_options);
    iri = road::international_roughness_index(profile, iri_options);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", flags.profile_file, e.what()));
  }
  if (!flags.psd_file.empty()) write_psd(flags.psd_file, iso);
  if (!flags.plot_file.empty()) {
    io::draw_figure(study::road_profile_figure(flags.profile_file, iso, iri), flags.plot_file);
  }

  const std::string road_class(1, road::to_char(iso.road_class));
  if (flags.json) {
    nlohmann::json segments = nlohmann::json::array();
    for (const auto& s : iri.segments) {
      segments.push_back(
          {{"start_m", s.start_m}, {"end_m", s.end_m}, {"iri_m_per_km", s.iri_m_per_km}});
    }
    const nlohmann::json summary = {
        {"profile", flags.profile_file},
        {"length_m", road::profile_length_m(profile)},
        {"iso8608",
         {{"class", road_class},
          {"reference_psd_m3", iso.reference_psd_m3},
          {"reference_cycles_per_m", road::kIso8608ReferenceCyclesPerM},
          {"waviness", iso.waviness},
          {"free_fit_reference_psd_m3", iso.free_fit_reference_psd_m3},
          {"band_cycles_per_m", {iso.band_low_cycles_per_m, iso.band_high_cycles_per_m}},
          {"psd_segment_m", iso.segment_length_m}}},
        {"iri",
         {{"iri_m_per_km", iri.iri_m_per_km},
          {"spacing_m", iri.spacing_m},
          {"segments", segments}}}};
    std::cout << summary.dump(2) << "\n";
    return;
  }
  std::cout << fmt::format("profile        {} ({:.1f} m)\n", flags.profile_file,
                           road::profile_length_m(profile));
  std::cout << fmt::format("ISO 8608 class {}\n", road_class);
  std::cout << fmt::format(
      "Gd(0.1)        {:.4g} m^3 (waviness 2, {:.4g}–{:.4g} cycles/m, {} bins)\n",
      iso.reference_psd_m3, iso.band_low_cycles_per_m, iso.band_high_cycles_per_m, iso.fit_bins);
  std::cout << fmt::format("free fit       Gd(0.1) {:.4g} m^3, waviness {:.3f}\n",
                           iso.free_fit_reference_psd_m3, iso.waviness);
  std::cout << fmt::format("IRI            {:.3f} m/km\n", iri.iri_m_per_km);
  std::cout << fmt::format("{:>10} {:>10} {:>12}\n", "start[m]", "end[m]", "IRI[m/km]");
  for (const auto& s : iri.segments) {
    std::cout << fmt::format("{:>10.1f} {:>10.1f} {:>12.3f}\n", s.start_m, s.end_m, s.iri_m_per_km);
  }
}

}  // namespace

void register_road(CLI::App& app) {
  auto flags = std::make_shared<RoadFlags>();
  CLI::App* command = app.add_subcommand(
      "road",
      "ISO 8608 class and IRI (ASTM E1926) of a road profile (CSV, an OpenCRG track, or a "
      "vehicle record's road channel)");
  command
      ->add_option("profile", flags->profile_file,
                   "Profile CSV (distance[m],elevation[m]) or .mat with those channels, OpenCRG "
                   "road (.crg), or vehicle record over time (time[s],road[m],…; needs --speed)")
      ->required();
  command->add_option("--lateral-offset", flags->lateral_offset_m,
                      "OpenCRG: the track's lateral position v in m (default 0, the reference "
                      "line; interpolated between long sections)");
  command->add_option("--speed", flags->speed,
                      "Vehicle record: the speed it was driven at, with its unit (50km/h, "
                      "13.9m/s); distance = speed × time");
  command->add_option("--channel", flags->channel,
                      "Vehicle record: the road channel (default road, or road_front when the "
                      "record has no road channel)");
  command->add_option("--segment", flags->segment_m,
                      "IRI reporting segment in m (default 100, or the whole profile if shorter)");
  command->add_option("--psd-segment", flags->psd_segment_m,
                      "Welch segment for the PSD in m (default min(100, length/4))");
  command->add_option("--psd", flags->psd_file,
                      "Write the PSD and its 90 % interval to a CSV (or .mat)");
  command->add_option("--plot", flags->plot_file,
                      "Figure (.png or .svg): the PSD with the ISO 8608 classes, IRI per segment");
  command->add_flag("--json", flags->json, "Print the results as JSON");
  command->callback([flags] { run(*flags); });
}

}  // namespace ridefit::cli
