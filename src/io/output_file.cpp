#include "stratum/io/output_file.hpp"

#include <fcntl.h>
#include <limits.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include "stratum/distributed.hpp"
#include "stratum/util/error.hpp"
#include "stratum/util/interrupt.hpp"

namespace stratum::io {

namespace fs = std::filesystem;

namespace {

// ---- the staging files alive now, removed by a signal handler ----------
// Fixed storage and lock-free atomics: the handler may only unlink and raise.
constexpr int registry_slots = 64;
char live_paths[registry_slots][PATH_MAX];
std::atomic<int> live_state[registry_slots];  // 0 free, 1 being filled, 2 live

int register_staging(const std::string& path) {
  if (path.size() >= PATH_MAX) return -1;
  for (int i = 0; i < registry_slots; ++i) {
    int expected = 0;
    if (live_state[i].compare_exchange_strong(expected, 1)) {
      std::memcpy(live_paths[i], path.c_str(), path.size() + 1);
      live_state[i].store(2);
      return i;
    }
  }
  return -1;  // more than 64 at once: still removed on errors, not on signals
}

void unregister_staging(int& slot) {
  if (slot >= 0) live_state[slot].store(0);
  slot = -1;
}

// > 0 while a command would rather stop on Ctrl-C and keep its work (StopOnInterrupt).
std::atomic<int> stop_scopes{0};

extern "C" void remove_staging_and_reraise(int signal) {
  // The first SIGINT of such a command asks it to stop; a second one (or
  // SIGTERM) ends the process at once, as without it.
  if (signal == SIGINT && stop_scopes.load() > 0 && !interrupt_requested()) {
    request_interrupt();
    return;
  }
  for (int i = 0; i < registry_slots; ++i)
    if (live_state[i].load() == 2) ::unlink(live_paths[i]);
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

std::string os_error(int error) { return error ? std::strerror(error) : "an unknown error"; }

/// What a non-regular file is, for messages.
std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

/// The PID in a staging file's name (".NAME.stratum-tmp.PID-K.EXT"), or 0.
long staging_pid(const std::string& name) {
  if (name.empty() || name[0] != '.') return 0;
  const auto at = name.rfind(staging_marker);
  if (at == std::string::npos) return 0;
  const char* digits = name.c_str() + at + std::strlen(staging_marker);
  char* end = nullptr;
  const long pid = std::strtol(digits, &end, 10);
  return end != digits && *end == '-' && pid > 0 ? pid : 0;
}

/// The file a path names after following symbolic links (the last one may dangle).
fs::path follow_links(const fs::path& path) {
  fs::path p = path;
  for (int hops = 0; hops < 40; ++hops) {
    std::error_code error;
    if (!fs::is_symlink(fs::symlink_status(p, error)) || error) return p;
    const fs::path next = fs::read_symlink(p, error);
    if (error) return p;
    p = next.is_absolute() ? next : p.parent_path() / next;
  }
  return p;
}

/// Writes all of `size` bytes to `fd`, retrying short writes; false with errno on error.
bool write_all(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t done = ::write(fd, data, size);
    if (done < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    data += done;
    size -= static_cast<std::size_t>(done);
  }
  return true;
}

std::atomic<unsigned> staging_counter{0};

/// A stream buffer over a file descriptor that keeps the OS error of the
/// first failed write (an ofstream loses it).
class FdBuffer : public std::streambuf {
 public:
  explicit FdBuffer(int fd) : fd_(fd), buffer_(1 << 16) { setp(buffer_.data(), buffer_.data() + buffer_.size()); }
  int error() const { return error_; }

 protected:
  int_type overflow(int_type c) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  std::streamsize xsputn(const char* data, std::streamsize size) override {
    if (size < static_cast<std::streamsize>(buffer_.size())) return std::streambuf::xsputn(data, size);
    if (!drain() || !send(data, static_cast<std::size_t>(size))) return 0;  // large blocks go straight out
    return size;
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  bool send(const char* data, std::size_t size) {
    if (error_) return false;
    if (!write_all(fd_, data, size)) {
      error_ = errno ? errno : EIO;
      return false;
    }
    return true;
  }
  bool drain() {
    const auto size = static_cast<std::size_t>(pptr() - pbase());
    if (size && !send(pbase(), size)) return false;
    setp(buffer_.data(), buffer_.data() + buffer_.size());
    return true;
  }
  int fd_;
  std::vector<char> buffer_;
  int error_ = 0;
};

/// Runs `body` on a stream into `fd`; the OS error of a failed write, or 0.
int write_through(int fd, const std::function<void(std::ostream&)>& body) {
  FdBuffer buffer(fd);
  std::ostream out(&buffer);
  body(out);
  out.flush();
  if (buffer.error()) return buffer.error();
  return out ? 0 : EIO;
}

}  // namespace

OutputFile::OutputFile(std::string argument, std::string path)
    : argument_(std::move(argument)), path_(std::move(path)) {}

OutputFile::~OutputFile() { discard(); }

void OutputFile::fail(const std::string& why) const { throw invalid_argument(argument_, path_, why); }

void OutputFile::prepare() {
  if (prepared_) return;
  if (path_.empty()) fail("must be a file name");
  if (!distributed::is_root()) {  // a distributed job writes once, from rank 0
    inactive_ = prepared_ = true;
    return;
  }
  // A FIFO or device is opened by the name given (/dev/stdout's link chain
  // ends in /proc); a regular file or a new one is the end of the link chain.
  struct stat info {};
  const bool exists = ::stat(path_.c_str(), &info) == 0;
  target_ = exists && !S_ISREG(info.st_mode) ? fs::path(path_) : follow_links(fs::path(path_));
  if (exists) {
    if (S_ISREG(info.st_mode)) {
      if (info.st_nlink > 1)
        fail("has " + std::to_string(info.st_nlink) +
             " hard links: replacing it would split them and writing in place could half-write it; "
             "remove it or write elsewhere");
      if (::access(target_.c_str(), W_OK) != 0) fail("must be writable (" + os_error(errno) + ")");
      existed_ = true;
      mode_ = info.st_mode & 07777;
      owner_ = info.st_uid;
      group_ = info.st_gid;
    } else if (S_ISCHR(info.st_mode) || S_ISFIFO(info.st_mode)) {
      if (::access(target_.c_str(), W_OK) != 0) fail("must be writable (" + os_error(errno) + ")");
      special_ = true;
    } else {
      fail("is " + kind_of(info.st_mode) + ": give a file name (a regular file, a FIFO or a character device)");
    }
    device_ = info.st_dev;
    inode_ = info.st_ino;
  } else if (errno != ENOENT) {
    fail("cannot be examined (" + os_error(errno) + ")");
  }
  const fs::path folder = special_                    ? fs::temp_directory_path()
                          : target_.has_parent_path() ? target_.parent_path()
                                                      : fs::path(".");
  std::error_code error;
  if (!fs::is_directory(folder, error)) fail("needs the folder " + folder.string() + ", which does not exist");
  remove_stale_staging(folder);
  std::string name = target_.filename().string();
  if (name.size() > 160) name.resize(160);  // the staging name stays under NAME_MAX
  name = "." + name + staging_marker + std::to_string(::getpid()) + "-" + std::to_string(staging_counter++) +
         target_.extension().string();
  const std::string staging = (folder / name).string();
  const int fd = ::open(staging.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, existed_ ? 0600 : 0666);
  if (fd < 0)
    fail("cannot be written: its folder " + folder.string() + " refuses a new file (" + os_error(errno) + ")");
  if (existed_) {
    // The replaced file's owner (where this user may give it) and bits, not the umask's.
    // (Not root: the new file is this user's, as after any editor's rewrite.)
    [[maybe_unused]] const int given = ::fchown(fd, static_cast<uid_t>(owner_), static_cast<gid_t>(group_));
    ::fchmod(fd, mode_);
  }
  ::close(fd);
  staging_ = staging;
  slot_ = register_staging(staging_);
  prepared_ = true;
}

const std::string& OutputFile::staging() const {
  if (!prepared_) throw std::logic_error("OutputFile::staging before prepare: " + path_);
  return staging_;
}

void OutputFile::write(const std::function<void(std::ostream&)>& body) {
  prepare();
  if (inactive_) return;
  const int fd = ::open(staging_.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  if (fd < 0) fail("cannot be written (" + os_error(errno) + ")");
  int error = write_through(fd, body);
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error) {
    discard();
    fail("could not be written completely (" + os_error(error) + ")");
  }
  check_staged();
}

void OutputFile::check_staged() {
  if (inactive_) return;
  const int fd = ::open(staging().c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) fail("could not be written (" + os_error(errno) + ")");
  struct stat info {};
  const bool sized = ::fstat(fd, &info) == 0;
  const bool synced = ::fsync(fd) == 0;
  const int error = errno;
  ::close(fd);
  if (!synced) {
    discard();
    fail("could not be written completely (" + os_error(error) + ")");
  }
  if (!sized || info.st_size == 0) {
    discard();
    fail("was written empty (no room on the disk?)");
  }
}

void OutputFile::commit() {
  if (committed_ || inactive_) return;
  if (!prepared_) throw std::logic_error("OutputFile::commit before prepare: " + path_);
  if (!special_) {
    if (::rename(staging_.c_str(), target_.c_str()) != 0) fail("cannot be replaced (" + os_error(errno) + ")");
    unregister_staging(slot_);
    staging_.clear();
    committed_ = true;
    const fs::path folder = target_.has_parent_path() ? target_.parent_path() : fs::path(".");
    const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir >= 0) {
      ::fsync(dir);  // the rename itself on disk
      ::close(dir);
    }
    return;
  }
  // A FIFO or device: copied in, every write checked (opening a FIFO waits for its reader).
  const int in = ::open(staging_.c_str(), O_RDONLY | O_CLOEXEC);
  if (in < 0) fail("could not be staged (" + os_error(errno) + ")");
  const int out = ::open(target_.c_str(), O_WRONLY | O_CLOEXEC);
  if (out < 0) {
    const int error = errno;
    ::close(in);
    fail("cannot be opened for writing (" + os_error(error) + ")");
  }
  std::vector<char> buffer(1 << 16);
  int error = 0;
  for (;;) {
    const ssize_t got = ::read(in, buffer.data(), buffer.size());
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) {
      error = errno;
      break;
    }
    if (got == 0) break;
    if (!write_all(out, buffer.data(), static_cast<std::size_t>(got))) {
      error = errno;
      break;
    }
  }
  ::close(in);
  if (::close(out) != 0 && error == 0 && errno != EINTR) error = errno;
  if (error) fail("could not be written completely (" + os_error(error) + ")");
  discard();
  committed_ = true;
}

void OutputFile::discard() noexcept {
  if (staging_.empty()) return;
  ::unlink(staging_.c_str());
  unregister_staging(slot_);
  staging_.clear();
}

void OutputFile::remove_committed() noexcept {
  if (committed_ && !special_) ::unlink(target_.c_str());
  committed_ = false;
}

OutputFile* OutputGroup::add(std::string argument, std::string path) {
  if (path.empty()) return nullptr;
  files_.push_back(std::make_unique<OutputFile>(std::move(argument), std::move(path)));
  return files_.back().get();
}

void OutputGroup::prepare() {
  // Same file: the same inode if it exists, else the same absolute path.
  auto key = [](const OutputFile& f) {
    std::error_code error;
    const fs::path absolute = fs::weakly_canonical(fs::absolute(f.target_), error);
    return error ? fs::absolute(f.target_).lexically_normal() : absolute;
  };
  try {
    for (std::size_t i = 0; i < files_.size(); ++i) {
      files_[i]->prepare();
      if (files_[i]->inactive_) continue;  // another rank's outputs: rank 0 checks them
      for (std::size_t j = 0; j < i; ++j) {
        const OutputFile &a = *files_[j], &b = *files_[i];
        const bool same_inode =
            (a.existed_ || a.special_) && (b.existed_ || b.special_) && a.device_ == b.device_ && a.inode_ == b.inode_;
        if (same_inode || key(a) == key(b))
          throw invalid_argument(
              b.argument_, b.path_,
              "names the same file as --" + a.argument_ + " (" + a.path_ + "): give each output its own file");
      }
    }
  } catch (...) {
    for (auto& file : files_) file->discard();  // nothing staged is left when one output is refused
    throw;
  }
}

void OutputGroup::commit() {
  for (std::size_t i = 0; i < files_.size(); ++i) {
    try {
      files_[i]->commit();
    } catch (...) {
      for (std::size_t j = 0; j < i; ++j) files_[j]->remove_committed();
      throw;
    }
  }
}

void remove_stale_staging(const fs::path& folder) {
  std::error_code error;
  std::vector<fs::path> stale;
  for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    const long pid = staging_pid(it->path().filename().string());
    if (pid == 0 || pid == static_cast<long>(::getpid())) continue;
    if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;  // alive, or not ours to judge
    stale.push_back(it->path());
  }
  for (const auto& path : stale) {  // left by a kill -9
    std::error_code ignored;
    const auto status = fs::symlink_status(path, ignored);
    if (fs::is_regular_file(status)) fs::remove(path, ignored);
    else if (fs::is_directory(status)) fs::remove_all(path, ignored);
  }
}

fs::path make_staging_folder(const fs::path& folder, const std::string& name) {
  remove_stale_staging(folder);
  for (int attempt = 0; attempt < 1000; ++attempt) {
    const fs::path path =
        folder / ("." + name + staging_marker + std::to_string(::getpid()) + "-" + std::to_string(staging_counter++));
    if (::mkdir(path.c_str(), 0777) == 0) return path;
    if (errno != EEXIST)
      throw invalid_argument("directory", folder.string(),
                             "must be a folder this user can write to (" + os_error(errno) + ")");
  }
  throw invalid_argument("directory", folder.string(), "has no room for a staging folder");
}

void install_signal_cleanup() {
  for (const int signal : {SIGINT, SIGTERM}) {
    struct sigaction current {};
    if (::sigaction(signal, nullptr, &current) != 0) continue;
    if (!(current.sa_flags & SA_SIGINFO) && current.sa_handler == SIG_DFL) {
      struct sigaction action {};
      action.sa_handler = remove_staging_and_reraise;
      sigemptyset(&action.sa_mask);
      ::sigaction(signal, &action, nullptr);
    }
  }
}

StopOnInterrupt::StopOnInterrupt() {
  clear_interrupt();
  stop_scopes.fetch_add(1);
}

StopOnInterrupt::~StopOnInterrupt() { stop_scopes.fetch_sub(1); }

void write_stdout(const std::function<void(std::ostream&)>& body) {
  if (!distributed::is_root()) return;  // rank 0 alone prints (the others' stdout is a sink)
  check_stdout();                       // what went before, in order
  const int error = write_through(STDOUT_FILENO, body);
  if (error) throw std::runtime_error("stdout: output was lost (" + os_error(error) + ")");
}

void check_stdout() {
  if (!distributed::is_root()) return;  // rank 0 alone prints (the others' stdout is a sink)
  errno = 0;
  std::cout.flush();
  int error = errno;
  const bool cpp_ok = static_cast<bool>(std::cout);
  errno = 0;
  const bool c_ok = std::fflush(stdout) == 0 && !std::ferror(stdout);
  if (!c_ok) error = errno ? errno : error;
  if (!cpp_ok || !c_ok) throw std::runtime_error("stdout: output was lost (" + os_error(error) + ")");
}

void require_regular_file(const std::string& argument, const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) {
    if (errno == ENOENT) throw invalid_argument(argument, path, "does not exist");
    throw invalid_argument(argument, path, "cannot be read (" + os_error(errno) + ")");
  }
  if (!S_ISREG(info.st_mode))
    throw invalid_argument(argument, path, "must be a regular file (this is " + kind_of(info.st_mode) + ")");
}

void refuse_special_file(const std::string& argument, const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) == 0 && !S_ISREG(info.st_mode))
    throw invalid_argument(argument, path, "must be a regular file (this is " + kind_of(info.st_mode) + ")");
}

std::string read_regular_file(const std::string& argument, const std::string& path, std::uint64_t max_bytes) {
  require_regular_file(argument, path);
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw invalid_argument(argument, path, "cannot be read (" + os_error(errno) + ")");
  std::error_code error;
  const std::uint64_t size = fs::file_size(path, error);
  if (!error && size > max_bytes)
    throw invalid_argument(
        argument, path,
        "is " + std::to_string(size) + " bytes, more than the " + std::to_string(max_bytes) + " allowed");
  std::string text;
  text.resize(static_cast<std::size_t>(error ? 0 : size));
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  return text;
}

}  // namespace stratum::io
