#include "output_file.h"
#include "write_all.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <map>
#include <mutex>
#include <set>
#include <utility>

namespace afford {
namespace {

namespace fs = std::filesystem;

constexpr size_t kMaxManifestBytes = size_t{16} << 20;

// The running command's policy and what it has written (absolute, normal paths).
struct OutputState {
  OutputPolicy policy;
  std::vector<std::pair<dev_t, ino_t>> input_ids;
  std::vector<std::string> input_paths;  // resolved
  std::set<std::string> written;
};

std::mutex& state_mutex() {
  static std::mutex m;
  return m;
}
OutputState& state() {
  static OutputState s;
  return s;
}
std::vector<OutputState>& saved_states() {
  static std::vector<OutputState> v;
  return v;
}

std::string normal(const std::string& path) { return fs::absolute(path).lexically_normal().string(); }

std::string resolved(const std::string& path) {
  std::error_code ec;
  const fs::path p = fs::weakly_canonical(fs::absolute(path), ec);
  return ec ? normal(path) : p.string();
}

fs::path folder_of(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? fs::path(".") : parent;
}

struct ManifestLine {
  std::string writer, name;
};

std::vector<ManifestLine> parse_manifest(const std::string& text, const std::string& file) {
  std::vector<ManifestLine> lines;
  int number = 0;
  for (size_t start = 0; start < text.size();) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(start, end - start);
    start = end + 1;
    ++number;
    if (line.empty() || line[0] == '#') continue;
    const size_t tab = line.find('\t');
    const std::string name = tab == std::string::npos ? std::string() : line.substr(tab + 1);
    if (tab == 0 || name.empty() || name == "." || name == ".." || name.find('/') != std::string::npos) {
      fail(SourceLoc{file, number, 1}, "WRITER<TAB>FILE NAME (a name in this folder)", shorten(line));
    }
    lines.push_back({line.substr(0, tab), name});
  }
  return lines;
}

// The manifest's lines; none when it does not exist. A damaged line is a
// located error: what it lists may be removed, so it is not guessed at.
std::vector<ManifestLine> read_manifest(const fs::path& folder) {
  const std::string file = (folder / kOutputManifest).string();
  struct stat st {};
  if (::lstat(file.c_str(), &st) != 0 && errno == ENOENT) return {};
  const std::string text = read_regular_file(file, kMaxManifestBytes);
  return parse_manifest(text, file);
}

// What the manifests hold, by folder, as last read or appended to with the
// file's identity then: a render of thousands of frames reads its folder's
// manifest once, not once a frame. A manifest changed since (another
// command, a folder removed and made again) is read again.
struct KnownManifest {
  dev_t dev = 0;
  ino_t ino = 0;
  off_t size = 0;
  timespec mtime{};
  std::set<std::pair<std::string, std::string>> entries;  // (writer, name)
  std::set<std::string> names;
};

std::mutex& manifest_mutex() {
  static std::mutex m;
  return m;
}
std::map<std::string, KnownManifest>& known_manifests() {
  static std::map<std::string, KnownManifest> m;
  return m;
}

bool same_file(const KnownManifest& k, const struct stat& st) {
  return k.dev == st.st_dev && k.ino == st.st_ino && k.size == st.st_size &&
         k.mtime.tv_sec == st.st_mtim.tv_sec && k.mtime.tv_nsec == st.st_mtim.tv_nsec;
}

void remember(KnownManifest* k, const struct stat& st) {
  k->dev = st.st_dev;
  k->ino = st.st_ino;
  k->size = st.st_size;
  k->mtime = st.st_mtim;
}

// The folder's manifest as it is now (manifest_mutex held); nullptr when it has none.
KnownManifest* current_manifest(const fs::path& folder) {
  const std::string file = (folder / kOutputManifest).string();
  std::map<std::string, KnownManifest>& known = known_manifests();
  struct stat st {};
  if (::lstat(file.c_str(), &st) != 0 && errno == ENOENT) {
    known.erase(file);
    return nullptr;
  }
  auto it = known.find(file);
  if (it != known.end() && same_file(it->second, st)) return &it->second;
  KnownManifest k;
  for (const ManifestLine& l : read_manifest(folder)) {
    k.entries.emplace(l.writer, l.name);
    k.names.insert(l.name);
  }
  remember(&k, st);  // as stat saw it before the read: a later change is read again
  return &(known[file] = std::move(k));
}

bool manifest_lists(const fs::path& folder, const std::string& name, const std::string* writer = nullptr) {
  const std::lock_guard<std::mutex> lock(manifest_mutex());
  const KnownManifest* k = current_manifest(folder);
  if (k == nullptr) return false;
  return writer == nullptr ? k->names.count(name) > 0 : k->entries.count({*writer, name}) > 0;
}

const char* kManifestHead = "# The files afford wrote into this folder, by command (WRITER<TAB>NAME): afford\n"
                            "# replaces these without --force, and clears a command's stale ones.\n";

// Lists path in its folder's manifest, once. Appended with O_APPEND: one
// short write, whole even when two commands write into one folder.
void list_in_manifest(const std::string& path, const std::string& writer) {
  const fs::path folder = folder_of(path);
  const std::string name = fs::path(path).filename().string();
  const std::lock_guard<std::mutex> lock(manifest_mutex());
  KnownManifest* k = current_manifest(folder);
  if (k != nullptr && k->entries.count({writer, name}) > 0) return;
  const std::string file = (folder / kOutputManifest).string();
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_NOFOLLOW | O_CLOEXEC, 0644);
  check_written(fd >= 0, file);
  std::string text = writer + "\t" + name + "\n";
  struct stat st {};
  if (::fstat(fd, &st) == 0 && st.st_size == 0) text = kManifestHead + text;
  const int e = write_all(fd, text.data(), text.size());
  if (e == 0 && ::fstat(fd, &st) == 0) {  // known as it is now, with the line added
    KnownManifest& known = known_manifests()[file];
    if (k == nullptr) known = KnownManifest{};
    known.entries.emplace(writer, name);
    known.names.insert(name);
    remember(&known, st);
  }
  ::close(fd);
  errno = e;
  check_written(e == 0, file);
}

[[noreturn]] void refuse(const std::string& path, const std::string& why) { throw OutputRefused(path + ": " + why); }

// A link to a character device (trace.csv -> /dev/null, to discard it):
// the one link written through, as there is nothing at its end to lose.
bool links_to_device(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISCHR(st.st_mode);
}

}  // namespace

int write_all(int fd, const void* data, size_t n) {
  const char* p = static_cast<const char*>(data);
  while (n > 0) {
    const ssize_t w = ::write(fd, p, n);
    if (w < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    p += w;
    n -= static_cast<size_t>(w);
  }
  return 0;
}

OutputScope::OutputScope(const OutputPolicy& policy) {
  OutputState next;
  next.policy = policy;
  for (const std::string& input : policy.inputs) {
    struct stat st {};
    if (::stat(input.c_str(), &st) == 0) next.input_ids.emplace_back(st.st_dev, st.st_ino);
    next.input_paths.push_back(resolved(input));
  }
  const std::lock_guard<std::mutex> lock(state_mutex());
  saved_states().push_back(std::move(state()));
  state() = std::move(next);
}

OutputScope::~OutputScope() {
  const std::lock_guard<std::mutex> lock(state_mutex());
  state() = std::move(saved_states().back());
  saved_states().pop_back();
}

bool listed_as_afford_output(const std::string& path) {
  return manifest_lists(folder_of(path), fs::path(path).filename().string());
}

void check_output(const std::string& path, bool own) {
  if (path.empty()) refuse("''", "expected a file name to write");
  OutputState s;
  {
    const std::lock_guard<std::mutex> lock(state_mutex());
    s.policy = state().policy;
    s.input_ids = state().input_ids;
    s.input_paths = state().input_paths;
  }
  const std::string where = resolved(path);
  for (const std::string& input : s.input_paths) {
    if (input == where) refuse(path, "one of this command's inputs; choose another output");
  }
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0) {
    if (errno == ENOENT) return;  // a new file
    refuse(path, std::string("cannot look at it: ") + std::strerror(errno));
  }
  if (S_ISLNK(st.st_mode)) {
    if (links_to_device(path)) return;
    refuse(path, "a symbolic link; afford does not write through links (remove it, or choose another name)");
  }
  if (S_ISDIR(st.st_mode)) refuse(path, "a folder; expected a file to write");
  if (S_ISCHR(st.st_mode)) return;  // /dev/null, a terminal: written into, holds nothing to lose
  if (!S_ISREG(st.st_mode)) refuse(path, "not a regular file; expected a file to write");
  for (const auto& [dev, ino] : s.input_ids) {
    if (st.st_dev == dev && st.st_ino == ino) refuse(path, "one of this command's inputs; choose another output");
  }
  if (own || s.policy.force || listed_as_afford_output(path)) return;
  refuse(path, "exists and afford did not write it; choose another name, or --force to replace it");
}

OutputFile::OutputFile(const std::string& path, Options options) : path_(path) {
  check_output(path, options.own);
  std::string writer;
  {
    const std::lock_guard<std::mutex> lock(state_mutex());
    writer = state().policy.writer;
    state().written.insert(normal(path));
  }
  errno = 0;
  struct stat st {};
  if (::lstat(path.c_str(), &st) == 0 && (S_ISCHR(st.st_mode) || S_ISLNK(st.st_mode)) && links_to_device(path)) {
    // A device, or a link to one: written into, no temporary file, no manifest.
    fd_ = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    check_written(fd_ >= 0, path);
    if (::fstat(fd_, &st) != 0 || !S_ISCHR(st.st_mode)) {
      ::close(fd_);
      refuse(path, "changed while opened; expected a device");
    }
    return;
  }
  if (options.in_place_when_new) {
    // Listed first: a crash leaves a file afford may replace.
    list_in_manifest(path, writer);
    fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd_ >= 0) return;
    check_written(errno == EEXIST, path);  // EEXIST: an earlier file, replaced by rename at commit()
  }
  const fs::path folder = folder_of(path);
  const std::string stem = "." + fs::path(path).filename().string().substr(0, 200) + ".afford-" +
                           std::to_string(::getpid()) + "-";
  static std::atomic<unsigned> counter{0};
  for (int attempt = 0; attempt < 100 && fd_ < 0; ++attempt) {
    temp_ = (folder / (stem + std::to_string(counter++))).string();
    fd_ = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd_ < 0 && errno != EEXIST) break;
  }
  if (fd_ < 0) {
    temp_.clear();
    check_written(false, path);
  }
}

OutputFile::~OutputFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_ && !temp_.empty()) ::unlink(temp_.c_str());
}

int OutputFile::release_fd() {
  const int fd = fd_;
  fd_ = -1;
  return fd;
}

void OutputFile::commit() {
  if (committed_) return;
  // A failed buffered write of another file, not yet checked, keeps its
  // errno (CheckedFile::close names the reason from it).
  const int earlier_errno = errno;
  if (fd_ >= 0) {
    const int fd = release_fd();
    errno = 0;
    check_written(::close(fd) == 0, path_);
  }
  committed_ = true;
  if (temp_.empty()) {  // written in place (listed when created), or a device
    errno = earlier_errno;
    return;
  }
  std::string writer;
  {
    const std::lock_guard<std::mutex> lock(state_mutex());
    writer = state().policy.writer;
  }
  try {
    list_in_manifest(path_, writer);
    // A link put there meanwhile is replaced itself (rename never follows it).
    errno = 0;
    check_written(::rename(temp_.c_str(), path_.c_str()) == 0, path_);
  } catch (...) {
    ::unlink(temp_.c_str());
    throw;
  }
  errno = earlier_errno;
}

std::vector<std::string> clear_stale_outputs(const std::string& folder_name) {
  const fs::path folder(folder_name);
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) return {};
  OutputState s;
  {
    const std::lock_guard<std::mutex> lock(state_mutex());
    s.policy = state().policy;
    s.written = state().written;
  }
  std::vector<ManifestLine> kept;
  std::set<std::pair<std::string, std::string>> seen;  // a line listed twice is kept once
  std::vector<std::string> removed;
  const std::vector<ManifestLine> lines = read_manifest(folder);
  std::set<std::string> others;  // names another command wrote too: its file now, not removed
  for (const ManifestLine& l : lines) {
    if (l.writer != s.policy.writer) others.insert(l.name);
  }
  for (const ManifestLine& l : lines) {
    const std::string path = (folder / l.name).string();
    if (l.writer != s.policy.writer || s.written.count(normal(path)) > 0) {
      if (seen.emplace(l.writer, l.name).second) kept.push_back(l);
      continue;
    }
    struct stat st {};
    if (others.count(l.name) == 0 && ::lstat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode)) {
      errno = 0;
      check_written(::unlink(path.c_str()) == 0, path);
      removed.push_back(path);
    }
  }
  if (kept.size() == lines.size()) return removed;  // nothing stale, nothing gone
  std::string text = kManifestHead;
  for (const ManifestLine& l : kept) text += l.writer + "\t" + l.name + "\n";
  const std::string file = (folder / kOutputManifest).string();
  const std::string temp = file + ".afford-" + std::to_string(::getpid());
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0644);
  check_written(fd >= 0, file);
  const int e = write_all(fd, text.data(), text.size());
  const bool closed = ::close(fd) == 0;
  errno = e;
  if (e != 0 || !closed || ::rename(temp.c_str(), file.c_str()) != 0) {
    const int why = errno;
    ::unlink(temp.c_str());
    errno = why;
    check_written(false, file);
  }
  return removed;
}

}  // namespace afford
