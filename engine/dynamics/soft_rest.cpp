#include "engine/dynamics/soft_rest.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <numbers>
#include <tuple>
#include <utility>

#include "engine/core/disjoint_sets.h"
#include "engine/geometry/friction.h"

namespace rugosim {
namespace {

auto key_of(const SoftRestImpulse& x) {
  return std::tie(x.body_a, x.body_b, x.segment_a, x.segment_b);
}

// Share of the room between a row's rest depth and its curves touching that the load a row
// carries may sag its spring (rest_softly). A quarter: the 1,000-body pile stands still inside
// by 6 s, and the 50- and 200-body piles slept within 5 s at every frame rate tried, where a
// half left the 200-body pile awake (§8.20).
constexpr double kLoadSagShare = 0.25;

// Box2D v3's soft constraint coefficients for a spring of `hertz` and `zeta` over a substep hs.
struct Softness {
  double bias_rate = 0.0;      // 1/s
  double mass_scale = 1.0;     // of the effective mass
  double impulse_scale = 0.0;  // of the accumulated impulse
};

Softness make_soft(double hertz, double zeta, double hs) {
  const double omega = 2.0 * std::numbers::pi * hertz;
  const double a1 = 2.0 * zeta + hs * omega;
  const double a2 = hs * omega * a1;
  const double a3 = 1.0 / (1.0 + a2);
  return {omega / a1, a2 * a3, a3};
}

// One contact row: arms' moments and masses taken once, the impulses accumulated over the
// substeps.
struct Row {
  std::size_t a = 0;
  std::size_t b = 0;
  std::size_t segment_a = 0;
  std::size_t segment_b = 0;
  Vec2 normal = Vec2::Zero();
  Vec2 tangent = Vec2::Zero();
  // The arms' moments along the normal and the tangent (cross(arm, direction)): a body's spin
  // moves the contact point by them, and an impulse along the direction spins it by them.
  double normal_arm_a = 0.0;
  double normal_arm_b = 0.0;
  double tangent_arm_a = 0.0;
  double tangent_arm_b = 0.0;
  double normal_mass = 0.0;
  double tangent_mass = 0.0;
  double mu = 0.0;
  double gap = 0.0;   // m, from the contact to its rest depth at the step's start (> 0: open)
  double room = 0.0;  // m, from its rest depth to the curves touching
  double normal_impulse = 0.0;
  double tangent_impulse = 0.0;
  Softness soft;  // its spring past the rest depth over this step's substeps (rest_softly)
};

// A body's working velocity, displacement and inverse mass over the substeps (0 for what does
// not move), side by side so that a row touches one cache line per body.
struct Mover {
  Vec2 velocity = Vec2::Zero();
  double spin = 0.0;
  Vec2 displacement = Vec2::Zero();
  double turn = 0.0;
  double inv_mass = 0.0;
  double inv_inertia = 0.0;
};

// A solve's working memory, kept from solve to solve by the thread that runs it: a pile's rows
// take hundreds of kB, which fresh vectors zeroed, or took from the kernel, at every step.
struct Workspace {
  std::vector<Row> made;     // in the manifolds' order
  std::vector<Row> ordered;  // the same rows by colour (order_by_colour); grows, never shrinks
  std::vector<std::uint8_t> touched;  // per body: in some row
  std::vector<std::uint64_t> used;    // per body: the colours its rows took (order_by_colour)
  std::vector<std::uint8_t> colour;   // per made row
  std::vector<Mover> movers;          // per body; only touched bodies' entries are set
};

// The rows of the contacts with a moving body, into work.made and work.touched; returns the
// pairs they rest.
std::vector<RestedPair> make_rows(std::span<const RigidBody> bodies,
                                  std::span<const std::uint8_t> moves,
                                  std::span<const ContactManifold> manifolds,
                                  const SoftRestSettings& settings, const SoftRestMemory& memory,
                                  double carry, Workspace& work) {
  std::vector<RestedPair> rested;
  work.made.clear();
  work.touched.assign(bodies.size(), 0);
  for (const ContactManifold& m : manifolds) {
    if (m.state() != PairState::kContact) continue;
    if (moves[m.body_a] == 0 && moves[m.body_b] == 0) continue;
    rested.push_back({m.body_a, m.body_b, 0.0, true});
    const RigidBody& body_a = bodies[m.body_a];
    const RigidBody& body_b = bodies[m.body_b];
    const double inv_mass_a = moves[m.body_a] != 0 ? body_a.inverse_mass() : 0.0;
    const double inv_inertia_a = moves[m.body_a] != 0 ? body_a.inverse_inertia() : 0.0;
    const double inv_mass_b = moves[m.body_b] != 0 ? body_b.inverse_mass() : 0.0;
    const double inv_inertia_b = moves[m.body_b] != 0 ? body_b.inverse_inertia() : 0.0;
    const double min_band = body_a.shape().min_band() + body_b.shape().min_band();
    for (const Contact& c : m.contacts) {
      Row r;
      r.a = m.body_a;
      r.b = m.body_b;
      r.segment_a = c.segment_a;
      r.segment_b = c.segment_b;
      const Vec2 arm_a = c.point - body_a.state().position;
      const Vec2 arm_b = c.point - body_b.state().position;
      r.normal = c.normal;
      r.tangent = perp(c.normal);
      r.normal_arm_a = cross(arm_a, r.normal);
      r.normal_arm_b = cross(arm_b, r.normal);
      r.tangent_arm_a = cross(arm_a, r.tangent);
      r.tangent_arm_b = cross(arm_b, r.tangent);
      const auto effective = [&](double ra, double rb) {
        return inv_mass_a + inv_mass_b + inv_inertia_a * ra * ra + inv_inertia_b * rb * rb;
      };
      const double kn = effective(r.normal_arm_a, r.normal_arm_b);
      const double kt = effective(r.tangent_arm_a, r.tangent_arm_b);
      if (!(kn > 0.0)) continue;
      r.normal_mass = 1.0 / kn;
      r.tangent_mass = kt > 0.0 ? 1.0 / kt : 0.0;
      const double band = std::max(c.lambda_a + c.lambda_b, min_band);
      r.room = (1.0 - settings.rest_depth) * band;
      r.gap = c.distance - r.room;
      r.mu =
          contact_friction(body_a.friction_coefficient(c.segment_a, c.t_a, settings.friction_gain),
                           body_b.friction_coefficient(c.segment_b, c.t_b, settings.friction_gain));
      if (carry > 0.0) {
        if (const SoftRestImpulse* x = memory.find(r.a, r.b, r.segment_a, r.segment_b)) {
          r.normal_impulse = carry * x->normal;
          const double limit = r.mu * r.normal_impulse;
          r.tangent_impulse = std::clamp(carry * x->tangent, -limit, limit);
        }
      }
      work.touched[r.a] = work.touched[r.b] = 1;
      work.made.push_back(r);
    }
  }
  return rested;
}

// The impulse p along a row's direction (unit, with the arms' moments arm_a and arm_b) on its
// two bodies, equal and opposite.
void push(Mover& a, Mover& b, const Vec2& direction, double arm_a, double arm_b, double p) {
  a.velocity += (a.inv_mass * p) * direction;
  a.spin += a.inv_inertia * p * arm_a;
  b.velocity -= (b.inv_mass * p) * direction;
  b.spin -= b.inv_inertia * p * arm_b;
}

// How fast a row's contact point on A moves along `direction` relative to B's (arms' moments
// arm_a and arm_b along it).
double speed_along(const Mover& a, const Mover& b, const Vec2& direction, double arm_a,
                   double arm_b) {
  return direction.dot(a.velocity - b.velocity) + a.spin * arm_a - b.spin * arm_b;
}

// Rows reordered so that rows sharing a moving body fall apart: each takes the lowest colour
// that neither of its moving bodies has yet (greedy, in the manifolds' order), and the rows go
// colour by colour, in their order within a colour. A sweep's rows then depend on the row
// before them only across a colour's edge, and the processor overlaps neighbouring rows
// instead of waiting on each one's writes (Box2D v3 colours its constraints for the same
// reason, and for SIMD). Rows beyond the last colour keep their order at the end.
std::span<Row> order_by_colour(Workspace& work, std::span<const std::uint8_t> moves) {
  constexpr std::size_t kColours = 64;
  const std::vector<Row>& rows = work.made;
  work.used.assign(moves.size(), 0);
  work.colour.resize(rows.size());
  std::array<std::size_t, kColours + 1> count{};
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const Row& r = rows[k];
    const std::uint64_t taken =
        (moves[r.a] != 0 ? work.used[r.a] : 0) | (moves[r.b] != 0 ? work.used[r.b] : 0);
    const std::size_t c =
        taken == ~std::uint64_t{0} ? kColours : static_cast<std::size_t>(std::countr_one(taken));
    work.colour[k] = static_cast<std::uint8_t>(c);
    ++count[c];
    if (c < kColours) {
      work.used[r.a] |= std::uint64_t{1} << c;
      work.used[r.b] |= std::uint64_t{1} << c;
    }
  }
  std::array<std::size_t, kColours + 1> first{};
  for (std::size_t c = 1; c <= kColours; ++c)
    first[c] = first[c - 1] + count[c - 1];
  if (work.ordered.size() < rows.size()) work.ordered.resize(rows.size());
  for (std::size_t k = 0; k < rows.size(); ++k)
    work.ordered[first[work.colour[k]]++] = rows[k];
  return std::span<Row>(work.ordered.data(), rows.size());
}

// One Gauss-Seidel sweep over the rows; `biased` lets deep rows push apart (the soft sweep),
// otherwise they only stop (the relax sweep).
void sweep(std::span<Row> rows, std::span<Mover> movers, double hs, bool biased) {
  for (Row& r : rows) {
    Mover& a = movers[r.a];
    Mover& b = movers[r.b];
    const double gap = r.gap + r.normal.dot(a.displacement - b.displacement) +
                       a.turn * r.normal_arm_a - b.turn * r.normal_arm_b;
    double bias = 0.0;
    double mass_scale = 1.0;
    double impulse_scale = 0.0;
    if (gap > 0.0) {
      bias = gap / hs;  // speculative: may close the gap within the substep
    } else if (biased) {
      bias = r.soft.bias_rate * gap;
      mass_scale = r.soft.mass_scale;
      impulse_scale = r.soft.impulse_scale;
    }
    const double vn = speed_along(a, b, r.normal, r.normal_arm_a, r.normal_arm_b);
    const double normal =
        std::max(0.0, r.normal_impulse - r.normal_mass * mass_scale * (vn + bias) -
                          impulse_scale * r.normal_impulse);
    push(a, b, r.normal, r.normal_arm_a, r.normal_arm_b, normal - r.normal_impulse);
    r.normal_impulse = normal;
    if (r.tangent_mass > 0.0) {
      const double vt = speed_along(a, b, r.tangent, r.tangent_arm_a, r.tangent_arm_b);
      const double limit = r.mu * r.normal_impulse;
      const double tangent = std::clamp(r.tangent_impulse - r.tangent_mass * vt, -limit, limit);
      push(a, b, r.tangent, r.tangent_arm_a, r.tangent_arm_b, tangent - r.tangent_impulse);
      r.tangent_impulse = tangent;
    }
  }
}

}  // namespace

const SoftRestImpulse* SoftRestMemory::find(std::size_t body_a, std::size_t body_b,
                                            std::size_t segment_a, std::size_t segment_b) const {
  const SoftRestImpulse probe{body_a, body_b, segment_a, segment_b, 0.0, 0.0};
  const auto it = std::lower_bound(
      impulses_.begin(), impulses_.end(), probe,
      [](const SoftRestImpulse& x, const SoftRestImpulse& y) { return key_of(x) < key_of(y); });
  return it != impulses_.end() && key_of(*it) == key_of(probe) ? &*it : nullptr;
}

void SoftRestMemory::replace(double substep, std::vector<SoftRestImpulse> impulses) {
  std::stable_sort(
      impulses.begin(), impulses.end(),
      [](const SoftRestImpulse& x, const SoftRestImpulse& y) { return key_of(x) < key_of(y); });
  // Keep the last of each run of equal keys.
  std::vector<SoftRestImpulse> unique;
  unique.reserve(impulses.size());
  for (std::size_t i = 0; i < impulses.size(); ++i) {
    if (i + 1 < impulses.size() && key_of(impulses[i]) == key_of(impulses[i + 1])) continue;
    unique.push_back(impulses[i]);
  }
  substep_ = unique.empty() ? 0.0 : substep;
  impulses_ = std::move(unique);
}

void SoftRestMemory::clear() {
  substep_ = 0.0;
  impulses_.clear();
}

void SoftRestMemory::save(ByteWriter& out) const {
  out.f64(substep_);
  out.u64(impulses_.size());
  for (const SoftRestImpulse& x : impulses_) {
    out.u64(x.body_a);
    out.u64(x.body_b);
    out.u64(x.segment_a);
    out.u64(x.segment_b);
    out.f64(x.normal);
    out.f64(x.tangent);
  }
}

void SoftRestMemory::restore(ByteReader& in, std::span<const RigidBody> bodies) {
  const double substep = in.f64();
  std::vector<SoftRestImpulse> impulses(in.count(48));
  const auto body = [&] {
    const std::uint64_t i = in.u64();
    if (i >= bodies.size()) throw ByteStreamError("a soft-rest impulse of a body past the last");
    return static_cast<std::size_t>(i);
  };
  const auto segment = [&](std::size_t b) {
    const std::uint64_t s = in.u64();
    if (s >= bodies[b].shape().curve().size())
      throw ByteStreamError("a soft-rest impulse of a segment past the body's last");
    return static_cast<std::size_t>(s);
  };
  for (SoftRestImpulse& x : impulses) {
    x.body_a = body();
    x.body_b = body();
    x.segment_a = segment(x.body_a);
    x.segment_b = segment(x.body_b);
    x.normal = in.f64();
    x.tangent = in.f64();
  }
  if (!std::is_sorted(
          impulses.begin(), impulses.end(),
          [](const SoftRestImpulse& x, const SoftRestImpulse& y) { return key_of(x) < key_of(y); }))
    throw ByteStreamError("soft-rest impulses out of order");
  substep_ = substep;
  impulses_ = std::move(impulses);
}

std::vector<std::uint8_t> soft_rest_movers(std::span<const std::uint8_t> moves,
                                           std::span<const ContactManifold> manifolds,
                                           int min_island, double min_band) {
  const std::size_t n = moves.size();
  std::vector<std::uint8_t> soft(moves.begin(), moves.end());
  if (min_island <= 1 && min_band <= 0.0) return soft;
  DisjointSets islands;
  islands.reset(n);
  for (const ContactManifold& m : manifolds) {
    if (m.state() == PairState::kContact && moves[m.body_a] != 0 && moves[m.body_b] != 0)
      islands.unite(m.body_a, m.body_b);
  }
  std::vector<std::size_t> size(n, 0);
  std::vector<std::uint8_t> narrow(n, 0);  // per island root: holds a contact below min_band
  for (std::size_t i = 0; i < n; ++i) {
    if (moves[i] != 0) ++size[islands.root(i)];
  }
  for (const ContactManifold& m : manifolds) {
    if (m.state() != PairState::kContact) continue;
    for (const Contact& c : m.contacts) {
      if (c.lambda_a + c.lambda_b >= min_band) continue;
      if (moves[m.body_a] != 0) narrow[islands.root(m.body_a)] = 1;
      if (moves[m.body_b] != 0) narrow[islands.root(m.body_b)] = 1;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (moves[i] == 0) continue;
    const std::size_t root = islands.root(i);
    if (size[root] < static_cast<std::size_t>(min_island) || narrow[root] != 0) soft[i] = 0;
  }
  return soft;
}

double soft_rest_min_band(const Vec2& gravity, double hertz) {
  const double omega = 2.0 * std::numbers::pi * hertz;
  return 10.0 * gravity.norm() / (omega * omega);
}

SoftRestCounts rest_softly(std::span<RigidBody> bodies, std::span<const std::uint8_t> moves,
                           std::span<const ContactManifold> manifolds, double h,
                           const SoftRestSettings& settings, SoftRestMemory& memory) {
  const int n = std::max(settings.substeps, 1);
  const double hs = h / n;
  // An impulse per substep scales with the substep. One remembered from a much shorter step
  // (a back-off's) says nothing about this one's: only up to twice its substep is carried.
  const double carry =
      memory.substep() > 0.0 && hs <= 2.0 * memory.substep() ? hs / memory.substep() : 0.0;
  thread_local Workspace work;
  SoftRestCounts counts;
  counts.rested = make_rows(bodies, moves, manifolds, settings, memory, carry, work);
  if (work.made.empty()) {
    memory.clear();
    return counts;
  }
  counts.contacts = work.made.size();
  const std::span<Row> rows = order_by_colour(work, moves);
  const std::vector<std::uint8_t>& touched = work.touched;

  const std::size_t nb = bodies.size();
  if (work.movers.size() < nb) work.movers.resize(nb);
  const std::span<Mover> movers(work.movers.data(), nb);
  for (std::size_t i = 0; i < nb; ++i) {
    if (touched[i] == 0) continue;
    Mover& m = movers[i];
    m = Mover{};
    m.velocity = bodies[i].state().velocity;
    m.spin = bodies[i].state().angular_velocity;
    if (moves[i] != 0) {
      m.inv_mass = bodies[i].inverse_mass();
      m.inv_inertia = bodies[i].inverse_inertia();
    }
  }
  // Stiffer than a quarter of the substep's rate, a spring would ring (Box2D caps it so too).
  const double top_hertz = 0.25 / hs;
  const Softness soft = make_soft(std::min(settings.hertz, top_hertz), settings.damping_ratio, hs);
  // Deep in a pile a row carries tens of bodies' weight, which the sweeps carry down slowly; what
  // they let sink past the rest depth only the spring (stiffness m·ω², m the row's effective
  // mass) pushes back, and at `hertz` it pushed too weakly: pairs of the 1,000-body pile crossed
  // at every step and the pile never settled (§8.20). A row that carried a load F last step (its
  // remembered impulse) gets the spring that F alone would sag by kLoadSagShare of the room
  // between its rest depth and the curves touching, where that is stiffer; lighter rows keep
  // `hertz`, whose softness stills rocking bodies.
  for (Row& r : rows) {
    r.soft = soft;
    const double load = r.normal_impulse / hs;  // N
    if (!(load > 0.0)) continue;
    const double omega = std::sqrt(load / (r.normal_mass * kLoadSagShare * r.room));
    const double hertz = omega / (2.0 * std::numbers::pi);
    if (hertz > settings.hertz)
      r.soft = make_soft(std::min(hertz, top_hertz), settings.damping_ratio, hs);
  }
  for (int k = 0; k < n; ++k) {
    for (std::size_t i = 0; i < nb; ++i) {
      if (touched[i] != 0 && moves[i] != 0) movers[i].velocity += hs * settings.gravity;
    }
    for (const Row& r : rows) {
      Mover& a = movers[r.a];
      Mover& b = movers[r.b];
      push(a, b, r.normal, r.normal_arm_a, r.normal_arm_b, r.normal_impulse);
      push(a, b, r.tangent, r.tangent_arm_a, r.tangent_arm_b, r.tangent_impulse);
    }
    sweep(rows, movers, hs, /*biased=*/true);
    for (std::size_t i = 0; i < nb; ++i) {
      if (touched[i] == 0 || moves[i] == 0) continue;
      movers[i].displacement += hs * movers[i].velocity;
      movers[i].turn += hs * movers[i].spin;
    }
    sweep(rows, movers, hs, /*biased=*/false);
  }

  // Only a step about as long as the remembered one replaces it: a short remainder's impulses
  // (an inelastic stop does not shrink with the step) would be scaled up next time, and once
  // blew a body to 8e7 m/s (§8.16).
  if (memory.substep() == 0.0 || hs >= 0.5 * memory.substep()) {
    std::vector<SoftRestImpulse> kept;
    for (const Row& r : rows) {
      if (r.normal_impulse > 0.0)
        kept.push_back({r.a, r.b, r.segment_a, r.segment_b, r.normal_impulse, r.tangent_impulse});
    }
    memory.replace(hs, std::move(kept));
  }
  for (std::size_t i = 0; i < nb; ++i) {
    if (touched[i] == 0 || moves[i] == 0) continue;
    BodyState s = bodies[i].state();
    s.velocity = movers[i].displacement / h - 0.5 * h * settings.gravity;
    s.angular_velocity = movers[i].turn / h;
    bodies[i].set_state(s);
    counts.end.push_back({i, movers[i].velocity, movers[i].spin});
  }
  return counts;
}

}  // namespace rugosim
