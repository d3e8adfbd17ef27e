#include "engine/dynamics/state_hash.h"

#include <string_view>

#include "engine/core/hash.h"
#include "engine/dynamics/world.h"

namespace rugosim {

std::uint64_t state_hash(const World& world) {
  Fnv1a hash;
  hash.add(world.time());
  for (std::size_t i = 0; i < world.body_count(); ++i) {
    const BodyState& s = world.body(i).state();
    hash.add(s.position.x());
    hash.add(s.position.y());
    hash.add(s.angle);
    hash.add(s.velocity.x());
    hash.add(s.velocity.y());
    hash.add(s.angular_velocity);
  }
  return hash.value();
}

std::uint64_t full_state_hash(const World& world) {
  Fnv1a hash;
  hash.add(std::string_view(world.save_state()));
  return hash.value();
}

}  // namespace rugosim
