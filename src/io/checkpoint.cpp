// SPDX-License-Identifier: MIT
#include "io/checkpoint.hpp"

#include "io/atomic_file.hpp"

#include <fmt/format.h>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace silodem {
namespace {

constexpr char kMagic[8] = {'S', 'I', 'L', 'O', 'C', 'K', 'P', 'T'};
constexpr std::uint32_t kVersion = 1;

}  // namespace

void write_checkpoint(const std::string& path, const ByteWriter& body) {
  const std::uint64_t n = body.bytes().size();
  auto view = [](const void* p, std::size_t size) {
    return std::string_view(static_cast<const char*>(p), size);
  };
  write_atomically(path,
                   {view(kMagic, sizeof kMagic), view(&kVersion, sizeof kVersion),
                    view(&n, sizeof n), view(body.bytes().data(), body.bytes().size())},
                   true);
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
