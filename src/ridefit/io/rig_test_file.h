#pragma once

#include <filesystem>

#include "ridefit/io/yaml_map.h"
#include "ridefit/road/rig_test.h"

namespace ridefit::io {

// A rig test file (docs/cli.md, `ridefit simulate-rig`):
//   waveform: sine            # sine | triangle | random
//   amplitude_m: 0.01         # sine, triangle: half the stroke
//   frequency_Hz: 2           # sine
//   speed_m_per_s: 0.05       # triangle
//   rms_m: 0.002              # random: the displacement's RMS
//   band_Hz: [0.5, 20]        # random: the band its lines fill
//   seed: 1                   # random: the phases (default 1)
//   duration_s: 10
//   sample_rate_Hz: 1000      # default 1000
//   rig: {stroke_m: 0.05, velocity_m_per_s: 1.5, force_N: 20000, frequency_Hz: 30}  # optional
// The keys that do not belong to the waveform are refused, as is any other key.
struct RigTestFile {
  road::RigTest test;
  road::RigLimits limits;
};

// Reads and checks (RigTest::validate against the file's limits, or `limits` when the file has
// no `rig:` block); InputError naming the file and key.
RigTestFile load_rig_test(const std::filesystem::path& path, const road::RigLimits& limits = {});
RigTestFile read_rig_test(const YamlMap& document, const road::RigLimits& limits = {});

// A rig's limits: the keys of `rig:` at the top level of its own file, each optional (the
// defaults of RigLimits), or under a `rig:` block (a model or test file's).
road::RigLimits load_rig_limits(const std::filesystem::path& path);
road::RigLimits read_rig_limits(const YamlMap& block, const road::RigLimits& defaults = {});

}  // namespace ridefit::io
