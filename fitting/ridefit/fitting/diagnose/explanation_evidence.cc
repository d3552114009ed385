#include "ridefit/fitting/diagnose/explanation_evidence.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

namespace ridefit::fitting::diagnose {
namespace {

std::vector<std::string> sorted(std::vector<std::string> ids) {
  std::sort(ids.begin(), ids.end());
  return ids;
}

}  // namespace

namespace {

// The choices `e` makes besides its free parameters (Explanation::structural_choices): `k0` the
// nothing-missing explanation's free parameters, `own` each single effect's.
int structural_choices(const Explanation& e, int k0, const std::map<std::string, int>& own) {
  int choices = e.outside_library ? 1 : 0;
  for (const auto& id : e.effects) {
    const auto it = own.find(id);
    if (it != own.end() && it->second == k0) ++choices;
  }
  return choices;
}

}  // namespace

void weigh_explanations(std::vector<Explanation>& explanations) {
  if (explanations.empty()) return;
  // τ from the library's explanations: one outside the library has no residual of its own.
  const Explanation* best = nullptr;
  std::optional<int> k0;
  std::map<std::string, int> own;
  for (const auto& e : explanations) {
    if (e.outside_library) continue;
    if (!best || e.training_cost + e.held_out_cost < best->training_cost + best->held_out_cost) {
      best = &e;
    }
    if (e.effects.empty()) k0 = e.free_parameters;
    if (e.effects.size() == 1) own[e.effects.front()] = e.free_parameters;
  }
  if (!best) best = &explanations.front();
  const double tau = std::max(best->correlation_time, 1.0);
  double lowest = std::numeric_limits<double>::infinity();
  for (auto& e : explanations) {
    e.structural_choices = k0 ? structural_choices(e, *k0, own) : (e.outside_library ? 1 : 0);
    // The judging data's cost where there is judging data; an explanation scored on its
    // training data alone (no held-out residuals) is weighed on that.
    const bool judged = e.held_out_residuals > 0;
    const double residuals =
        static_cast<double>(std::max<std::size_t>(judged ? e.held_out_residuals : e.residuals, 1));
    const double independent = std::max(residuals / tau, 2.0);
    const double cost =
        std::max(judged ? e.held_out_cost : e.training_cost + e.held_out_cost, 1e-300);
    e.bic = independent * std::log(2.0 * cost / residuals) +
            static_cast<double>(e.free_parameters + e.structural_choices) * std::log(independent);
    lowest = std::min(lowest, e.bic);
  }
  double total = 0.0;
  for (auto& e : explanations) {
    e.probability = std::exp(-0.5 * (e.bic - lowest) / kEvidenceTemperature);
    total += e.probability;
  }
  for (auto& e : explanations) e.probability /= total;
  std::stable_sort(
      explanations.begin(), explanations.end(),
      [](const Explanation& a, const Explanation& b) { return a.probability > b.probability; });
}

void add_outside_library(std::vector<Explanation>& explanations,
                         const std::vector<std::string>& named, double held_out_cost_removed,
                         int terms) {
  const Explanation* final_one = find_explanation(explanations, named);
  if (terms <= 0 || !final_one) return;
  Explanation e = *final_one;
  e.outside_library = true;
  e.free_parameters += terms;
  e.held_out_cost = std::max(e.held_out_cost - std::max(held_out_cost_removed, 0.0), 0.0);
  e.held_out_signals.clear();  // the shape's force is not simulated through the model
  explanations.push_back(std::move(e));
  weigh_explanations(explanations);
}

std::string explanation_name(const std::vector<std::string>& effects) {
  if (effects.empty()) return "nothing missing";
  std::string name;
  for (const auto& id : effects) name += (name.empty() ? "" : " + ") + id;
  return name;
}

std::string explanation_label(const Explanation& e) {
  if (!e.outside_library) return explanation_name(e.effects);
  return (e.effects.empty() ? "" : explanation_name(e.effects) + " + ") +
         "a force outside the library";
}

const Explanation* find_explanation(const std::vector<Explanation>& explanations,
                                    const std::vector<std::string>& effects) {
  const auto wanted = sorted(effects);
  for (const auto& e : explanations) {
    if (!e.outside_library && sorted(e.effects) == wanted) return &e;
  }
  return nullptr;
}

std::string leading_explanations(const std::vector<Explanation>& weighed, std::size_t count) {
  std::string words;
  for (std::size_t i = 0; i < weighed.size() && i < count; ++i) {
    words += fmt::format("{}{} {:.2f}", words.empty() ? "" : ", ", explanation_label(weighed[i]),
                         weighed[i].probability);
  }
  return words;
}

namespace {

// Whether `e` says the `named` effects are missing (all of them; nothing named: nothing missing).
bool includes(const Explanation& e, const std::vector<std::string>& named) {
  if (named.empty()) return e.effects.empty() && !e.outside_library;
  return std::all_of(named.begin(), named.end(), [&](const std::string& id) {
    return std::find(e.effects.begin(), e.effects.end(), id) != e.effects.end();
  });
}

}  // namespace

double named_probability(const std::vector<Explanation>& weighed,
                         const std::vector<std::string>& named) {
  double p = 0.0;
  for (const auto& e : weighed) {
    if (includes(e, named)) p += e.probability;
  }
  return p;
}

const Explanation* strongest_rival(const std::vector<Explanation>& weighed,
                                   const std::vector<std::string>& named) {
  const Explanation* rival = nullptr;
  for (const auto& e : weighed) {
    if (e.outside_library || includes(e, named)) continue;
    if (!rival || e.probability > rival->probability) rival = &e;
  }
  return rival;
}

std::string evidence_words(const std::vector<Explanation>& weighed,
                           const std::vector<std::string>& named, const std::string& separates) {
  const bool weighed_at_all = std::any_of(weighed.begin(), weighed.end(),
                                          [&](const Explanation& e) { return includes(e, named); });
  if (!weighed_at_all) return "";
  const double p = named_probability(weighed, named);
  std::string words = fmt::format(" (p = {:.2f})", p);
  if (p >= kConfidentProbability) return words;
  const Explanation* rival = strongest_rival(weighed, named);
  if (!rival) return words;
  words += fmt::format("; {} or {}, the data cannot tell them apart ({:.2f} / {:.2f})",
                       explanation_name(named), explanation_label(*rival), p, rival->probability);
  if (!separates.empty()) words += ": " + separates;
  return words;
}

double outside_probability(const std::vector<Explanation>& weighed,
                           const std::vector<std::string>& named) {
  double p = 0.0;
  const auto wanted = sorted(named);
  for (const auto& e : weighed) {
    if (e.outside_library && sorted(e.effects) == wanted) p += e.probability;
  }
  return p;
}

std::string outside_evidence_words(const std::vector<Explanation>& weighed) {
  const bool weighed_at_all = std::any_of(weighed.begin(), weighed.end(), [](const Explanation& e) {
    return e.outside_library && e.effects.empty();
  });
  if (!weighed_at_all) return "";
  const double p = outside_probability(weighed, {});
  std::string words = fmt::format(" (p = {:.2f} that the library lacks it)", p);
  if (p >= kConfidentProbability) return words;
  const Explanation* rival = nullptr;
  for (const auto& e : weighed) {
    if (e.outside_library) continue;
    if (!rival || e.probability > rival->probability) rival = &e;
  }
  if (rival) {
    words += fmt::format("; {} explains it nearly as well ({:.2f})", explanation_label(*rival),
                         rival->probability);
  }
  return words;
}

}  // namespace ridefit::fitting::diagnose
