// Fnv1a (hash.h): the published FNV-1a 64 test vectors, and bit patterns (not values) hashed.
#include "engine/core/hash.h"

#include <gtest/gtest.h>

namespace rugosim {
namespace {

std::uint64_t of_text(std::string_view text) {
  Fnv1a h;
  h.add_bytes(text.data(), text.size());
  return h.value();
}

TEST(Fnv1a, MatchesThePublishedVectors) {
  EXPECT_EQ(of_text(""), 0xcbf29ce484222325ull);
  EXPECT_EQ(of_text("a"), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(of_text("foobar"), 0x85944171f73967e8ull);
}

TEST(Fnv1a, HashesBitPatterns) {
  Fnv1a zero, negative_zero, tiny;
  zero.add(0.0);
  negative_zero.add(-0.0);
  tiny.add(4.9e-324);
  EXPECT_NE(zero.value(), negative_zero.value());
  EXPECT_NE(zero.value(), tiny.value());
  Fnv1a again;
  again.add(0.0);
  EXPECT_EQ(zero.value(), again.value());
}

}  // namespace
}  // namespace rugosim
