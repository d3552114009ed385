#include "ridefit/fitting/diagnose/effect_selection.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <mutex>

#include "ridefit/io/input_error.h"
#include "ridefit/study/parallel_for.h"

namespace ridefit::fitting::diagnose {
namespace {

double bic(const ScoredFit& s, std::size_t parameters) {
  const double n = static_cast<double>(s.training_residuals);
  return n * std::log(std::max(2.0 * s.training_cost / n, 1e-300)) +
         static_cast<double>(parameters) * std::log(n);
}

}  // namespace

std::string verdict_of(const std::vector<std::string>& named,
                       const std::vector<std::string>& unexplained) {
  std::string verdict = named.empty() ? "" : "missing effect found: ";
  for (std::size_t i = 0; i < named.size(); ++i) verdict += (i ? ", then " : "") + named[i];
  if (!unexplained.empty()) {
    verdict += fmt::format(
        "{}a significant disagreement remains that no effect of the library explains: {}",
        verdict.empty() ? "" : "; ", unexplained.front());
    if (unexplained.size() > 1) {
      verdict += fmt::format(" (and {} more region(s))", unexplained.size() - 1);
    }
  } else if (named.empty()) {
    verdict = "no missing effect found";
  }
  return verdict;
}

std::vector<const Effect*> effects_to_try(const std::vector<std::string>& ids) {
  std::vector<const Effect*> library;
  if (ids.empty()) {
    for (const auto& effect : effect_library()) library.push_back(effect.get());
  } else {
    for (const auto& id : ids) library.push_back(&find_effect(id));
  }
  return library;
}

Selection select_effects(const DiagnosisModel& baseline, std::vector<std::string> free,
                         ParameterBounds bounds, const std::vector<const Effect*>& library,
                         const FitAndScore& fit, const SelectionOptions& options,
                         const std::function<void(const std::string&)>& say) {
  auto refine = [&](const ScoredFit& screened, const std::vector<std::string>& names,
                    const ParameterBounds& limits) {
    if (!options.refine) return screened;
    ScoredFit fine = fit(screened.model, names, limits, true);
    return fine.failure.empty() ? fine : screened;
  };
  Selection selection;
  ScoredFit current = fit(baseline, free, bounds, false);
  if (!current.failure.empty()) {
    throw RunError(fmt::format("the baseline cannot be fitted: {}", current.failure));
  }
  selection.baseline = refine(current, free, bounds);
  ScoredFit reported = selection.baseline;
  say(fmt::format("baseline fitted: held-out gap {:.2f} {}", selection.baseline.held_out_gap,
                  options.gap_unit));

  for (int round = 0; round < options.max_effects; ++round) {
    DiagnosisRound this_round;
    // The model so far, refitted from its own optimum (the reported fit when there is one:
    // finer and allowed more iterations): a screening fit stopped by its iteration cap or the
    // integrator's resolution would otherwise leave room that any trial's refit takes, and an
    // effect that changes nothing (a bump stop the wheel never reaches) was credited with it.
    if (round > 0) {
      ScoredFit again = options.refine ? reported : fit(current.model, free, bounds, false);
      if (again.failure.empty() && again.training_cost < current.training_cost) {
        current = std::move(again);
      }
    }
    const double start_bic = bic(current, free.size());
    DiagnosisModel start = current.model;
    start.free = free;
    std::vector<EffectTrial> trials;
    std::vector<std::pair<std::size_t, EffectChange>> to_try;
    for (const Effect* effect : library) {
      EffectTrial trial;
      trial.id = std::string(effect->id());
      if (std::find(selection.named.begin(), selection.named.end(), trial.id) !=
          selection.named.end()) {
        trial.skipped = "already added";
      } else {
        trial.skipped = effect->not_applicable(start);
      }
      if (trial.skipped.empty()) to_try.emplace_back(trials.size(), effect->change(start));
      trials.push_back(std::move(trial));
    }
    std::vector<ScoredFit> scores(trials.size());
    std::vector<std::vector<std::string>> trial_free(trials.size());
    std::vector<ParameterBounds> trial_bounds(trials.size(), bounds);
    std::mutex lock;
    study::parallel_for(
        to_try.size(), options.threads,
        [&](std::size_t i) {
          const auto& [index, change] = to_try[i];
          EffectTrial& trial = trials[index];
          for (const auto& p : change.free) {
            trial_free[index].push_back(p.name);
            trial_bounds[index][p.name] = {p.lower, p.upper};
          }
          for (const auto& name : free) {
            if (std::find(trial_free[index].begin(), trial_free[index].end(), name) ==
                trial_free[index].end()) {
              trial_free[index].push_back(name);
            }
          }
          trial.free_parameters = static_cast<int>(trial_free[index].size());
          scores[index] = fit(apply(start, change), trial_free[index], trial_bounds[index], false);
          for (const auto& other_start : change.other_starts) {
            EffectChange other = change;
            for (const auto& [key, value] : other_start) other.set[key] = value;
            ScoredFit alternative =
                fit(apply(start, other), trial_free[index], trial_bounds[index], false);
            if (alternative.failure.empty() &&
                (!scores[index].failure.empty() ||
                 alternative.training_cost < scores[index].training_cost)) {
              scores[index] = std::move(alternative);
            }
          }
          const ScoredFit& scored = scores[index];
          trial.failed = scored.failure;
          if (scored.failure.empty()) {
            trial.parameters = scored.values;
            trial.training_cost = scored.training_cost;
            trial.iterations = scored.iterations;
            trial.held_out_cost = scored.held_out_cost;
            trial.bic = bic(scored, trial_free[index].size());
            trial.held_out_improvement = 1.0 - scored.held_out_cost / current.held_out_cost;
            trial.bic_change = trial.bic - start_bic;
            trial.held_out_gap = scored.held_out_gap;
            trial.significant = trial.held_out_improvement >= options.min_held_out_improvement &&
                                trial.bic_change <= -options.min_bic_drop;
            trial.model = scored.model;
          }
        },
        [&](std::size_t i) {
          const EffectTrial& trial = trials[to_try[i].first];
          std::lock_guard guard(lock);
          say(trial.failed.empty()
                  ? fmt::format("round {}: {} held-out cost {:.4g} ({:+.0f} %), BIC {:+.1f}, {} "
                                "iterations",
                                round + 1, trial.id, trial.held_out_cost,
                                -100.0 * trial.held_out_improvement, trial.bic_change,
                                trial.iterations)
                  : fmt::format("round {}: {} failed: {}", round + 1, trial.id, trial.failed));
        });
    // Tried and fitted first, best held-out cost first; then failed, then skipped.
    auto rank = [&](std::size_t i) {
      return !trials[i].skipped.empty() ? 2 : !trials[i].failed.empty() ? 1 : 0;
    };
    std::vector<std::size_t> order(trials.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      if (rank(a) != rank(b)) return rank(a) < rank(b);
      return rank(a) == 0 && trials[a].held_out_cost < trials[b].held_out_cost;
    });
    for (std::size_t i : order) this_round.trials.push_back(trials[i]);
    const bool accept =
        !order.empty() && rank(order.front()) == 0 && trials[order.front()].significant;
    if (accept) {
      const std::size_t best = order.front();
      this_round.accepted = trials[best].id;
      selection.named.push_back(trials[best].id);
      free = trial_free[best];
      bounds = trial_bounds[best];
      current = scores[best];
      reported = refine(current, free, bounds);
      say(fmt::format("round {}: accepted {}", round + 1, trials[best].id));
    } else {
      say(fmt::format("round {}: no effect is significant", round + 1));
    }
    selection.rounds.push_back(std::move(this_round));
    if (!accept) break;
  }
  selection.final_fit = reported;
  return selection;
}

}  // namespace ridefit::fitting::diagnose
