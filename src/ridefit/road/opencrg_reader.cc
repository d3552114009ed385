#include "ridefit/road/opencrg_file.h"
#include "ridefit/road/opencrg_format.h"

#include <fmt/core.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string_view>

#include "ridefit/common/errors.h"
#include "ridefit/road/road_limits.h"

namespace ridefit::road {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

// Up to an in-line "!" comment.
std::string_view before_comment(std::string_view s) {
  const std::size_t bang = s.find('!');
  return bang == std::string_view::npos ? s : s.substr(0, bang);
}

// A real number filling all of `text` (blanks around allowed; a Fortran "D" exponent too).
std::optional<double> parse_real(std::string_view text) {
  text = trim(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty() || text.size() > 64) return std::nullopt;
  char buffer[65];
  std::size_t n = 0;
  for (char c : text) buffer[n++] = (c == 'D' || c == 'd') ? 'E' : c;
  double value = 0.0;
  const auto [end, error] = std::from_chars(buffer, buffer + n, value);
  if (error != std::errc() || end != buffer + n || !std::isfinite(value)) return std::nullopt;
  return value;
}

enum class ChannelKind { kSection, kSlope, kBanking, kDropped };

struct Channel {
  ChannelKind kind = ChannelKind::kSection;
  std::optional<double> v_m;  // a long section's v, when its name gives it
  std::size_t line = 0;
};

struct Key {
  double value = 0.0;
  std::size_t line = 0;
};

struct Header {
  std::map<std::string, Key> keys;  // $ROAD_CRG, upper case
  std::optional<Key> u_line_start;  // from "U:name,unit,start,increment"
  std::optional<Key> u_line_increment;
  std::optional<CrgFormat> format;
  std::vector<Channel> channels;
  std::string comment;
  std::size_t data_offset = 0;  // the first byte after the "$$$$" line
  std::size_t data_line = 0;    // the line number of the first data line

  const Key* key(const std::string& name) const {
    const auto it = keys.find(name);
    return it == keys.end() ? nullptr : &it->second;
  }
};

class Reader {
 public:
  Reader(std::filesystem::path path, std::string content)
      : path_(std::move(path)), content_(std::move(content)) {}

  CrgGrid read() {
    const Header header = read_header();
    CrgGrid grid;
    grid.comment = header.comment;
    layout_channels(header);
    const std::size_t rows =
        is_binary(*header.format) ? read_binary(header, grid) : read_ascii(header, grid);
    set_u_range(header, rows, grid);
    set_v(header, grid);
    return grid;
  }

 private:
  [[noreturn]] void fail_line(std::size_t line, const std::string& what) const {
    throw InputError(fmt::format("{}: line {}: {}", path_.string(), line, what));
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(fmt::format("{}: {}", path_.string(), what));
  }

  // One line from `offset` (without its "\n" or "\r\n"); advances `offset`.
  std::string_view next_line(std::size_t& offset) const {
    const std::size_t end = content_.find('\n', offset);
    const std::size_t stop = end == std::string::npos ? content_.size() : end;
    std::string_view line(content_.data() + offset, stop - offset);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    offset = end == std::string::npos ? content_.size() : end + 1;
    return line;
  }

  Header read_header() const {
    Header header;
    std::string block;
    std::size_t offset = 0;
    std::size_t line_number = 0;
    bool separator = false;
    while (offset < content_.size()) {
      const std::string_view line = next_line(offset);
      ++line_number;
      if (line.starts_with("$$$$")) {
        separator = true;
        break;
      }
      if (line.starts_with("$!") || line.starts_with("*")) continue;  // comments
      if (line.starts_with("$")) {
        const std::string_view rest = trim(before_comment(line.substr(1)));
        block = upper(rest.substr(0, rest.find_first_of(" \t")));
        continue;
      }
      if (block == "CT") {
        header.comment += std::string(line) + "\n";
      } else if (block == "ROAD_CRG") {
        read_key(line, line_number, header);
      } else if (block == "KD_DEFINITION") {
        read_definition(line, line_number, header);
      }
      // Other blocks ($ROAD_CRG_OPTS, $ROAD_CRG_MODS, ...) and text outside blocks: skipped.
    }
    if (!separator) {
      fail(fmt::format(
          "no line starting with \"$$$$\" after {} lines; an OpenCRG file's header ends with "
          "one, followed by the data",
          line_number));
    }
    if (!header.format) {
      fail(
          "the $KD_DEFINITION block gives no data format; expected a line \"#:LRFI\", "
          "\"#:LDFI\", \"#:KRBI\" or \"#:KDBI\"");
    }
    header.data_offset = offset;
    header.data_line = line_number + 1;
    return header;
  }

  void read_key(std::string_view line, std::size_t line_number, Header& header) const {
    const std::string_view text = trim(before_comment(line));
    if (text.empty()) return;
    const std::size_t equals = text.find('=');
    if (equals == std::string_view::npos) {
      fail_line(line_number, fmt::format("'{}' in $ROAD_CRG: expected KEY = VALUE", text));
    }
    const std::string key = upper(trim(text.substr(0, equals)));
    static const char* const kKnown[] = {"REFERENCE_LINE_START_U",   "REFERENCE_LINE_END_U",
                                         "REFERENCE_LINE_INCREMENT", "LONG_SECTION_V_RIGHT",
                                         "LONG_SECTION_V_LEFT",      "LONG_SECTION_V_INCREMENT"};
    if (std::find(std::begin(kKnown), std::end(kKnown), key) == std::end(kKnown)) return;
    const std::string_view value_text = text.substr(equals + 1);
    const std::optional<double> value = parse_real(value_text);
    if (!value) {
      fail_line(line_number,
                fmt::format("{} = '{}' is not a finite number", key, trim(value_text)));
    }
    if (header.keys.count(key)) {
      fail_line(line_number,
                fmt::format("{} is given twice (also on line {})", key, header.keys.at(key).line));
    }
    header.keys[key] = Key{*value, line_number};
  }

  void read_definition(std::string_view line, std::size_t line_number, Header& header) const {
    const std::string_view text = trim(before_comment(line));
    if (text.empty()) return;
    if (text.starts_with("#:")) {
      const std::string_view name = trim(text.substr(2));
      const std::string format = upper(name.substr(0, name.find_first_of(" \t")));
      static const std::map<std::string, CrgFormat> kFormats{{"LRFI", CrgFormat::kLrfi},
                                                             {"LDFI", CrgFormat::kLdfi},
                                                             {"KRBI", CrgFormat::kKrbi},
                                                             {"KDBI", CrgFormat::kKdbi}};
      const auto it = kFormats.find(format);
      if (it == kFormats.end()) {
        fail_line(line_number, fmt::format("unknown data format '#:{}'; expected #:LRFI, #:LDFI, "
                                           "#:KRBI or #:KDBI",
                                           format));
      }
      header.format = it->second;
      return;
    }
    const std::string kind = upper(text.substr(0, 2));
    if (kind == "U:") {
      // U:name,unit,start,increment (start and increment optional).
      std::vector<std::string_view> fields;
      std::string_view rest = text.substr(2);
      for (std::size_t comma; (comma = rest.find(',')) != std::string_view::npos;) {
        fields.push_back(rest.substr(0, comma));
        rest.remove_prefix(comma + 1);
      }
      fields.push_back(rest);
      if (fields.size() >= 3 && !trim(fields[2]).empty()) {
        const auto start = parse_real(fields[2]);
        if (!start) fail_line(line_number, fmt::format("U: start '{}' is not a number", fields[2]));
        header.u_line_start = Key{*start, line_number};
      }
      if (fields.size() >= 4 && !trim(fields[3]).empty()) {
        const auto increment = parse_real(fields[3]);
        if (!increment) {
          fail_line(line_number, fmt::format("U: increment '{}' is not a number", fields[3]));
        }
        header.u_line_increment = Key{*increment, line_number};
      }
      return;
    }
    if (kind == "D:") {
      std::string name(trim(text.substr(2)));
      name = name.substr(0, name.find(','));
      std::string lower = name;
      for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      Channel channel;
      channel.line = line_number;
      if (lower.starts_with("reference line")) {
        channel.kind = lower.find("slope") != std::string::npos  ? ChannelKind::kSlope
                       : lower.find("bank") != std::string::npos ? ChannelKind::kBanking
                                                                 : ChannelKind::kDropped;
      } else if (const std::size_t at = lower.find("at v"); at != std::string::npos) {
        std::string_view rest = trim(std::string_view(lower).substr(at + 4));
        const std::optional<double> v =
            rest.starts_with("=") ? parse_real(rest.substr(1)) : std::nullopt;
        if (!v) {
          fail_line(line_number,
                    fmt::format("long section '{}': expected 'at v = <number>'", name));
        }
        channel.v_m = v;
      }
      header.channels.push_back(channel);
      return;
    }
    fail_line(line_number,
              fmt::format("'{}' in $KD_DEFINITION: expected a #:format, U: or D: line", text));
  }

  // Where each channel's value goes: a z column, slope, banking or nowhere.
  void layout_channels(const Header& header) {
    if (header.channels.empty()) fail("$KD_DEFINITION defines no data channels (D: lines)");
    std::size_t column = 0;
    for (const Channel& channel : header.channels) {
      if (channel.kind == ChannelKind::kSection) {
        target_.push_back(static_cast<long>(column++));
      } else {
        target_.push_back(channel.kind == ChannelKind::kSlope     ? kSlopeTarget
                          : channel.kind == ChannelKind::kBanking ? kBankingTarget
                                                                  : kDropTarget);
        has_slope_ |= channel.kind == ChannelKind::kSlope;
        has_banking_ |= channel.kind == ChannelKind::kBanking;
      }
    }
    sections_ = column;
    if (sections_ == 0) fail("$KD_DEFINITION defines no long section (a D: line with elevations)");
  }

  // How many rows the header's u range gives, if it gives the end.
  std::optional<std::size_t> declared_rows(const Header& header) const {
    const Key* end = header.key("REFERENCE_LINE_END_U");
    if (!end) return std::nullopt;
    const auto [start, increment] = u_start_and_increment(header);
    if (end->value < start) {
      fail_line(end->line, fmt::format("REFERENCE_LINE_END_U = {:g} is less than the start u "
                                       "{:g}; expected end >= start",
                                       end->value, start));
    }
    const double steps = (end->value - start) / increment;
    if (!(steps + 1.0 <= kMaxCrgPoints / static_cast<double>(header.channels.size()))) {
      fail_line(end->line,
                fmt::format("REFERENCE_LINE_END_U = {:g}: {:.3g} rows of {} channels are more "
                            "than {:g} points",
                            end->value, steps + 1.0, header.channels.size(), kMaxCrgPoints));
    }
    if (std::abs(steps - std::round(steps)) > 1e-3) {
      fail_line(end->line, fmt::format("REFERENCE_LINE_END_U = {:g} is not a whole number of "
                                       "increments {:g} from the start {:g}",
                                       end->value, increment, start));
    }
    return static_cast<std::size_t>(std::llround(steps)) + 1;
  }

  std::pair<double, double> u_start_and_increment(const Header& header) const {
    double start = 0.0;
    if (const Key* key = header.key("REFERENCE_LINE_START_U")) {
      start = key->value;
    } else if (header.u_line_start) {
      start = header.u_line_start->value;
    }
    std::optional<Key> increment;
    if (const Key* key = header.key("REFERENCE_LINE_INCREMENT")) {
      increment = *key;
    } else {
      increment = header.u_line_increment;
    }
    if (!increment) {
      fail(
          "REFERENCE_LINE_INCREMENT is missing in $ROAD_CRG (and no U: line gives the "
          "increment); expected the u spacing of the rows in m, > 0");
    }
    if (!(increment->value > 0.0)) {
      fail_line(increment->line,
                fmt::format("REFERENCE_LINE_INCREMENT is {:g}; expected > 0", increment->value));
    }
    if (std::abs(start) > 1e9) {
      fail(fmt::format("REFERENCE_LINE_START_U is {:g}; expected within +-1e9 m", start));
    }
    return {start, increment->value};
  }

  void set_u_range(const Header& header, std::size_t rows, CrgGrid& grid) const {
    const auto [start, increment] = u_start_and_increment(header);
    if (rows < 2) fail(fmt::format("{} data rows; an OpenCRG grid needs at least 2", rows));
    grid.u_start_m = start;
    grid.u_increment_m = increment;
    grid.u_end_m = start + static_cast<double>(rows - 1) * increment;
  }

  void set_v(const Header& header, CrgGrid& grid) const {
    const std::size_t n = sections_;
    const Key* right = header.key("LONG_SECTION_V_RIGHT");
    const Key* left = header.key("LONG_SECTION_V_LEFT");
    const Key* increment = header.key("LONG_SECTION_V_INCREMENT");
    std::size_t named = 0;
    for (const Channel& c : header.channels) named += c.v_m.has_value() ? 1 : 0;
    grid.v_m.clear();
    if (named > 0) {
      for (const Channel& c : header.channels) {
        if (c.kind != ChannelKind::kSection) continue;
        if (!c.v_m) {
          fail_line(c.line, fmt::format("this long section's name gives no v while {} others "
                                        "do ('long section at v = <m>'); name all or none",
                                        named));
        }
        grid.v_m.push_back(*c.v_m);
      }
      const auto agrees = [](double a, double b) { return std::abs(a - b) <= 1e-6; };
      if (right && !agrees(right->value, grid.v_m.front())) {
        fail_line(right->line, fmt::format("LONG_SECTION_V_RIGHT = {:g} but the first long "
                                           "section is at v = {:g}",
                                           right->value, grid.v_m.front()));
      }
      if (left && !agrees(left->value, grid.v_m.back())) {
        fail_line(left->line, fmt::format("LONG_SECTION_V_LEFT = {:g} but the last long "
                                          "section is at v = {:g}",
                                          left->value, grid.v_m.back()));
      }
    } else {
      const double count = static_cast<double>(n);
      double first = 0.0;
      double step = 0.0;
      if (right && left) {
        first = right->value;
        step = n > 1 ? (left->value - right->value) / (count - 1.0) : 0.0;
        if (increment && n > 1 && std::abs(step - increment->value) > 1e-6) {
          fail_line(increment->line,
                    fmt::format("LONG_SECTION_V_INCREMENT = {:g} disagrees with {} long sections "
                                "from LONG_SECTION_V_RIGHT = {:g} to _LEFT = {:g} (spacing {:g})",
                                increment->value, n, right->value, left->value, step));
        }
      } else if (increment) {
        step = increment->value;
        first = right  ? right->value
                : left ? left->value - (count - 1.0) * step
                       : -0.5 * (count - 1.0) * step;
      } else if (n == 1) {
        first = right ? right->value : left ? left->value : 0.0;
      } else {
        fail(fmt::format(
            "the v positions of the {} long sections are not given: expected "
            "LONG_SECTION_V_INCREMENT (or _RIGHT and _LEFT) in $ROAD_CRG, or names like "
            "'D:long section at v = -1.5,m'",
            n));
      }
      for (std::size_t k = 0; k < n; ++k) grid.v_m.push_back(first + static_cast<double>(k) * step);
    }
    for (std::size_t k = 0; k < n; ++k) {
      if (!(std::abs(grid.v_m[k]) <= 1e4) || (k > 0 && !(grid.v_m[k] > grid.v_m[k - 1]))) {
        fail(fmt::format(
            "long section {} is at v = {:g} m{}; the long sections' v must be finite "
            "and increase from right to left",
            k + 1, grid.v_m[k], k > 0 ? fmt::format(", after v = {:g} m", grid.v_m[k - 1]) : ""));
      }
    }
  }

  void reserve(CrgGrid& grid, std::size_t rows) const {
    grid.z_m.reserve(rows * sections_);
    if (has_slope_) grid.slope.reserve(rows);
    if (has_banking_) grid.banking.reserve(rows);
  }

  // Stores channel `channel`'s value of the current row.
  void store(CrgGrid& grid, std::size_t channel, double value) const {
    const long target = target_[channel];
    if (target >= 0) {
      grid.z_m.push_back(value);
    } else if (target == kSlopeTarget) {
      grid.slope.push_back(value);
    } else if (target == kBankingTarget) {
      grid.banking.push_back(value);
    }
  }

  std::size_t read_ascii(const Header& header, CrgGrid& grid) const {
    const CrgFormat format = *header.format;
    const std::size_t width = value_width(format);
    const std::size_t per_line = values_per_record(format);
    const std::size_t channels = header.channels.size();
    const std::optional<std::size_t> declared = declared_rows(header);
    if (declared) reserve(grid, *declared);
    const double max_rows = kMaxCrgPoints / static_cast<double>(channels);
    std::size_t offset = header.data_offset;
    std::size_t line_number = header.data_line - 1;
    std::size_t rows = 0;
    std::size_t channel = 0;  // of the current row
    std::size_t row_line = 0;
    while (offset < content_.size()) {
      const std::string_view line = next_line(offset);
      ++line_number;
      if (trim(line).empty()) continue;
      if (channel == 0) {
        if (static_cast<double>(rows + 1) > max_rows) {
          fail_line(line_number, fmt::format("more than {:g} data points", kMaxCrgPoints));
        }
        row_line = line_number;
      }
      const std::size_t count = std::min(per_line, channels - channel);
      for (std::size_t i = 0; i < count; ++i, ++channel) {
        const std::size_t begin = i * width;
        if (begin >= line.size()) {
          fail_line(line_number,
                    fmt::format("{} values found, expected {} of {} characters ({}: {} to a line, "
                                "{} channels to a row); truncated?",
                                i, count, width, format_name(format), per_line, channels));
        }
        const std::string_view field = line.substr(begin, width);
        const std::string_view text = trim(field);
        double value = kNaN;
        if (!text.starts_with("*")) {
          const std::optional<double> parsed = parse_real(text);
          if (!parsed || !(std::abs(*parsed) <= kCrgMaxElevation_m)) {
            fail_line(
                line_number,
                fmt::format("value {} ('{}', characters {} to {}) is not a number within "
                            "+-{:g} m nor a missing-value placeholder starting with '*'",
                            i + 1, field, begin + 1, begin + field.size(), kCrgMaxElevation_m));
          }
          value = *parsed;
        }
        store(grid, channel, value);
      }
      if (line.size() > count * width && !trim(line.substr(count * width)).empty()) {
        fail_line(line_number,
                  fmt::format("more than {} values of {} characters ({}, {} channels to a row)",
                              count, width, format_name(format), channels));
      }
      if (channel == channels) {
        channel = 0;
        ++rows;
      }
    }
    if (channel != 0) {
      fail_line(row_line,
                fmt::format("the last row is truncated: {} of its {} values", channel, channels));
    }
    if (declared && rows != *declared) {
      fail(
          fmt::format("{} data rows from line {}, but the u range (REFERENCE_LINE_START_U, "
                      "_END_U, _INCREMENT) gives {}",
                      rows, header.data_line, *declared));
    }
    return rows;
  }

  std::size_t read_binary(const Header& header, CrgGrid& grid) const {
    const CrgFormat format = *header.format;
    const std::size_t size = value_width(format);
    const std::size_t per_record = values_per_record(format);
    const std::size_t channels = header.channels.size();
    const std::size_t bytes = content_.size() - header.data_offset;
    if (bytes % kCrgRecordBytes != 0) {
      fail(
          fmt::format("the {} data after the header (line {} on) are {} bytes, not a whole "
                      "number of {}-byte records; truncated?",
                      format_name(format), header.data_line, bytes, kCrgRecordBytes));
    }
    if (bytes == 0) fail(fmt::format("no {} data after the header", format_name(format)));
    const std::size_t records = bytes / kCrgRecordBytes;
    const std::size_t values = bytes / size;
    const unsigned char* data =
        reinterpret_cast<const unsigned char*>(content_.data() + header.data_offset);
    const auto value_at = [&](std::size_t k) {
      const unsigned char* p = data + k * size;
      if (size == 4) {
        const std::uint32_t bits = (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) |
                                   (std::uint32_t{p[2]} << 8) | std::uint32_t{p[3]};
        return static_cast<double>(std::bit_cast<float>(bits));
      }
      std::uint64_t bits = 0;
      for (std::size_t b = 0; b < 8; ++b) bits = (bits << 8) | p[b];
      return std::bit_cast<double>(bits);
    };
    std::size_t rows = 0;
    if (const std::optional<std::size_t> declared = declared_rows(header)) {
      rows = *declared;
      const std::size_t needed = (rows * channels + per_record - 1) / per_record;
      if (records != needed) {
        fail(
            fmt::format("{} {}-byte records of {} data, but the u range (REFERENCE_LINE_START_U, "
                        "_END_U, _INCREMENT) gives {} rows of {} channels: {} records",
                        records, kCrgRecordBytes, format_name(format), rows, channels, needed));
      }
    } else {
      // Rows as the records hold; rows wholly within the last record's NaN padding are none.
      rows = values / channels;
      const std::size_t last_record_start = values - per_record;
      while (rows > 0 && (rows - 1) * channels >= last_record_start) {
        bool all_nan = true;
        for (std::size_t c = 0; c < channels && all_nan; ++c) {
          all_nan = std::isnan(value_at((rows - 1) * channels + c));
        }
        if (!all_nan) break;
        --rows;
      }
    }
    if (static_cast<double>(rows) * static_cast<double>(channels) > kMaxCrgPoints) {
      fail(fmt::format("{} rows of {} channels are more than {:g} points", rows, channels,
                       kMaxCrgPoints));
    }
    reserve(grid, rows);
    std::size_t k = 0;
    for (std::size_t row = 0; row < rows; ++row) {
      for (std::size_t c = 0; c < channels; ++c, ++k) {
        const double value = value_at(k);
        if (!std::isnan(value) && !(std::abs(value) <= kCrgMaxElevation_m)) {
          fail(
              fmt::format("record {} (byte {} of the data), row {}, channel {}: value {:g} is "
                          "not within +-{:g} m (NaN marks a missing value)",
                          k / per_record + 1, k * size, row + 1, c + 1, value, kCrgMaxElevation_m));
        }
        store(grid, c, value);
      }
    }
    return rows;
  }

  static constexpr long kSlopeTarget = -1;
  static constexpr long kBankingTarget = -2;
  static constexpr long kDropTarget = -3;

  std::filesystem::path path_;
  std::string content_;
  std::vector<long> target_;  // per channel
  std::size_t sections_ = 0;
  bool has_slope_ = false;
  bool has_banking_ = false;
};

}  // namespace

std::size_t CrgGrid::missing() const {
  return static_cast<std::size_t>(
      std::count_if(z_m.begin(), z_m.end(), [](double z) { return std::isnan(z); }));
}

CrgGrid read_opencrg(const std::filesystem::path& path) {
  check_data_file(path, "an OpenCRG road file (.crg)");
  std::ifstream in(path, std::ios::binary);
  if (!std::filesystem::exists(path))
    throw InputError(fmt::format("{}: file not found", path.string()));
  if (!in) throw InputError(fmt::format("{}: cannot open for reading", path.string()));
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (!error && static_cast<double>(size) > 24.0 * kMaxCrgPoints) {
    throw InputError(fmt::format("{}: {} bytes, more than an OpenCRG grid of {:g} points needs",
                                 path.string(), size, kMaxCrgPoints));
  }
  std::string content;
  if (!error) content.resize(static_cast<std::size_t>(size));
  in.read(content.data(), static_cast<std::streamsize>(content.size()));
  content.resize(static_cast<std::size_t>(in.gcount()));
  return Reader(path, std::move(content)).read();
}

}  // namespace ridefit::road
