// A World's state between two calls of advance_to, exactly (docs/research/checkpoints.md): what
// steers the steps that follow. Everything else is rebuilt from the scene (shapes, trees,
// materials, settings) or is scratch overwritten before it is read. The pipeline's leaf-pair
// caches are left out: they change no result (body_pair_collider.h), and the resume tests,
// which compare every later frame bit for bit, hold that to account.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "engine/core/byte_stream.h"
#include "engine/dynamics/world.h"

namespace rugosim {
namespace {

// 2: the fallbacks in a row; 3: soft-rest impulses; 4: the sleep test's soft windows; 5: the
// soft rest's retried steps
constexpr std::uint64_t kStateFormat = 5;

void write_vec(ByteWriter& out, const Vec2& v) {
  out.f64(v.x());
  out.f64(v.y());
}

Vec2 read_vec(ByteReader& in) {
  const double x = in.f64();
  return Vec2(x, in.f64());
}

void write_manifolds(ByteWriter& out, const std::vector<ContactManifold>& manifolds) {
  out.u64(manifolds.size());
  for (const ContactManifold& m : manifolds) {
    out.u64(m.body_a);
    out.u64(m.body_b);
    out.u64(m.intersections.size());
    for (const Intersection& x : m.intersections) {
      out.u64(x.segment_a);
      out.u64(x.segment_b);
      out.f64(x.t_a);
      out.f64(x.t_b);
      write_vec(out, x.point);
    }
    out.u64(m.contacts.size());
    for (const Contact& c : m.contacts) {
      out.u64(c.segment_a);
      out.u64(c.segment_b);
      out.f64(c.t_a);
      out.f64(c.t_b);
      out.f64(c.lambda_a);
      out.f64(c.lambda_b);
      write_vec(out, c.point_a);
      write_vec(out, c.point_b);
      write_vec(out, c.point);
      write_vec(out, c.normal);
      out.f64(c.distance);
    }
  }
}

std::size_t read_body(ByteReader& in, std::size_t bodies) {
  const std::uint64_t i = in.u64();
  if (i >= bodies) throw ByteStreamError("a body index past the last body");
  return static_cast<std::size_t>(i);
}

// A segment of `body`: an index past its last segment would be read out of bounds later.
std::size_t read_segment(ByteReader& in, const RigidBody& body) {
  const std::uint64_t s = in.u64();
  if (s >= body.shape().curve().size()) throw ByteStreamError("a segment past the body's last");
  return static_cast<std::size_t>(s);
}

std::vector<ContactManifold> read_manifolds(ByteReader& in, const std::vector<RigidBody>& b) {
  const std::size_t bodies = b.size();
  std::vector<ContactManifold> manifolds(in.count(32));
  for (ContactManifold& m : manifolds) {
    m.body_a = read_body(in, bodies);
    m.body_b = read_body(in, bodies);
    m.intersections.resize(in.count(48));
    for (Intersection& x : m.intersections) {
      x.segment_a = read_segment(in, b[m.body_a]);
      x.segment_b = read_segment(in, b[m.body_b]);
      x.t_a = in.f64();
      x.t_b = in.f64();
      x.point = read_vec(in);
    }
    m.contacts.resize(in.count(120));
    for (Contact& c : m.contacts) {
      c.segment_a = read_segment(in, b[m.body_a]);
      c.segment_b = read_segment(in, b[m.body_b]);
      c.t_a = in.f64();
      c.t_b = in.f64();
      c.lambda_a = in.f64();
      c.lambda_b = in.f64();
      c.point_a = read_vec(in);
      c.point_b = read_vec(in);
      c.point = read_vec(in);
      c.normal = read_vec(in);
      c.distance = in.f64();
    }
  }
  return manifolds;
}

// Every counter of StepStats, in one order for writing and reading.
template <typename Stats, typename Count, typename Real>
void visit_stats(Stats& s, Count&& count, Real&& real) {
  for (auto* c : {&s.steps,
                  &s.bisections,
                  &s.collisions,
                  &s.contacts,
                  &s.fallbacks,
                  &s.min_step_fallbacks,
                  &s.pass_fallbacks,
                  &s.rigid_clusters,
                  &s.unresolved_states,
                  &s.crossing_fallbacks,
                  &s.stalled_steps,
                  &s.crossings,
                  &s.passes,
                  &s.islands_slept,
                  &s.islands_woken,
                  &s.idle_jumps,
                  &s.free_steps,
                  &s.rest_steps,
                  &s.rest_contacts,
                  &s.rest_sweeps,
                  &s.rest_unconverged,
                  &s.rest_withdrawn,
                  &s.soft_rest_retries,
                  &s.body_steps})
    count(*c);
  real(s.stalled_time);
  real(s.sim_time);
}

}  // namespace

std::string World::save_state() const {
  ByteWriter out;
  out.u64(kStateFormat);
  out.u64(bodies_.size());
  out.f64(time_);
  for (const RigidBody& body : bodies_) {
    const BodyState& s = body.state();
    write_vec(out, s.position);
    out.f64(s.angle);
    write_vec(out, s.velocity);
    out.f64(s.angular_velocity);
  }
  out.u8(contacts_known_ ? 1 : 0);
  write_manifolds(out, manifolds_);
  out.u64(near_pairs_.size());
  for (const BodyPair& p : near_pairs_) {
    out.u64(p.a);
    out.u64(p.b);
  }
  sleep_.save(out);
  StepStats stats = stats_;
  visit_stats(
      stats, [&](std::uint64_t& c) { out.u64(c); }, [&](double& r) { out.f64(r); });
  out.u8(first_crossing_ ? 1 : 0);
  if (first_crossing_) {
    out.f64(first_crossing_->time);
    out.u64(first_crossing_->body_a);
    out.u64(first_crossing_->body_b);
    out.f64(first_crossing_->depth);
  }
  // Min-step fallbacks in a row carry across frames: the crossing fallback counts them.
  out.i64(consecutive_fallbacks_);
  // soft_rest_substeps: the warm starts of the next rest step (empty without it).
  soft_memory_.save(out);
  return out.bytes();
}

void World::restore_state(std::string_view record) {
  ByteReader in(record);
  if (in.u64() != kStateFormat) throw ByteStreamError("a state of another format");
  const std::size_t n = bodies_.size();
  if (in.u64() != n) throw ByteStreamError("a state of another number of bodies");
  const double time = in.f64();
  std::vector<BodyState> states(n);
  for (BodyState& s : states) {
    s.position = read_vec(in);
    s.angle = in.f64();
    s.velocity = read_vec(in);
    s.angular_velocity = in.f64();
  }
  const bool contacts_known = in.u8() != 0;
  std::vector<ContactManifold> manifolds = read_manifolds(in, bodies_);
  std::vector<BodyPair> near_pairs(in.count(16));
  for (BodyPair& p : near_pairs) {
    p.a = static_cast<std::uint32_t>(read_body(in, n));
    p.b = static_cast<std::uint32_t>(read_body(in, n));
  }
  SleepTracker sleep(sleep_.settings());
  sleep.restore(in, n);
  StepStats stats;
  visit_stats(
      stats, [&](std::uint64_t& c) { c = in.u64(); }, [&](double& r) { r = in.f64(); });
  std::optional<CrossingRecord> first_crossing;
  if (in.u8() != 0) {
    CrossingRecord r;
    r.time = in.f64();
    r.body_a = read_body(in, n);
    r.body_b = read_body(in, n);
    r.depth = in.f64();
    first_crossing = r;
  }
  const std::int64_t fallbacks_in_a_row = in.i64();
  SoftRestMemory soft_memory;
  soft_memory.restore(in, bodies_);
  if (!in.at_end()) throw ByteStreamError("bytes after the state");

  // All read: only now is the World changed, so a refused record leaves it as it was.
  time_ = time;
  for (std::size_t i = 0; i < n; ++i)
    bodies_[i].set_state(states[i]);
  contacts_known_ = contacts_known;
  manifolds_ = std::move(manifolds);
  near_pairs_ = std::move(near_pairs);
  sleep_ = std::move(sleep);
  stats_ = stats;
  first_crossing_ = first_crossing;
  events_.clear();
  consecutive_fallbacks_ = static_cast<int>(fallbacks_in_a_row);
  soft_memory_ = std::move(soft_memory);
}

}  // namespace rugosim
