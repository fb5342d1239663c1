// Files in and out, hardened: only regular files are read, with a size cap
// (a FIFO, /dev/zero or /dev/urandom is an error at once, not a hang), and
// every write is checked, so that a full disk or an unwritable folder is an
// error naming the path and the reason, never a silent half-written file.
#pragma once

#include <cstddef>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "errors.h"

namespace afford {

// The whole of a regular file of at most max_bytes; a DataError naming the
// file otherwise (missing, a directory, a FIFO or device, too large, unreadable).
std::string read_regular_file(const std::string& path, size_t max_bytes);

// A failed write: the path and the reason (strerror), for the command line
// to print and exit 1.
class WriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws WriteError("cannot write PATH: REASON") when a stream (or a C
// file's error flag / fclose) says a write failed. Call after the last write
// and flush; errno names the reason.
void check_written(bool ok, const std::string& path);

class OutputFile;  // output_file.h

// A C file opened for writing (an OutputFile: a temporary file beside the
// target); close() checks every buffered write and the close itself, throws
// WriteError naming the path and the reason, and renames the file into
// place. The destructor closes without checking (an exception is already on
// its way) and removes the unfinished file: the earlier one stays.
class CheckedFile {
 public:
  explicit CheckedFile(const std::string& path);
  ~CheckedFile();
  CheckedFile(const CheckedFile&) = delete;
  CheckedFile& operator=(const CheckedFile&) = delete;
  void close();
  std::FILE* file;

 private:
  std::string path_;
  std::unique_ptr<OutputFile> output_;
  std::unique_ptr<char[]> buffer_;  // the file's buffer: freed after the file is closed
};

// Writes `text` to `path` (an OutputFile: replacing it only as
// output_file.h allows), checked to the last byte.
void write_file_checked(const std::string& path, const std::string& text);

}  // namespace afford
