#pragma once

// Values as bytes and back, for results that travel between the ranks of one run: numbers as
// their bits (exact, so a result gathered to rank 0 is the one computed), in the machine's own
// order (every rank of a run is the same program on the same kind of machine).

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace ridefit::common {

class ByteWriter {
 public:
  template <typename T>
  requires std::is_arithmetic_v<T>
  void put(T value) { bytes_.append(reinterpret_cast<const char*>(&value), sizeof value); }
  void put(const std::string& text) {
    put(static_cast<std::uint64_t>(text.size()));
    bytes_ += text;
  }
  void put(const std::vector<double>& values) {
    put(static_cast<std::uint64_t>(values.size()));
    for (double v : values) put(v);
  }
  const std::string& bytes() const { return bytes_; }
  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
};

// Reads what a ByteWriter wrote, in the same order; std::out_of_range past the end.
class ByteReader {
 public:
  explicit ByteReader(const std::string& bytes) : bytes_(bytes) {}
  template <typename T>
  requires std::is_arithmetic_v<T> T get() {
    T value{};
    if (at_ + sizeof value > bytes_.size()) throw std::out_of_range("ByteReader: past the end");
    std::memcpy(&value, bytes_.data() + at_, sizeof value);
    at_ += sizeof value;
    return value;
  }
  std::string get_string() {
    const auto n = static_cast<std::size_t>(get<std::uint64_t>());
    if (at_ + n > bytes_.size()) throw std::out_of_range("ByteReader: past the end");
    std::string text = bytes_.substr(at_, n);
    at_ += n;
    return text;
  }
  std::vector<double> get_doubles() {
    std::vector<double> values(static_cast<std::size_t>(get<std::uint64_t>()));
    for (double& v : values) v = get<double>();
    return values;
  }
  bool done() const { return at_ == bytes_.size(); }

 private:
  const std::string& bytes_;
  std::size_t at_ = 0;
};

}  // namespace ridefit::common
