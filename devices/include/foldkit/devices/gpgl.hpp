#pragma once
// GP-GL in the Silhouette dialect: a pure function from a planned job to the byte stream, following the
// job skeleton of docs/plotter-protocols.md 2.6 and the Cameo 3 recording (ETX after every command).
#include <string>

#include "foldkit/devices/job.hpp"

namespace foldkit::devices {

constexpr char kEtx = '\x03';  ///< GP-GL command terminator
constexpr char kEsc = '\x1b';  ///< starts the out-of-band escape commands (status, initialise)

/// Silhouette families: handshake (ESC 05 status, FG firmware, ESC 04 initialise, TB71/FA, and TC on the
/// Cameo 3), set-up (TG mat, FN0, TB50,0 portrait, the \ and Z window in machine coordinates), the
/// registration-mark search when the job has one, per pass the family's tool set-up (J only on
/// multi-holder machines; !, FX, FE, FF, FC, TF for an AutoBlade) and one point per M/D, and the end of
/// job (L0, \0,0, M0,0, J0, FN0, TB50,0). Graphtec family: window, `!` and `*` per pass, strokes, H.
std::string encode_gpgl(const Job& job);

/// What to send after an interrupted GP-GL stream of `job`'s family: tool up and the end-of-job commands.
std::string gpgl_abort_tail(const Job& job);
/// The Silhouette (Cameo 3, two holders) abort tail.
std::string gpgl_abort_tail();

}  // namespace foldkit::devices
