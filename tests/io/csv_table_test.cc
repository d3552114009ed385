#include "ridefit/io/csv_table.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "ridefit/common/errors.h"

namespace ridefit::io {
namespace {

// A fresh directory per test, so parallel test processes never share files.
class CsvTableTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           (std::string("ridefit_csv_") + info->name() + "_" + std::to_string(getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path write(const std::string& name, const std::string& content) const {
    const auto path = dir_ / name;
    std::ofstream(path, std::ios::binary) << content;
    return path;
  }

  std::filesystem::path dir_;
};

// Runs `action`, expects an InputError, and checks every fragment is in its message.
void expect_input_error(const std::function<void()>& action,
                        const std::vector<std::string>& fragments) {
  try {
    action();
    ADD_FAILURE() << "no InputError thrown";
  } catch (const InputError& e) {
    const std::string message = e.what();
    for (const auto& fragment : fragments) {
      EXPECT_NE(message.find(fragment), std::string::npos)
          << "message lacks '" << fragment << "': " << message;
    }
  }
}

TEST_F(CsvTableTest, ConvertsEveryAcceptedUnitToSi) {
  const auto path = write("units.csv",
                          "time[ms],road[mm],body_acc[g],force[kN],stiffness[N/mm],speed[mm/s],"
                          "angle[deg],stuck[1],count[-],acc[m/s^2],f[Hz],x[m],t2[s]\n"
                          "250,12.5,0.5,1.5,30,100,90,1,2,3.5,13.3,0.1,7\n");
  const CsvTable table = CsvTable::read(path);
  ASSERT_EQ(table.rows(), 1u);
  EXPECT_DOUBLE_EQ(table.column("time").values[0], 0.25);
  EXPECT_EQ(table.column("time").unit, "s");
  EXPECT_DOUBLE_EQ(table.column("road").values[0], 0.0125);
  EXPECT_EQ(table.column("road").unit, "m");
  EXPECT_DOUBLE_EQ(table.column("body_acc").values[0], 0.5 * 9.80665);
  EXPECT_EQ(table.column("body_acc").unit, "m/s^2");
  EXPECT_DOUBLE_EQ(table.column("force").values[0], 1500.0);
  EXPECT_EQ(table.column("force").unit, "N");
  EXPECT_DOUBLE_EQ(table.column("stiffness").values[0], 30000.0);
  EXPECT_EQ(table.column("stiffness").unit, "N/m");
  EXPECT_DOUBLE_EQ(table.column("speed").values[0], 0.1);
  EXPECT_EQ(table.column("speed").unit, "m/s");
  EXPECT_DOUBLE_EQ(table.column("angle").values[0], 0.5 * 3.14159265358979323846);
  EXPECT_EQ(table.column("angle").unit, "rad");
  EXPECT_EQ(table.column("stuck").unit, "1");
  EXPECT_EQ(table.column("count").unit, "1");
  EXPECT_DOUBLE_EQ(table.column("count").values[0], 2.0);
  EXPECT_DOUBLE_EQ(table.column("acc").values[0], 3.5);
  EXPECT_DOUBLE_EQ(table.column("f").values[0], 13.3);
  EXPECT_DOUBLE_EQ(table.column("t2").values[0], 7.0);
}

TEST_F(CsvTableTest, AcceptsSpacesCrlfBomPlusSignsAndTrailingBlankLines) {
  const auto path =
      write("loose.csv", "\xEF\xBB\xBFtime [s] , road[ mm ]\r\n0, +1.5\r\n 0.001 ,-2e-1\r\n\r\n\n");
  const CsvTable table = CsvTable::read(path);
  ASSERT_EQ(table.rows(), 2u);
  EXPECT_EQ(table.columns()[0].name, "time");
  EXPECT_DOUBLE_EQ(table.column("road").values[0], 1.5e-3);
  EXPECT_DOUBLE_EQ(table.column("road").values[1], -0.2e-3);
  EXPECT_DOUBLE_EQ(table.time_s()[1], 0.001);
}

TEST_F(CsvTableTest, WriteThenReadRoundTripsEveryDoubleExactly) {
  CsvTable table;
  const std::vector<double> time{0.0, 0.1, 1.0 / 3.0, 2.5e7};
  const std::vector<double> road{1e-12, -0.123456789012345678, 3.0e-310, 42.0};
  table.add("time", "s", time);
  table.add("road", "mm", {1.0, 2.0, 3.0, 4.0});  // converted on add
  table.add("body_acc", "m/s^2", road);
  const auto path = dir_ / "out.csv";
  table.write(path);

  std::ifstream in(path);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "time[s],road[m],body_acc[m/s^2]");
  const CsvTable back = CsvTable::read(path);
  ASSERT_EQ(back.rows(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(back.column("time").values[k], time[k]);
    EXPECT_EQ(back.column("road").values[k], 1e-3 * static_cast<double>(k + 1));
    EXPECT_EQ(back.column("body_acc").values[k], road[k]);
  }
  // Only the target file is left: the temporary file was renamed into place.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir_), {}), 1);
}

TEST_F(CsvTableTest, WriteRefusesNanAndLeavesNoFile) {
  CsvTable table;
  table.add("time", "s", {0.0, 1.0});
  table.add("road", "m", {0.0, std::nan("")});
  const auto path = dir_ / "nan.csv";
  EXPECT_THROW(table.write(path), RunError);
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir_), {}), 0);
}

TEST_F(CsvTableTest, TimeMustIncreaseStrictlyAndTheRowIsNamed) {
  const auto path = write("time.csv", "time[s],road[m]\n0,0\n0.1,0\n0.2,0\n0.2,0\n0.3,0\n");
  const CsvTable table = CsvTable::read(path);
  expect_input_error([&] { table.time_s(); }, {"time.csv", "row 5", "'time'", "strictly"});
  const auto good = write("good.csv", "time[ms],road[m]\n0,0\n1,0\n2,0\n");
  EXPECT_DOUBLE_EQ(CsvTable::read(good).time_s()[2], 0.002);
}

TEST_F(CsvTableTest, MissingColumnNamesTheColumnsThatExist) {
  const CsvTable table = CsvTable::read(write("cols.csv", "time[s],road[mm]\n0,1\n"));
  expect_input_error([&] { table.column("body_acc"); },
                     {"cols.csv", "'body_acc'", "time[s]", "road[mm]"});
  // The units as the file wrote them, not the SI units the columns hold.
  const CsvTable xy = CsvTable::read(write("xy.csv", "x[m], y[mm] ,t[ms]\n0,1,2\n"));
  expect_input_error([&] { xy.column("distance"); }, {"x[m], y[mm], t[ms]"});
  // A table built in memory has no file to ask: SI units.
  CsvTable built(dir_ / "never_written.csv");
  built.add("road", "mm", {1.0});
  try {
    built.column("time");
    ADD_FAILURE() << "no InputError thrown";
  } catch (const InputError& e) {
    EXPECT_TRUE(std::string(e.what()).ends_with("road[m]")) << e.what();
  }
}

struct BadCsv {
  std::string name;
  std::string content;
  std::vector<std::string> fragments;  // besides the file name
};

TEST_F(CsvTableTest, EveryBadFileIsAnInputErrorNamingFileRowAndColumn) {
  const std::vector<BadCsv> cases{
      {"empty.csv", "", {"empty"}},
      {"blank.csv", "\n\n  \n", {"empty"}},
      {"header_only.csv", "time[s],road[m]\n", {"no data rows", "row 1"}},
      {"no_unit.csv", "time[s],road\n0,1\n", {"row 1", "column 2", "'road'", "name[unit]"}},
      {"empty_unit.csv", "time[s],road[]\n0,1\n", {"row 1", "column 2", "name[unit]"}},
      {"unknown_unit.csv",
       "time[s],road[furlong]\n0,1\n",
       {"row 1", "column 2", "'road'", "unknown unit 'furlong'", "mm", "m/s^2", "kN", "deg"}},
      {"not_a_number.csv",
       "time[s],road[m]\n0,1\n0.1,abc\n",
       {"row 3", "column 2", "'road'", "'abc'", "not a number"}},
      {"empty_cell.csv", "time[s],road[m]\n0,\n", {"row 2", "column 2", "'road'"}},
      {"too_few.csv",
       "time[s],road[m],body_acc[g]\n0,1,2\n0.1,1\n",
       {"row 3", "2 cells", "expected 3", "column 3", "'body_acc'"}},
      {"too_many.csv", "time[s],road[m]\n0,1\n0.1,1,7\n", {"row 3", "3 cells", "column 3"}},
      {"blank_inside.csv", "time[s],road[m]\n0,1\n\n0.2,1\n", {"row 3", "empty"}},
      {"nan.csv", "time[s],road[m]\n0,1\n0.1,nan\n", {"row 3", "'road'", "finite"}},
      {"inf.csv", "time[s],road[m]\n0,1\n0.1,-inf\n", {"row 3", "'road'", "finite"}},
      {"overflow.csv", "time[s],road[m]\n0,1e999\n", {"row 2", "'road'", "finite"}},
      {"duplicate.csv",
       "time[s],road[m],road[mm]\n0,1,2\n",
       {"row 1", "column 3", "duplicate", "'road'", "column 2"}},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const auto path = write(c.name, c.content);
    std::vector<std::string> fragments = c.fragments;
    fragments.push_back(c.name);
    expect_input_error([&] { CsvTable::read(path); }, fragments);
  }
  expect_input_error([&] { CsvTable::read(dir_ / "absent.csv"); }, {"absent.csv", "not found"});
}

TEST_F(CsvTableTest, SpectraAndAngularUnitsConvertToo) {
  const auto path = write("psd.csv",
                          "frequency[Hz],body_acc_psd[g^2/Hz],road_psd[mm^2/Hz],pitch_acc[deg/s^2],"
                          "damping[Ns/m]\n1,2,3,180,1500\n");
  const CsvTable table = CsvTable::read(path);
  EXPECT_DOUBLE_EQ(table.column("body_acc_psd").values[0], 2.0 * 9.80665 * 9.80665);
  EXPECT_EQ(table.column("body_acc_psd").unit, "(m/s^2)^2/Hz");
  EXPECT_DOUBLE_EQ(table.column("road_psd").values[0], 3e-6);
  EXPECT_DOUBLE_EQ(table.column("pitch_acc").values[0], 3.14159265358979323846);
  EXPECT_EQ(table.column("pitch_acc").unit, "rad/s^2");
  EXPECT_DOUBLE_EQ(table.column("damping").values[0], 1500.0);
}

TEST(CsvTableAdd, RejectsUnitsReadCannotReadDuplicatesAndRaggedColumns) {
  CsvTable table;
  table.add("time", "ms", {0.0, 5.0});
  EXPECT_DOUBLE_EQ(table.time_s()[1], 0.005);
  EXPECT_THROW(table.add("x", "furlong", {1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(table.add("time", "s", {1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(table.add("road", "m", {1.0}), std::invalid_argument);
  table.add("psd", "(m/s^2)^2/Hz", {1.0, 2.0});
  EXPECT_EQ(table.columns().size(), 2u);
}

TEST(CsvUnits, UnknownUnitListsTheAcceptedOnes) {
  EXPECT_DOUBLE_EQ(unit_to_si("kN").factor_to_si, 1e3);
  EXPECT_EQ(unit_to_si("-").si_unit, "1");
  expect_input_error([] { unit_to_si("km"); }, {"'km'", "s, ms, m, mm"});
}

}  // namespace
}  // namespace ridefit::io

namespace ridefit::io {
namespace {

TEST(CsvPsdUnit, EverySiUnitHasAPsdUnitThatReadsBack) {
  EXPECT_EQ(psd_unit_of("m/s^2"), "(m/s^2)^2/Hz");
  EXPECT_EQ(psd_unit_of("m"), "m^2/Hz");
  EXPECT_EQ(psd_unit_of("1"), "1/Hz");
  for (const char* unit :
       {"s", "m", "m/s", "m/s^2", "N", "N/m", "Ns/m", "Hz", "rad", "rad/s", "rad/s^2", "1"}) {
    const UnitConversion si = unit_to_si(unit);
    EXPECT_EQ(si.si_unit, unit);
    EXPECT_NO_THROW(unit_to_si(psd_unit_of(unit))) << unit;
    EXPECT_EQ(unit_to_si(psd_unit_of(unit)).factor_to_si, 1.0) << unit;
  }
}

}  // namespace
}  // namespace ridefit::io
