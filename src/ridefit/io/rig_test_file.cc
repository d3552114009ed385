#include "ridefit/io/rig_test_file.h"

#include <fmt/core.h>

#include "ridefit/common/errors.h"

namespace ridefit::io {
namespace {

// The test's own checks, their messages prefixed with the file.
template <typename Check>
void checked(const YamlMap& document, Check check) {
  try {
    check();
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", document.path().string(), e.what()));
  }
}

}  // namespace

road::RigLimits read_rig_limits(const YamlMap& block, const road::RigLimits& defaults) {
  road::RigLimits limits = defaults;
  limits.stroke_m = block.number_or("stroke_m", limits.stroke_m);
  limits.velocity_m_per_s = block.number_or("velocity_m_per_s", limits.velocity_m_per_s);
  limits.force_N = block.number_or("force_N", limits.force_N);
  limits.frequency_Hz = block.number_or("frequency_Hz", limits.frequency_Hz);
  block.finish();
  checked(block, [&] { limits.validate(); });
  return limits;
}

road::RigLimits load_rig_limits(const std::filesystem::path& path) {
  const YamlMap document = YamlMap::load(path);
  if (document.has("rig") && document.is_mapping("rig")) {
    const road::RigLimits limits = read_rig_limits(document.map("rig"));
    document.finish();
    return limits;
  }
  return read_rig_limits(document);
}

RigTestFile read_rig_test(const YamlMap& document, const road::RigLimits& limits) {
  RigTestFile file;
  file.limits = document.has("rig") ? read_rig_limits(document.map("rig"), limits) : limits;
  road::RigTest& t = file.test;
  const std::string waveform = document.choice("waveform", {"sine", "triangle", "random"});
  if (waveform == "sine") {
    t.waveform = road::RigWaveform::kSine;
    t.amplitude_m = document.positive("amplitude_m");
    t.frequency_Hz = document.positive("frequency_Hz");
  } else if (waveform == "triangle") {
    t.waveform = road::RigWaveform::kTriangle;
    t.amplitude_m = document.positive("amplitude_m");
    t.speed_m_per_s = document.positive("speed_m_per_s");
  } else {
    t.waveform = road::RigWaveform::kRandom;
    t.rms_m = document.positive("rms_m");
    const std::vector<double> band = document.numbers("band_Hz");
    if (band.size() != 2) {
      throw InputError(fmt::format("{} holds {} numbers; give two, [low, high] in Hz",
                                   document.locate("band_Hz"), band.size()));
    }
    t.band_low_Hz = band[0];
    t.band_high_Hz = band[1];
    const long seed = document.integer_or("seed", 1);
    if (seed < 0 || seed > 4294967295L) {
      throw InputError(fmt::format("{} is {}; give a whole number from 0 to 4294967295",
                                   document.locate("seed"), seed));
    }
    t.seed = static_cast<unsigned>(seed);
  }
  t.duration_s = document.positive("duration_s");
  t.sample_rate_Hz = document.number_or("sample_rate_Hz", t.sample_rate_Hz);
  document.finish();
  checked(document, [&] { t.validate(file.limits); });
  return file;
}

RigTestFile load_rig_test(const std::filesystem::path& path, const road::RigLimits& limits) {
  return read_rig_test(YamlMap::load(path), limits);
}

}  // namespace ridefit::io
