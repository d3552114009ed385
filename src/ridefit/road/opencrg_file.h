#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace ridefit::road {

// An OpenCRG 1.2 road surface (ASAM OpenCRG; the sample files' own comments describe it): an
// elevation grid over the reference line's coordinate u (rows, uniform from u_start_m to
// u_end_m by u_increment_m) and the lateral positions v of the long sections (columns, right
// to left, v > 0 to the left of the reference line). Missing points are NaN.
//
// z is the elevation relative to the reference line. A file may also carry the reference
// line's longitudinal slope (dz/du) and banking (cross slope dz/dv) as channels; they are kept
// here (empty when absent) but the opencrg excitation ignores them: see opencrg_road.h.
struct CrgGrid {
  double u_start_m = 0.0;
  double u_end_m = 0.0;
  double u_increment_m = 0.0;
  std::vector<double> v_m;      // the long sections' v, strictly increasing
  std::vector<double> z_m;      // rows() x columns(), row-major: z_m[row * columns() + col]
  std::vector<double> slope;    // per row, or empty
  std::vector<double> banking;  // per row, or empty
  std::string comment;          // the $CT block's text (written back by the writers)

  std::size_t rows() const { return v_m.empty() ? 0 : z_m.size() / v_m.size(); }
  std::size_t columns() const { return v_m.size(); }
  double z(std::size_t row, std::size_t column) const { return z_m[row * v_m.size() + column]; }
  double u(std::size_t row) const { return u_start_m + static_cast<double>(row) * u_increment_m; }
  std::size_t missing() const;  // NaN points of z
};

// The data block's representation (the "#:" marker of $KD_DEFINITION).
enum class CrgFormat {
  kLrfi,  // ASCII, 10-character reals, 8 to an 80-character record (a line)
  kLdfi,  // ASCII, 20-character doubles, 4 to a record
  kKrbi,  // binary, IEEE big-endian float32, 20 to an 80-byte record
  kKdbi,  // binary, IEEE big-endian float64, 10 to an 80-byte record
};

// The most grid points (rows x channels) a file may declare or hold: 1e8 points are 800 MB.
inline constexpr double kMaxCrgPoints = 1e8;

// Reads an OpenCRG file, ASCII (LRFI, LDFI) or binary (KRBI, KDBI), told apart by the data
// format marker of its header. Understood:
// - blocks $CT (comment text), $ROAD_CRG, $KD_DEFINITION (names in either case); other blocks
//   ($ROAD_CRG_OPTS, $ROAD_CRG_MODS, ...) are skipped; "*" in column 1 and "$!" lines are
//   comments, "!" starts an in-line comment; a line of "$$$$" ends the header;
// - $ROAD_CRG keys (either case) REFERENCE_LINE_START_U, _END_U, _INCREMENT, LONG_SECTION_V_
//   RIGHT, _LEFT, _INCREMENT; others (x, y, phi, ...) are skipped. The increment may also come
//   from the "U:" line (U:name,unit,start,increment); u starts at 0 unless given; the end
//   follows from the number of rows and, when given, must agree with it;
// - "D:" channels: "reference line slope" and "reference line banking" are kept, other
//   "reference line ..." channels (phi, x, y) are read and dropped; every other channel is a
//   long section. A long section's v is taken from its name ("long section at v = -1.5,m")
//   or, when no name gives it, from LONG_SECTION_V_RIGHT/LEFT/INCREMENT (only the increment:
//   centred on the reference line);
// - ASCII data: fixed-width fields, each row starting a new line; a field starting with "*"
//   ("*missing*", "**unused**") is missing (NaN). Binary data: values fill 80-byte records
//   row after row; the last record is padded with NaN.
// Bad input is an InputError naming the file and the line (ASCII, header) or the record
// (binary): no "$$$$" line, an unknown format, u increment <= 0, u end < start, row counts
// that disagree with the u range, truncated data, a number that does not parse, values beyond
// +-1e4 m, v positions that do not increase, more than kMaxCrgPoints points.
CrgGrid read_opencrg(const std::filesystem::path& path);

// Writes `grid` in `format` (with its header: $CT, $ROAD_CRG with the u range and v right /
// left, $KD_DEFINITION with one "D:long section at v = ..." per column), to a temporary file
// renamed onto `path`. ASCII reals are written as fixed point when they fit (LRFI: 7 decimals)
// and in E notation otherwise; NaN as "*missing*". Throws InputError for an inconsistent grid.
void write_opencrg(const CrgGrid& grid, const std::filesystem::path& path, CrgFormat format);

// The elevation along the track at lateral position `v_m` (v_right <= v_m <= v_left), one
// value per row: linear interpolation between the two long sections around v_m. Missing
// points of those sections are first filled along u, linearly between the nearest valid
// points of the same long section; missing points at a section's start or end take the
// nearest valid value. A long section used by the track with no valid point at all is an
// InputError naming `source`, the section (1-based, with its v) and its u range.
std::vector<double> crg_track(const CrgGrid& grid, double v_m, const std::string& source);

}  // namespace ridefit::road
