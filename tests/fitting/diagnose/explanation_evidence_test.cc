// The weighing of a diagnosis's explanations: the judging data's BIC weights against their
// definition, and the verdict's words (the correlation time:
// tests/signal/correlation_time_test.cc).
#include "ridefit/fitting/diagnose/explanation_evidence.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace ridefit::fitting::diagnose {
namespace {

Explanation candidate(std::vector<std::string> effects, int k, double cost, double tau = 1.0) {
  Explanation e;
  e.effects = std::move(effects);
  e.free_parameters = k;
  e.training_cost = cost;
  e.held_out_cost = cost;
  e.residuals = 2000;
  e.held_out_residuals = 1000;
  e.correlation_time = tau;
  return e;
}

TEST(ExplanationEvidence, WeightsAreBicWeightsOverTheIndependentJudgingResiduals) {
  // τ = 10 on the best fit: n = 1000/10 = 100 independent judging residuals.
  std::vector<Explanation> e{candidate({}, 2, 120.0, 30.0), candidate({"a"}, 3, 100.0, 10.0),
                             candidate({"b"}, 3, 101.0, 12.0)};
  weigh_explanations(e);
  ASSERT_EQ(e.size(), 3u);
  EXPECT_EQ(e[0].effects, std::vector<std::string>{"a"});
  EXPECT_EQ(e[1].effects, std::vector<std::string>{"b"});
  const double n = 100.0;
  auto bic = [&](double cost, int k) {
    return n * std::log(2.0 * cost / 1000.0) + k * std::log(n);
  };
  EXPECT_NEAR(e[0].bic, bic(100.0, 3), 1e-9);
  const double t = kEvidenceTemperature;
  const double ab = std::exp(-0.5 * (bic(101.0, 3) - bic(100.0, 3)) / t);
  const double an = std::exp(-0.5 * (bic(120.0, 2) - bic(100.0, 3)) / t);
  EXPECT_NEAR(e[0].probability, 1.0 / (1.0 + ab + an), 1e-12);
  EXPECT_NEAR(e[1].probability, ab / (1.0 + ab + an), 1e-12);
  EXPECT_NEAR(e[0].probability + e[1].probability + e[2].probability, 1.0, 1e-12);
}

TEST(ExplanationEvidence, AnExtraParameterThatFitsNothingMoreLoses) {
  std::vector<Explanation> e{candidate({}, 2, 100.0), candidate({"a"}, 3, 100.0)};
  weigh_explanations(e);
  EXPECT_TRUE(e[0].effects.empty());
  // Odds ln(n)/(2T) in BIC over n = 1000 judging residuals: n^(1/(2T)) to one.
  const double odds = std::pow(1000.0, 0.5 / kEvidenceTemperature);
  EXPECT_NEAR(e[0].probability / e[1].probability, odds, 1e-6 * odds);
}

TEST(ExplanationEvidence, AnEffectThatFitsOnlyTheTrainingDataBetterGainsNothing) {
  // "a" halves the training cost and leaves the judging cost where it was: it fitted the
  // training data's noise (or stood in for a wrong baseline there), and loses by its parameter.
  Explanation nothing = candidate({}, 2, 100.0);
  Explanation a = candidate({"a"}, 3, 100.0);
  a.training_cost = 50.0;
  std::vector<Explanation> e{nothing, a};
  weigh_explanations(e);
  EXPECT_TRUE(e[0].effects.empty());
  // Equal judging costs: "a" pays its parameter alone, odds 1000^(1/(2T)) to one against it.
  const double odds = std::pow(1000.0, 0.5 / kEvidenceTemperature);
  EXPECT_NEAR(e[0].probability, odds / (1.0 + odds), 1e-12);
  EXPECT_GT(e[0].probability, 0.95);
  // Weighed on the training and judging data together (no judging residuals given), it wins.
  Explanation a_train = a, nothing_train = nothing;
  a_train.held_out_residuals = nothing_train.held_out_residuals = 0;
  std::vector<Explanation> training_only{nothing_train, a_train};
  weigh_explanations(training_only);
  EXPECT_EQ(training_only[0].effects, std::vector<std::string>{"a"});
  // With no judging residuals the cost is the whole cost over all residuals.
  const double n = 2000.0;
  EXPECT_NEAR(training_only[0].bic, n * std::log(2.0 * 150.0 / n) + 3.0 * std::log(n), 1e-9);
}

TEST(ExplanationEvidence, VerdictWordsSayHowSureAndWhatTheDataCannotTellApart) {
  std::vector<Explanation> confident{candidate({}, 2, 150.0), candidate({"a"}, 3, 100.0)};
  weigh_explanations(confident);
  EXPECT_EQ(evidence_words(confident, {"a"}), " (p = 1.00)");
  // Two that fit alike: the verdict names both and what separates them.
  std::vector<Explanation> split{candidate({}, 2, 150.0), candidate({"a"}, 3, 100.0),
                                 candidate({"b"}, 3, 100.05)};
  weigh_explanations(split);
  const std::string words = evidence_words(split, {"a"}, "they differ at 10 Hz");
  EXPECT_NE(words.find("a or b, the data cannot tell them apart"), std::string::npos) << words;
  EXPECT_NE(words.find(": they differ at 10 Hz"), std::string::npos) << words;
  // Pairs are found in any order; a set that was never fitted has no words.
  std::vector<Explanation> pair{candidate({"b", "a"}, 4, 50.0), candidate({}, 2, 150.0)};
  weigh_explanations(pair);
  EXPECT_NE(find_explanation(pair, {"a", "b"}), nullptr);
  EXPECT_EQ(evidence_words(pair, {"c"}), "");
  EXPECT_EQ(explanation_name({}), "nothing missing");
  EXPECT_EQ(explanation_name({"a", "b"}), "a + b");
  EXPECT_EQ(leading_explanations(pair, 1), "b + a 1.00");
}

TEST(ExplanationEvidence, ANamedEffectIsAsProbableAsEveryExplanationThatContainsIt) {
  // "a" alone, "a" with a "b" that fits a little more (its parameter costs more than that: odds
  // of a few to one against it), and "c" far behind: that "a" is missing is nearly certain though
  // "a" alone holds less than 0.99 of it.
  std::vector<Explanation> e{candidate({"a"}, 3, 100.0), candidate({"a", "b"}, 4, 99.5),
                             candidate({"c"}, 3, 130.0), candidate({}, 2, 150.0)};
  weigh_explanations(e);
  const Explanation* alone = find_explanation(e, {"a"});
  const Explanation* with_b = find_explanation(e, {"a", "b"});
  ASSERT_NE(alone, nullptr);
  ASSERT_NE(with_b, nullptr);
  EXPECT_LT(alone->probability, 0.99);
  EXPECT_NEAR(named_probability(e, {"a"}), alone->probability + with_b->probability, 1e-12);
  EXPECT_GT(named_probability(e, {"a"}), 0.999);
  EXPECT_EQ(evidence_words(e, {"a"}), " (p = 1.00)");
  // The rival is the strongest explanation without "a"; nothing named counts the empty one only.
  ASSERT_NE(strongest_rival(e, {"a"}), nullptr);
  EXPECT_EQ(strongest_rival(e, {"a"})->effects, std::vector<std::string>{"c"});
  EXPECT_NEAR(named_probability(e, {}), find_explanation(e, {})->probability, 1e-15);
  EXPECT_NEAR(named_probability(e, {"a", "b"}), with_b->probability, 1e-15);
}

TEST(ExplanationEvidence, AnEffectThatFreesNoParameterCountsAsOneChoice) {
  // "s" is a switch (tyre lift-off on a car whose tyre never lifts): it frees no parameter and
  // predicts what nothing missing predicts. Counted at its free parameters it would tie with
  // nothing (p = 0.5 each on a control); as one choice it loses by the odds of one parameter.
  std::vector<Explanation> e{candidate({}, 2, 100.0), candidate({"s"}, 2, 100.0),
                             candidate({"a"}, 3, 100.0), candidate({"s", "a"}, 3, 100.0)};
  weigh_explanations(e);
  const Explanation* nothing = find_explanation(e, {});
  const Explanation* s = find_explanation(e, {"s"});
  const Explanation* a = find_explanation(e, {"a"});
  const Explanation* sa = find_explanation(e, {"a", "s"});
  ASSERT_TRUE(nothing && s && a && sa);
  EXPECT_EQ(nothing->structural_choices, 0);
  EXPECT_EQ(s->structural_choices, 1);
  EXPECT_EQ(a->structural_choices, 0);  // "a" frees a parameter of its own
  EXPECT_EQ(sa->structural_choices, 1);
  const double n = 1000.0, odds = std::pow(n, 0.5 / kEvidenceTemperature);
  EXPECT_NEAR(s->bic - nothing->bic, std::log(n), 1e-9);
  EXPECT_NEAR(nothing->probability / s->probability, odds, 1e-6 * odds);
  EXPECT_NEAR(s->probability, a->probability, 1e-15);
  EXPECT_NEAR(nothing->probability / sa->probability, odds * odds, 1e-6 * odds * odds);
  EXPECT_GT(nothing->probability, 0.9);
}

TEST(ExplanationEvidence, AForceOutsideTheLibraryIsWeighedBesideTheLibrary) {
  // A moving mass the library does not have: a gas force takes a little of it (180 against 200),
  // the shape's two terms, fitted on the training data, take 150 of the 200 off the judging data.
  std::vector<Explanation> e{candidate({}, 2, 200.0, 4.0), candidate({"g"}, 3, 180.0, 5.0)};
  weigh_explanations(e);
  EXPECT_EQ(e[0].effects, std::vector<std::string>{"g"});
  EXPECT_GT(e[0].probability, 0.99);
  add_outside_library(e, {}, 150.0, 2);
  ASSERT_EQ(e.size(), 3u);
  ASSERT_TRUE(e[0].outside_library);  // weighed again, most probable first
  EXPECT_TRUE(e[0].effects.empty());
  EXPECT_EQ(e[0].free_parameters, 4);
  EXPECT_EQ(e[0].structural_choices, 1);
  EXPECT_DOUBLE_EQ(e[0].held_out_cost, 50.0);
  // τ from the library's best fit (the gas force's, 5): n = 200 independent residuals.
  const double n = 200.0;
  auto bic = [&](double cost, int k) {
    return n * std::log(2.0 * cost / 1000.0) + k * std::log(n);
  };
  EXPECT_NEAR(e[0].bic, bic(50.0, 5), 1e-9);
  EXPECT_NEAR(find_explanation(e, {"g"})->bic, bic(180.0, 3), 1e-9);
  EXPECT_GT(outside_probability(e, {}), 0.999);
  // Nothing missing is the library's empty explanation alone, not the one outside it.
  ASSERT_NE(find_explanation(e, {}), nullptr);
  EXPECT_FALSE(find_explanation(e, {})->outside_library);
  EXPECT_NEAR(named_probability(e, {}), find_explanation(e, {})->probability, 1e-15);
  EXPECT_EQ(explanation_label(e[0]), "a force outside the library");
  EXPECT_EQ(outside_evidence_words(e), " (p = 1.00 that the library lacks it)");
  // The strongest rival to simulate is a library explanation.
  ASSERT_NE(strongest_rival(e, {}), nullptr);
  EXPECT_EQ(strongest_rival(e, {})->effects, std::vector<std::string>{"g"});

  // A shape that takes little: the library's gas force stays ahead and the words name it.
  std::vector<Explanation> weak{candidate({}, 2, 200.0, 4.0), candidate({"g"}, 3, 180.0, 5.0)};
  weigh_explanations(weak);
  add_outside_library(weak, {}, 25.0, 2);
  EXPECT_LT(outside_probability(weak, {}), 0.5);
  const std::string words = outside_evidence_words(weak);
  EXPECT_NE(words.find("g explains it nearly as well"), std::string::npos) << words;

  // Beside a named effect: the named effect is missing in both explanations.
  std::vector<Explanation> beside{candidate({}, 2, 200.0), candidate({"g"}, 3, 100.0)};
  weigh_explanations(beside);
  add_outside_library(beside, {"g"}, 40.0, 1);
  EXPECT_EQ(explanation_label(beside[0]), "g + a force outside the library");
  EXPECT_NEAR(named_probability(beside, {"g"}), 1.0, 1e-9);
  EXPECT_GT(outside_probability(beside, {"g"}), 0.99);

  // No terms, or no explanation of the named effects: nothing is added.
  std::vector<Explanation> none{candidate({}, 2, 200.0)};
  add_outside_library(none, {}, 100.0, 0);
  add_outside_library(none, {"x"}, 100.0, 2);
  EXPECT_EQ(none.size(), 1u);
  EXPECT_EQ(outside_evidence_words(none), "");
}

}  // namespace
}  // namespace ridefit::fitting::diagnose
