// A 128-bit content hash for fingerprints and cache keys: two 64-bit
// FNV-1a lanes with different offsets, the second over a rotated stream so
// the lanes do not collide together. Not cryptographic; it tells "made
// from the same inputs" from "made from other inputs", nothing more.
//
//   Hash128 h;
//   h.add("shader text").add(640).add(0.5);
//   std::string id = h.hex();    // 32 lower-case hex digits
#pragma once
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace ms {

class Hash128 {
 public:
  // Bytes, prefixed by their length, so ("ab", "c") and ("a", "bc") differ.
  Hash128& add(std::string_view bytes) {
    add_raw(static_cast<std::uint64_t>(bytes.size()));
    for (unsigned char c : bytes) byte(c);
    return *this;
  }
  Hash128& add(const char* s) { return add(std::string_view(s)); }
  Hash128& add(const std::string& s) { return add(std::string_view(s)); }
  Hash128& add(std::int64_t v) { return add_raw(static_cast<std::uint64_t>(v)); }
  Hash128& add(int v) { return add(static_cast<std::int64_t>(v)); }
  Hash128& add(bool v) { return add(static_cast<std::int64_t>(v)); }
  // Floats by their bits: 0.1f and 0.1 differ, as they render differently.
  Hash128& add(double v) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    return add_raw(bits);
  }
  Hash128& add(float v) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    return add_raw(bits);
  }
  Hash128& add_bytes(const void* data, std::size_t size) {
    add_raw(static_cast<std::uint64_t>(size));
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) byte(p[i]);
    return *this;
  }

  std::string hex() const {
    static const char digits[] = "0123456789abcdef";
    std::string out(32, '0');
    for (int i = 0; i < 16; ++i) {
      out[15 - i] = digits[(a_ >> (4 * i)) & 15];
      out[31 - i] = digits[(b_ >> (4 * i)) & 15];
    }
    return out;
  }

 private:
  static constexpr std::uint64_t kPrime = 1099511628211ull;
  void byte(unsigned char c) {
    a_ = (a_ ^ c) * kPrime;
    b_ = (b_ ^ static_cast<unsigned char>(c + 0x5b)) * kPrime;
    b_ = (b_ << 7) | (b_ >> 57);
  }
  Hash128& add_raw(std::uint64_t v) {
    for (int i = 0; i < 8; ++i) byte(static_cast<unsigned char>(v >> (8 * i)));
    return *this;
  }
  std::uint64_t a_ = 1469598103934665603ull;
  std::uint64_t b_ = 0x84222325cbf29ce4ull;
};

}  // namespace ms
