// SPDX-License-Identifier: MIT
#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace silodem {

void write_atomically(const std::string& path, const std::vector<std::string_view>& parts,
                      bool sync) {
  const std::string tmp = path + ".partial";
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0)
    throw std::runtime_error(fmt::format("cannot write {}: {}", tmp, std::strerror(errno)));
  auto fail = [&](const char* what) {
    const int err = errno;
    ::close(fd);
    throw std::runtime_error(fmt::format("cannot {} {}: {}", what, tmp, std::strerror(err)));
  };
  for (std::string_view part : parts) {
    const char* p = part.data();
    std::size_t n = part.size();
    while (n > 0) {
      const ssize_t k = ::write(fd, p, n);
      if (k < 0) {
        if (errno == EINTR) continue;
        fail("write");
      }
      p += k, n -= std::size_t(k);
    }
  }
  if (sync && ::fsync(fd) != 0) fail("sync");
  if (::close(fd) != 0) throw std::runtime_error(fmt::format("cannot close {}", tmp));
  std::filesystem::rename(tmp, path);
  if (!sync) return;
  const std::string dir = std::filesystem::path(path).parent_path().string();
  const int dfd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  write_atomically(path.string(), {text}, false);
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace silodem
