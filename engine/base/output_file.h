// Outputs that never lose a user's data (issue 31). Every file afford
// writes goes through here:
//   - it is written to a temporary file beside the target (same folder,
//     O_EXCL | O_NOFOLLOW) and renamed into place once whole, so that a
//     failed or interrupted command leaves the earlier file as it was;
//   - a symbolic link at the target is refused, never followed;
//   - one of the command's inputs is never a target (by device and inode,
//     and by resolved path);
//   - a character device (/dev/null), or a link to one, is written into
//     as it is: there is nothing at its end to lose;
//   - an existing file that afford did not write is replaced only with
//     --force. What afford wrote into a folder is listed in the folder's
//     manifest, kOutputManifest ("writer<TAB>name" a line), so that a
//     re-run replaces its own files, and a command can clear its own stale
//     files (the maps of an earlier run's actees) and only those.
// The policy (which inputs, --force) is the command's, one per process:
// the command line sets it with an OutputScope once the inputs are known.
#pragma once

#include <string>
#include <vector>

#include "files.h"

namespace afford {

inline constexpr const char* kOutputManifest = ".afford-outputs";

// What the running command may write over.
struct OutputPolicy {
  std::string writer = "afford";    // the command, as listed in the manifest: "run", "explore"
  bool force = false;               // replace existing files afford did not write
  std::vector<std::string> inputs;  // the files the command reads: never an output
};

// Sets the policy for its lifetime; the one before comes back after.
class OutputScope {
 public:
  explicit OutputScope(const OutputPolicy& policy);
  ~OutputScope();
  OutputScope(const OutputScope&) = delete;
  OutputScope& operator=(const OutputScope&) = delete;
};

// Why a target may not be written: names the file. Thrown before any byte
// is written (exit 1, like a WriteError).
class OutputRefused : public WriteError {
 public:
  using WriteError::WriteError;
};

// Throws OutputRefused unless `path` may be written now: not a link, not a
// folder, not an input, and absent, afford's own or --force. `own`: the
// caller recognised the existing file as afford's (a recording's header).
// Commands call it for their known targets before long work starts.
void check_output(const std::string& path, bool own = false);

// Whether the file at path is listed in its folder's manifest.
bool listed_as_afford_output(const std::string& path);

// A file being written. Created by the constructor (after check_output),
// renamed into place by commit(); the destructor removes an uncommitted
// temporary file. Throws WriteError / OutputRefused naming the path.
class OutputFile {
 public:
  struct Options {
    // Write at the target itself when nothing is there (O_CREAT | O_EXCL):
    // a stream that must survive a crash (a recording) keeps what it wrote
    // at its name. An existing target is still replaced by rename.
    bool in_place_when_new = false;
    bool own = false;  // as check_output's
  };
  explicit OutputFile(const std::string& path) : OutputFile(path, Options{}) {}
  OutputFile(const std::string& path, Options options);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  int fd() const { return fd_; }
  // Hands the descriptor to a FILE* (fdopen): the caller closes it before commit().
  int release_fd();
  // Closes the descriptor if still held, lists the file in its folder's
  // manifest and renames it into place.
  void commit();
  const std::string& path() const { return path_; }
  // Where the bytes go until commit(): the temporary file, or the target
  // when written in place. For a program that writes the file itself
  // (ffmpeg), whose file is then renamed into place like any other.
  const std::string& written_path() const { return temp_.empty() ? path_ : temp_; }

 private:
  std::string path_, temp_;  // temp_ empty when written in place
  int fd_ = -1;
  bool committed_ = false;
};

// Removes from `folder` the files this command's writer listed there in an
// earlier run and did not write in this one (nor since this process began),
// and drops them from the manifest. Files of other writers, and files not
// listed, are left alone. Returns the paths removed.
std::vector<std::string> clear_stale_outputs(const std::string& folder);

}  // namespace afford
