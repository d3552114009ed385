// One libFuzzer executable per parser: compiled once per target with RIDEFIT_FUZZ_TARGET set to
// its name (tests/CMakeLists.txt). A refused input is fine; anything else that escapes is a
// finding (an exception other than InputError terminates, which libFuzzer reports as a crash).
#include <cstddef>
#include <cstdint>

#include "fuzz/parser_fuzz_entries.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const ridefit::fuzz::Target& target = ridefit::fuzz::target(RIDEFIT_FUZZ_TARGET);
  (void)target.run({data, size});
  return 0;
}
