// The hash of a World's state (every body's position, angle, velocity and angular velocity, bit
// for bit, and the time), as Box2D's determinism test hashes its bodies: a golden value pins the
// simulation, so any change to its results is noticed and made on purpose.
#pragma once

#include <cstdint>

namespace rugosim {

class World;

std::uint64_t state_hash(const World& world);

// The hash of everything a checkpoint holds (World::save_state): the bodies and time as above,
// and all else that steers the next step (the last state's manifolds and near pairs, the sleep
// records, the statistics). Two Worlds with equal full hashes continue identically.
std::uint64_t full_state_hash(const World& world);

}  // namespace rugosim
