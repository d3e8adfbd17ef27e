#include "engine/dynamics/frame_snapshot.h"

#include "engine/dynamics/world.h"

namespace rugosim {

FrameSnapshot take_snapshot(const World& world, std::size_t frame) {
  FrameSnapshot snapshot;
  snapshot.frame = frame;
  snapshot.time = world.time();
  snapshot.bodies.reserve(world.body_count());
  for (std::size_t i = 0; i < world.body_count(); ++i) {
    const RigidBody& body = world.body(i);
    snapshot.bodies.push_back(BodyPose{body.placement(), body.state().velocity,
                                       body.state().angular_velocity, world.asleep(i)});
  }
  snapshot.events = world.events();
  return snapshot;
}

}  // namespace rugosim
