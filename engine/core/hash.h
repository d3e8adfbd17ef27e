// A deterministic 64-bit hash (FNV-1a) of exact bit patterns, for determinism checks: the same
// states give the same hash on every run, thread count and build of the same platform, and any
// change of a single bit gives another (std::hash promises neither).
#pragma once

#include <bit>
#include <cstdint>
#include <string_view>

namespace rugosim {

class Fnv1a {
 public:
  void add_bytes(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
      hash_ = (hash_ ^ bytes[i]) * kPrime;
    }
  }
  void add(std::uint64_t value) { add_bytes(&value, sizeof value); }
  // The bit pattern: −0.0 and 0.0 differ, as they may in what follows from them.
  void add(double value) { add(std::bit_cast<std::uint64_t>(value)); }
  void add(std::string_view text) {
    add(static_cast<std::uint64_t>(text.size()));
    add_bytes(text.data(), text.size());
  }
  std::uint64_t value() const { return hash_; }

 private:
  static constexpr std::uint64_t kOffset = 0xcbf29ce484222325ull;
  static constexpr std::uint64_t kPrime = 0x100000001b3ull;
  std::uint64_t hash_ = kOffset;
};

}  // namespace rugosim
