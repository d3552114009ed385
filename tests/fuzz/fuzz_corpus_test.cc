// The fuzzers' corpora and every input a fuzzer ever crashed on, replayed through the same
// entry points in the ordinary build: each must be read or refused with an InputError.
#include <gtest/gtest.h>

#include <filesystem>
#include <ostream>
#include <span>
#include <string>
#include <typeinfo>

#include "fuzz/parser_fuzz_entries.h"
#include "support/temp_dir.h"

namespace ridefit::fuzz {
namespace {

namespace fs = std::filesystem;

}  // namespace

// gtest prints a failing parameter by this.
void PrintTo(const Target& t, std::ostream* os) { *os << t.name; }

namespace {

class FuzzCorpus : public ::testing::TestWithParam<Target> {};

TEST_P(FuzzCorpus, EveryInputIsReadOrRefusedWithAMessage) {
  const Target& t = GetParam();
  const fs::path fuzz_dir = fs::path(RIDEFIT_SOURCE_DIR) / "tests" / "fuzz";
  std::size_t accepted = 0;
  std::size_t inputs = 0;
  for (const char* kind : {"corpus", "crashes"}) {
    const fs::path dir = fuzz_dir / kind / std::string(t.name);
    if (!fs::is_directory(dir)) continue;
    for (const auto& entry : fs::directory_iterator(dir)) {
      if (!entry.is_regular_file()) continue;
      ++inputs;
      const std::string text = testing::text_of(entry.path());
      const std::span<const std::uint8_t> input(reinterpret_cast<const std::uint8_t*>(text.data()),
                                                text.size());
      try {
        if (t.run(input) == Outcome::kAccepted) ++accepted;
      } catch (const std::exception& e) {
        ADD_FAILURE() << entry.path() << ": escaped as " << typeid(e).name() << ": " << e.what();
      }
    }
  }
  // The seeds are the shipped files of that kind, so some inputs parse: a corpus the parser
  // refuses whole would only exercise its first check.
  EXPECT_GE(inputs, 5u) << "tests/fuzz/corpus/" << t.name << " is missing or nearly empty";
  EXPECT_GE(accepted, 1u) << "no input of tests/fuzz/corpus/" << t.name << " parses";
}

INSTANTIATE_TEST_SUITE_P(Parsers, FuzzCorpus, ::testing::ValuesIn(targets()),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

}  // namespace
}  // namespace ridefit::fuzz
