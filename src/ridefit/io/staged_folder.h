#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace ridefit::io {

// A folder output written as a whole: the run writes into a temporary sibling
// (`.NAME.tmpPID`, holding hard links to the files already in the folder that the run does not
// write), and commit() swaps it into place in one atomic rename (renameat2 RENAME_EXCHANGE), so a
// run killed midway never leaves a folder that mixes its files with an earlier run's: the folder
// is either the old one or the new one. Without commit() (an error) the staging folder is
// removed and the folder stays as it was; a killed run's staging folder is removed by the next
// run (remove_stale_temporaries). A folder that is the working directory or holds it is written
// in place (swapping it would leave the shell in a removed folder).
class StagedFolder {
 public:
  // `files`: the names the run writes (they are not carried over from the old folder).
  StagedFolder(const std::filesystem::path& dir, const std::vector<std::string>& files);
  ~StagedFolder();
  StagedFolder(const StagedFolder&) = delete;
  StagedFolder& operator=(const StagedFolder&) = delete;

  // Where the run writes its files.
  const std::filesystem::path& path() const { return staging_; }

  // Writes the folder's manifest (finish_output_folder) and puts the staged folder in place.
  void commit();

 private:
  std::filesystem::path dir_;
  std::filesystem::path staging_;
  std::vector<std::string> files_;
  bool in_place_ = false;
  bool committed_ = false;
};

}  // namespace ridefit::io
