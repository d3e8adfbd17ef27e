// The hash of a World's state (every body's position, angle, velocity and angular velocity, bit
// for bit, and the time), as Box2D's determinism test hashes its bodies: a golden value pins the
// simulation, so any change to its results is noticed and made on purpose.
#pragma once

#include <cstdint>

namespace rugosim {

class World;

std::uint64_t state_hash(const World& world);

}  // namespace rugosim
