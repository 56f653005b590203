// SPDX-License-Identifier: MIT
#include "io/checkpoint.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace silodem {
namespace {

constexpr char kMagic[8] = {'S', 'I', 'L', 'O', 'C', 'K', 'P', 'T'};
constexpr std::uint32_t kVersion = 1;

void write_all(int fd, const void* data, std::size_t n, const std::string& path) {
  const auto* p = static_cast<const unsigned char*>(data);
  while (n > 0) {
    const ssize_t k = ::write(fd, p, n);
    if (k < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error(fmt::format("cannot write {}: {}", path, std::strerror(errno)));
    }
    p += k, n -= std::size_t(k);
  }
}

}  // namespace

void write_checkpoint(const std::string& path, const ByteWriter& body) {
  const std::string tmp = path + ".partial";
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0)
    throw std::runtime_error(fmt::format("cannot write {}: {}", tmp, std::strerror(errno)));
  try {
    write_all(fd, kMagic, sizeof kMagic, tmp);
    write_all(fd, &kVersion, sizeof kVersion, tmp);
    const std::uint64_t n = body.bytes().size();
    write_all(fd, &n, sizeof n, tmp);
    write_all(fd, body.bytes().data(), body.bytes().size(), tmp);
    if (::fsync(fd) != 0)
      throw std::runtime_error(fmt::format("cannot sync {}: {}", tmp, std::strerror(errno)));
  } catch (...) {
    ::close(fd);
    throw;
  }
  ::close(fd);
  std::filesystem::rename(tmp, path);
  const std::string dir = std::filesystem::path(path).parent_path().string();
  const int dfd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd >= 0) {
    ::fsync(dfd);  // the rename itself is durable
    ::close(dfd);
  }
}

ByteReader read_checkpoint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("no checkpoint {}", path));
  std::vector<unsigned char> all((std::istreambuf_iterator<char>(in)),
                                 std::istreambuf_iterator<char>());
  const std::size_t head = sizeof kMagic + sizeof kVersion + sizeof(std::uint64_t);
  if (all.size() < head || std::memcmp(all.data(), kMagic, sizeof kMagic) != 0)
    throw std::runtime_error(fmt::format("{} is not a silodem checkpoint", path));
  std::uint32_t version = 0;
  std::uint64_t n = 0;
  std::memcpy(&version, all.data() + sizeof kMagic, sizeof version);
  std::memcpy(&n, all.data() + sizeof kMagic + sizeof version, sizeof n);
  if (version != kVersion)
    throw std::runtime_error(
        fmt::format("{} has format version {}, this silodem reads {}", path, version, kVersion));
  if (all.size() - head != n)
    throw std::runtime_error(
        fmt::format("{} is truncated ({} of {} bytes)", path, all.size() - head, n));
  return ByteReader(std::vector<unsigned char>(all.begin() + long(head), all.end()));
}

std::uint64_t text_hash(const std::string& text) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char ch : text) h = (h ^ ch) * 1099511628211ull;
  return h;
}

}  // namespace silodem
