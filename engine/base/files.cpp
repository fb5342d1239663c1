#include "files.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "output_file.h"

namespace afford {
namespace {

std::string kind_of(mode_t mode) {
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

}  // namespace

std::string read_regular_file(const std::string& path, size_t max_bytes) {
  const SourceLoc at{path, 0, 0};
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    if (errno == ELOOP) fail(at, "a readable file", "a loop of symbolic links");
    if (errno == ENOENT) fail(at, "a readable file", "none");
    fail(at, "a readable file", std::strerror(errno));
  }
  if (S_ISDIR(st.st_mode)) fail(at, "a readable file", "a directory");
  // Checked before opening: opening a FIFO blocks, a device never ends.
  if (!S_ISREG(st.st_mode)) fail(at, "a regular file", kind_of(st.st_mode));
  if (static_cast<unsigned long long>(st.st_size) > max_bytes) {
    fail(at, "a file of at most " + std::to_string(max_bytes) + " bytes",
         std::to_string(st.st_size) + " bytes");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(at, "a readable file", std::strerror(errno));
  // Read in pieces, no more than the cap even if the file grows meanwhile
  // (and without setting aside the whole cap for a small file).
  std::string text;
  text.reserve(static_cast<size_t>(st.st_size));
  char piece[1 << 16];
  while (text.size() <= max_bytes && in.read(piece, sizeof piece).gcount() > 0) {
    text.append(piece, static_cast<size_t>(in.gcount()));
  }
  if (in.bad()) fail(at, "a readable file", std::strerror(errno));
  if (text.size() > max_bytes) {
    fail(at, "a file of at most " + std::to_string(max_bytes) + " bytes", "a file still growing");
  }
  return text;
}

void check_written(bool ok, const std::string& path) {
  if (ok) return;
  const int e = errno;
  throw WriteError("cannot write " + path + ": " + (e ? std::strerror(e) : "write failed"));
}

CheckedFile::CheckedFile(const std::string& path) : file(nullptr), path_(path) {
  output_ = std::make_unique<OutputFile>(path);
  const int fd = output_->release_fd();
  file = ::fdopen(fd, "w");
  if (file == nullptr) ::close(fd);
  check_written(file != nullptr, path_);
  // Traces are hundreds of kilobytes: written in pieces of 64 KiB, not of
  // the default 4 KiB, they take a sixteenth of the system calls. (glibc
  // ignores the size unless it is given the buffer.)
  constexpr size_t kBufferBytes = size_t{1} << 16;
  buffer_ = std::make_unique_for_overwrite<char[]>(kBufferBytes);
  std::setvbuf(file, buffer_.get(), _IOFBF, kBufferBytes);
}

CheckedFile::~CheckedFile() {
  if (file != nullptr) std::fclose(file);
}

void CheckedFile::close() {
  // errno is left as the failed buffered write set it (ENOSPC, EIO, ...).
  const bool flushed = std::fflush(file) == 0 && !std::ferror(file);
  const int flush_errno = errno;
  const bool closed = std::fclose(file) == 0;
  file = nullptr;
  if (!flushed) errno = flush_errno;
  check_written(flushed && closed, path_);
  output_->commit();  // renamed into place only once whole
}

void write_file_checked(const std::string& path, const std::string& text) {
  OutputFile out(path);
  const char* p = text.data();
  size_t left = text.size();
  while (left > 0) {
    const ssize_t w = ::write(out.fd(), p, left);
    if (w < 0 && errno == EINTR) continue;
    check_written(w > 0, path);
    p += w;
    left -= static_cast<size_t>(w);
  }
  out.commit();
}

}  // namespace afford
