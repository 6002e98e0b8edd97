// sphtroch/io/output_file.hpp — the one buffered writer behind every file and stream the library
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
//     replaces (new files 0666 & ~umask), fsynced and renamed onto the target by commit(). Until
//     then the target is untouched; an OutputFile destroyed without commit() removes its
//     temporary, and install_output_signal_cleanup() removes it on SIGINT, SIGTERM, SIGHUP and
//     on a fault's death (SIGABRT, SIGSEGV, ...: detail::kCleanupSignals; any number of live
//     temporaries). finish_writing() closes a staged temporary early (no
//     descriptor, no buffer held until commit: thousands of outputs can wait for one commit,
//     whose single syncfs replaces their fsyncs). Renames are not followed by a directory fsync.
//   - refused (OutputError): a path with a NUL byte, a loop of symbolic links (ELOOP), a directory.
// Errors throw OutputError (field, path, errno); a reader that went away (EPIPE, with SIGPIPE
// ignored) throws BrokenPipe, an OutputError that a command-line filter ends on quietly.
// Several outputs that must appear together: commit_together() (all or none; see there).
// Not thread-safe: one OutputFile per thread.
// Tests: compiled with SPHTROCH_OUTPUT_FAULT_INJECTION, detail::output_fault_hook makes any system
// call or allocation of the writer fail (tests/io/test_io.cpp checks that nothing partial is left).
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <mutex>
#include <new>
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

#ifdef SPHTROCH_OUTPUT_FAULT_INJECTION
/// Test seam, compiled only with SPHTROCH_OUTPUT_FAULT_INJECTION: called before each system call
/// and allocation of OutputFile with its name ("mkostemp", "write", "fsync", "close", "link",
/// "rename", "alloc"); a nonzero return makes that call fail with it as errno ("alloc": as
/// std::bad_alloc).
inline int (*output_fault_hook)(const char* operation) = nullptr;
inline int injected_fault(const char* operation) { return output_fault_hook ? output_fault_hook(operation) : 0; }
#else
constexpr int injected_fault(const char*) { return 0; }
#endif

/// The system calls of OutputFile, each failing as the test seam says (else the call itself).
inline int sys_mkostemp(char* tmpl, int flags) {
  if (const int e = injected_fault("mkostemp")) return errno = e, -1;
  return ::mkostemp(tmpl, flags);
}
inline ssize_t sys_write(int fd, const void* p, std::size_t n) {
  if (const int e = injected_fault("write")) return errno = e, -1;
  return ::write(fd, p, n);
}
inline int sys_fsync(int fd) {
  if (const int e = injected_fault("fsync")) return errno = e, -1;
  return ::fsync(fd);
}
inline int sys_close(int fd) {  // the descriptor is released in every case
  const int e = injected_fault("close");
  const int r = ::close(fd);
  return e ? (errno = e, -1) : r;
}
inline int sys_link(const char* from, const char* to) {
  if (const int e = injected_fault("link")) return errno = e, -1;
  return ::link(from, to);
}
inline int sys_rename(const char* from, const char* to) {
  if (const int e = injected_fault("rename")) return errno = e, -1;
  return ::rename(from, to);
}
/// new T / new char[n], failing as the seam says; throw std::bad_alloc.
template <class T>
T* sys_new() {
  if (injected_fault("alloc")) throw std::bad_alloc();
  return new T();
}
inline char* sys_new_chars(std::size_t n) {
  if (injected_fault("alloc")) throw std::bad_alloc();
  return new char[n];
}

/// Temporary files alive in this process, removable from a signal handler. Unbounded: a list of
/// nodes that only grows (a node is reused once free, never freed), so that the handler walks it
/// without locks or allocation. A node's path is written while it is unused and published by
/// setting `used` last; `next` is set before the node is published and never changes. add() and
/// remove() may be called from any thread (a mutex), never from the handler.
class TempRegistry {
 public:
  struct Node {
    std::atomic<int> used{0};
    std::unique_ptr<char[]> path;
    std::size_t capacity = 0;
    Node* next = nullptr;
  };
  static_assert(std::atomic<int>::is_always_lock_free, "the signal handler reads `used` without a lock");

  static TempRegistry& instance() {
    static TempRegistry* registry = new TempRegistry;  // never destroyed: a handler may run at exit
    return *registry;
  }
  /// Registers `path`; throws std::bad_alloc (then nothing is registered).
  Node* add(const std::string& path) {
    std::lock_guard<std::mutex> lock(mutex_);
    Node* node = nullptr;
    for (Node* n = head_.load(); n && !node; n = n->next)
      if (!n->used.load() && n->capacity > path.size()) node = n;
    if (!node) {
      std::unique_ptr<Node> fresh(sys_new<Node>());
      fresh->path.reset(sys_new_chars(path.size() + 1));
      fresh->capacity = path.size() + 1;
      fresh->next = head_.load();
      node = fresh.release();
      head_.store(node);  // published with used == 0: the handler skips it
    }
    std::memcpy(node->path.get(), path.c_str(), path.size() + 1);
    node->used.store(1);
    return node;
  }
  void remove(Node* node) noexcept {
    if (node) node->used.store(0);
  }
  void unlink_all() noexcept {  // async-signal-safe
    for (Node* n = head_.load(); n; n = n->next)
      if (n->used.load()) ::unlink(n->path.get());
  }

 private:
  std::mutex mutex_;
  std::atomic<Node*> head_{nullptr};
};

/// The signals whose arrival removes every live temporary (install_output_signal_cleanup): the
/// requests to stop (SIGINT, SIGTERM, SIGHUP) and the deaths a fault causes (SIGABRT: abort(), a
/// failed assertion, glibc's "stack smashing detected" or heap check; SIGSEGV, SIGBUS, SIGFPE,
/// SIGILL: a bad access or instruction, unless it is a stack overflow, whose handler has no stack
/// to run on; SIGXFSZ: the file size limit). SIGKILL and a power cut cannot be caught: there a
/// ".sphtroch-XXXXXX" may remain (the target itself is never partial).
constexpr int kCleanupSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGXFSZ};
constexpr std::size_t kCleanupSignalCount = sizeof(kCleanupSignals) / sizeof(kCleanupSignals[0]);

/// The actions the cleanup replaced (one per kCleanupSignals entry), restored before the signal is
/// raised again: the default death, or a handler installed earlier (a sanitizer's report).
struct ReplacedSignalActions {
  struct sigaction action[kCleanupSignalCount];
};
inline ReplacedSignalActions& replaced_signal_actions() {
  static ReplacedSignalActions actions{};
  return actions;
}

/// The handler (async-signal-safe; errno kept): removes the temporaries and puts the replaced
/// action back. A fault the kernel raised (si_code > 0: a bad access, a bad instruction) is left to
/// happen again on return, so that the replaced action sees the real fault and its address; a
/// signal sent by a process or raise() (abort() included) is raised again.
inline void remove_temporaries_and_reraise(int sig, siginfo_t* info, void*) {
  const int saved_errno = errno;
  TempRegistry::instance().unlink_all();
  for (std::size_t i = 0; i < kCleanupSignalCount; ++i)
    if (kCleanupSignals[i] == sig) ::sigaction(sig, &replaced_signal_actions().action[i], nullptr);
  const bool kernel_fault = info && info->si_code > 0 && sig != SIGINT && sig != SIGTERM && sig != SIGHUP &&
                            sig != SIGABRT && sig != SIGXFSZ;
  if (!kernel_fault) ::raise(sig);
  errno = saved_errno;
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

/// Removes every live temporary file of this process on each of detail::kCleanupSignals (stop
/// requests and fault deaths, SIGABRT included), then lets the signal do what it did before (dies
/// of it, or runs the handler that was installed, e.g. a sanitizer's); ignores SIGPIPE so that a
/// closed pipe becomes BrokenPipe. An ignored signal stays ignored (nohup, `cmd &`). For programs
/// (the CLI calls it first); a library user decides about signals. Call it once.
inline void install_output_signal_cleanup() {
  detail::TempRegistry::instance();  // constructed before any handler can run
  struct sigaction sa {};
  sa.sa_sigaction = detail::remove_temporaries_and_reraise;
  sa.sa_flags = SA_SIGINFO;
  sigemptyset(&sa.sa_mask);
  for (std::size_t i = 0; i < detail::kCleanupSignalCount; ++i) {
    const int sig = detail::kCleanupSignals[i];
    struct sigaction& old = detail::replaced_signal_actions().action[i];
    ::sigaction(sig, nullptr, &old);
    if (old.sa_handler != SIG_IGN) ::sigaction(sig, &sa, nullptr);
  }
  ::signal(SIGPIPE, SIG_IGN);
}

class OutputFile {
 public:
  /// Bytes buffered before a write(2); large blocks bypass the buffer. The buffer lives from
  /// open() to finish_writing()/commit(): a finished staged file holds no buffer and no descriptor.
  static constexpr std::size_t kBufferBytes = std::size_t(1) << 20;

  /// Opens `path` ("" or "-": stdout) as described at the top. `field` names the option in errors.
  /// A path with a NUL byte is refused (OutputError), never cut at the NUL.
  static OutputFile open(const std::string& path, const std::string& field) {
    OutputFile f;
    f.field_ = field;
    f.path_ = path.empty() ? "-" : path;
    if (const auto nul = f.path_.find('\0'); nul != std::string::npos) {
      f.path_.replace(nul, 1, "\\0");  // shown, not cut
      f.fail("contains a NUL byte", 0, "a path without NUL bytes");
    }
    if (f.path_ == "-") {
      f.field_ = "stdout";  // errors name what failed, also when no option named it ("stdout = -: ...")
      f.fd_ = STDOUT_FILENO;
      f.kind_ = Kind::stream;
    } else {
      f.open_path();
    }
    f.allocate_buffer();
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
      kind_ = std::exchange(o.kind_, Kind::closed);
      needs_sync_ = o.needs_sync_;
      fd_ = std::exchange(o.fd_, -1);
      slot_ = std::exchange(o.slot_, nullptr);
      buffer_ = std::move(o.buffer_);
      used_ = std::exchange(o.used_, 0);
    }
    return *this;
  }
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  ~OutputFile() { discard(); }

  const std::string& path() const noexcept { return path_; }
  const std::string& field() const noexcept { return field_; }
  bool is_stdout() const noexcept { return path_ == "-"; }
  /// True for a file written to a temporary and renamed onto its target by commit().
  bool is_staged() const noexcept { return kind_ == Kind::staged; }

  /// Room for n <= kBufferBytes bytes at the returned pointer; advance(end) keeps them.
  char* reserve(std::size_t n) {
    if (!buffer_) fail("written after it was finished", 0, "write before finish_writing() or commit()");
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

  /// Ends the writing: flushes; a staged file is closed (it keeps its temporary name until
  /// commit()) after an fsync, or with `sync_now` false marked for one sync of its file system
  /// by commit_together() (thousands of outputs: one syncfs instead of thousands of fsyncs); a
  /// device or FIFO is closed; frees the buffer. No write may follow. Idempotent. Throws
  /// OutputError (the temporary is then removed by discard() or the destructor).
  void finish_writing(bool sync_now = true) {
    if (kind_ == Kind::closed) fail("already closed", 0, "one commit per output");
    if (!buffer_) return;  // already finished
    flush();
    buffer_.reset();
    if (kind_ == Kind::stream) return;  // stdout or stderr: never closed here
    if (kind_ == Kind::staged && sync_now && detail::sys_fsync(fd_) != 0)
      fail("could not be written to disk (fsync)", errno, "a writable target with free space");
    needs_sync_ = kind_ == Kind::staged && !sync_now;
    const int fd = std::exchange(fd_, -1);
    if (detail::sys_close(fd) != 0 && errno != EINTR) fail("write failed", errno, "a writable target with free space");
  }

  /// Finishes and, for a staged file, renames it onto its target. Throws OutputError.
  void commit() {
    finish_writing();
    if (kind_ == Kind::staged) {
      if (detail::sys_rename(tmp_.c_str(), target_.c_str()) != 0)
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
    buffer_.reset();
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

  /// The write buffer; OutputError (ENOMEM) when it cannot be allocated (the destructor then
  /// removes the temporary).
  void allocate_buffer() {
    try {
      buffer_.reset(detail::sys_new_chars(kBufferBytes));
    } catch (const std::bad_alloc&) {
      fail("no memory for the write buffer", ENOMEM, "more free memory");
    }
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
  /// that does not exist yet; canonical (realpath) when the target exists. Empty for a loop (still
  /// a link after 40 hops: a shell's > fails with ELOOP there).
  static std::string follow_links(std::string path) {
    for (int hop = 0;; ++hop) {
      struct stat st {};
      if (::lstat(path.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) break;
      if (hop == 40) return {};
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
    open_staged();
  }

  /// A regular file, possibly through symlinks: replace the file itself. A symlink whose target
  /// does not exist yet gets that target created (as a shell's > does), the link kept.
  void open_staged() {
    target_ = follow_links(path_);
    if (target_.empty()) fail("is a loop of symbolic links", ELOOP, "a file path, or a symlink that reaches one");
    std::string tmpl = detail::split_path(target_).first + "/.sphtroch-XXXXXX";
    fd_ = detail::sys_mkostemp(tmpl.data(), O_CLOEXEC);
    if (fd_ < 0) fail("cannot be written", errno, "a path in an existing, writable directory");
    tmp_ = tmpl;
    kind_ = Kind::staged;  // from here discard() removes the temporary
    try {
      slot_ = detail::TempRegistry::instance().add(tmp_);
    } catch (const std::bad_alloc&) {
      discard();
      fail("no memory to register the temporary file", ENOMEM, "more free memory");
    }
    struct stat old {};
    if (::stat(target_.c_str(), &old) == 0 && S_ISREG(old.st_mode)) {
      ::fchmod(fd_, old.st_mode & 07777);
      if (::fchown(fd_, old.st_uid, old.st_gid) != 0) { /* keep our own owner */ }
    } else {
      ::fchmod(fd_, detail::new_file_mode());
    }
  }

  void write_all(const char* p, std::size_t n) {
    if (fd_ < 0) fail("written after it was finished", 0, "write before finish_writing() or commit()");
    while (n > 0) {
      const ssize_t k = detail::sys_write(fd_, p, n);
      if (k < 0) {
        if (errno == EINTR) continue;
        fail("write failed", errno, "a writable target with free space");
      }
      p += k;
      n -= static_cast<std::size_t>(k);
    }
  }

  /// Syncs the file system of the staged temporary (Linux: syncfs; elsewhere sync), once per
  /// directory in `synced`. Throws OutputError.
  void sync_file_system(std::vector<std::string>& synced) const {
    const std::string dir = detail::split_path(tmp_).first;
    if (std::find(synced.begin(), synced.end(), dir) != synced.end()) return;
    const int fd = ::open(dir.c_str(), O_RDONLY | O_CLOEXEC | O_DIRECTORY);
    int err = fd < 0 ? errno : 0;
    if (fd >= 0) {
      if (const int e = detail::injected_fault("fsync")) err = e;
#ifdef __linux__
      else if (::syncfs(fd) != 0) err = errno;
#else
      else ::sync();
#endif
      ::close(fd);
    }
    if (err) fail("could not be written to disk (syncfs)", err, "a writable target with free space");
    synced.push_back(dir);
  }

  void unregister() noexcept {
    detail::TempRegistry::instance().remove(slot_);
    slot_ = nullptr;
  }

  std::string field_, path_, target_, tmp_;
  Kind kind_ = Kind::closed;
  int fd_ = -1;
  bool needs_sync_ = false;  // finished without fsync: commit_together syncs its file system
  detail::TempRegistry::Node* slot_ = nullptr;
  std::unique_ptr<char[]> buffer_;
  std::size_t used_ = 0;
};

/// Commits several outputs so that they appear together or not at all: every output is finished
/// and its contents synced to disk first (a write or sync error leaves every target untouched); then the staged files are
/// renamed one by one, each existing target kept under a hard-linked backup name until all are in
/// place. If a backup or a rename fails, the targets already replaced get their previous file back
/// (or are removed if they did not exist) and OutputError is thrown. Outputs written directly
/// (stdout, devices, FIFOs) cannot be taken back: they are written as the bytes come.
inline void commit_together(std::vector<OutputFile*> outputs) {
  std::vector<std::string> synced;
  for (OutputFile* o : outputs) {
    o->finish_writing();  // no-op for those already finished
    if (o->needs_sync_) o->sync_file_system(synced);
  }
  struct Done {
    OutputFile* output;
    std::string backup;  // empty: the target did not exist
    detail::TempRegistry::Node* slot;
  };
  std::vector<Done> done;
  auto forget_backups = [&done] {
    for (Done& d : done) {
      if (!d.backup.empty()) ::unlink(d.backup.c_str());
      detail::TempRegistry::instance().remove(d.slot);
    }
  };
  auto roll_back = [&](OutputFile* o, const std::string& problem, int err) {
    for (auto d = done.rbegin(); d != done.rend(); ++d) {
      if (!d->backup.empty()) ::rename(d->backup.c_str(), d->output->target_.c_str());
      else ::unlink(d->output->target_.c_str());
      d->backup.clear();
    }
    forget_backups();
    o->fail(problem + " (no output of this run was kept)", err, "a writable file path");
  };
  done.reserve(outputs.size());
  for (OutputFile* o : outputs) {
    if (o->kind_ != OutputFile::Kind::staged) continue;
    Done d{o, {}, nullptr};
    struct stat st {};
    if (::lstat(o->target_.c_str(), &st) == 0) {
      d.backup = o->tmp_ + "b";
      try {
        d.slot = detail::TempRegistry::instance().add(d.backup);
      } catch (const std::bad_alloc&) {
        roll_back(o, "no memory to keep a backup of the previous file", ENOMEM);
      }
      if (detail::sys_link(o->target_.c_str(), d.backup.c_str()) != 0) {
        const int err = errno;
        detail::TempRegistry::instance().remove(d.slot);
        roll_back(o, "cannot keep a backup of the previous file", err);
      }
    }
    if (detail::sys_rename(o->tmp_.c_str(), o->target_.c_str()) != 0) {
      const int err = errno;
      if (!d.backup.empty()) ::unlink(d.backup.c_str());
      detail::TempRegistry::instance().remove(d.slot);
      roll_back(o, "cannot be replaced", err);
    }
    o->unregister();
    o->kind_ = OutputFile::Kind::closed;
    done.push_back(d);
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
