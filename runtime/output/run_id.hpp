// The id of this run: written into summary.json, the .pvd and every .vtu, so that a
// reader of a directory that two runs wrote into (one killed with -9 half-way over an
// older result) can tell which files belong together.
#pragma once

#include <string>

namespace pd {

// "20261201T211500Z-12345-1a2b3c4d": UTC start time, process id, 32 random bits. Made
// once per process (a study's points, written to separate directories, share it).
const std::string& run_id();

}  // namespace pd
