// What the renderer needs of one output frame (DESIGN.md, "Data flow"): where every body is,
// how it moves, and the impulses applied since the previous frame. A snapshot is a plain copy,
// so the simulation thread can go on while the renderer draws it.
#pragma once

#include <cstddef>
#include <vector>

#include "engine/core/transform.h"
#include "engine/core/types.h"
#include "engine/dynamics/event_record.h"

namespace rugosim {

class World;

struct BodyPose {
  Transform2 placement;           // the body's curve frame → world (RigidBody::placement)
  Vec2 velocity = Vec2::Zero();   // m/s, of the centre of mass
  double angular_velocity = 0.0;  // rad/s
  bool asleep = false;
};

struct FrameSnapshot {
  std::size_t frame = 0;             // frame k shows the state at t = k / fps
  double time = 0.0;                 // s
  std::vector<BodyPose> bodies;      // in the World's body order
  std::vector<ContactEvent> events;  // impulses applied since the previous frame
};

// The World's state now, with the events it recorded since they were last cleared.
FrameSnapshot take_snapshot(const World& world, std::size_t frame);

}  // namespace rugosim
