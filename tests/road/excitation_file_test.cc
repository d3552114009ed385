#include "ridefit/road/excitation_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/road/log_sweep.h"
#include "ridefit/road/measured_road.h"
#include "ridefit/road/spatial_profile_road.h"

namespace ridefit::road {
namespace {

const std::filesystem::path kExcitations =
    std::filesystem::path(RIDEFIT_SOURCE_DIR) / "datasets" / "excitations";

TEST(ExcitationDatasets, SweepsAreTheSeedsSweeps) {
  for (const auto& [file, amplitude_m] : std::vector<std::pair<std::string, double>>{
           {"sweep_2mm.yaml", 0.002}, {"sweep_10mm.yaml", 0.010}}) {
    SCOPED_TRACE(file);
    const auto road = load_excitation(kExcitations / file);
    const auto* sweep = dynamic_cast<const LogSweep*>(road.get());
    ASSERT_NE(sweep, nullptr);
    EXPECT_DOUBLE_EQ(sweep->duration_s(), 60.0);
    EXPECT_DOUBLE_EQ(sweep->amplitude_m(0.0), amplitude_m);
    EXPECT_NEAR(sweep->amplitude_m(60.0), amplitude_m / 100.0, 1e-15);
    EXPECT_DOUBLE_EQ(sweep->instantaneous_frequency_Hz(0.0), 0.1);
    EXPECT_NEAR(sweep->instantaneous_frequency_Hz(60.0), 30.0, 1e-12);
  }
}

TEST(ExcitationDatasets, DrivenRoadsHaveTheirSpeedsAndDurations) {
  struct Expected {
    std::string file;
    double speed_m_per_s;
    double duration_s;
  };
  for (const auto& e : std::vector<Expected>{
           {"iso8608_class_a_50kmh.yaml", 50.0 / 3.6, 60.0},
           {"smooth_road_seed001.yaml", 20.0 / 3.6, 60.0},
           {"cleat_semicircular_20mm.yaml", 40.0 / 3.6, (2.0 + 0.04 + 0.05) / (40.0 / 3.6) + 3.0},
           {"profile_example.yaml", 30.0 / 3.6, 20.0 / (30.0 / 3.6)}}) {
    SCOPED_TRACE(e.file);
    const auto road = load_excitation(kExcitations / e.file);
    const auto* profile = dynamic_cast<const SpatialProfileRoad*>(road.get());
    ASSERT_NE(profile, nullptr);
    EXPECT_DOUBLE_EQ(profile->speed_m_per_s().value(), e.speed_m_per_s);
    EXPECT_NEAR(profile->duration_s(), e.duration_s, 1e-12);
    EXPECT_EQ(road->at(0.0).elevation_m, 0.0);  // every dataset starts the car on h = 0
  }
  // Seeded: loading twice gives the same road.
  const auto a = load_excitation(kExcitations / "iso8608_class_a_50kmh.yaml");
  const auto b = load_excitation(kExcitations / "iso8608_class_a_50kmh.yaml");
  EXPECT_EQ(a->at(31.7).elevation_m, b->at(31.7).elevation_m);
  EXPECT_NE(a->at(31.7).elevation_m, 0.0);
  // The example profile's hump (25 mm at 4.5 m) and dip (−10 mm at 12.3 m), in metres.
  const auto p = load_excitation(kExcitations / "profile_example.yaml");
  EXPECT_NEAR(p->at(4.5 / (30.0 / 3.6)).elevation_m, 0.025, 1e-12);
  EXPECT_NEAR(p->at(12.3 / (30.0 / 3.6)).elevation_m, -0.010, 1e-12);
  // The cleat's enveloped peak.
  const auto c = load_excitation(kExcitations / "cleat_semicircular_20mm.yaml");
  EXPECT_NEAR(c->at(2.02 / (40.0 / 3.6)).elevation_m, std::numbers::pi * 0.02 * 0.04 / 0.4, 1e-6);
}

class ExcitationFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           (std::string("ridefit_excitation_") + info->name() + "_" + std::to_string(getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_ / "data");
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path write(const std::string& name, const std::string& content) const {
    std::ofstream(dir_ / name) << content;
    return dir_ / name;
  }
  // The InputError message of loading `content` (as bad.yaml), checked for the file name.
  std::string error_of(const std::string& content) const {
    const auto path = write("bad.yaml", content);
    try {
      load_excitation(path);
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("bad.yaml"), std::string::npos) << message;
      return message;
    }
    ADD_FAILURE() << "no InputError for:\n" << content;
    return "";
  }
  std::filesystem::path dir_;
};

#define EXPECT_CONTAINS(haystack, needle) \
  EXPECT_NE((haystack).find(needle), std::string::npos) << (haystack)

TEST_F(ExcitationFileTest, BadFilesNameTheKey) {
  const std::string sweep = "type: log_sweep\ninitial_amplitude_m: 0.01\n";
  EXPECT_CONTAINS(error_of(sweep + "duraton_s: 60\n"), "'duraton_s'");  // unknown key
  EXPECT_CONTAINS(error_of("type: log_sweep\nduration_s: 60\n"), "'initial_amplitude_m'");
  EXPECT_CONTAINS(error_of("type: log_sweep\ninitial_amplitude_m: ten\n"), "'initial_amplitude_m'");
  EXPECT_CONTAINS(error_of(sweep + "end_frequency_Hz: [1, 2]\n"), "'end_frequency_Hz'");
  EXPECT_CONTAINS(error_of(sweep + "start_frequency_Hz: -1\n"), "'start_frequency_Hz'");
  EXPECT_CONTAINS(error_of("type: sine\n"), "'type'");
  EXPECT_CONTAINS(error_of("type: sine\n"), "log_sweep");  // lists the types
  EXPECT_CONTAINS(error_of("initial_amplitude_m: 0.01\n"), "'type'");

  const std::string iso = "type: iso8608\nclass: B\nduration_s: 10\n";
  const std::string both = error_of(iso + "speed_m_per_s: 10\nspeed_km_per_h: 36\n");
  EXPECT_CONTAINS(both, "'speed_m_per_s'");
  EXPECT_CONTAINS(both, "'speed_km_per_h'");
  EXPECT_CONTAINS(error_of(iso), "'speed_m_per_s'");  // neither
  EXPECT_CONTAINS(error_of(iso + "speed_km_per_h: fast\n"), "'speed_km_per_h'");
  EXPECT_CONTAINS(error_of(iso + "speed_km_per_h: 50\nseed: -3\n"), "'seed'");
  EXPECT_CONTAINS(error_of(iso + "speed_km_per_h: 50\nseed: 1.5\n"), "'seed'");
  EXPECT_CONTAINS(error_of(iso + "speed_km_per_h: 50\nsample_spacing_m: 1\n"),
                  "'sample_spacing_m'");
  EXPECT_CONTAINS(error_of("type: iso8608\nclass: Z\nduration_s: 10\nspeed_m_per_s: 5\n"),
                  "'class'");

  EXPECT_CONTAINS(error_of("type: power_law\nroughness_coefficient_m3: 4.8e-7\nwaviness: 9\n"
                           "speed_m_per_s: 5\nduration_s: 10\n"),
                  "'waviness'");
  EXPECT_CONTAINS(error_of("type: cleat\nshape: triangular\nheight_m: 0.02\nlength_m: 0.04\n"
                           "speed_m_per_s: 5\n"),
                  "'shape'");
  EXPECT_CONTAINS(error_of("type: cleat\nshape: rectangular\nheight_m: 0.02\nlength_m: 0.04\n"
                           "speed_m_per_s: 5\nstart_distance_m: 0\n"),
                  "'start_distance_m'");
  EXPECT_CONTAINS(error_of("type: profile\nspeed_m_per_s: 5\n"), "'file'");
}

TEST_F(ExcitationFileTest, FilesAreReadRelativeToTheYamlAndTheirErrorsNameTheCsv) {
  write("data/drive.csv", "time[s],road[mm],road_rear[mm]\n0,0\n0.1,1\n");  // ragged row 2
  const std::string ragged = error_of("type: measured\nfile: data/drive.csv\n");
  EXPECT_CONTAINS(ragged, "drive.csv");
  EXPECT_CONTAINS(ragged, "row 2");

  write("data/drive.csv",
        "time[s],road[mm],road_rear[mm]\n0,0,0\n0.1,1,0\n0.2,2,1\n0.3,3,2\n0.4,4,3\n");
  const auto front = load_excitation(write("m.yaml", "type: measured\nfile: data/drive.csv\n"));
  EXPECT_NEAR(front->at(0.2).elevation_m, 0.002, 1e-15);
  const auto rear = load_excitation(
      write("r.yaml", "type: measured\nfile: data/drive.csv\nchannel: road_rear\n"));
  EXPECT_NEAR(rear->at(0.2).elevation_m, 0.001, 1e-15);
  EXPECT_CONTAINS(error_of("type: measured\nfile: data/drive.csv\nchannel: road_left\n"),
                  "'road_left'");

  write("data/p.csv", "distance[mm],elevation[mm]\n0,0\n100,1\n200,2\n300,1\n400,0\n");
  const auto profile = load_excitation(
      write("p.yaml", "type: profile\nfile: data/p.csv\nspeed_m_per_s: 0.5\noffset_m: 0.1\n"));
  EXPECT_NEAR(profile->at(0.2).elevation_m, 0.002, 1e-15);  // 0.1 + 0.5·0.2 = 0.2 m
  EXPECT_NEAR(profile->duration_s(), 0.3 / 0.5, 1e-12);
  EXPECT_CONTAINS(error_of("type: profile\nfile: data/p.csv\nspeed_m_per_s: 0.5\noffset_m: 1\n"),
                  "'offset_m'");
  EXPECT_CONTAINS(error_of("type: profile\nfile: data/missing.csv\nspeed_m_per_s: 0.5\n"),
                  "not found");
}

// Each of these crashed (std::bad_alloc, an "internal error"), hung or ate gigabytes before.
TEST_F(ExcitationFileTest, AdversarialValuesAreInputErrorsNamingTheKey) {
  const std::string sweep = "type: log_sweep\ninitial_amplitude_m: 0.01\n";
  EXPECT_CONTAINS(error_of(sweep + "duration_s: 1e9\n"), "'duration_s'");
  const std::string high = error_of(sweep + "end_frequency_Hz: 1e6\n");
  EXPECT_CONTAINS(high, "'end_frequency_Hz'");
  EXPECT_CONTAINS(high, "500 Hz");

  const std::string iso = "type: iso8608\nclass: B\n";
  const std::string long_road = error_of(iso + "speed_km_per_h: 50\nduration_s: 1e9\n");
  EXPECT_CONTAINS(long_road, "'duration_s'");
  EXPECT_CONTAINS(long_road, "'sample_spacing_m'");
  EXPECT_CONTAINS(long_road, "2.78e+11 samples");  // 1e9 s at 13.9 m/s every 0.05 m
  EXPECT_CONTAINS(error_of(iso + "speed_km_per_h: 50\nduration_s: 60\nsample_spacing_m: 1e-9\n"),
                  "'sample_spacing_m'");
  const std::string crawl = error_of(iso + "speed_m_per_s: 1e-6\nduration_s: 10\n");
  EXPECT_CONTAINS(crawl, "'speed_m_per_s'");
  EXPECT_CONTAINS(crawl, "'duration_s'");
  const std::string fast = error_of(iso + "speed_m_per_s: 1e6\nduration_s: 10\n");
  EXPECT_CONTAINS(fast, "'speed_m_per_s'");
  EXPECT_CONTAINS(fast, "150 m/s");
  EXPECT_CONTAINS(error_of(iso + "speed_km_per_h: 1e6\nduration_s: 10\n"), "'speed_km_per_h'");
  const std::string fade = error_of(iso + "speed_m_per_s: 10\nduration_s: 1\nfade_in_m: 50\n");
  EXPECT_CONTAINS(fade, "'fade_in_m'");
  EXPECT_CONTAINS(fade, "10 m");
  EXPECT_CONTAINS(
      error_of(iso + "speed_m_per_s: 10\nduration_s: 10\nband_low_cycles_per_m: 1e-9\n"),
      "'band_low_cycles_per_m'");
  EXPECT_CONTAINS(error_of("type: power_law\nroughness_coefficient_m3: 4.8e-7\nwaviness: 2\n"
                           "speed_m_per_s: 5e3\nduration_s: 10\n"),
                  "'speed_m_per_s'");

  const std::string cleat = error_of(
      "type: cleat\nshape: semicircular\nheight_m: 0.02\nlength_m: 0.04\nspeed_km_per_h: 40\n"
      "duration_s: 0.1\n");
  EXPECT_CONTAINS(cleat, "'duration_s'");
  EXPECT_CONTAINS(cleat, "0.1881");  // the tyre leaves the cleat 2.09 m in, at 0.1881 s

  write("data/nm.csv", "distance[m],elevation[mm]\n0,0\n1.25e-9,0\n2.5e-9,0\n3.75e-9,0\n5e-9,0\n");
  EXPECT_CONTAINS(error_of("type: profile\nfile: data/nm.csv\nspeed_km_per_h: 50\n"),
                  "'speed_m_per_s'");

  const std::string profile_dir = error_of("type: profile\nfile: .\nspeed_km_per_h: 50\n");
  EXPECT_CONTAINS(profile_dir, "'file'");
  EXPECT_CONTAINS(profile_dir, "is a directory");
  EXPECT_CONTAINS(profile_dir, "distance[m],elevation[mm]");
  const std::string measured_dir = error_of("type: measured\nfile: data\n");
  EXPECT_CONTAINS(measured_dir, "is a directory");
  EXPECT_CONTAINS(measured_dir, "time[s]");
  if (std::filesystem::exists("/dev/null")) {  // reading a device would never end (/dev/zero)
    EXPECT_CONTAINS(error_of("type: measured\nfile: /dev/null\n"), "not a regular file");
  }

  // Values that would overflow the road's arithmetic.
  EXPECT_CONTAINS(error_of("type: log_sweep\ninitial_amplitude_m: 1e300\n"),
                  "'initial_amplitude_m'");
  EXPECT_CONTAINS(error_of("type: power_law\nroughness_coefficient_m3: 4.8e7\nwaviness: 2.1\n"
                           "speed_m_per_s: 5\nduration_s: 10\n"),
                  "'roughness_coefficient_m3'");
  EXPECT_CONTAINS(error_of("type: cleat\nshape: rectangular\nheight_m: 1e300\nlength_m: 1e3\n"
                           "speed_m_per_s: 5\n"),
                  "'height_m'");
}

TEST_F(ExcitationFileTest, EveryRoadTypeHasAPositiveFiniteMaxStep) {
  write("data/p.csv", "distance[mm],elevation[mm]\n0,0\n100,1\n200,2\n300,1\n400,0\n");
  write("data/m.csv", "time[ms],road[mm]\n0,0\n4,1\n8,2\n12,1\n16,0\n");
  struct Case {
    std::string yaml;
    double max_step_s;
  };
  for (const auto& c : std::vector<Case>{
           {"type: log_sweep\ninitial_amplitude_m: 0.01\n", 0.25 / 30.0},
           {"type: iso8608\nclass: A\nspeed_m_per_s: 10\nduration_s: 5\n", 0.05 / 10.0},
           {"type: power_law\nroughness_coefficient_m3: 4.8e-7\nwaviness: 2.1\n"
            "speed_m_per_s: 20\nduration_s: 5\nsample_spacing_m: 0.025\n",
            0.025 / 20.0},
           {"type: cleat\nshape: rectangular\nheight_m: 0.02\nlength_m: 0.2\nspeed_m_per_s: 5\n",
            0.1 / 40.0 / 5.0},
           {"type: profile\nfile: data/p.csv\nspeed_m_per_s: 0.5\n", 0.1 / 0.5},
           {"type: measured\nfile: data/m.csv\n", 0.004}}) {
    SCOPED_TRACE(c.yaml);
    const auto road = load_excitation(write("ok.yaml", c.yaml));
    EXPECT_GT(road->max_step_s(), 0.0);
    EXPECT_TRUE(std::isfinite(road->max_step_s()));
    EXPECT_NEAR(road->max_step_s(), c.max_step_s, 1e-12 * c.max_step_s);
  }
}

TEST(ExcitationFile, SpeedCanBeReplacedForDrivenRoadsOnly) {
  const auto road = load_excitation(kExcitations / "smooth_road_seed001.yaml", 80.0 / 3.6);
  EXPECT_DOUBLE_EQ(road->speed_m_per_s().value(), 80.0 / 3.6);
  EXPECT_THROW(load_excitation(kExcitations / "sweep_2mm.yaml", 10.0), InputError);
  EXPECT_THROW(load_excitation(kExcitations / "smooth_road_seed001.yaml", 1e6), InputError);
}

TEST(ExcitationFile, RandomRoadsGiveTheirSpectrum) {
  const auto smooth = load_road_spectrum(kExcitations / "smooth_road_seed001.yaml");
  ASSERT_TRUE(smooth.has_value());
  EXPECT_DOUBLE_EQ(smooth->spectrum.psd_m3(1.0), 4.8e-7);  // Cr at 1 cycle/m
  EXPECT_DOUBLE_EQ(smooth->speed_m_per_s, 20.0 / 3.6);
  const auto fast = load_road_spectrum(kExcitations / "iso8608_class_a_50kmh.yaml", 30.0);
  ASSERT_TRUE(fast.has_value());
  EXPECT_DOUBLE_EQ(fast->spectrum.psd_m3(0.1), 16e-6);
  EXPECT_DOUBLE_EQ(fast->speed_m_per_s, 30.0);
  EXPECT_FALSE(load_road_spectrum(kExcitations / "cleat_semicircular_20mm.yaml").has_value());
}

}  // namespace
}  // namespace ridefit::road
