// Shipped data that cannot drift: the lab set and one hidden dataset of each kind are made again
// by their generators and must match the files in datasets/ to the digits printed there. A
// change to a model, an integrator or a generator that would change them fails here until the
// data are regenerated (the commands are in datasets/hidden/README.md and `ridefit generate-lab`).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "ridefit/synthetic/hidden_dataset_spec.h"
#include "ridefit/synthetic/hidden_datasets.h"
#include "ridefit/synthetic/hidden_truth_model.h"
#include "ridefit/synthetic/lab_test_set.h"
#include "support/cli_runner.h"
#include "support/temp_dir.h"

namespace ridefit {
namespace {

namespace fs = std::filesystem;

// One unit in the last digit `text` prints ("3.204" → 0.001, "-3.72634e-07" → 1e-12); 0 for text
// that is no number.
double last_digit_unit(const std::string& text) {
  char* end = nullptr;
  std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0') return 0.0;
  const auto e = text.find_first_of("eE");
  const std::string mantissa = text.substr(0, e);
  const int exponent = e == std::string::npos ? 0 : std::stoi(text.substr(e + 1));
  const auto dot = mantissa.find('.');
  const int decimals = dot == std::string::npos ? 0 : static_cast<int>(mantissa.size() - dot - 1);
  return std::pow(10.0, exponent - decimals);
}

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream s(line);
  std::string field;
  while (std::getline(s, field, ',')) out.push_back(field);
  return out;
}

// "" when `made` equals `shipped` line by line, each number within one unit of the shipped
// file's last printed digit (text that is no number must be equal); else where they part.
std::string difference(const fs::path& shipped, const fs::path& made) {
  std::ifstream a(shipped), b(made);
  if (!a || !b) return "cannot open " + (a ? made : shipped).string();
  std::string line_a, line_b;
  for (int row = 1;; ++row) {
    const bool more_a = static_cast<bool>(std::getline(a, line_a));
    const bool more_b = static_cast<bool>(std::getline(b, line_b));
    if (!more_a && !more_b) return "";
    if (more_a != more_b) return "line " + std::to_string(row) + ": one file ends";
    const auto fa = fields(line_a), fb = fields(line_b);
    if (fa.size() != fb.size()) return "line " + std::to_string(row) + ": field count";
    for (std::size_t i = 0; i < fa.size(); ++i) {
      const double unit = last_digit_unit(fa[i]);
      const bool same = unit > 0.0 && last_digit_unit(fb[i]) > 0.0
                            ? std::abs(std::stod(fa[i]) - std::stod(fb[i])) <= 1.0001 * unit
                            : fa[i] == fb[i];
      if (!same) {
        return "line " + std::to_string(row) + " field " + std::to_string(i + 1) + ": shipped " +
               fa[i] + ", made " + fb[i];
      }
    }
  }
}

TEST(ShippedDataDrift, ComparisonReadsThePrintedDigits) {
  EXPECT_DOUBLE_EQ(last_digit_unit("3.204"), 0.001);
  EXPECT_DOUBLE_EQ(last_digit_unit("-3.72634e-07"), 1e-12);
  EXPECT_DOUBLE_EQ(last_digit_unit("122"), 1.0);
  EXPECT_EQ(last_digit_unit("force[N]"), 0.0);
  const testing::TempDir dir("ridefit_drift_compare");
  const auto a = dir.write("a.csv", "x[m],y[N]\n0.0050,3.204\n");
  EXPECT_EQ(difference(a, dir.write("b.csv", "x[m],y[N]\n0.005,3.2045\n")), "");
  EXPECT_NE(difference(a, dir.write("c.csv", "x[m],y[N]\n0.005,3.206\n")), "");
  EXPECT_NE(difference(a, dir.write("d.csv", "x[m],z[N]\n0.005,3.204\n")), "");
  EXPECT_NE(difference(a, dir.write("e.csv", "x[m],y[N]\n")), "");
}

// `ridefit generate-lab` at the shipped seed writes datasets/lab/ again.
TEST(ShippedDataDrift, LabSetIsWhatItsGeneratorWrites) {
  const testing::TempDir dir("ridefit_drift_lab");
  const auto run = testing::run_cli("generate-lab " + (dir.path() / "lab").string() + " --seed 1");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const fs::path shipped = fs::path(RIDEFIT_SOURCE_DIR) / "datasets" / "lab";
  for (const std::string& name : synthetic::lab_test_files()) {
    SCOPED_TRACE(name);
    EXPECT_EQ(difference(shipped / name, dir.path() / "lab" / name), "");
  }
}

// One vehicle and one rig dataset of the shipped spec, written by the generator that wrote them.
TEST(ShippedDataDrift, HiddenDatasetsAreWhatTheirGeneratorWrites) {
  const fs::path hidden = fs::path(RIDEFIT_SOURCE_DIR) / "datasets" / "hidden";
  const auto datasets = synthetic::read_hidden_spec(hidden / "hidden_datasets.yaml");
  const testing::TempDir dir("ridefit_drift_hidden");
  for (const std::string name : {"damper_friction", "rig_gas_force"}) {
    SCOPED_TRACE(name);
    const auto d = std::find_if(datasets.begin(), datasets.end(),
                                [&](const synthetic::HiddenDataset& h) { return h.name == name; });
    ASSERT_NE(d, datasets.end());
    synthetic::write_hidden_dataset(*d, synthetic::load_truth_model(*d), hidden, dir.path(), 0,
                                    [](const fs::path&, double, double) {});
    for (int record = 1; record <= 2; ++record) {
      const std::string file = synthetic::record_file_name(*d, record);
      EXPECT_EQ(difference(hidden / file, dir.path() / file), "") << file;
    }
  }
}

}  // namespace
}  // namespace ridefit
