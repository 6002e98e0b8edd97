// sphtroch/io/input_file.hpp — reading a file or standard input in large blocks (POSIX).
//
//   std::ofstream("x.csv") << "1,0,0\n0,1,0\n";
//   sphtroch::InputFile in = sphtroch::InputFile::open("x.csv", "input");   // "-": standard input
//   std::size_t got = in.read(buffer, size);   // < size only at the end of the input
//   sphtroch::InputLines lines(in, 4096);       // or InputLines(text, 4096) over bytes in memory
//   for (std::string_view line; lines.next(line);) { }   // each line without its '\n'
//
// Errors throw InvalidInput(field, path, problem, "a readable file, or - for standard input"):
// a path that does not exist, cannot be opened, is a directory, has a NUL byte, or fails while
// being read, and a FIFO that no writer opens within kFifoWriterWaitMs (a named pipe with no
// writer would otherwise block forever). Once a writer has opened the FIFO, reading blocks like
// cat until the end of the input, however long the writer stays silent.
#pragma once

#include "sphtroch/core/errors.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sphtroch {

/// How long open() waits for a writer to open a FIFO given as input, in milliseconds.
constexpr int kFifoWriterWaitMs = 10000;
/// How often it looks for the writer meanwhile, in milliseconds.
constexpr int kFifoWriterPollMs = 10;

class InputFile {
 public:
  static InputFile open(const std::string& path, const std::string& field) {
    InputFile f;
    f.path_ = path;
    f.field_ = field;
    if (const auto nul = path.find('\0'); nul != std::string::npos) {
      f.path_.replace(nul, 1, "\\0");  // shown, not cut
      f.fail("contains a NUL byte", 0);
    }
    if (path == "-") {
      f.fd_ = STDIN_FILENO;
    } else {
      // O_NONBLOCK: opening a FIFO must not wait for its writer here (see wait_for_writer).
      f.fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK);
      if (f.fd_ < 0) f.fail("cannot be read", errno);
      f.owned_ = true;
      struct stat st {};
      if (::fstat(f.fd_, &st) == 0 && S_ISFIFO(st.st_mode)) f.wait_for_writer();
      ::fcntl(f.fd_, F_SETFL, ::fcntl(f.fd_, F_GETFL) & ~O_NONBLOCK);
    }
    struct stat st {};
    if (::fstat(f.fd_, &st) == 0) {
      if (S_ISDIR(st.st_mode)) f.fail("is a directory", 0);
      if (S_ISREG(st.st_mode)) f.size_ = static_cast<std::uint64_t>(st.st_size);
#ifdef F_SETPIPE_SZ
      if (S_ISFIFO(st.st_mode)) (void)::fcntl(f.fd_, F_SETPIPE_SZ, 1 << 20);  // fewer, larger reads; a hint
#endif
    }
    return f;
  }

  InputFile() = default;
  InputFile(InputFile&& o) noexcept
      : path_(std::move(o.path_)), field_(std::move(o.field_)), fd_(std::exchange(o.fd_, -1)),
        owned_(std::exchange(o.owned_, false)), size_(o.size_), pending_(o.pending_) {}
  InputFile& operator=(InputFile&&) = delete;
  InputFile(const InputFile&) = delete;
  ~InputFile() {
    if (owned_) ::close(fd_);
  }

  const std::string& path() const noexcept { return path_; }
  const std::string& field() const noexcept { return field_; }
  /// The size of a regular file when opened; nullopt for pipes, FIFOs and devices.
  std::optional<std::uint64_t> size() const noexcept { return size_; }

  /// Reads up to n bytes; fewer only at the end of the input.
  std::size_t read(char* out, std::size_t n) {
    std::size_t got = 0;
    if (pending_ && n > 0) {  // the byte wait_for_writer() read
      out[got++] = *pending_;
      pending_.reset();
    }
    while (got < n) {
      const ssize_t k = ::read(fd_, out + got, n - got);
      if (k < 0) {
        if (errno == EINTR) continue;
        fail("cannot be read", errno);
      }
      if (k == 0) break;
      got += static_cast<std::size_t>(k);
    }
    return got;
  }

 private:
  /// Returns once a writer has opened the FIFO (fd_ is O_NONBLOCK): it sent data or closed
  /// (poll), or it is open and silent (a 1-byte read gives EAGAIN, not the 0 of "no writer";
  /// a byte read there is kept in pending_). Throws after kFifoWriterWaitMs without a writer.
  void wait_for_writer() {
    for (int waited = 0;; waited += kFifoWriterPollMs) {
      struct pollfd p {fd_, POLLIN, 0};
      if (::poll(&p, 1, 0) > 0) return;
      char c;
      const ssize_t k = ::read(fd_, &c, 1);
      if (k == 1) pending_ = c;
      if (k == 1 || (k < 0 && errno == EAGAIN)) return;
      if (waited >= kFifoWriterWaitMs)
        throw InvalidInput(field_, path_,
                           "a FIFO that no writer opened within " + std::to_string(kFifoWriterWaitMs / 1000) + " s",
                           "a readable file, or a FIFO or pipe with a writer");
      ::usleep(kFifoWriterPollMs * 1000);
    }
  }

  [[noreturn]] void fail(const std::string& problem, int error_number) const {
    throw InvalidInput(field_, path_, problem + (error_number ? std::string(" (") + std::strerror(error_number) + ")" : ""),
                       "a readable file, or - for standard input");
  }

  std::string path_, field_;
  int fd_ = -1;
  bool owned_ = false;
  std::optional<std::uint64_t> size_;
  std::optional<char> pending_;
};

/// The whole of a file or standard input as bytes; InvalidInput when it holds more than max_bytes.
inline std::string read_whole_input(const std::string& path, const std::string& field,
                                    std::size_t max_bytes = static_cast<std::size_t>(-1)) {
  InputFile in = InputFile::open(path, field);
  std::string text;
  std::size_t got = 0;
  do {
    const std::size_t chunk = std::size_t(1) << 20;
    text.resize(got + chunk);
    const std::size_t k = in.read(text.data() + got, chunk);
    got += k;
    text.resize(got);
    if (got > max_bytes)
      throw InvalidInput(field, path, "larger than " + std::to_string(max_bytes) + " bytes",
                         "a file of at most " + std::to_string(max_bytes) + " bytes");
    if (k < chunk) break;
  } while (true);
  return text;
}


/// A line over InputLines' bound: InvalidInput of its own type, so that a reader can tell a file
/// whose content is not what it expects from one it cannot read at all.
class LineTooLong : public InvalidInput {
 public:
  using InvalidInput::InvalidInput;
};

/// The lines of an InputFile (read in 64 KiB blocks) or of bytes in memory, one at a time, in
/// memory bounded by the block and the longest line. A line longer than max_line bytes throws
/// LineTooLong(field, path, "line N is longer than max_line bytes").
class InputLines {
 public:
  InputLines(InputFile& in, std::size_t max_line)
      : source_([&in](char* out, std::size_t n) { return in.read(out, n); }), path_(in.path()), field_(in.field()),
        max_line_(max_line) {}
  InputLines(std::string_view text, std::string path, std::string field, std::size_t max_line)
      : path_(std::move(path)), field_(std::move(field)), max_line_(max_line) {
    source_ = [text](char* out, std::size_t n) mutable {
      const std::size_t k = std::min(n, text.size());
      if (k > 0) std::memcpy(out, text.data(), k);
      text.remove_prefix(k);
      return k;
    };
  }

  /// The next line without its '\n' (valid until the next call); false at the end of the input.
  bool next(std::string_view& line) {
    for (;;) {
      const char* nl =  // memchr of 0 bytes at a null data() would be undefined
          end_ > begin_ ? static_cast<const char*>(std::memchr(buf_.data() + begin_, '\n', end_ - begin_)) : nullptr;
      if (nl) {
        line = std::string_view(buf_.data() + begin_, static_cast<std::size_t>(nl - (buf_.data() + begin_)));
        begin_ += line.size() + 1;
        return count(line, true);
      }
      if (end_ - begin_ > max_line_) too_long();
      if (at_end_) {
        if (begin_ == end_) return false;
        line = std::string_view(buf_.data() + begin_, end_ - begin_);
        begin_ = end_;
        return count(line, false);
      }
      refill();
    }
  }
  /// Lines returned so far; whether the last of them ended with '\n'.
  std::size_t line_number() const noexcept { return lines_; }
  bool last_ended_with_newline() const noexcept { return newline_; }

 private:
  static constexpr std::size_t kBlock = std::size_t(1) << 16;

  bool count(std::string_view line, bool newline) {
    if (line.size() > max_line_) too_long();
    ++lines_;
    newline_ = newline;
    return true;
  }
  void refill() {
    buf_.erase(buf_.begin(), buf_.begin() + static_cast<std::ptrdiff_t>(begin_));
    end_ -= begin_;
    begin_ = 0;
    buf_.resize(end_ + kBlock);
    const std::size_t got = source_(buf_.data() + end_, kBlock);
    end_ += got;
    buf_.resize(end_);
    if (got < kBlock) at_end_ = true;
  }
  [[noreturn]] void too_long() const {
    throw LineTooLong(field_, path_,
                       "line " + std::to_string(lines_ + 1) + " is longer than " + std::to_string(max_line_) + " bytes",
                       "lines of at most " + std::to_string(max_line_) + " bytes");
  }

  std::function<std::size_t(char*, std::size_t)> source_;
  std::string path_, field_;
  std::size_t max_line_;
  std::vector<char> buf_;
  std::size_t begin_ = 0, end_ = 0, lines_ = 0;
  bool at_end_ = false, newline_ = false;
};

}  // namespace sphtroch
