// sphtroch/output_file.hpp — the one buffered writer behind every file and stream the library
// and the tool write (POSIX).
//
//   sphtroch::OutputFile out = sphtroch::OutputFile::open("t.csv", "--output");  // or "-": stdout
//   out.write("t,x,y,z\n");
//   char* p = out.reserve(64); p = sphtroch::write_number(p, 0.5); out.advance(p);
//   out.commit();   // flush; a new or regular file appears complete (rename), or throws
//
// Targets, decided when opened:
//   - "" or "-": standard output, written as the bytes come (validate before the first byte).
//   - an existing path that is not a regular file (character device, FIFO, socket), or the file
//     standard output already writes to (/dev/stdout): written directly, never renamed over.
//   - anything else (a new file, a regular file, a symlink to one): a temporary file with a short
//     name (".sphtroch-XXXXXX") in the target's directory, given the mode of the file it
//     replaces (new files 0666 & ~umask), renamed onto the target by commit(). Until then the
//     target is untouched; an OutputFile destroyed without commit() removes its temporary, and
//     install_output_signal_cleanup() removes it on SIGINT, SIGTERM, SIGHUP too.
// Errors throw OutputError (field, path, errno); a reader that went away (EPIPE, with SIGPIPE
// ignored) throws BrokenPipe, an OutputError that a command-line filter ends on quietly.
// Several outputs that must appear together: commit_together() (all or none; see there).
// Not thread-safe: one OutputFile per thread.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <streambuf>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sphtroch {

/// Writing to a FIFO waits this long for a reader to open it (milliseconds), polling every kFifoPollMs.
constexpr int kFifoReaderWaitMs = 10000;
constexpr int kFifoPollMs = 10;

/// A file or stream could not be written. what() reads "<field> = <path>: <problem> (<strerror>);
/// valid: <what would work>" — one line.
class OutputError : public std::runtime_error {
 public:
  OutputError(const std::string& field, const std::string& path, const std::string& problem, int error_number,
              const std::string& valid)
      : std::runtime_error(field + " = " + path + ": " + problem +
                           (error_number ? std::string(" (") + std::strerror(error_number) + ")" : std::string()) +
                           "; valid: " + valid),
        field_(field),
        path_(path),
        error_number_(error_number) {}
  const std::string& field() const noexcept { return field_; }
  const std::string& path() const noexcept { return path_; }
  int error_number() const noexcept { return error_number_; }

 private:
  std::string field_, path_;
  int error_number_;
};

/// The reader of a pipe went away (EPIPE). Filters end quietly on it.
class BrokenPipe : public OutputError {
 public:
  using OutputError::OutputError;
};

namespace detail {

/// Temporary files alive in this process, removable from a signal handler (fixed storage, no
/// allocation; a slot is published by setting `used` last).
struct TempRegistry {
  static constexpr int kSlots = 64;
  struct Slot {
    volatile sig_atomic_t used = 0;
    char path[PATH_MAX] = {};
  };
  Slot slots[kSlots];

  static TempRegistry& instance() {
    static TempRegistry registry;
    return registry;
  }
  int add(const std::string& path) {
    if (path.size() >= PATH_MAX) return -1;
    for (int i = 0; i < kSlots; ++i)
      if (!slots[i].used) {
        std::memcpy(slots[i].path, path.c_str(), path.size() + 1);
        slots[i].used = 1;
        return i;
      }
    return -1;  // full: the file is still removed by its owner, just not on a signal
  }
  void remove(int slot) {
    if (slot >= 0) slots[slot].used = 0;
  }
  void unlink_all() noexcept {  // async-signal-safe
    for (Slot& s : slots)
      if (s.used) ::unlink(s.path);
  }
};

inline void remove_temporaries_and_reraise(int sig) {
  TempRegistry::instance().unlink_all();
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

/// The directory part of a path ("." for a bare name) and its file name.
inline std::pair<std::string, std::string> split_path(const std::string& path) {
  const auto slash = path.rfind('/');
  if (slash == std::string::npos) return {".", path};
  return {slash == 0 ? "/" : path.substr(0, slash), path.substr(slash + 1)};
}

inline mode_t new_file_mode() {
  static const mode_t mode = [] {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    return static_cast<mode_t>(0666 & ~mask);
  }();
  return mode;
}

}  // namespace detail

/// Removes every live temporary file of this process on SIGINT, SIGTERM and SIGHUP, then dies of
/// the signal as before; ignores SIGPIPE so that a closed pipe becomes BrokenPipe. For programs
/// (the CLI calls it first); a library user decides about signals.
inline void install_output_signal_cleanup() {
  detail::TempRegistry::instance();  // constructed before any handler can run
  struct sigaction sa {};
  sa.sa_handler = detail::remove_temporaries_and_reraise;
  sigemptyset(&sa.sa_mask);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction old {};
    ::sigaction(sig, nullptr, &old);
    if (old.sa_handler != SIG_IGN) ::sigaction(sig, &sa, nullptr);  // keep nohup's and `cmd &`'s ignores
  }
  ::signal(SIGPIPE, SIG_IGN);
}

class OutputFile {
 public:
  /// Bytes buffered before a write(2); large blocks bypass the buffer.
  static constexpr std::size_t kBufferBytes = std::size_t(1) << 20;

  /// Opens `path` ("" or "-": stdout) as described at the top. `field` names the option in errors.
  static OutputFile open(const std::string& path, const std::string& field) {
    OutputFile f;
    f.field_ = field;
    f.path_ = path.empty() ? "-" : path;
    if (f.path_ == "-") {
      f.field_ = "stdout";  // errors name what failed, also when no option named it ("stdout = -: ...")
      f.fd_ = STDOUT_FILENO;
      f.kind_ = Kind::stream;
    } else {
      f.open_path();
    }
    f.buffer_.reset(new char[kBufferBytes]);
    return f;
  }

  OutputFile() = default;
  OutputFile(OutputFile&& o) noexcept { *this = std::move(o); }
  OutputFile& operator=(OutputFile&& o) noexcept {
    if (this != &o) {
      discard();
      field_ = std::move(o.field_);
      path_ = std::move(o.path_);
      target_ = std::move(o.target_);
      tmp_ = std::move(o.tmp_);
      kind_ = o.kind_;
      fd_ = std::exchange(o.fd_, -1);
      slot_ = std::exchange(o.slot_, -1);
      buffer_ = std::move(o.buffer_);
      used_ = std::exchange(o.used_, 0);
      o.kind_ = Kind::closed;
    }
    return *this;
  }
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  ~OutputFile() { discard(); }

  const std::string& path() const noexcept { return path_; }
  const std::string& field() const noexcept { return field_; }
  bool is_stdout() const noexcept { return path_ == "-"; }

  /// Room for n <= kBufferBytes bytes at the returned pointer; advance(end) keeps them.
  char* reserve(std::size_t n) {
    if (used_ + n > kBufferBytes) flush();
    return buffer_.get() + used_;
  }
  void advance(const char* end) { used_ = static_cast<std::size_t>(end - buffer_.get()); }

  void write(std::string_view s) {
    if (s.size() >= kBufferBytes / 2) {
      flush();
      write_all(s.data(), s.size());
      return;
    }
    char* p = reserve(s.size());
    std::memcpy(p, s.data(), s.size());
    used_ += s.size();
  }

  /// Hands the buffered bytes to the kernel.
  void flush() {
    if (used_ == 0) return;
    const std::size_t n = std::exchange(used_, 0);
    write_all(buffer_.get(), n);
  }

  /// Flushes and closes; a staged file is renamed onto its target. Throws OutputError.
  void commit() {
    finish();
    if (kind_ == Kind::staged) {
      if (::rename(tmp_.c_str(), target_.c_str()) != 0)
        fail("cannot be replaced", errno, "a writable file path");
      unregister();
    }
    kind_ = Kind::closed;
  }

  /// Removes a staged temporary (no-op after commit()). Never throws.
  void discard() noexcept {
    if (kind_ == Kind::closed) return;
    if (fd_ >= 0 && kind_ != Kind::stream) ::close(fd_);
    fd_ = -1;
    if (kind_ == Kind::staged) {
      ::unlink(tmp_.c_str());
      unregister();
    }
    kind_ = Kind::closed;
  }

 private:
  enum class Kind { closed, stream, direct, staged };
  friend void commit_together(std::vector<OutputFile*> outputs);

  [[noreturn]] void fail(const std::string& problem, int error_number, const std::string& valid) const {
    if (error_number == EPIPE) throw BrokenPipe(field_, path_, "the reader closed the pipe", EPIPE, valid);
    throw OutputError(field_, path_, problem, error_number, valid);
  }

  /// True when `st` is the file this process's standard output or error already writes to
  /// (`-o /dev/stdout` with stdout redirected to a file): it must be written, not replaced.
  /// Returns that descriptor, or -1.
  static int standard_stream_of(const struct stat& st) {
    for (int fd : {STDOUT_FILENO, STDERR_FILENO}) {
      struct stat s {};
      if (::fstat(fd, &s) == 0 && s.st_dev == st.st_dev && s.st_ino == st.st_ino) return fd;
    }
    return -1;
  }

  /// `path` with the symbolic links of its last component followed (at most 40), also to a target
  /// that does not exist yet; canonical (realpath) when the target exists.
  static std::string follow_links(std::string path) {
    for (int hop = 0; hop < 40; ++hop) {
      struct stat st {};
      if (::lstat(path.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) break;
      std::string link(PATH_MAX, '\0');
      const ssize_t n = ::readlink(path.c_str(), link.data(), link.size());
      if (n <= 0) break;
      link.resize(static_cast<std::size_t>(n));
      path = link[0] == '/' ? link : detail::split_path(path).first + "/" + link;
    }
    char resolved[PATH_MAX];
    return ::realpath(path.c_str(), resolved) != nullptr ? std::string(resolved) : path;
  }

  /// A FIFO opens for writing only once a reader has it open; wait for one at most
  /// kFifoReaderWaitMs instead of blocking forever (then fail naming the path).
  int open_fifo_with_reader() {
    for (int waited = 0;; waited += kFifoPollMs) {
      const int fd = ::open(path_.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK);
      if (fd >= 0) {
        const int flags = ::fcntl(fd, F_GETFL);
        if (flags >= 0) (void)::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);  // blocking writes from here
        return fd;
      }
      if (errno != ENXIO) return -1;  // ENXIO: no reader yet
      if (waited >= kFifoReaderWaitMs)
        fail("is a FIFO that no reader opened within " + std::to_string(kFifoReaderWaitMs / 1000) + " s", 0,
             "a FIFO with a reader, a file or a device");
      ::usleep(kFifoPollMs * 1000);
    }
  }

  void open_path() {
    struct stat st {};
    const bool exists = ::stat(path_.c_str(), &st) == 0;
    if (exists && S_ISREG(st.st_mode) && standard_stream_of(st) >= 0) {  // its offset and append mode stay
      fd_ = standard_stream_of(st);
      kind_ = Kind::stream;
      return;
    }
    if (exists && !S_ISREG(st.st_mode)) {
      if (S_ISDIR(st.st_mode)) fail("is a directory", 0, "a file path");
      fd_ = S_ISFIFO(st.st_mode) ? open_fifo_with_reader() : ::open(path_.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
      if (fd_ < 0) fail("cannot be opened for writing", errno, "a writable file, device or FIFO");
      kind_ = Kind::direct;
      return;
    }
    // A regular file, possibly through symlinks: replace the file itself. A symlink whose target
    // does not exist yet gets that target created (as a shell's > does), the link kept.
    target_ = follow_links(path_);
    const std::string dir = detail::split_path(target_).first;
    std::string tmpl = dir + "/.sphtroch-XXXXXX";
    fd_ = ::mkostemp(tmpl.data(), O_CLOEXEC);
    if (fd_ < 0) fail("cannot be written", errno, "a path in an existing, writable directory");
    tmp_ = tmpl;
    kind_ = Kind::staged;
    slot_ = detail::TempRegistry::instance().add(tmp_);
    struct stat old {};
    if (::stat(target_.c_str(), &old) == 0 && S_ISREG(old.st_mode)) {
      ::fchmod(fd_, old.st_mode & 07777);
      if (::fchown(fd_, old.st_uid, old.st_gid) != 0) { /* keep our own owner */ }
    } else {
      ::fchmod(fd_, detail::new_file_mode());
    }
  }

  void write_all(const char* p, std::size_t n) {
    while (n > 0) {
      const ssize_t k = ::write(fd_, p, n);
      if (k < 0) {
        if (errno == EINTR) continue;
        fail("write failed", errno, "a writable target with free space");
      }
      p += k;
      n -= static_cast<std::size_t>(k);
    }
  }

  void finish() {
    if (kind_ == Kind::closed) fail("already closed", 0, "one commit per output");
    flush();
    if (kind_ == Kind::stream) return;  // stdout or stderr: never closed here
    const int fd = std::exchange(fd_, -1);
    if (::close(fd) != 0 && errno != EINTR) fail("write failed", errno, "a writable target with free space");
  }

  void unregister() noexcept {
    detail::TempRegistry::instance().remove(slot_);
    slot_ = -1;
  }

  std::string field_, path_, target_, tmp_;
  Kind kind_ = Kind::closed;
  int fd_ = -1;
  int slot_ = -1;
  std::unique_ptr<char[]> buffer_;
  std::size_t used_ = 0;
};

/// Commits several outputs so that they appear together or not at all: every output is flushed
/// and closed first (a write error leaves every target untouched); then the staged files are
/// renamed one by one, each existing target kept under a hard-linked backup name until all are in
/// place. If a rename fails, the targets already replaced get their previous file back (or are
/// removed if they did not exist) and OutputError is thrown. Outputs written directly (stdout,
/// devices, FIFOs) cannot be taken back: they are written as the bytes come.
inline void commit_together(std::vector<OutputFile*> outputs) {
  for (OutputFile* o : outputs) o->finish();
  struct Done {
    OutputFile* output;
    std::string backup;
    int slot;
  };
  std::vector<Done> done;
  auto forget_backups = [&done] {
    for (Done& d : done) {
      if (!d.backup.empty()) ::unlink(d.backup.c_str());
      detail::TempRegistry::instance().remove(d.slot);
    }
  };
  for (OutputFile* o : outputs) {
    if (o->kind_ != OutputFile::Kind::staged) continue;
    std::string backup;
    int slot = -1;
    struct stat st {};
    if (::lstat(o->target_.c_str(), &st) == 0) {
      backup = o->tmp_ + "b";
      if (::link(o->target_.c_str(), backup.c_str()) != 0) backup.clear();  // cannot restore; go on
      else slot = detail::TempRegistry::instance().add(backup);
    }
    if (::rename(o->tmp_.c_str(), o->target_.c_str()) != 0) {
      const int err = errno;
      for (auto d = done.rbegin(); d != done.rend(); ++d) {
        if (!d->backup.empty()) ::rename(d->backup.c_str(), d->output->target_.c_str());
        else ::unlink(d->output->target_.c_str());
        d->backup.clear();
      }
      if (!backup.empty()) ::unlink(backup.c_str());
      detail::TempRegistry::instance().remove(slot);
      forget_backups();
      o->fail("cannot be replaced (no output of this run was kept)", err, "a writable file path");
    }
    o->unregister();
    o->kind_ = OutputFile::Kind::closed;
    done.push_back({o, backup, slot});
  }
  forget_backups();
  for (OutputFile* o : outputs) o->kind_ = OutputFile::Kind::closed;
}

/// A std::streambuf over an OutputFile, for writers that print with operator<<. Errors of the
/// file propagate as its exceptions when the stream has exceptions(std::ios::badbit) set (as
/// OutputStream does: libstdc++ rethrows the streambuf's own exception then).
class OutputStreambuf : public std::streambuf {
 public:
  explicit OutputStreambuf(OutputFile& file) : file_(file) {}

 protected:
  int_type overflow(int_type ch) override {
    if (traits_type::eq_int_type(ch, traits_type::eof())) return traits_type::not_eof(ch);
    const char c = traits_type::to_char_type(ch);
    file_.write(std::string_view(&c, 1));
    return ch;
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    file_.write(std::string_view(s, static_cast<std::size_t>(n)));
    return n;
  }

 private:
  OutputFile& file_;
};

/// std::ostream onto an OutputFile; write errors throw the file's OutputError / BrokenPipe.
///   sphtroch::OutputStream os(file); os << "text"; file.commit();
class OutputStream : public std::ostream {
 public:
  explicit OutputStream(OutputFile& file) : std::ostream(nullptr), buf_(file) {
    rdbuf(&buf_);
    exceptions(std::ios::badbit);
  }

 private:
  OutputStreambuf buf_;
};

}  // namespace sphtroch
