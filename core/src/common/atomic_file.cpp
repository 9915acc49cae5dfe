#include "multidir/core/common/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <random>
#include <streambuf>

namespace multidir::core {
namespace {

namespace fs = std::filesystem;

// A stream buffer over a file descriptor we opened ourselves: std::ofstream cannot open a file
// exclusively or refuse to follow a symbolic link.
class DescriptorBuffer : public std::streambuf {
 public:
  explicit DescriptorBuffer(int fd) : m_fd(fd) { setp(m_buffer.data(), m_buffer.data() + m_buffer.size()); }
  DescriptorBuffer(const DescriptorBuffer&) = delete;
  DescriptorBuffer& operator=(const DescriptorBuffer&) = delete;
  ~DescriptorBuffer() override = default;
  int error() const { return m_error; }

 protected:
  int overflow(int c) override {
    if (!drain()) return traits_type::eof();
    if (c != traits_type::eof()) {
      *pptr() = static_cast<char>(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  bool drain() {
    const char* p = pbase();
    while (p < pptr()) {
      const ssize_t n = ::write(m_fd, p, static_cast<std::size_t>(pptr() - p));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        m_error = n < 0 ? errno : EIO;
        return false;
      }
      p += n;
    }
    setp(m_buffer.data(), m_buffer.data() + m_buffer.size());
    return true;
  }

  int m_fd;
  int m_error = 0;
  std::array<char, 1 << 16> m_buffer{};
};

// Creates `<path>.<random>.partial` exclusively: O_EXCL fails on anything already there (a planted
// symbolic link included) and O_NOFOLLOW refuses a link in the last component, so the write can only
// ever go to a new file of our own. Mode 0666 less the umask, like any other file the program saves.
int createTemporary(const std::string& path, std::string& temporary, int& error) {
  static std::atomic<unsigned> counter{0};
  std::random_device device;
  for (int attempt = 0; attempt < 32; ++attempt) {
    const unsigned long long salt =
        (static_cast<unsigned long long>(device()) << 20) ^ static_cast<unsigned long long>(::getpid()) ^
        (static_cast<unsigned long long>(counter.fetch_add(1)) << 44) ^
        static_cast<unsigned long long>(std::chrono::steady_clock::now().time_since_epoch().count());
    char suffix[32];
    std::snprintf(suffix, sizeof suffix, ".%012llx.partial", salt & 0xffffffffffffull);
    temporary = path + suffix;
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd >= 0) return fd;
    error = errno;
    if (error != EEXIST) return -1;
  }
  return -1;
}

}  // namespace

Status writeFileAtomically(const std::string& path, const std::string& name,
                           const std::function<Status(std::ostream&)>& write) {
  std::string temporary;
  int openError = 0;
  const int fd = createTemporary(path, temporary, openError);
  if (fd < 0)
    return Error{ErrorCode::WriteFailed,
                 "cannot create the file (does the folder exist and is it writable?): " +
                     std::string(std::strerror(openError)),
                 name};
  bool closed = false;
  auto closeOnce = [&]() -> int {
    if (closed) return 0;
    closed = true;
    return ::close(fd);
  };
  auto discard = [&] {
    closeOnce();
    ::unlink(temporary.c_str());
  };
  try {
    DescriptorBuffer buffer(fd);
    std::ostream out(&buffer);
    if (Status s = write(out); !s) {
      discard();
      return Error{s.error().code, s.error().message, name};
    }
    out.flush();
    if (!out || buffer.error() != 0) {
      const int e = buffer.error();
      discard();
      return Error{ErrorCode::WriteFailed,
                   "writing failed (is the disk full?)" + (e != 0 ? ": " + std::string(std::strerror(e)) : ""), name};
    }
    // The content must be on disk before the rename makes it the file, or a crash could leave an empty one.
    if (::fsync(fd) != 0 || closeOnce() != 0) {
      const int e = errno;
      discard();
      return Error{ErrorCode::WriteFailed, "writing failed (is the disk full?): " + std::string(std::strerror(e)),
                   name};
    }
    // rename() replaces `path` itself, never what a link at `path` points to.
    if (::rename(temporary.c_str(), path.c_str()) != 0) {
      const int e = errno;
      discard();
      return Error{ErrorCode::WriteFailed, "cannot replace the file: " + std::string(std::strerror(e)), name};
    }
  } catch (const std::exception& e) {
    discard();
    return Error{ErrorCode::WriteFailed, std::string("writing failed: ") + e.what(), name};
  }
  return Done{};
}

Status writeTextFileAtomically(const std::string& path, const std::string& text, const std::string& name) {
  return writeFileAtomically(path, name.empty() ? path : name, [&](std::ostream& out) -> Status {
    out << text;
    return Done{};
  });
}

}  // namespace multidir::core
