#include "ridefit/road/opencrg_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/road/excitation_file.h"
#include "ridefit/road/opencrg_road.h"
#include "ridefit/road/spatial_profile_road.h"
#include "support/temp_dir.h"
#include "support/throws_input_error.h"

namespace ridefit::road {
namespace {

namespace fs = std::filesystem;
using testing::TempDir;
using testing::throws_input_error;

const fs::path kSamples = fs::path(RIDEFIT_SOURCE_DIR) / "datasets" / "roads" / "opencrg";

std::string bytes_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_bytes(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// The data block: everything after the "$$$$" line.
std::string data_block(const std::string& file) {
  const std::size_t separator = file.find("\n$$$$");
  const std::size_t end = file.find('\n', separator + 1);
  return file.substr(end + 1);
}

bool same_or_both_nan(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

// --- the ASAM samples ------------------------------------------------------------------------

TEST(OpenCrgFile, StraightSampleHeaderAndValues) {
  const CrgGrid grid = read_opencrg(kSamples / "handmade_straight.crg");
  EXPECT_EQ(grid.u_start_m, 0.0);
  EXPECT_EQ(grid.u_end_m, 22.0);
  EXPECT_EQ(grid.u_increment_m, 1.0);
  ASSERT_EQ(grid.rows(), 23u);
  EXPECT_EQ(grid.v_m, (std::vector<double>{-1.5, -1.0, -0.5, 0.0, 0.5, 1.0, 1.5}));
  EXPECT_TRUE(grid.slope.empty());
  EXPECT_TRUE(grid.banking.empty());
  EXPECT_NE(grid.comment.find("CRG file example"), std::string::npos);
  // Values as written in the file's rows 2, 16 (counting from 1) and its *missing* points.
  EXPECT_DOUBLE_EQ(grid.z(1, 3), 0.0111111);
  EXPECT_DOUBLE_EQ(grid.z(15, 4), -0.0111111);  // "0.0000000-0.0111111": fixed width fields
  EXPECT_DOUBLE_EQ(grid.z(15, 6), -0.0333333);
  EXPECT_EQ(grid.missing(), 3u);
  EXPECT_TRUE(std::isnan(grid.z(7, 0)));
  EXPECT_TRUE(std::isnan(grid.z(7, 6)));
  EXPECT_TRUE(std::isnan(grid.z(8, 0)));
  EXPECT_DOUBLE_EQ(grid.z(8, 6), 0.0222222);
}

TEST(OpenCrgFile, MinimalistSampleEqualsTheCommentedOne) {
  const CrgGrid full = read_opencrg(kSamples / "handmade_straight.crg");
  const CrgGrid minimal = read_opencrg(kSamples / "handmade_straight_minimalist.crg");
  EXPECT_EQ(minimal.u_start_m, full.u_start_m);
  EXPECT_EQ(minimal.u_end_m, full.u_end_m);
  EXPECT_EQ(minimal.v_m, full.v_m);  // centred from LONG_SECTION_V_INCREMENT alone
  ASSERT_EQ(minimal.z_m.size(), full.z_m.size());
  for (std::size_t k = 0; k < full.z_m.size(); ++k) {
    EXPECT_TRUE(same_or_both_nan(minimal.z_m[k], full.z_m[k])) << k;
  }
}

TEST(OpenCrgFile, SlopedBankedAndCurvedSamplesNameTheirSections) {
  const std::vector<double> v{-1.5, -1.25, -1.0, 0.0, 1.0, 1.25, 1.5};
  const CrgGrid sloped = read_opencrg(kSamples / "handmade_sloped.crg");
  const CrgGrid banked = read_opencrg(kSamples / "handmade_banked.crg");
  const CrgGrid curved = read_opencrg(kSamples / "handmade_curved.crg");
  for (const CrgGrid* grid : {&sloped, &banked, &curved}) {
    EXPECT_EQ(grid->v_m, v);
    EXPECT_EQ(grid->rows(), 23u);
    EXPECT_EQ(grid->u_end_m, 22.0);
    EXPECT_EQ(grid->missing(), 0u);  // the curved file's "**unused**" is its phi channel's
    EXPECT_DOUBLE_EQ(grid->z(1, 3), 0.0111111);
    EXPECT_DOUBLE_EQ(grid->z(7, 6), 0.0333333);
  }
  ASSERT_EQ(sloped.slope.size(), 23u);
  EXPECT_DOUBLE_EQ(sloped.slope[2], 0.011);
  EXPECT_DOUBLE_EQ(sloped.slope[11], 0.11);
  EXPECT_TRUE(sloped.banking.empty());
  ASSERT_EQ(banked.banking.size(), 23u);
  EXPECT_DOUBLE_EQ(banked.banking[12], 0.11);
  EXPECT_TRUE(curved.slope.empty() && curved.banking.empty());
}

// --- the binary writer against the format's description -------------------------------------

CrgGrid tiny_grid() {
  CrgGrid grid;
  grid.u_start_m = 0.0;
  grid.u_end_m = 1.0;
  grid.u_increment_m = 0.5;
  grid.v_m = {-1.0, 1.0};
  grid.z_m = {1.0, -2.0, 0.5, std::nan(""), 0.0, 0.25};  // 3 rows x 2 sections
  return grid;
}

std::string hex_bytes(const std::vector<std::uint64_t>& words, int bytes_per_word) {
  std::string out;
  for (std::uint64_t w : words) {
    for (int shift = 8 * (bytes_per_word - 1); shift >= 0; shift -= 8) {
      out.push_back(static_cast<char>((w >> shift) & 0xFF));
    }
  }
  return out;
}

TEST(OpenCrgBinary, KrbiIsBigEndianFloat32In80ByteRecordsPaddedWithNaN) {
  TempDir dir("opencrg");
  write_opencrg(tiny_grid(), dir.path() / "tiny.crg", CrgFormat::kKrbi);
  const std::string file = bytes_of(dir.path() / "tiny.crg");
  EXPECT_NE(file.find("\n#:KRBI\n"), std::string::npos);
  // By hand: 1.0f = 3F800000, -2.0f = C0000000, 0.5f = 3F000000, NaN = 7FC00000,
  // 0.25f = 3E800000; six values row by row, then 14 NaNs fill the one 80-byte record.
  std::vector<std::uint64_t> words{0x3F800000, 0xC0000000, 0x3F000000,
                                   0x7FC00000, 0x00000000, 0x3E800000};
  words.resize(20, 0x7FC00000);
  EXPECT_EQ(data_block(file), hex_bytes(words, 4));
  const CrgGrid back = read_opencrg(dir.path() / "tiny.crg");
  EXPECT_EQ(back.rows(), 3u);
  EXPECT_EQ(back.v_m, tiny_grid().v_m);
  for (std::size_t k = 0; k < 6; ++k) {
    EXPECT_TRUE(same_or_both_nan(back.z_m[k], tiny_grid().z_m[k])) << k;
  }
}

TEST(OpenCrgBinary, KdbiIsBigEndianFloat64In80ByteRecordsPaddedWithNaN) {
  TempDir dir("opencrg");
  write_opencrg(tiny_grid(), dir.path() / "tiny.crg", CrgFormat::kKdbi);
  std::vector<std::uint64_t> words{0x3FF0000000000000, 0xC000000000000000, 0x3FE0000000000000,
                                   0x7FF8000000000000, 0x0000000000000000, 0x3FD0000000000000};
  words.resize(10, 0x7FF8000000000000);
  EXPECT_EQ(data_block(bytes_of(dir.path() / "tiny.crg")), hex_bytes(words, 8));
}

TEST(OpenCrgBinary, RowsSpanRecordsAndPaddingRowsAreNotData) {
  // 3 rows x 7 sections = 21 floats: two records, the second holding 1 value and 19 NaNs
  // (enough for two all-NaN "rows"); without REFERENCE_LINE_END_U the reader must not count
  // them. Remove the end key from the written header to check that.
  CrgGrid grid;
  grid.u_increment_m = 0.25;
  grid.v_m = {-3, -2, -1, 0, 1, 2, 3};
  for (int k = 0; k < 21; ++k) grid.z_m.push_back(0.001 * k);
  TempDir dir("opencrg");
  const fs::path path = dir.path() / "g.crg";
  write_opencrg(grid, path, CrgFormat::kKrbi);
  std::string file = bytes_of(path);
  EXPECT_EQ(data_block(file).size(), 160u);
  const std::size_t key = file.find("REFERENCE_LINE_END_U");
  file.erase(key, file.find('\n', key) + 1 - key);
  write_bytes(path, file);
  const CrgGrid back = read_opencrg(path);
  ASSERT_EQ(back.rows(), 3u);
  EXPECT_DOUBLE_EQ(back.u_end_m, 0.5);
  EXPECT_EQ(back.z(2, 6), static_cast<double>(static_cast<float>(0.020)));
}

// --- round trips ----------------------------------------------------------------------------

TEST(OpenCrgRoundTrip, AsciiToKrbiToLrfi) {
  TempDir dir("opencrg");
  for (const char* sample : {"handmade_straight.crg", "handmade_sloped.crg"}) {
    SCOPED_TRACE(sample);
    const CrgGrid ascii = read_opencrg(kSamples / sample);
    write_opencrg(ascii, dir.path() / "k.crg", CrgFormat::kKrbi);
    const CrgGrid binary = read_opencrg(dir.path() / "k.crg");
    ASSERT_EQ(binary.z_m.size(), ascii.z_m.size());
    EXPECT_EQ(binary.v_m, ascii.v_m);
    EXPECT_EQ(binary.u_end_m, ascii.u_end_m);
    EXPECT_EQ(binary.slope.size(), ascii.slope.size());
    for (std::size_t k = 0; k < ascii.z_m.size(); ++k) {  // exactly the float32 of each value
      EXPECT_TRUE(same_or_both_nan(binary.z_m[k], static_cast<float>(ascii.z_m[k]))) << k;
    }
    write_opencrg(binary, dir.path() / "a.crg", CrgFormat::kLrfi);
    const CrgGrid again = read_opencrg(dir.path() / "a.crg");
    ASSERT_EQ(again.z_m.size(), ascii.z_m.size());
    EXPECT_EQ(again.missing(), ascii.missing());
    for (std::size_t k = 0; k < ascii.z_m.size(); ++k) {  // the file's 7 decimals
      if (!std::isnan(ascii.z_m[k])) {
        EXPECT_NEAR(again.z_m[k], ascii.z_m[k], 5e-8) << k;
      }
    }
    for (std::size_t k = 0; k < ascii.slope.size(); ++k) {  // row 1 is "**unused**": NaN
      EXPECT_TRUE(std::isnan(ascii.slope[k]) ? std::isnan(again.slope[k])
                                             : std::abs(again.slope[k] - ascii.slope[k]) < 5e-8)
          << k;
    }
  }
}

TEST(OpenCrgRoundTrip, KdbiAndLdfiKeepDoubles) {
  CrgGrid grid;
  grid.u_start_m = 100.0;
  grid.u_increment_m = 0.01;
  grid.v_m = {-1.7, -0.3, 0.0, 0.45, 1.2};  // 5 + banking = 6 channels: LDFI rows wrap
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal(0.0, 0.01);
  for (int r = 0; r < 40; ++r) {
    grid.banking.push_back(normal(rng));
    for (int c = 0; c < 5; ++c) grid.z_m.push_back(normal(rng));
  }
  grid.z_m[17] = std::nan("");
  TempDir dir("opencrg");
  write_opencrg(grid, dir.path() / "d.crg", CrgFormat::kKdbi);
  const CrgGrid binary = read_opencrg(dir.path() / "d.crg");
  EXPECT_EQ(binary.u_start_m, 100.0);
  EXPECT_EQ(binary.v_m, grid.v_m);
  EXPECT_EQ(binary.banking, grid.banking);
  for (std::size_t k = 0; k < grid.z_m.size(); ++k) {
    EXPECT_TRUE(same_or_both_nan(binary.z_m[k], grid.z_m[k])) << k;
  }
  write_opencrg(binary, dir.path() / "l.crg", CrgFormat::kLdfi);
  const CrgGrid ascii = read_opencrg(dir.path() / "l.crg");
  ASSERT_EQ(ascii.z_m.size(), grid.z_m.size());
  EXPECT_EQ(ascii.missing(), 1u);
  for (std::size_t k = 0; k < grid.z_m.size(); ++k) {  // 14 significant digits
    if (!std::isnan(grid.z_m[k])) {
      EXPECT_NEAR(ascii.z_m[k], grid.z_m[k], 1e-15) << k;
    }
  }
}

// --- the track ------------------------------------------------------------------------------

TEST(OpenCrgTrack, BetweenTwoSectionsIsTheirLinearMix) {
  const CrgGrid grid = read_opencrg(kSamples / "handmade_sloped.crg");
  // v = 0.3 between v = 0 (column 3) and v = 1 (column 4); v = -1.2 between -1.25 and -1.
  const std::vector<double> a = crg_track(grid, 0.3, "test");
  const std::vector<double> b = crg_track(grid, -1.2, "test");
  for (std::size_t r = 0; r < grid.rows(); ++r) {
    EXPECT_NEAR(a[r], 0.7 * grid.z(r, 3) + 0.3 * grid.z(r, 4), 1e-15) << r;
    EXPECT_NEAR(b[r], 0.8 * grid.z(r, 1) + 0.2 * grid.z(r, 2), 1e-15) << r;
  }
  EXPECT_EQ(crg_track(grid, 1.5, "test")[7], grid.z(7, 6));  // on the outermost section
}

TEST(OpenCrgTrack, MissingPointsAreFilledAlongU) {
  CrgGrid grid;
  grid.u_increment_m = 1.0;
  grid.v_m = {0.0, 1.0};
  const double nan = std::nan("");
  const std::vector<double> first{nan, 1.0, nan, nan, 4.0, nan};
  for (double z : first) grid.z_m.insert(grid.z_m.end(), {z, nan});
  // Inner gaps linear, ends held; the all-missing second section is not needed at v = 0.
  EXPECT_EQ(crg_track(grid, 0.0, "f.crg"), (std::vector<double>{1, 1, 2, 3, 4, 4}));
  EXPECT_TRUE(throws_input_error([&] { crg_track(grid, 0.5, "f.crg"); },
                                 "f.crg: long section 2 (v = 1 m) has no valid elevation: all 6 "
                                 "values from u = 0 to 5 m are missing"));
  EXPECT_TRUE(throws_input_error([&] { crg_track(grid, 1.5, "f.crg"); }, "outside"));
  // The ASAM sample's *missing* points: rows 8 and 9 of the rightmost section.
  const std::vector<double> right =
      crg_track(read_opencrg(kSamples / "handmade_straight.crg"), -1.5, "s");
  EXPECT_DOUBLE_EQ(right[7], 0.0111111);
  EXPECT_DOUBLE_EQ(right[8], 0.0111111);
}

// --- bad input ------------------------------------------------------------------------------

class OpenCrgBadInput : public ::testing::Test {
 protected:
  // The straight sample with `from` replaced by `to` (first occurrence).
  fs::path edited(const std::string& from, const std::string& to) {
    std::string text = bytes_of(kSamples / "handmade_straight.crg");
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    const fs::path path = dir_.path() / "bad.crg";
    write_bytes(path, text);
    return path;
  }
  // The straight sample up to `from`.
  fs::path cut_at(const std::string& from) {
    const std::string text = bytes_of(kSamples / "handmade_straight.crg");
    const fs::path path = dir_.path() / "cut.crg";
    write_bytes(path, text.substr(0, text.find(from)));
    return path;
  }
  TempDir dir_{"opencrg"};
};

TEST_F(OpenCrgBadInput, HeaderErrorsNameTheKeyAndLine) {
  EXPECT_TRUE(throws_input_error(
      [&] {
        read_opencrg(edited("REFERENCE_LINE_INCREMENT = 1.0", "REFERENCE_LINE_INCREMENT = 0"));
      },
      "line 32: REFERENCE_LINE_INCREMENT is 0; expected > 0"));
  EXPECT_TRUE(throws_input_error(
      [&] { read_opencrg(edited("REFERENCE_LINE_END_U     = 22.0", "reference_line_end_u = -3")); },
      "line 28: REFERENCE_LINE_END_U = -3 is less than the start u 0"));
  EXPECT_TRUE(throws_input_error(
      [&] { read_opencrg(edited("REFERENCE_LINE_END_U     = 22.0", "REFERENCE_LINE_END_U = 30")); },
      "23 data rows from line 77, but the u range"));
  EXPECT_TRUE(throws_input_error(
      [&] {
        read_opencrg(edited("REFERENCE_LINE_END_U     = 22.0", "REFERENCE_LINE_END_U = 1e9"));
      },
      "more than 1e+08 points"));
  EXPECT_TRUE(throws_input_error([&] { read_opencrg(edited("#:LRFI", "#:KXYZ")); },
                                 "unknown data format '#:KXYZ'"));
  EXPECT_TRUE(throws_input_error([&] { read_opencrg(edited("#:LRFI", "")); }, "no data format"));
  EXPECT_TRUE(throws_input_error([&] { read_opencrg(cut_at("$$$$$$$$10")); },
                                 "no line starting with \"$$$$\" after 75 lines"));
  EXPECT_TRUE(throws_input_error(
      [&] {
        read_opencrg(edited("LONG_SECTION_V_INCREMENT = 0.50", "LONG_SECTION_V_INCREMENT = 0.4"));
      },
      "LONG_SECTION_V_INCREMENT = 0.4 disagrees"));
  EXPECT_TRUE(throws_input_error([&] { read_opencrg(dir_.path() / "none.crg"); }, "not found"));
  EXPECT_TRUE(throws_input_error([&] { read_opencrg(dir_.path()); }, "is a directory"));
}

TEST_F(OpenCrgBadInput, DataErrorsNameTheLine) {
  EXPECT_TRUE(throws_input_error(
      [&] {
        read_opencrg(edited(" 0.0000000 0.0111111 0.0222222 0.0333333", " 0.0000000 0.01x1111"));
      },
      "line 96: value 2 (' 0.01x1111'"));
  EXPECT_TRUE(throws_input_error(
      [&] {
        read_opencrg(edited(" 0.0000000 0.0111111 0.0222222 0.0333333", " 0.0000000 0.0111111"));
      },
      "line 96: 5 values found, expected 7"));
  EXPECT_TRUE(throws_input_error(
      [&] {
        read_opencrg(edited("0.0222222 0.0333333 0.0222222", "0.0222222 9.9E+0999 0.0222222"));
      },
      "line 96: value 4"));
}

TEST_F(OpenCrgBadInput, BinaryErrorsNameTheRecord) {
  CrgGrid grid = tiny_grid();
  for (int k = 0; k < 50; ++k) grid.z_m.insert(grid.z_m.end(), {0.001 * k, 0.0});
  const fs::path path = dir_.path() / "b.crg";
  write_opencrg(grid, path, CrgFormat::kKrbi);
  const std::string good = bytes_of(path);
  write_bytes(path, good.substr(0, good.size() - 7));
  EXPECT_TRUE(throws_input_error([&] { read_opencrg(path); }, "not a whole number of 80-byte"));
  write_bytes(path, good.substr(0, good.size() - 80));
  EXPECT_TRUE(throws_input_error([&] { read_opencrg(path); }, "records"));
  std::string inf = good;
  const std::size_t at = good.size() - data_block(good).size() + 4 * 25;  // record 2
  inf.replace(at, 4, std::string("\x7F\x80\x00\x00", 4));
  write_bytes(path, inf);
  EXPECT_TRUE(throws_input_error([&] { read_opencrg(path); }, "record 2 (byte 100 of the data)"));
}

// Truncated and garbled files: an InputError or a consistent grid, never a crash, a hang or
// another exception.
TEST_F(OpenCrgBadInput, TruncatedAndGarbledFilesAreRefusedOrConsistent) {
  CrgGrid grid;
  grid.u_increment_m = 0.1;
  grid.v_m = {-0.5, 0.0, 0.5};
  for (int k = 0; k < 90; ++k) grid.z_m.push_back(0.001 * (k % 7));
  const fs::path binary = dir_.path() / "k.crg";
  write_opencrg(grid, binary, CrgFormat::kKrbi);
  const std::vector<std::string> sources{bytes_of(kSamples / "handmade_straight.crg"),
                                         bytes_of(kSamples / "handmade_sloped.crg"),
                                         bytes_of(binary)};
  std::mt19937_64 rng(2026);
  const fs::path path = dir_.path() / "fuzz.crg";
  int refused = 0;
  int read = 0;
  for (const std::string& source : sources) {
    for (int trial = 0; trial < 150; ++trial) {
      std::string text = source;
      if (trial % 3 == 0) {
        text.resize(std::uniform_int_distribution<std::size_t>(0, text.size())(rng));
      } else {
        const int flips = trial % 3 == 1 ? 1 : 8;
        for (int f = 0; f < flips; ++f) {
          const std::size_t at =
              std::uniform_int_distribution<std::size_t>(0, text.size() - 1)(rng);
          text[at] = static_cast<char>(std::uniform_int_distribution<int>(0, 255)(rng));
        }
      }
      write_bytes(path, text);
      try {
        const CrgGrid g = read_opencrg(path);
        ++read;
        ASSERT_GE(g.rows(), 2u);
        ASSERT_EQ(g.z_m.size(), g.rows() * g.columns());
        ASSERT_GT(g.u_increment_m, 0.0);
        for (double z : g.z_m) ASSERT_TRUE(std::isnan(z) || std::abs(z) <= 1e4);
        for (std::size_t c = 1; c < g.columns(); ++c) ASSERT_GT(g.v_m[c], g.v_m[c - 1]);
      } catch (const InputError&) {
        ++refused;
      }
    }
  }
  EXPECT_GT(refused, 50);
  EXPECT_GT(read, 50);
}

// --- the excitation -------------------------------------------------------------------------

TEST(OpenCrgExcitation, YamlDrivesOneTrackAtTheSpeed) {
  TempDir dir("opencrg");
  fs::copy_file(kSamples / "handmade_sloped.crg", dir.path() / "road.crg");
  const auto road = load_excitation(dir.write(
      "e.yaml", "type: opencrg\nfile: road.crg\nlateral_offset_m: 0.3\nspeed_km_per_h: 36\n"));
  const auto* profile = dynamic_cast<const SpatialProfileRoad*>(road.get());
  ASSERT_NE(profile, nullptr);
  EXPECT_DOUBLE_EQ(profile->speed_m_per_s().value(), 10.0);
  EXPECT_NEAR(profile->duration_s(), 2.2, 1e-12);
  const CrgGrid grid = read_opencrg(kSamples / "handmade_sloped.crg");
  for (std::size_t r = 0; r < grid.rows(); ++r) {  // the spline passes through every row
    EXPECT_NEAR(road->at(0.1 * static_cast<double>(r)).elevation_m,
                0.7 * grid.z(r, 3) + 0.3 * grid.z(r, 4), 1e-12)
        << r;
  }
}

TEST(OpenCrgExcitation, BadKeysAreNamed) {
  TempDir dir("opencrg");
  fs::copy_file(kSamples / "handmade_straight.crg", dir.path() / "road.crg");
  const auto load = [&](const std::string& text) { load_excitation(dir.write("e.yaml", text)); };
  EXPECT_TRUE(throws_input_error(
      [&] { load("type: opencrg\nfile: road.crg\nlateral_offset_m: 1.6\nspeed_m_per_s: 5\n"); },
      "key 'lateral_offset_m' is 1.6 m, outside the long sections of"));
  EXPECT_TRUE(throws_input_error(
      [&] { load("type: opencrg\nfile: road.crg\nlateral_offset_m: -2\nspeed_m_per_s: 5\n"); },
      "expected -1.5 <= lateral_offset_m <= 1.5 m"));
  EXPECT_TRUE(throws_input_error(
      [&] { load("type: opencrg\nfile: road.crg\nlateral: 0\nspeed_m_per_s: 5\n"); }, "lateral"));
  EXPECT_TRUE(
      throws_input_error([&] { load("type: opencrg\nfile: road.crg\n"); }, "speed_m_per_s"));
  EXPECT_TRUE(throws_input_error(
      [&] { load("type: opencrg\nfile: nothere.crg\nspeed_m_per_s: 5\n"); }, "nothere.crg"));
}

TEST(OpenCrgExcitation, ShippedExampleLoads) {
  const auto road = load_excitation(fs::path(RIDEFIT_SOURCE_DIR) / "datasets" / "excitations" /
                                    "opencrg_handmade_straight.yaml");
  EXPECT_NEAR(road->duration_s(), 22.0 / (30.0 / 3.6), 1e-12);
  EXPECT_EQ(road->at(0.0).elevation_m, 0.0);
  EXPECT_NEAR(road->at(3.0 / (30.0 / 3.6)).elevation_m, 0.0111111, 1e-12);  // u = 3 m
}

}  // namespace
}  // namespace ridefit::road
