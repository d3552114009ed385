// ridefit generate-hidden SPEC.yaml -o DIR [--seed N]
// Measurement records of a richer truth than the model the diagnosis is given: a model file plus
// effects switched on, simulated (CVODE) over a road, measured through a sensor model
// (study/sensor_model.h), written as CSVs with a separate truth file the diagnosis never reads.
//
// SPEC.yaml (paths relative to it):
//   datasets:
//     - name: seed_top_mount_stiffening          # file stem: NAME.csv, NAME_2.csv, NAME_truth.yaml
//       model: ../vehicles/passat_b8_front.yaml  # the truth's base
//       damper_state: stick_slip                 # optional: replaces the model's
//       set: {top_mount_small_amplitude_stiffness_N_per_m: 707000,
//             top_mount_transition_deflection_m: 0.0005}   # model keys switched on / changed
//       effects: [top_mount_amplitude_stiffening]          # library ids (or sensor_mount), truth
//       only excitation: ../excitations/iso8608_class_a_50kmh.yaml duration_s: 60 # default: the
//       excitation's sample_rate_Hz: 500             # default 500 records: 2 # default 2; record k
//       >= 2 drives another realisation of a
//                                       # random road (seed + k - 1) with other noise
//       sensor: {noise: 0.005, high_pass_Hz: 0.1, low_pass_Hz: 100,
//                mount: {channel: body_acc, frequency_Hz: 12, damping_ratio: 0.05}}
//       seed: 11                        # noise seed (default 1)
//     - name: rig_gas_force                      # a strut rig test instead (kind: strut_rig)
//       kind: strut_rig
//       model: ../vehicles/passat_b8_front.yaml  # its strut, put on the rig (strut_on_rig)
//       set: {gas_stiffness_N_per_m: 15000}      # strut-test keys (fitting/strut_parameters.h)
//       effects: [gas_force]
//       rig: {amplitudes_mm: [3, 1.5, 0.8], frequencies_Hz: [0.7, 2.3, 6.1]}  # a multisine;
//                                       # record k >= 2 takes seeded random phases
//       duration_s: 30                  # required
//       sample_rate_Hz: 1000            # default 1000
//       noise_N: 0.6                    # Gaussian load-cell noise (default 0.6 N)
#include <fmt/core.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <numbers>
#include <random>
#include <set>

#include <unistd.h>

#include <yaml-cpp/yaml.h>

#include "command_options.h"
#include "ridefit/common/errors.h"
#include "ridefit/fitting/diagnose/effect.h"
#include "ridefit/fitting/strut_parameters.h"
#include "ridefit/io/atomic_file.h"
#include "ridefit/io/output_paths.h"
#include "ridefit/io/quarter_car_file.h"
#include "ridefit/io/staged_folder.h"
#include "ridefit/io/temporary_files.h"
#include "ridefit/io/yaml_map.h"
#include "ridefit/road/excitation_file.h"
#include "ridefit/road/log_sweep.h"
#include "ridefit/simulate/quarter_car_simulation.h"
#include "ridefit/simulate/strut_test_reference.h"
#include "ridefit/study/sensor_model.h"
#include "subcommands.h"

namespace ridefit::cli {
namespace {

struct GenerateHiddenFlags {
  std::string spec_file;
  std::string output_dir;
  long seed_offset = 0;
  bool force = false;
};

struct Dataset {
  std::string name;
  bool strut_rig = false;
  std::vector<double> rig_amplitudes_m, rig_frequencies_Hz;
  double noise_N = 0.6;
  std::filesystem::path model;
  std::string damper_state;
  std::map<std::string, double> set;
  std::string set_location;  // where `set:` is in the spec, for messages
  std::string location;      // the dataset's entry in the spec
  std::vector<std::string> effects;
  std::filesystem::path excitation;
  double duration_s = 0.0;
  double sample_rate_Hz = 500.0;
  int records = 2;
  study::SensorModel sensor;
  std::string mount_channel;
  long seed = 1;
};

Dataset read_dataset(const io::YamlMap& d) {
  Dataset out;
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
  std::set<std::string> known{"sensor_mount"};
  for (const auto& e : fitting::diagnose::effect_library()) known.emplace(e->id());
  if (d.has("effects")) {
    for (const auto& id : d.texts("effects")) {
      if (!known.count(id)) {
        std::string list;
        for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
        throw InputError(
            fmt::format("{}: unknown effect '{}'; one of: {}", d.locate("effects"), id, list));
      }
      out.effects.push_back(id);
    }
  }
  if (out.strut_rig) {
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
  } else {
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
  out.records = static_cast<int>(d.has("records") ? d.integer("records") : 2);
  if (out.records < 1 || out.records > 20) {
    throw InputError(fmt::format("{} is {}, expected 1 to 20", d.locate("records"), out.records));
  }
  out.seed = d.integer_or("seed", 1);
  if (d.has("sensor") && out.strut_rig) {
    throw InputError(
        fmt::format("{}: a strut rig dataset takes noise_N, not a sensor", d.locate("sensor")));
  }
  if (d.has("sensor")) {
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
      out.sensor.mount =
          study::SensorMount{m.positive("frequency_Hz"), m.positive("damping_ratio")};
      below_nyquist(m, "frequency_Hz", out.sensor.mount->frequency_Hz);
      m.finish();
    }
    s.finish();
  }
  d.finish();
  return out;
}

// The excitation of record k: random roads get seed + k − 1 (another realisation).
std::unique_ptr<road::RoadInput> excitation_for(const Dataset& d, int record,
                                                const std::filesystem::path& scratch) {
  YAML::Node node = YAML::LoadFile(d.excitation.string());
  const std::string type = node["type"] ? node["type"].as<std::string>() : "";
  if (record == 1 || (type != "iso8608" && type != "power_law")) {
    return road::load_excitation(d.excitation);
  }
  const long seed = node["seed"] ? node["seed"].as<long>() : 1;
  node["seed"] = seed + record - 1;
  const io::TemporaryFile registered(scratch);  // removed if the run is interrupted
  {
    std::ofstream out(scratch);
    out << node << "\n";
  }
  auto road = road::load_excitation(scratch);
  std::filesystem::remove(scratch);
  return road;
}

// A strut rig dataset: each record a multisine displacement (record 1 in sine phase, record
// k >= 2 with seeded random phases), the strut-test force at the truth plus Gaussian noise.
void write_rig_dataset(const Dataset& d, const model::StrutTestParameters<double>& strut,
                       const std::filesystem::path& dir, const std::filesystem::path& out_dir,
                       long seed_offset) {
  YAML::Node truth;
  truth["dataset"] = d.name;
  truth["kind"] = "strut_rig";
  truth["model"] = std::filesystem::relative(d.model, dir).string();
  for (const auto& [key, value] : d.set) truth["set"][key] = value;
  truth["effects"] = YAML::Node(YAML::NodeType::Sequence);
  for (const auto& id : d.effects) truth["effects"].push_back(id);
  for (std::size_t p = 0; p < fitting::kStrutParameters.size(); ++p) {
    truth["strut"][std::string(fitting::kStrutParameters[p].name())] =
        fitting::strut_parameter(strut, p);
  }
  truth["sample_rate_Hz"] = d.sample_rate_Hz;
  truth["noise_N"] = d.noise_N;
  const auto samples = static_cast<std::size_t>(std::floor(d.duration_s * d.sample_rate_Hz)) + 1;
  for (int k = 1; k <= d.records; ++k) {
    std::mt19937_64 rng(static_cast<unsigned long>(d.seed + seed_offset) * 1000u +
                        static_cast<unsigned long>(k));
    std::uniform_real_distribution<double> phase(0.0, 2.0 * std::numbers::pi);
    std::vector<double> phases(d.rig_amplitudes_m.size(), 0.0);
    if (k > 1) {
      for (double& p : phases) p = phase(rng);
    }
    auto displacement = [&](double time) {
      double x = 0.0;
      for (std::size_t j = 0; j < phases.size(); ++j) {
        x += d.rig_amplitudes_m[j] *
             std::sin(2.0 * std::numbers::pi * d.rig_frequencies_Hz[j] * time + phases[j]);
      }
      return x;
    };
    std::vector<double> t(samples), x(samples);
    for (std::size_t n = 0; n < samples; ++n) {
      t[n] = static_cast<double>(n) / d.sample_rate_Hz;
      x[n] = displacement(t[n]);
    }
    // CVODE at rtol 1e-10 on the exact multisine: not the ESDIRK the diagnosis fits with.
    const auto force = simulate::reference_strut_test_force(t, displacement, strut);
    std::normal_distribution<double> noise(0.0, d.noise_N);
    const std::string file = k == 1 ? d.name + ".csv" : fmt::format("{}_{}.csv", d.name, k);
    io::write_atomically(out_dir / file, [&](std::ostream& out) {
      out << "time[s],displacement[mm],force[N]\n";
      for (std::size_t n = 0; n < samples; ++n) {
        out << fmt::format("{:.6g},{:.6g},{:.6g}\n", t[n], 1e3 * x[n],
                           force[n] + (d.noise_N > 0.0 ? noise(rng) : 0.0));
      }
    });
    truth["records"].push_back(file);
    std::cerr << fmt::format("generate-hidden: {} ({:.0f} s at {:g} Hz)\n", (dir / file).string(),
                             t.back(), d.sample_rate_Hz);
  }
  io::write_atomically(out_dir / (d.name + "_truth.yaml"), [&](std::ostream& out) {
    out << "# The truth behind " << d.name
        << " (ridefit generate-hidden): not to be read by the diagnosis\n"
        << truth << "\n";
  });
}

void run(const GenerateHiddenFlags& flags) {
  const io::YamlMap spec = io::YamlMap::load(flags.spec_file);
  std::vector<Dataset> datasets;
  for (const auto& d : spec.maps("datasets")) datasets.push_back(read_dataset(d));
  spec.finish();
  if (datasets.empty()) throw InputError(fmt::format("{}: no datasets", flags.spec_file));
  // Every file the run writes, each once; none an input.
  std::vector<std::string> files;
  io::RunOutputs outputs({flags.spec_file});
  for (std::size_t i = 0; i < datasets.size(); ++i) {
    const Dataset& d = datasets[i];
    for (std::size_t j = 0; j < i; ++j) {
      if (datasets[j].name == d.name) {
        throw InputError(fmt::format(
            "{}: dataset name '{}' is also the name of dataset {} ({}); each dataset's files are "
            "named after it, so give each its own name",
            d.location, d.name, j + 1, datasets[j].location));
      }
    }
    outputs.add_input(d.model);
    if (!d.strut_rig) outputs.add_input(d.excitation);
    for (int k = 1; k <= d.records; ++k) {
      files.push_back(k == 1 ? d.name + ".csv" : fmt::format("{}_{}.csv", d.name, k));
    }
    files.push_back(d.name + "_truth.yaml");
  }
  outputs.add_folder(flags.output_dir, "-o", files, flags.force);
  // Every model and excitation is checked before anything is simulated or written.
  std::vector<model::QuarterCar> truths;
  std::vector<model::StrutTestParameters<double>> struts;
  for (const auto& d : datasets) {
    if (d.strut_rig) {
      const io::QuarterCarFile file = io::load_quarter_car(d.model);
      model::StrutTestParameters<double> strut = fitting::strut_on_rig(file.make_model());
      for (const auto& [key, value] : d.set) {
        try {
          fitting::strut_parameter(strut, fitting::strut_parameter_index(key)) = value;
        } catch (const InputError& e) {
          throw InputError(fmt::format("{}: {}", d.set_location, e.what()));
        }
      }
      truths.push_back(file.make_model());
      struts.push_back(strut);
      continue;
    }
    try {
      truths.push_back(io::load_quarter_car(d.model, d.set, d.damper_state).make_model());
    } catch (const InputError& e) {
      throw InputError(
          with_override_origin(e.what(), fmt::format("given in {} as ", d.set_location)));
    }
    struts.emplace_back();
    road::load_excitation(d.excitation);
    study::SensorModel check = d.sensor;
    std::mt19937_64 rng(0);
    study::measure(std::vector<double>(8, 0.0), d.sample_rate_Hz, check, rng);
  }
  io::prepare_output_directory(flags.output_dir, "-o");
  const std::filesystem::path dir = flags.output_dir;
  // Written into a staged copy of the folder, put in place as a whole; paths in the truth files
  // are relative to the folder itself.
  io::StagedFolder staged(dir, files);
  const std::filesystem::path out_dir = staged.path();
  for (std::size_t i = 0; i < datasets.size(); ++i) {
    const Dataset& d = datasets[i];
    if (d.strut_rig) {
      write_rig_dataset(d, struts[i], dir, out_dir, flags.seed_offset);
      continue;
    }
    YAML::Node truth;
    truth["dataset"] = d.name;
    truth["model"] = std::filesystem::relative(d.model, dir).string();
    if (!d.damper_state.empty()) truth["damper_state"] = d.damper_state;
    for (const auto& [key, value] : d.set) truth["set"][key] = value;
    truth["effects"] = YAML::Node(YAML::NodeType::Sequence);
    for (const auto& id : d.effects) truth["effects"].push_back(id);
    truth["excitation"] = std::filesystem::relative(d.excitation, dir).string();
    truth["sample_rate_Hz"] = d.sample_rate_Hz;
    truth["noise_fraction"] = d.sensor.noise_fraction;
    truth["high_pass_Hz"] = d.sensor.high_pass_Hz;
    truth["low_pass_Hz"] = d.sensor.low_pass_Hz > 0 ? d.sensor.low_pass_Hz : 0.4 * d.sample_rate_Hz;
    if (d.sensor.mount) {
      truth["mount"]["channel"] = d.mount_channel;
      truth["mount"]["frequency_Hz"] = d.sensor.mount->frequency_Hz;
      truth["mount"]["damping_ratio"] = d.sensor.mount->damping_ratio;
    }
    for (int k = 1; k <= d.records; ++k) {
      const auto road = excitation_for(
          d, k, out_dir / fmt::format(".road_{}.yaml.tmp{}", d.name, static_cast<long>(getpid())));
      simulate::SimulationOptions options;
      options.output_rate_Hz = d.sample_rate_Hz;
      options.duration_s = d.duration_s;
      // CVODE, not the ESDIRK that `diagnose` fits with (no inverse crime), at the tolerance the
      // shipped records were made with (bit for bit); its error is far below the sensor noise.
      options.integrator.method = simulate::Method::kCvodeBdf;
      options.integrator.relative_tolerance = 1e-6;
      const auto run = simulate::simulate(truths[i], *road, options);
      std::mt19937_64 rng(static_cast<unsigned long>(d.seed + flags.seed_offset) * 1000u +
                          static_cast<unsigned long>(k));
      study::SensorModel plain = d.sensor;
      plain.mount.reset();
      const auto& mounted = d.sensor;
      const auto body = study::measure(run.body_acc_m_per_s2, d.sample_rate_Hz,
                                       d.mount_channel == "body_acc" ? mounted : plain, rng);
      const auto wheel = study::measure(run.wheel_acc_m_per_s2, d.sample_rate_Hz,
                                        d.mount_channel == "wheel_acc" ? mounted : plain, rng);
      const std::string file = k == 1 ? d.name + ".csv" : fmt::format("{}_{}.csv", d.name, k);
      io::write_atomically(out_dir / file, [&](std::ostream& out) {
        out << "time[s],road[m],body_acc[m/s^2],wheel_acc[m/s^2]\n";
        for (std::size_t n = 0; n < run.time_s.size(); ++n) {
          out << fmt::format("{:.6g},{:.6g},{:.6g},{:.6g}\n", run.time_s[n], run.road_m[n], body[n],
                             wheel[n]);
        }
      });
      truth["records"].push_back(file);
      std::cerr << fmt::format("generate-hidden: {} ({:.0f} s at {:g} Hz)\n", (dir / file).string(),
                               run.time_s.back(), d.sample_rate_Hz);
    }
    io::write_atomically(out_dir / (d.name + "_truth.yaml"), [&](std::ostream& out) {
      out << "# The truth behind " << d.name
          << " (ridefit generate-hidden): not to be read by the diagnosis\n"
          << truth << "\n";
    });
  }
  staged.commit();
}

}  // namespace

void register_generate_hidden(CLI::App& app) {
  auto flags = std::make_shared<GenerateHiddenFlags>();
  CLI::App* command = app.add_subcommand(
      "generate-hidden",
      "Simulate measurement records of a model with hidden effects switched on (CSV) and their "
      "truth files, for testing `ridefit diagnose`");
  command->add_option("spec", flags->spec_file, "Datasets to generate (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("-o,--output", flags->output_dir, "Output folder")->required();
  command->add_option("--seed", flags->seed_offset, "Added to every dataset's noise seed")
      ->capture_default_str();
  command->add_flag("--force", flags->force,
                    "Write into an existing -o folder that holds files ridefit did not write "
                    "there (files of the same name are replaced; inputs never are)");
  command->callback([flags] { run(*flags); });
}

}  // namespace ridefit::cli
