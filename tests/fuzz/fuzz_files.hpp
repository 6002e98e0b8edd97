// tests/fuzz/fuzz_files.hpp — for targets whose parser takes paths (the timed polyline reader,
// synth merge): one scratch directory per process under $TMPDIR (default /tmp), removed with
// what it holds at exit, and files in it rewritten in place for every input.
#pragma once

#include "fuzz_common.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

namespace fuzz {

/// Removes every file of `dir`, then `dir` (the scratch directory holds no subdirectory).
inline void remove_dir(const std::string& dir) {
  if (DIR* d = ::opendir(dir.c_str())) {
    while (const dirent* e = ::readdir(d)) {
      const std::string name = e->d_name;
      if (name != "." && name != "..") ::unlink((dir + "/" + name).c_str());
    }
    ::closedir(d);
  }
  ::rmdir(dir.c_str());
}

/// The process's scratch directory (created on first use, removed at exit).
inline const std::string& scratch_dir() {
  static const std::string dir = [] {
    const char* tmp = std::getenv("TMPDIR");
    std::string templ = std::string(tmp && *tmp ? tmp : "/tmp") + "/sphtroch-fuzz-XXXXXX";
    FUZZ_CHECK(::mkdtemp(templ.data()) != nullptr);
    return templ;
  }();
  static const bool cleanup = [] { return std::atexit([] { remove_dir(scratch_dir()); }) == 0; }();
  (void)cleanup;
  return dir;
}

/// Writes `bytes` to scratch_dir()/name (replacing what was there) and returns its path.
inline std::string write_file(const std::string& name, std::string_view bytes) {
  const std::string path = scratch_dir() + "/" + name;
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  FUZZ_CHECK(fd >= 0);
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t k = ::write(fd, bytes.data() + done, bytes.size() - done);
    FUZZ_CHECK(k > 0);
    done += static_cast<std::size_t>(k);
  }
  FUZZ_CHECK(::close(fd) == 0);
  return path;
}

/// The whole content of a file, or nothing when it cannot be opened.
inline bool read_file(const std::string& path, std::string& out) {
  out.clear();
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  char buf[1 << 14];
  for (ssize_t k; (k = ::read(fd, buf, sizeof buf)) > 0;) out.append(buf, static_cast<std::size_t>(k));
  ::close(fd);
  return true;
}

/// FNV-1a (64 bits) of the bytes: choices made from the input itself (so that a reproducer
/// reproduces), and the digest synth merge checks (synth_ratios.hpp).
inline std::uint64_t fnv1a(std::string_view s) {
  std::uint64_t h = 14695981039346656037ull;  // FNV-1a 64: offset basis, prime 2^40 + 2^8 + 0xb3
  for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
  return h;
}

}  // namespace fuzz
