#pragma once
// HP-GL for cutters: a pure function from a planned job to the byte stream (docs/plotter-protocols.md 3).
#include <string>

#include "foldkit/devices/job.hpp"

namespace foldkit::devices {

/// `IN;PA;` then per pass `SPn;VSv;FSf;` (or Roland `!FSf;`) and per stroke `PUa,b;` and one `PDa,b;` per
/// point, ending `PU;SP0;IN;` (the
/// final IN; releases cutters that otherwise wait for more). Coordinates in the job's device order.
std::string encode_hpgl(const Job& job);

/// What to send after an interrupted HP-GL stream: tool up, park, initialise.
std::string hpgl_abort_tail();

}  // namespace foldkit::devices
