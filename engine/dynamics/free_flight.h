// Free flight between contacts (DESIGN.md, "Dynamics"): under constant gravity and no other
// force, the centre of mass follows a parabola and the body spins at a constant rate, and both
// have closed forms. Evaluating them instead of integrating leaves no integration error to
// accumulate between contacts, and gives the time-of-flight bounds that the search for the
// first contact needs.
#pragma once

#include <optional>

#include "engine/core/types.h"
#include "engine/dynamics/rigid_body.h"

namespace rugosim {

// The state dt (s) later under gravity g (m/s²): x = x0 + v0·dt + ½·g·dt², v = v0 + g·dt,
// θ = θ0 + ω·dt, ω unchanged. Exact to rounding for any dt, negative dt included (it runs the
// motion backwards), so advancing by dt1 then dt2 is advancing by dt1 + dt2.
BodyState free_flight(const BodyState& state, const Vec2& gravity, double dt);

// The state dt (s) later under a constant linear acceleration (m/s², gravity included) and a
// constant angular acceleration (rad/s²), as contact forces held over a step give
// (contact_forces.h): x = x0 + v0·dt + ½·a·dt², v = v0 + a·dt, θ = θ0 + ω0·dt + ½·α·dt²,
// ω = ω0 + α·dt. With α = 0 it is free_flight.
BodyState driven_flight(const BodyState& state, const Vec2& acceleration,
                        double angular_acceleration, double dt);

// Advances a body by free flight; a fixed body stays where it is.
void advance_free_flight(RigidBody& body, const Vec2& gravity, double dt);

// The heights below are measured against gravity (along −g/|g|), relative to where the centre
// of mass is now. With zero gravity there is no "up", and they have no value.

// s: when the upward velocity vanishes, −(v·g)/|g|²; negative when the apex has passed.
std::optional<double> apex_time(const Vec2& velocity, const Vec2& gravity);

// m: the highest height reached from now on, (v·ĝ)²/(2|g|) while rising, 0 once falling.
std::optional<double> apex_rise(const Vec2& velocity, const Vec2& gravity);

// s: when the height, having passed its apex, has fallen to −drop (drop >= 0, m), i.e. the
// larger root of −drop = u·t − ½|g|·t² with u the upward speed. A projectile launched from the
// ground upwards at u lands after time_to_fall(u, g, 0) = 2u/|g|. No value for a negative drop.
std::optional<double> time_to_fall(const Vec2& velocity, const Vec2& gravity, double drop);

// m: an upper bound on how far any point within `radius` (m) of the centre of mass moves
// during the next dt >= 0 (s) of free flight, at every instant in between: the parabola's
// chord is at most |v|·dt + ½|g|·dt², and a turn by φ moves a point at distance r by
// 2r·|sin(φ/2)| <= r·min(|φ|, 2). Conservative advancement (Mirtich) steps by this.
double motion_bound(const BodyState& state, const Vec2& gravity, double dt, double radius);

}  // namespace rugosim
