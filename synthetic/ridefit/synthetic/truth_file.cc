#include "ridefit/synthetic/truth_file.h"

#include <ostream>

#include "ridefit/io/atomic_file.h"

namespace ridefit::synthetic {

YAML::Node truth_header(const HiddenDataset& d, const std::filesystem::path& dir) {
  YAML::Node truth;
  truth["dataset"] = d.name;
  if (d.strut_rig) truth["kind"] = "strut_rig";
  truth["model"] = std::filesystem::relative(d.model, dir).string();
  if (!d.damper_state.empty()) truth["damper_state"] = d.damper_state;
  for (const auto& [key, value] : d.set) truth["set"][key] = value;
  truth["effects"] = YAML::Node(YAML::NodeType::Sequence);
  for (const auto& id : d.effects) truth["effects"].push_back(id);
  return truth;
}

void write_truth_file(const HiddenDataset& d, const YAML::Node& truth,
                      const std::filesystem::path& out_dir) {
  io::write_atomically(out_dir / (d.name + "_truth.yaml"), [&](std::ostream& out) {
    out << "# The truth behind " << d.name
        << " (ridefit generate-hidden): not to be read by the diagnosis\n"
        << truth << "\n";
  });
}

}  // namespace ridefit::synthetic
