#include "ridefit/fitting/diagnose/diagnosis_report.h"

#include <fmt/core.h>

#include <algorithm>
#include <optional>

#include "ridefit/fitting/diagnose/effect.h"
#include "ridefit/fitting/fit_json.h"

namespace ridefit::fitting::diagnose {

void write_parameters(std::ostream& out, const std::vector<FittedValue>& values) {
  out << "| parameter | value | standard error |\n| --- | --- | --- |\n";
  for (const auto& p : values) {
    out << fmt::format(
        "| {} | {:.6g} | {} |\n", p.name, p.value,
        p.standard_error ? fmt::format("{:.3g}", *p.standard_error) : std::string("—"));
  }
  out << "\n";
}

void write_rounds(std::ostream& out, const DiagnosisResult& result, const std::string& cost_words,
                  const std::string& gap_unit) {
  for (std::size_t k = 0; k < result.rounds.size(); ++k) {
    const DiagnosisRound& round = result.rounds[k];
    out << fmt::format("## Round {}: effects tried\n\n", k + 1);
    out << fmt::format(
        "Held-out improvement: how much the held-out cost ({}) falls; ΔBIC on the training data "
        "(negative is better; extra parameters pay ln n each).\n\n| rank | effect | free | "
        "held-out improvement | ΔBIC | gap [{}] | significant |\n| --- | --- | --- | --- | --- | "
        "--- | --- |\n",
        cost_words, gap_unit);
    int rank = 0;
    for (const auto& t : round.trials) {
      if (!t.skipped.empty() || !t.failed.empty()) continue;
      out << fmt::format("| {} | `{}` | {} | {:+.1f} % | {:+.1f} | {:.2f} | {} |\n", ++rank, t.id,
                         t.free_parameters, 100.0 * t.held_out_improvement, t.bic_change,
                         t.held_out_gap, t.significant ? "yes" : "no");
    }
    out << "\n";
    for (const auto& t : round.trials) {
      if (!t.failed.empty()) out << fmt::format("- `{}` failed: {}\n", t.id, t.failed);
      if (!t.skipped.empty()) out << fmt::format("- `{}` skipped: {}\n", t.id, t.skipped);
    }
    out << "\n"
        << (round.accepted.empty() ? std::string("No effect is significant.")
                                   : fmt::format("Accepted: `{}` — {}.", round.accepted,
                                                 find_effect(round.accepted).description()))
        << "\n\n";
  }
}

void write_explanations(std::ostream& out, const DiagnosisResult& result) {
  if (result.explanations.empty()) return;
  out << "## How sure: the explanations weighed\n\n"
         "Each explanation fitted on the way (nothing missing, each effect, the pairs of the first "
         "round's significant effects fitted jointly; where a disagreement is left that has a "
         "shape, the final model with that shape beside it, a force outside the library), weighed "
         "by BIC on the judging data, whose parameters were fitted without it, counting one "
         "independent residual per correlation time of the best library fit's judging residual "
         "and one parameter for each structural choice (an effect that frees no parameter of its "
         "own, the shape outside the library); probabilities exp(−BIC/(2T)) with equal prior odds "
         "(T in docs/diagnosis.md). Where screening fits are coarser than the reported ones "
         "(spectra), the leading three are refitted as the reported fits are before they are "
         "weighed.\n\n"
         "| explanation | free | choices | training cost | held-out cost | BIC | probability |\n"
         "| --- | --- | --- | --- | --- | --- | --- |\n";
  const std::size_t shown = std::min<std::size_t>(result.explanations.size(), 10);
  for (std::size_t i = 0; i < shown; ++i) {
    const Explanation& e = result.explanations[i];
    out << fmt::format("| {} | {} | {} | {:.4g} | {:.4g} | {:.1f} | {:.3f} |\n",
                       explanation_label(e), e.free_parameters, e.structural_choices,
                       e.training_cost, e.held_out_cost, e.bic, e.probability);
  }
  if (shown < result.explanations.size()) {
    out << fmt::format("\n({} more, each at most {:.3f}.)\n", result.explanations.size() - shown,
                       result.explanations[shown].probability);
  }
  out << "\n";
  if (reports_outside_library(result)) {
    out << fmt::format(
        "Probability that the records show a force outside the library: {:.3f} (the explanation "
        "outside the library above).\n\n",
        reported_probability(result));
  } else {
    out << fmt::format(
        "Probability that {}: {:.3f} (every explanation above that contains {}).\n\n",
        result.named.empty() ? std::string("nothing is missing")
                             : explanation_name(result.named) + " is missing",
        reported_probability(result),
        result.named.empty() ? std::string("no effect") : std::string("it"));
  }
  const Explanation* rival = strongest_rival(result.explanations, result.named);
  if (rival && !result.separation.empty()) {
    out << fmt::format("What separates it from the strongest rival, {} ({:.3f}): {}.\n\n",
                       explanation_name(rival->effects), rival->probability, result.separation);
  }
}

nlohmann::json explanations_json(const std::vector<Explanation>& explanations) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& e : explanations) {
    j.push_back({{"effects", e.effects},
                 {"outside_library", e.outside_library},
                 {"structural_choices", e.structural_choices},
                 {"probability", e.probability},
                 {"bic", e.bic},
                 {"free_parameters", e.free_parameters},
                 {"training_cost", e.training_cost},
                 {"held_out_cost", e.held_out_cost},
                 {"residuals", e.residuals},
                 {"held_out_residuals", e.held_out_residuals},
                 {"correlation_time_samples", e.correlation_time}});
  }
  return j;
}

void write_sheet_values(std::ostream& out, const std::vector<DiagnosisResult::SheetValue>& values,
                        const std::string& how) {
  if (values.empty()) return;
  out << "## The data sheet against the records\n\nThe baseline's uncertain values, " << how
      << ", as the final fit put them:\n\n| parameter | sheet | tolerance | fitted | change "
         "|\n| --- | --- | --- | --- | --- |\n";
  for (const auto& v : values) {
    const std::string se =
        v.standard_error ? fmt::format(" ± {:.1f} %", 100.0 * *v.standard_error / v.sheet) : "";
    out << fmt::format("| {} | {:.6g} | ±{:.0f} % | {:.6g} | {:+.1f} %{} |\n", v.name, v.sheet,
                       100.0 * v.tolerance, v.fitted, 100.0 * (v.fitted / v.sheet - 1.0), se);
  }
  out << "\n";
}

nlohmann::json sheet_values_json(const std::vector<DiagnosisResult::SheetValue>& values) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& v : values) {
    list.push_back({{"name", v.name},
                    {"sheet", v.sheet},
                    {"tolerance", v.tolerance},
                    {"fitted", v.fitted},
                    {"change", v.fitted / v.sheet - 1.0},
                    {"standard_error", number_or_null(v.standard_error)}});
  }
  return list;
}

nlohmann::json values_json(const std::vector<FittedValue>& values) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& v : values) {
    j.push_back({{"name", v.name},
                 {"value", v.value},
                 {"standard_error", number_or_null(v.standard_error)}});
  }
  return j;
}

nlohmann::json rounds_json(const DiagnosisResult& result, const std::string& gap_key) {
  nlohmann::json rounds = nlohmann::json::array();
  for (const auto& round : result.rounds) {
    nlohmann::json ranked = nlohmann::json::array();
    for (const auto& t : round.trials) {
      nlohmann::json e = {{"id", t.id}};
      if (!t.skipped.empty()) {
        e["skipped"] = t.skipped;
      } else if (!t.failed.empty()) {
        e["failed"] = t.failed;
      } else {
        e["held_out_improvement"] = t.held_out_improvement;
        e["bic_change"] = t.bic_change;
        e["held_out_cost"] = t.held_out_cost;
        e[gap_key] = t.held_out_gap;
        e["significant"] = t.significant;
        e["parameters"] = values_json(t.parameters);
      }
      ranked.push_back(e);
    }
    rounds.push_back({{"accepted", round.accepted}, {"effects", ranked}});
  }
  return rounds;
}

}  // namespace ridefit::fitting::diagnose
