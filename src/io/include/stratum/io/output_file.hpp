#pragma once
/// Output files that are never destroyed or half-written (docs/outputs.md).
///
/// An OutputFile is prepared before a command does its work (every check a
/// write could fail later is made then, and its staging file is created), is
/// written through its staging file, and committed at the end:
/// - a regular file, or a path not there yet: the staging file is hidden in
///   the target's folder (`.NAME.stratum-tmp.PID-K.EXT`), written, checked,
///   synced, given the existing file's permission bits (and owner, where
///   this user may) and renamed over the target; a failure leaves the
///   target as it was and no staging file;
/// - a symbolic link: the file it points to is the target (written through,
///   the link kept);
/// - a regular file with more than one hard link: refused (replacing it would
///   split the links, writing in place could half-write it);
/// - a character device or FIFO: staged in the temporary folder, then copied
///   into it with every write checked; sockets, block devices and folders are
///   refused.
/// Staging files are removed on SIGINT/SIGTERM (install_signal_cleanup) and
/// those of dead processes at the next prepare() in the same folder.
/// In a distributed job (docs/distributed.md) only rank 0 writes: on the
/// other ranks an output is inactive (prepare, write and commit do nothing).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace stratum::io {

class OutputFile {
 public:
  /// `argument` names the option in messages ("output", "exr", ...).
  OutputFile(std::string argument, std::string path);
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  ~OutputFile();  ///< removes an uncommitted staging file

  /// Checks the target and creates the staging file; throws
  /// stratum::invalid_argument naming the argument, the path and the reason.
  void prepare();
  /// Where a writer that needs a path writes (same extension as the target).
  const std::string& staging() const;
  /// Writes the staging file through a stream; a failed write throws with the OS error.
  void write(const std::function<void(std::ostream&)>& body);
  /// Throws unless the staging file was written completely (for writers that
  /// take staging() as a path): fsyncs it and checks it is not empty.
  void check_staged();
  /// Puts the staged file in place (rename, or a checked copy into a special file).
  void commit();
  /// Removes the staging file (nothing committed).
  void discard() noexcept;
  /// Removes a committed regular file again (a later output of the same command failed).
  void remove_committed() noexcept;

  const std::string& argument() const { return argument_; }
  const std::string& path() const { return path_; }
  /// The file written after symbolic links are followed (valid after prepare()).
  const std::filesystem::path& target() const { return target_; }
  bool committed() const { return committed_; }
  /// False on the ranks of a distributed job other than 0: nothing is written.
  bool active() const { return !inactive_; }
  bool special() const { return special_; }

 private:
  [[noreturn]] void fail(const std::string& why) const;
  std::string argument_, path_;
  std::filesystem::path target_;
  std::string staging_;
  bool prepared_ = false, special_ = false, existed_ = false, committed_ = false, inactive_ = false;
  unsigned mode_ = 0, owner_ = 0, group_ = 0;  // of the file replaced (existed_)
  std::uint64_t device_ = 0, inode_ = 0;
  int slot_ = -1;  // in the registry of staging files removed on a signal
  friend class OutputGroup;
};

/// The outputs of one command: prepared together (two that name the same
/// file are refused), committed together (when one fails, those committed
/// before it are removed).
class OutputGroup {
 public:
  /// Adds an output; an empty path adds nothing and returns null.
  OutputFile* add(std::string argument, std::string path);
  void prepare();
  void commit();
  std::size_t size() const { return files_.size(); }

 private:
  std::vector<std::unique_ptr<OutputFile>> files_;
};

/// Removes live staging files on SIGINT and SIGTERM, then lets the signal
/// take its default action (only signals whose action is the default; for
/// programs, not libraries loaded into another's process).
void install_signal_cleanup();

/// While one is alive, in a program that called install_signal_cleanup, the
/// first SIGINT asks the work to stop (stratum::request_interrupt, see
/// stratum/util/interrupt.hpp) instead of ending the process, so that a
/// command can write what it has done (a render its partial image); a second
/// SIGINT removes the staging files and ends the process at once, as without
/// it. Constructing one forgets an earlier request.
class StopOnInterrupt {
 public:
  StopOnInterrupt();
  StopOnInterrupt(const StopOnInterrupt&) = delete;
  StopOnInterrupt& operator=(const StopOnInterrupt&) = delete;
  ~StopOnInterrupt();
};

/// Writes to stdout (after what C and C++ streams hold) through a stream
/// whose every write is checked; throws std::runtime_error with the OS error.
void write_stdout(const std::function<void(std::ostream&)>& body);

/// Flushes stdout (C and C++ streams); throws std::runtime_error with the OS
/// error if anything written to it was lost (a full disk, a closed stdout).
void check_stdout();

/// Throws stratum::invalid_argument unless `path` names a regular file
/// (symbolic links followed): a FIFO or device is refused before it is opened.
void require_regular_file(const std::string& argument, const std::string& path);

/// Throws as require_regular_file when `path` exists and is not a regular
/// file; a missing file is left to the caller's own message.
void refuse_special_file(const std::string& argument, const std::string& path);

/// The whole content of a regular file (require_regular_file), at most
/// `max_bytes` (a larger one is refused naming its size).
std::string read_regular_file(const std::string& argument, const std::string& path,
                              std::uint64_t max_bytes = std::uint64_t{1} << 32);

/// Removes the staging files and folders in `folder` whose process is gone
/// (prepare() calls it for its own folder).
void remove_stale_staging(const std::filesystem::path& folder);

/// Creates a staging folder `FOLDER/.NAME.stratum-tmp.PID-K` (after removing
/// stale ones there): for outputs built as a folder, as the report's page.
std::filesystem::path make_staging_folder(const std::filesystem::path& folder, const std::string& name);

/// The prefix of staging files, for tests and docs: ".NAME" + this + "PID-K".
inline constexpr const char* staging_marker = ".stratum-tmp.";

}  // namespace stratum::io
