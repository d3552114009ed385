#include "ridefit/fitting/diagnose/explanation_evidence.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ridefit::fitting::diagnose {
namespace {

std::vector<std::string> sorted(std::vector<std::string> ids) {
  std::sort(ids.begin(), ids.end());
  return ids;
}

}  // namespace

void weigh_explanations(std::vector<Explanation>& explanations) {
  if (explanations.empty()) return;
  const Explanation* best = &explanations.front();
  for (const auto& e : explanations) {
    if (e.training_cost + e.held_out_cost < best->training_cost + best->held_out_cost) best = &e;
  }
  const double tau = std::max(best->correlation_time, 1.0);
  double lowest = std::numeric_limits<double>::infinity();
  for (auto& e : explanations) {
    // The judging data's cost where there is judging data; an explanation scored on its
    // training data alone (no held-out residuals) is weighed on that.
    const bool judged = e.held_out_residuals > 0;
    const double residuals =
        static_cast<double>(std::max<std::size_t>(judged ? e.held_out_residuals : e.residuals, 1));
    const double independent = std::max(residuals / tau, 2.0);
    const double cost =
        std::max(judged ? e.held_out_cost : e.training_cost + e.held_out_cost, 1e-300);
    e.bic = independent * std::log(2.0 * cost / residuals) +
            static_cast<double>(e.free_parameters) * std::log(independent);
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

std::string explanation_name(const std::vector<std::string>& effects) {
  if (effects.empty()) return "nothing missing";
  std::string name;
  for (const auto& id : effects) name += (name.empty() ? "" : " + ") + id;
  return name;
}

const Explanation* find_explanation(const std::vector<Explanation>& explanations,
                                    const std::vector<std::string>& effects) {
  const auto wanted = sorted(effects);
  for (const auto& e : explanations) {
    if (sorted(e.effects) == wanted) return &e;
  }
  return nullptr;
}

std::string leading_explanations(const std::vector<Explanation>& weighed, std::size_t count) {
  std::string words;
  for (std::size_t i = 0; i < weighed.size() && i < count; ++i) {
    words += fmt::format("{}{} {:.2f}", words.empty() ? "" : ", ",
                         explanation_name(weighed[i].effects), weighed[i].probability);
  }
  return words;
}

namespace {

// Whether `e` says the `named` effects are missing (all of them; nothing named: nothing missing).
bool includes(const Explanation& e, const std::vector<std::string>& named) {
  if (named.empty()) return e.effects.empty();
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
    if (includes(e, named)) continue;
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
  words +=
      fmt::format("; {} or {}, the data cannot tell them apart ({:.2f} / {:.2f})",
                  explanation_name(named), explanation_name(rival->effects), p, rival->probability);
  if (!separates.empty()) words += ": " + separates;
  return words;
}

}  // namespace ridefit::fitting::diagnose
