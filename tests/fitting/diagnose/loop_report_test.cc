// The loop diagnosis' report and JSON carry the shape of an unexplained disagreement, and say
// nothing of one when there is none.
#include "ridefit/fitting/diagnose/loop_report.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace ridefit::fitting::diagnose {
namespace {

DiagnosisResult result_with_a_mass() {
  DiagnosisResult r;
  r.kind = DataKind::kStrutLoops;
  r.verdict = "a significant disagreement remains";
  ShapeTerm mass;
  mass.id = "acceleration";
  mass.words = "a mass moving with the rod";
  mass.unit = "kg";
  mass.coefficient = 11.5;
  mass.standard_error = 0.4;
  mass.judged_share = 0.5;
  r.residual_shape.terms.push_back(mass);
  r.residual_shape.judged_share = 0.5;
  r.residual_shape.travel_centre_m = 0.001;
  r.residual_shape.half_stroke_m = 0.004;
  return r;
}

TEST(LoopReport, ShowsTheShapeOfWhatIsLeft) {
  const DiagnosisResult r = result_with_a_mass();
  std::ostringstream report;
  write_loop_report(report, "strut.yaml", r, {}, "");
  EXPECT_NE(report.str().find("## What the model still lacks, in named terms"), std::string::npos);
  EXPECT_NE(report.str().find("by at least 5 % and stands 4 standard errors"), std::string::npos);
  EXPECT_NE(
      report.str().find("| acceleration | a mass moving with the rod | +11.5 ± 0.4 kg | 50.0 % |"),
      std::string::npos)
      << report.str();
  const nlohmann::json j = loop_summary_json(r);
  ASSERT_EQ(j.at("residual_shape").at("terms").size(), 1u);
  EXPECT_EQ(j["residual_shape"]["terms"][0]["term"], "acceleration");
  EXPECT_DOUBLE_EQ(j["residual_shape"]["terms"][0]["coefficient"].get<double>(), 11.5);
  EXPECT_DOUBLE_EQ(j["residual_shape"]["half_stroke_m"].get<double>(), 0.004);
}

TEST(LoopReport, SaysNothingOfAShapeWhenThereIsNone) {
  DiagnosisResult r = result_with_a_mass();
  r.residual_shape = {};
  std::ostringstream report;
  write_loop_report(report, "strut.yaml", r, {}, "");
  EXPECT_EQ(report.str().find("in named terms"), std::string::npos);
  EXPECT_TRUE(loop_summary_json(r).at("residual_shape").at("terms").empty());
}

}  // namespace
}  // namespace ridefit::fitting::diagnose
