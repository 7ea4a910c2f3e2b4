// Chatter (Zeno) against a limiter (MODEL.md, event 4): after an impact the pellet is pressed
// back by a_free, so impact speeds and flight times shrink geometrically, with ratio
//   r = k·sqrt(a_toward / a_away),
// and infinitely many impacts accumulate at t* = t_n + T_{n+1} / (1 − r).
#pragma once

#include <optional>

#include "core/model/model.h"

namespace vibro {

struct ChatterSeries {
  double r = 0.0;       // ratio of successive impact speeds and flight times
  double t_next = 0.0;  // the next flight T_{n+1}, s
  double t_star = 0.0;  // accumulation time, s
  int impacts = 0;      // impacts summed until the speed is below round-off of the first
};

// The series after an impact at time t on the limiter at angle theta, leaving with speed u > 0
// toward side `side` (+1: phi > theta), with free acceleration a_free there. Empty when the
// pellet is not pressed back hard enough for chatter (it then sticks at the top of its flight
// or flies off).
std::optional<ChatterSeries> chatter_series(const Model& model, double t, double theta, int side,
                                            double u, double k, double a_free);

}  // namespace vibro
