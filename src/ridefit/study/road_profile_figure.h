#pragma once

#include <string>

#include "ridefit/io/gnuplot_figure.h"
#include "ridefit/road/international_roughness_index.h"
#include "ridefit/road/iso8608_classification.h"

namespace ridefit::study {

// The figure of `ridefit road --plot`: the profile's displacement PSD over spatial frequency
// with its confidence band, the fitted ISO 8608 line (waviness 2) and the class boundaries
// (A|B … G|H) over 0.011–2.83 cycles/m; beside it the IRI per segment over distance.
io::Figure road_profile_figure(const std::string& title, const road::Iso8608Classification& iso,
                               const road::InternationalRoughnessIndex& iri);

}  // namespace ridefit::study
