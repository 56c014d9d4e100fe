#pragma once
// GP-GL in the Silhouette dialect: a pure function from a planned job to the byte stream, following the
// job skeleton of docs/plotter-protocols.md 2.6 and the Cameo 3 recording (ETX after every command).
#include <string>

#include "foldkit/devices/job.hpp"

namespace foldkit::devices {

constexpr char kEtx = '\x03';  ///< GP-GL command terminator
constexpr char kEsc = '\x1b';  ///< starts the out-of-band escape commands (status, initialise)

/// Handshake (ESC 05 status, FG firmware, ESC 04 initialise, TB71/FA calibration queries), set-up (TG
/// mat, FN0, TB50,0 portrait), registration-mark search when the job has one, the \ and Z window, per pass
/// the tool set-up (J, !, FX, FE, FC) and M/D strokes, and the end of job (L0, \0,0, M0,0, J0, FN0, TB50,0).
std::string encode_gpgl(const Job& job);

/// What to send after an interrupted GP-GL stream: tool up and the end-of-job commands.
std::string gpgl_abort_tail();

}  // namespace foldkit::devices
