// A run writes its files into a fresh staging directory, DIR/unfinished-RUNID/, and only
// publishes them into DIR when it ends (done, failed or stopped by a signal). A run killed
// with -9 therefore leaves DIR's older result whole, beside the staging directory of the
// killed run (its snapshots and checkpoint, from which --restart can resume).
//
// Publishing, in this order: DIR/summary.json is removed; the files of the run before
// (listed in DIR/.pd.files, written by the last publish) are removed; the staged files
// are renamed into DIR; DIR/.pd.files lists them; summary.json comes last (its "files"
// renamed to DIR). So a directory holding summary.json holds exactly that run's result,
// every file carrying its run_id; one without summary.json holds an unfinished run.
#pragma once

#include <string>
#include <vector>

namespace pd {

class StagingDirectory {
 public:
  // Creates DIR/unfinished-RUNID (DIR already claimed: output_directory.hpp). Throws
  // std::runtime_error naming it when it cannot be made.
  explicit StagingDirectory(const std::string& directory);
  // Removes the staging directory and what is in it when it was not published.
  ~StagingDirectory();
  StagingDirectory(const StagingDirectory&) = delete;
  StagingDirectory& operator=(const StagingDirectory&) = delete;

  const std::string& path() const { return staging_; }
  // Moves the staged files into DIR as described above; returns the published names. A
  // run that staged no file (a static run that failed or was stopped) leaves DIR as it was.
  std::vector<std::string> publish();
  // Staging directories of earlier runs that did not finish (killed), to be named in the log.
  std::vector<std::string> leftovers() const;

 private:
  std::string directory_, staging_;
  bool published_ = false;
};

}  // namespace pd
