// ridefit generate-lab OUT_DIR [--seed N]
// Synthetic strut rig tests with known truth (the data set in datasets/lab/ comes from here):
// seed 000's calibration test (quasi-static triangle, 3 mm at 1 mm/s, 10 cycles), a dynamic
// history, and three shim settings whose friction grows with the spring's compression (its
// Figure 4). Force = the strut-test model at the true parameters (CVODE at rtol 1e-10 on the
// exact displacement) + load-cell offset + seeded
// Gaussian noise, quantised like a 16-bit load cell over ±5 kN. Last, a semi-active (MR-like)
// strut under a random displacement with a coil current switching at random
// (semi_active_random.csv, with a current[A] column), and the same kind of damper in a car on the
// road (semi_active_drive.csv: road, accelerations and the current).
#include <fmt/core.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <numbers>
#include <random>

#include "command_options.h"
#include "ridefit/common/errors.h"
#include "ridefit/io/atomic_file.h"
#include "ridefit/io/output_paths.h"
#include "ridefit/io/staged_folder.h"
#include "ridefit/model/quarter_car.h"
#include "ridefit/model/strut_test.h"
#include "ridefit/road/commanded_road.h"
#include "ridefit/road/iso8608.h"
#include "ridefit/signal/statistics.h"
#include "ridefit/simulate/quarter_car_simulation.h"
#include "ridefit/simulate/strut_test_reference.h"
#include "subcommands.h"

namespace ridefit::cli {
namespace {

struct GenerateLabFlags {
  std::string output_dir;
  bool force = false;
  unsigned seed = 1;
};

constexpr double kNoise_N = 0.6;                  // 1 % of Fc = 60 N
constexpr double kOffset_N = 2.5;                 // load-cell zero error
constexpr double kQuantum_N = 10000.0 / 65536.0;  // 16 bit over ±5 kN

model::StrutTestParameters<double> truth(double coulomb_force_N) {
  // seed 000's Passat strut: σ0 well above the 488 N/mm top mount, Fc, d = 1, c = 887 Ns/m
  return {5e6, coulomb_force_N, 1.0, 488000.0, 886.9, 0.0, 0.0, kOffset_N};
}

double triangle(double time) {
  const double phase = std::fmod(time, 12.0) / 12.0;  // 0 → 3 → 0 → −3 → 0 mm at 1 mm/s
  return phase < 0.25   ? 0.012 * phase
         : phase < 0.75 ? 0.006 - 0.012 * phase
                        : -0.012 + 0.012 * phase;
}

double three_sines(double time) {
  const double w = 2.0 * std::numbers::pi;
  return 0.003 * std::sin(w * 0.7 * time) + 0.0015 * std::sin(w * 2.3 * time) +
         0.0008 * std::sin(w * 6.1 * time);
}

// The force by CVODE at rtol 1e-10 on the exact displacement (simulate/strut_test_reference.h):
// not the ESDIRK that `fit hysteresis` runs.
void write_test(const std::filesystem::path& path, const std::vector<double>& t,
                double (*displacement)(double), const model::StrutTestParameters<double>& p,
                std::mt19937_64& rng) {
  const std::vector<double> force = simulate::reference_strut_test_force(t, displacement, p);
  std::vector<double> x;
  for (double time : t) x.push_back(displacement(time));
  std::normal_distribution<double> noise(0.0, kNoise_N);
  io::write_atomically(path, [&](std::ostream& out) {
    out << "time[s],displacement[mm],force[N]\n";
    for (std::size_t k = 0; k < t.size(); ++k) {
      const double f = std::round((force[k] + noise(rng)) / kQuantum_N) * kQuantum_N;
      out << fmt::format("{:.4f},{:.6f},{:.3f}\n", t[k], 1e3 * x[k], f);
    }
  });
}

// An MR-like controlled strut (strut_test.h): passive c = 800 N·s/m and Fc = 40 N, rising by
// 1500 N·s/m and 180 N per ampere of coil current after a 12 ms lag.
model::StrutTestParameters<double> semi_active_truth() {
  model::StrutTestParameters<double> p{3e6, 40.0, 1.0, 500000.0, 800.0, 0.0, 0.0, kOffset_N};
  p.damping_per_command_Ns_per_m = 1500.0;
  p.coulomb_force_per_command_N = 180.0;
  p.command_lag_s = 0.012;
  return p;
}

// A coil current switching between random levels in [0, 2] A every 0.15–0.5 s with 2 ms smooth
// (tanh) edges, so that the reference integrator sees a smooth input.
struct SwitchingCurrent {
  std::vector<double> switch_s, levels;
  SwitchingCurrent(double duration_s, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> hold(0.15, 0.5), level(0.0, 2.0);
    levels.push_back(level(rng));
    for (double t = hold(rng); t < duration_s; t += hold(rng)) {
      switch_s.push_back(t);
      levels.push_back(level(rng));
    }
  }
  double operator()(double t) const {
    double u = levels[0];
    for (std::size_t i = 0; i < switch_s.size(); ++i) {
      u += 0.5 * (levels[i + 1] - levels[i]) * (1.0 + std::tanh((t - switch_s[i]) / 0.002));
    }
    return u;
  }
};

// 30 s at 1 kHz: 40 sines over 0.5–20 Hz (amplitudes ∝ 1/f, about 3 mm RMS) and a current
// switching between random levels in [0, 2] A every 0.15–0.5 s with 2 ms smooth edges; the force
// by CVODE at rtol 1e-10 on both exact signals.
void write_semi_active_test(const std::filesystem::path& path, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> angle(0.0, 2.0 * std::numbers::pi);
  std::vector<double> amplitude, frequency, phase;
  for (int i = 0; i < 40; ++i) {
    frequency.push_back(0.5 * std::pow(40.0, i / 39.0));
    amplitude.push_back(0.0012 / frequency.back());
    phase.push_back(angle(rng));
  }
  const auto x = [&](double t) {
    double sum = 0.0;
    for (std::size_t i = 0; i < amplitude.size(); ++i) {
      sum += amplitude[i] * std::sin(2.0 * std::numbers::pi * frequency[i] * t + phase[i]);
    }
    return sum;
  };
  const SwitchingCurrent current(30.0, rng);
  std::vector<double> t;
  for (int k = 0; k <= 30000; ++k) t.push_back(k * 1e-3);
  const std::vector<double> force =
      simulate::reference_strut_test_force(t, x, semi_active_truth(), current);
  std::normal_distribution<double> noise(0.0, kNoise_N);
  io::write_atomically(path, [&](std::ostream& out) {
    out << "time[s],displacement[mm],force[N],current[A]\n";
    for (std::size_t k = 0; k < t.size(); ++k) {
      const double f = std::round((force[k] + noise(rng)) / kQuantum_N) * kQuantum_N;
      out << fmt::format("{:.4f},{:.6f},{:.3f},{:.5f}\n", t[k], 1e3 * x(t[k]), f, current(t[k]));
    }
  });
}

// The MR-like damper in a car: the Passat corner (slip) with c = 600 + 1200·ū N·s/m, ū lagging
// the coil current by 12 ms, 120 s over an ISO 8608 class B road at 50 km/h with a current
// switching like the rig test's. CVODE at rtol 1e-10; 200 Hz; the accelerometers read with seeded
// Gaussian noise of 1 % of each channel's RMS.
model::QuarterCarParameters<double> semi_active_car() {
  // datasets/vehicles/passat_b8_front.yaml's corner, its damper replaced.
  model::QuarterCarParameters<double> p{};
  p.sprung_mass_kg = 385.40;
  p.unsprung_mass_kg = 46.761;
  p.tyre_stiffness_N_per_m = 288180.0;
  p.tyre_damping_Ns_per_m = 100.0;
  p.spring_stiffness_N_per_m = 29000.0;
  p.top_mount_spring_path_stiffness_N_per_m = 800000.0;
  p.top_mount_stiffness_N_per_m = 488000.0;
  p.dahl_sigma0_N_per_m = 5.0e6;
  p.dahl_exponent = 1.0;
  p.damping_Ns_per_m = 600.0;
  p.damping_per_command_Ns_per_m = 1200.0;
  p.command_lag_s = 0.012;
  return p;
}

void write_semi_active_drive(const std::filesystem::path& path, std::mt19937_64& rng) {
  constexpr double kDuration_s = 120.0, kRate_Hz = 200.0;
  road::Iso8608RoadParameters r;
  r.road_class = road::Iso8608Class::kB;
  r.random.speed_m_per_s = 50.0 / 3.6;
  r.random.duration_s = kDuration_s;
  r.random.seed = static_cast<unsigned>(rng() % 100000);
  const auto iso_road = road::make_iso8608_road(r);
  const SwitchingCurrent current(kDuration_s, rng);
  const road::CommandedRoad road(
      iso_road, [&](double t) { return current(t); }, "A");
  simulate::SimulationOptions options;
  options.output_rate_Hz = kRate_Hz;
  options.integrator.method = simulate::Method::kCvodeBdf;
  options.integrator.relative_tolerance = 1e-10;
  const model::QuarterCar car(model::DamperState::kSlip, semi_active_car(),
                              model::DamperCommand::kFromRoad);
  const auto run = simulate::simulate(car, road, options);
  std::normal_distribution<double> unit(0.0, 1.0);
  const double body_noise = 0.01 * signal::rms(run.body_acc_m_per_s2);
  const double wheel_noise = 0.01 * signal::rms(run.wheel_acc_m_per_s2);
  io::write_atomically(path, [&](std::ostream& out) {
    out << "time[s],road[mm],body_acc[m/s^2],wheel_acc[m/s^2],current[A]\n";
    for (std::size_t k = 0; k < run.time_s.size(); ++k) {
      const double body = run.body_acc_m_per_s2[k] + body_noise * unit(rng);
      const double wheel = run.wheel_acc_m_per_s2[k] + wheel_noise * unit(rng);
      out << fmt::format("{:.3f},{:.5f},{:.6f},{:.5f},{:.5f}\n", run.time_s[k], 1e3 * run.road_m[k],
                         body, wheel, current(run.time_s[k]));
    }
  });
}

void run(const GenerateLabFlags& flags) {
  const std::vector<std::string> files = {
      "triangle_3mm_1mmps.csv", "dynamic_60s.csv",        "shim_0mm.csv",          "shim_2mm.csv",
      "shim_4mm.csv",           "semi_active_random.csv", "semi_active_drive.csv", "truth.yaml"};
  io::RunOutputs({}).add_folder(flags.output_dir, "DIR", files, flags.force);
  io::prepare_output_directory(flags.output_dir, "DIR");
  // Written into a staged copy of the folder, put in place as a whole.
  io::StagedFolder staged(flags.output_dir, files);
  const std::filesystem::path dir = staged.path();
  std::mt19937_64 rng(flags.seed);
  std::vector<double> t;
  for (int k = 0; k <= 10 * 12 * 200; ++k) t.push_back(k / 200.0);
  write_test(dir / "triangle_3mm_1mmps.csv", t, triangle, truth(60.0), rng);
  std::vector<double> td;
  for (int k = 0; k <= 60000; ++k) td.push_back(k * 1e-3);
  write_test(dir / "dynamic_60s.csv", td, three_sines, truth(60.0), rng);
  std::vector<double> ts;
  for (int k = 0; k <= 3 * 12 * 200; ++k) ts.push_back(k / 200.0);
  for (int shim_mm : {0, 2, 4}) {
    write_test(dir / fmt::format("shim_{}mm.csv", shim_mm), ts, triangle,
               truth(40.0 + 5.0 * shim_mm), rng);
  }
  write_semi_active_test(dir / "semi_active_random.csv", rng);
  write_semi_active_drive(dir / "semi_active_drive.csv", rng);
  io::write_atomically(dir / "truth.yaml", [&](std::ostream& out) {
    out << fmt::format(
        "# The truth behind the synthetic rig tests of this folder (ridefit generate-lab, seed "
        "{}).\n# Strut: seed 000's Passat strut; the shim files differ only in Fc.\n"
        "dahl_sigma0_N_per_m: 5.0e6\ndahl_exponent: 1\ntop_mount_stiffness_N_per_m: 488000\n"
        "damping_Ns_per_m: 886.9\nforce_offset_N: {}\nforce_noise_std_N: {}\n"
        "force_quantum_N: {:.6f}\ncoulomb_force_N:\n  triangle_3mm_1mmps.csv: 60\n"
        "  dynamic_60s.csv: 60\n  shim_0mm.csv: 40\n  shim_2mm.csv: 50\n  shim_4mm.csv: 60\n"
        "# Fc = 40 N + 5 N/mm · spring compression (seed 000 Figure 4's kind of relation)\n"
        "semi_active_random.csv:  # an MR-like strut, its current in the file\n"
        "  dahl_sigma0_N_per_m: 3.0e6\n  coulomb_force_N: 40\n  dahl_exponent: 1\n"
        "  top_mount_stiffness_N_per_m: 500000\n  damping_Ns_per_m: 800\n"
        "  damping_per_command_Ns_per_m: 1500\n  coulomb_force_per_command_N: 180\n"
        "  command_lag_s: 0.012\n"
        "semi_active_drive.csv:  # the MR-like damper in the Passat corner (slip), on the road\n"
        "  damper_state: slip\n  damping_Ns_per_m: 600\n  damping_per_command_Ns_per_m: 1200\n"
        "  command_lag_s: 0.012\n  accelerometer_noise_share_of_rms: 0.01\n",
        flags.seed, kOffset_N, kNoise_N, kQuantum_N);
  });
  staged.commit();
  std::cout << "Rig tests written to " << flags.output_dir << "\n";
}

}  // namespace

void register_generate_lab(CLI::App& app) {
  auto flags = std::make_shared<GenerateLabFlags>();
  CLI::App* command = app.add_subcommand(
      "generate-lab", "Write synthetic strut rig tests with known truth (CSV + truth.yaml)");
  command->add_option("directory", flags->output_dir, "Output directory (created if missing)")
      ->required();
  command->add_option("--seed", flags->seed, "Seed of the force noise")->capture_default_str();
  command->add_flag("--force", flags->force,
                    "Write into an existing folder that holds files ridefit did not write there "
                    "(files of the same name are replaced)");
  command->callback([flags] { run(*flags); });
}

}  // namespace ridefit::cli
