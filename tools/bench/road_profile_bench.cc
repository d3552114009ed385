// Road profile evaluation: IRI (ASTM E1926) and ISO 8608 classification of a measured-style
// profile. Run with
//   road_profile_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cstddef>

#include "ridefit/road/international_roughness_index.h"
#include "ridefit/road/iso8608.h"
#include "ridefit/road/iso8608_classification.h"
#include "ridefit/road/random_profile.h"
#include "ridefit/road/road_profile.h"

namespace {

using ridefit::road::RoadProfile;

// 10 km of class C road at 0.25 m (40 001 samples); the band stops at 1 cycle/m, which the
// generator's 4-samples-per-wave rule allows at this spacing.
RoadProfile class_c_10km_at_025m() {
  const ridefit::road::PowerLawSpectrum spectrum =
      ridefit::road::iso8608_spectrum(ridefit::road::Iso8608Class::kC);
  const ridefit::road::RandomProfile raw =
      ridefit::road::random_profile([&](double n) { return spectrum.psd_m3(n); },
                                    ridefit::road::SpatialBand{0.011, 1.0}, 10000.0, 0.25, 1);
  RoadProfile profile;
  profile.elevation_m = raw.elevation_m;
  for (std::size_t k = 0; k < raw.elevation_m.size(); ++k) {
    profile.distance_m.push_back(static_cast<double>(k) * raw.spacing_m);
  }
  return profile;
}

void BM_Iri10kmAt025m(benchmark::State& state) {
  const RoadProfile profile = class_c_10km_at_025m();
  for (auto _ : state) {
    auto iri = ridefit::road::international_roughness_index(profile);
    benchmark::DoNotOptimize(iri);
  }
}
BENCHMARK(BM_Iri10kmAt025m)->Unit(benchmark::kMillisecond);

void BM_Iso8608Classification10kmAt025m(benchmark::State& state) {
  const RoadProfile profile = class_c_10km_at_025m();
  for (auto _ : state) {
    auto result = ridefit::road::classify_iso8608(profile);
    benchmark::DoNotOptimize(result);
  }
}
BENCHMARK(BM_Iso8608Classification10kmAt025m)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
