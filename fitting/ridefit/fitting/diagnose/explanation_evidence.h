#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace ridefit::fitting::diagnose {

// How sure a diagnosis is: the candidate explanations it fitted (nothing missing, each effect,
// each pair of the effects that passed screening, fitted jointly, and, where a disagreement is
// left that has a shape, the final model with a force the library does not have) weighed against
// each other by the evidence of the judging data.

struct Explanation {
  std::vector<std::string> effects;  // in the order they were added; empty: nothing is missing
  // The effects and, beside them, something outside the library: the shape of what the final
  // model lacks (residual_shape.h, spectral_shape.h), fitted on the training data, each of its
  // terms one free parameter (add_outside_library).
  bool outside_library = false;
  int free_parameters = 0;
  double training_cost = 0.0;          // ½·Σ r² on the fitted data
  double held_out_cost = 0.0;          // ½·Σ r² on the judging data, with the same parameters
  std::size_t residuals = 0;           // training and judging residuals together
  std::size_t held_out_residuals = 0;  // the judging data's share of them
  // Samples per independent residual of this fit on the judging data
  // (signal::correlation_time_samples): residuals of a model that misses something, and of a
  // sampled force, are far from independent, and counting each as a datum makes any difference
  // certain.
  double correlation_time = 1.0;
  // Choices the explanation makes besides its parameters, each counted as one parameter in the
  // BIC (set by weigh_explanations): every effect that frees no parameter of its own (a switch
  // such as tyre_lift_off, which without lift-off predicts what nothing missing predicts and
  // would otherwise tie with it), and the choice of a shape outside the library.
  int structural_choices = 0;
  double bic = 0.0;          // set by weigh_explanations
  double probability = 0.0;  // set by weigh_explanations
  // What it predicts for the judging data (the kind's held-out signals), for what separates two.
  std::vector<std::vector<double>> held_out_signals;
};

// How much sharper than plain BIC weights the evidence is taken: probabilities are
// exp(−BIC/(2T)) normalised. Calibrated, not derived: `tools/diagnosis-benchmark --calibrate`
// on the 50 cases of seed 5 (data-sheet baselines, vehicle spectra and rig loops). With the
// judging data alone it gave the lowest Brier score of the reported explanation at T = 0.5
// (0.089; 0.111 at T = 1); with the structural choices and the explanation outside the library
// (2026-12-07, fourth session) at T = 0.8 (0.051; 0.059 at 0.5, 0.056 at 1). T < 1 sharpens the
// Occam penalty with the fit. The benchmark is scored on other seeds (docs/diagnosis.md).
inline constexpr double kEvidenceTemperature = 0.8;

// Fills structural_choices, bic and probability from the judging data, whose parameters were
// fitted without it, so an effect that only fits the training data's noise gains nothing there.
// With N judging residuals, their cost C, k free parameters, s structural choices and n = N/τ
// independent ones (τ: the correlation time of the library explanation with the lowest cost, the
// best stand-in for the noise), BIC = n·ln(2C/N) + (k + s)·ln n, and the probabilities are
// exp(−BIC/(2T)) normalised (kEvidenceTemperature; equal prior odds). An effect frees no
// parameter of its own when its single-effect explanation has as many free parameters as the
// nothing-missing one. An explanation without judging residuals is weighed on its training cost
// and residuals. Sorted most probable first. (Until 2026-12-07 the cost was the training and
// judging data's together at T = 1: on the seed-5 benchmark that gave the nothing-missing
// explanation 0.03 where nothing was named, right in 40 % of those cases; Brier 0.190.)
void weigh_explanations(std::vector<Explanation>& explanations);

// "a + b", or "nothing missing".
std::string explanation_name(const std::vector<std::string>& effects);
// An explanation's name: explanation_name of its effects, or "a + a force outside the library" /
// "a force outside the library" for one outside the library.
std::string explanation_label(const Explanation& e);

// Adds the explanation "the `named` effects and a force the library does not have" beside the
// named effects' own explanation (which must be among `explanations`): its judging cost lowered by
// `held_out_cost_removed`, what the shape's `terms` (fitted on the training data) take off the
// judging data, its training cost as the named explanation's, one free parameter per term; then
// weighs them all again. Does nothing without terms or without the named explanation.
// A disagreement the verdict calls unexplained thereby gets a probability: before, the library's
// explanations shared it out among themselves (a moving mass outside the library went to a gas
// force with p = 1.00, so the right verdict "unexplained" had p = 0).
void add_outside_library(std::vector<Explanation>& explanations,
                         const std::vector<std::string>& named, double held_out_cost_removed,
                         int terms);

// The probability the weighed explanations give to the `named` effects with a force outside the
// library beside them (0 when there is no such explanation).
double outside_probability(const std::vector<Explanation>& weighed,
                           const std::vector<std::string>& named);

// The words for a verdict that names nothing and leaves an unexplained disagreement: " (p = 0.97
// that the library lacks it)", with the strongest library explanation when that is below
// kConfidentProbability. "" when no explanation outside the library was weighed.
std::string outside_evidence_words(const std::vector<Explanation>& weighed);

// The library explanation with exactly these effects (in any order), or nullptr.
const Explanation* find_explanation(const std::vector<Explanation>& explanations,
                                    const std::vector<std::string>& effects);

// How probable it is that the `named` effects are missing: the summed probability of every
// weighed explanation that contains them all (an explanation that adds a further effect to them,
// or a force outside the library, says they are missing too; the further effect may do next to
// nothing, a band limit above the band). Nothing named: the probability that nothing is missing,
// of the library or outside it.
double named_probability(const std::vector<Explanation>& weighed,
                         const std::vector<std::string>& named);

// The named set is what the selection decided (its tests on the judging data and BIC); below this
// probability the verdict says which other explanation the data cannot tell it from.
inline constexpr double kConfidentProbability = 0.9;

// The verdict's words on the evidence for `named` among `weighed`: " (p = 0.93)"
// (named_probability) when it is at least kConfidentProbability, else " (p = 0.52); a or b, the
// data cannot tell them apart (0.52 / 0.44)" naming the strongest rival, followed by `separates`
// (what would separate them, from the caller's data kind) when not empty. "" when no weighed
// explanation contains the named effects.
std::string evidence_words(const std::vector<Explanation>& weighed,
                           const std::vector<std::string>& named,
                           const std::string& separates = "");

// The leading explanations for a figure's title: "free_play 0.97, nothing missing 0.03" (at most
// `count`, most probable first); "" when nothing was weighed.
std::string leading_explanations(const std::vector<Explanation>& weighed, std::size_t count = 3);

// The most probable library explanation that does not contain all the `named` effects (named
// empty: that names any effect), or nullptr. One outside the library is no rival to simulate.
const Explanation* strongest_rival(const std::vector<Explanation>& weighed,
                                   const std::vector<std::string>& named);

}  // namespace ridefit::fitting::diagnose
