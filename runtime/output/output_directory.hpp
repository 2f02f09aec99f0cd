// The output directory of a run, claimed before the solve: created if missing, proved
// writable (a probe file created, written and removed) and locked (flock(2) on
// DIR/.pd.lock) for as long as the claim lives, so that a read-only directory, a file
// given as --out, a full disk or a second run into the same directory is found in a
// second, not after the whole solve, and two runs never interleave their files.
#pragma once

#include <string>

#include "input/yaml_keys.hpp"

namespace pd {

// Bad input like a bad scene (`pd run` exits 2): the message names the directory.
class OutputDirectoryError : public SceneError {
 public:
  using SceneError::SceneError;
};

class OutputDirectoryClaim {
 public:
  // Throws OutputDirectoryError. The lock file holds the claiming process id.
  explicit OutputDirectoryClaim(const std::string& directory);
  // Unlocks and removes the lock file; removes the directory too when the claim created
  // it and the run left it empty (a run stopped by bad input leaves nothing behind).
  ~OutputDirectoryClaim();
  OutputDirectoryClaim(const OutputDirectoryClaim&) = delete;
  OutputDirectoryClaim& operator=(const OutputDirectoryClaim&) = delete;

  const std::string& lock_path() const { return lock_path_; }

 private:
  std::string directory_, lock_path_;
  bool created_ = false;
  int fd_ = -1;
};

}  // namespace pd
