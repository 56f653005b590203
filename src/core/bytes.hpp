// SPDX-License-Identifier: MIT
// A plain byte stream for checkpoints: trivially copyable values and vectors of them, in the
// machine's byte order (a checkpoint is read back on the machine that wrote it). Each component
// writes its own state with put() and reads it back in the same order with get().
#pragma once
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace silodem {

class ByteWriter {
 public:
  template <class T>
  void put(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* b = reinterpret_cast<const unsigned char*>(&v);
    bytes_.insert(bytes_.end(), b, b + sizeof(T));
  }
  template <class T>
  void put(const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    put(std::uint64_t(v.size()));
    const auto* b = reinterpret_cast<const unsigned char*>(v.data());
    bytes_.insert(bytes_.end(), b, b + v.size() * sizeof(T));
  }
  void put(const std::string& s) {
    put(std::uint64_t(s.size()));
    bytes_.insert(bytes_.end(), s.begin(), s.end());
  }
  // A tag that get_tag() checks: a misaligned or foreign stream fails loudly, not silently.
  void tag(const char (&name)[5]) {
    put(std::uint32_t(name[0] | name[1] << 8 | name[2] << 16 | name[3] << 24));
  }
  const std::vector<unsigned char>& bytes() const { return bytes_; }

 private:
  std::vector<unsigned char> bytes_;
};

class ByteReader {
 public:
  explicit ByteReader(std::vector<unsigned char> bytes) : bytes_(std::move(bytes)) {}
  template <class T>
  void get(T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    need(sizeof(T));
    std::memcpy(&v, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
  }
  template <class T>
  void get(std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    std::uint64_t n = 0;
    get(n);
    if (n > (bytes_.size() - at_) / (sizeof(T) ? sizeof(T) : 1)) fail("vector length");
    v.resize(std::size_t(n));
    need(std::size_t(n) * sizeof(T));
    if (n) std::memcpy(v.data(), bytes_.data() + at_, std::size_t(n) * sizeof(T));
    at_ += std::size_t(n) * sizeof(T);
  }
  void get(std::string& s) {
    std::uint64_t n = 0;
    get(n);
    need(std::size_t(n));
    s.assign(reinterpret_cast<const char*>(bytes_.data() + at_), std::size_t(n));
    at_ += std::size_t(n);
  }
  template <class T>
  T get() {
    T v{};
    get(v);
    return v;
  }
  void tag(const char (&name)[5]) {
    const std::uint32_t want =
        std::uint32_t(name[0] | name[1] << 8 | name[2] << 16 | name[3] << 24);
    if (get<std::uint32_t>() != want) fail(std::string("section ") + name);
  }
  // True if the next bytes are this tag (nothing is read): for an optional section.
  bool next_is(const char (&name)[5]) const {
    const std::uint32_t want =
        std::uint32_t(name[0] | name[1] << 8 | name[2] << 16 | name[3] << 24);
    std::uint32_t have = 0;
    if (bytes_.size() - at_ < sizeof have) return false;
    std::memcpy(&have, bytes_.data() + at_, sizeof have);
    return have == want;
  }
  bool done() const { return at_ == bytes_.size(); }
  // A count of items that take at least `min_bytes` each: refused if the bytes left cannot hold
  // them (a damaged count fails here instead of allocating without bound).
  std::size_t get_count(std::size_t min_bytes) {
    const auto n = get<std::uint64_t>();
    if (min_bytes > 0 && n > (bytes_.size() - at_) / min_bytes) fail("count");
    return std::size_t(n);
  }

 private:
  void need(std::size_t n) const {
    if (n > bytes_.size() - at_) fail("truncated");
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("checkpoint is damaged or from another version (" + what +
                             " at byte " + std::to_string(at_) + ")");
  }
  std::vector<unsigned char> bytes_;
  std::size_t at_ = 0;
};

}  // namespace silodem
