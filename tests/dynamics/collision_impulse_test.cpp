#include "engine/dynamics/collision_impulse.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <Eigen/LU>
#include <gtest/gtest.h>

#include "engine/core/random.h"

namespace rugosim {
namespace {

// A body in the world: the tests compute momenta and energies from these, independently of the
// collision matrix.
struct Body {
  double mass = 0.0;     // kg; 0 means fixed
  double inertia = 0.0;  // kg·m²
  Vec2 centre = Vec2::Zero();
  Vec2 velocity = Vec2::Zero();
  double angular_velocity = 0.0;

  bool fixed() const { return mass == 0.0; }
  ContactBodyState at(const Vec2& point) const {
    ContactBodyState s;
    s.inverse_mass = fixed() ? 0.0 : 1.0 / mass;
    s.inverse_inertia = fixed() ? 0.0 : 1.0 / inertia;
    s.velocity = velocity;
    s.angular_velocity = angular_velocity;
    s.arm = point - centre;
    return s;
  }
  double kinetic_energy() const {
    if (fixed()) return 0.0;
    return 0.5 * mass * velocity.squaredNorm() +
           0.5 * inertia * angular_velocity * angular_velocity;
  }
};

double kinetic_energy(const ContactBodyState& s) {
  double e = 0.0;
  if (s.inverse_mass > 0.0) e += 0.5 * s.velocity.squaredNorm() / s.inverse_mass;
  if (s.inverse_inertia > 0.0)
    e += 0.5 * s.angular_velocity * s.angular_velocity / s.inverse_inertia;
  return e;
}

// One random collision: masses spread over six decades (ratios up to 1e6), radii of gyration and
// arms over two, a random normal flipped so that the contact approaches.
struct Case {
  Body a;
  Body b;
  Vec2 point = Vec2::Zero();
  Vec2 normal = Vec2::UnitY();
  double restitution = 0.0;
  double friction = 0.0;
};

Body random_body(Rng& rng, const Vec2& point) {
  Body body;
  body.mass = std::pow(10.0, rng.uniform(-3.0, 3.0));
  const double gyration = std::pow(10.0, rng.uniform(-1.0, 1.0));
  body.inertia = body.mass * gyration * gyration;
  const double arm_length = std::pow(10.0, rng.uniform(-1.0, 1.0));
  body.centre = point + arm_length * Vec2(rng.normal(), rng.normal()).normalized();
  body.velocity = Vec2(rng.normal(), rng.normal());
  body.angular_velocity = rng.normal();
  return body;
}

Case random_case(Rng& rng, bool allow_fixed) {
  Case c;
  c.point = Vec2(rng.uniform(-10.0, 10.0), rng.uniform(-10.0, 10.0));
  c.a = random_body(rng, c.point);
  c.b = random_body(rng, c.point);
  if (allow_fixed && rng.uniform() < 0.25) c.b = Body{0.0, 0.0, c.b.centre, Vec2::Zero(), 0.0};
  const double angle = rng.uniform(0.0, 2.0 * std::numbers::pi);
  c.normal = Vec2(std::cos(angle), std::sin(angle));
  const Vec2 u = relative_contact_velocity(c.a.at(c.point), c.b.at(c.point));
  if (u.dot(c.normal) > 0.0) c.normal = -c.normal;
  c.restitution = rng.uniform() < 0.1 ? 1.0 : rng.uniform(0.0, 1.0);
  c.friction = rng.uniform() < 0.1 ? 0.0 : rng.uniform(0.0, 2.0);
  return c;
}

// The bodies after the impulse.
struct Outcome {
  ImpulseResult result;
  Body a;
  Body b;
};

Outcome collide(const Case& c) {
  ContactBodyState sa = c.a.at(c.point);
  ContactBodyState sb = c.b.at(c.point);
  Outcome out{collision_impulse(sa, sb, c.normal, c.restitution, c.friction), c.a, c.b};
  apply_impulse(out.result.impulse, sa, sb);
  out.a.velocity = sa.velocity;
  out.a.angular_velocity = sa.angular_velocity;
  out.b.velocity = sb.velocity;
  out.b.angular_velocity = sb.angular_velocity;
  return out;
}

Vec2 linear_momentum(const Body& a, const Body& b) {
  return a.mass * a.velocity + b.mass * b.velocity;
}

double angular_momentum(const Body& a, const Body& b) {  // about the origin
  double l = 0.0;
  for (const Body* body : {&a, &b}) {
    l += body->mass * cross(body->centre, body->velocity) + body->inertia * body->angular_velocity;
  }
  return l;
}

// Plain Newton + Coulomb, written independently with a 2×2 inverse: the sticking impulse (12)
// if it lies in the cone, otherwise the cone edge whose friction opposes the remaining slip.
Vec2 plain_newton_coulomb(const Case& c, bool* sticks = nullptr) {
  const ContactBodyState sa = c.a.at(c.point);
  const ContactBodyState sb = c.b.at(c.point);
  const Mat2 k = collision_matrix(sa, sb);
  const Vec2 u = relative_contact_velocity(sa, sb);
  const Vec2 n = c.normal;
  const Vec2 t = perp(n);
  const double un = u.dot(n);
  const Vec2 stick = -k.inverse() * (u + c.restitution * un * n);
  const bool in_cone = stick.dot(n) >= 0.0 && std::abs(stick.dot(t)) <= c.friction * stick.dot(n);
  if (sticks != nullptr) *sticks = in_cone;
  if (in_cone) return stick;
  for (const double s : {1.0, -1.0}) {
    const Vec2 dir = n - c.friction * s * t;
    const double jn = -(1.0 + c.restitution) * un / n.dot(k * dir);
    if (!(jn > 0.0)) continue;
    const Vec2 j = jn * dir;
    if (s * (u + k * j).dot(t) > 0.0) return j;
  }
  ADD_FAILURE() << "no consistent Newton-Coulomb impulse";
  return Vec2::Zero();
}

TEST(CollisionMatrix, IsTheVelocityResponseToUnitImpulses) {
  Rng rng(1);
  for (int i = 0; i < 1000; ++i) {
    const Case c = random_case(rng, true);
    const ContactBodyState sa = c.a.at(c.point);
    const ContactBodyState sb = c.b.at(c.point);
    const Mat2 k = collision_matrix(sa, sb);
    for (int axis = 0; axis < 2; ++axis) {
      ContactBodyState ta = sa;
      ContactBodyState tb = sb;
      apply_impulse(Vec2::Unit(axis), ta, tb);
      const Vec2 du = relative_contact_velocity(ta, tb) - relative_contact_velocity(sa, sb);
      EXPECT_LE((du - k.col(axis)).norm(), 1e-9 * (1.0 + k.norm()));
    }
    EXPECT_DOUBLE_EQ(k(0, 1), k(1, 0));
    EXPECT_GE(k.trace(), 0.0);
    EXPECT_GE(k.determinant(), -1e-12 * k.squaredNorm());
  }
}

TEST(CollisionMatrix, EnergyChangeFormulaMatchesTheBodies) {
  Rng rng(2);
  for (int i = 0; i < 1000; ++i) {
    const Case c = random_case(rng, false);
    ContactBodyState sa = c.a.at(c.point);
    ContactBodyState sb = c.b.at(c.point);
    const Vec2 j(rng.normal(), rng.normal());
    const double formula =
        kinetic_energy_change(collision_matrix(sa, sb), relative_contact_velocity(sa, sb), j);
    const double before = kinetic_energy(sa) + kinetic_energy(sb);
    apply_impulse(j, sa, sb);
    const double after = kinetic_energy(sa) + kinetic_energy(sb);
    EXPECT_NEAR(after - before, formula, 1e-9 * (before + after));
  }
}

TEST(CollisionImpulse, ConservesLinearAndAngularMomentum) {
  Rng rng(3);
  double worst_linear = 0.0;
  double worst_angular = 0.0;
  for (int i = 0; i < 20000; ++i) {
    const Case c = random_case(rng, false);
    const Outcome out = collide(c);
    ASSERT_TRUE(out.result.collision);
    const double scale_p =
        c.a.mass * c.a.velocity.norm() + c.b.mass * c.b.velocity.norm() + out.result.impulse.norm();
    double scale_l = out.result.impulse.norm() * (1.0 + c.point.norm());
    for (const Body* body : {&c.a, &c.b}) {
      scale_l += body->mass * body->centre.norm() * body->velocity.norm() +
                 body->inertia * std::abs(body->angular_velocity);
    }
    const double dp = (linear_momentum(out.a, out.b) - linear_momentum(c.a, c.b)).norm() / scale_p;
    const double dl =
        std::abs(angular_momentum(out.a, out.b) - angular_momentum(c.a, c.b)) / scale_l;
    worst_linear = std::max(worst_linear, dp);
    worst_angular = std::max(worst_angular, dl);
  }
  std::printf("worst relative momentum error: linear %.3g, angular %.3g\n", worst_linear,
              worst_angular);
  EXPECT_LE(worst_linear, 1e-9);
  EXPECT_LE(worst_angular, 1e-9);
}

TEST(CollisionImpulse, ElasticFrictionlessCollisionsConserveEnergy) {
  Rng rng(4);
  double worst = 0.0;
  for (int i = 0; i < 20000; ++i) {
    Case c = random_case(rng, true);
    c.restitution = 1.0;
    c.friction = 0.0;
    const Outcome out = collide(c);
    const double before = c.a.kinetic_energy() + c.b.kinetic_energy();
    const double after = out.a.kinetic_energy() + out.b.kinetic_energy();
    worst = std::max(worst, std::abs(after - before) / before);
    EXPECT_FALSE(out.result.energy_clamped);
    EXPECT_NEAR(out.result.restitution, 1.0, 0.0);
  }
  std::printf("worst relative energy change (eps = 1, mu = 0): %.3g\n", worst);
  EXPECT_LE(worst, 1e-9);
}

// The energy guard: never a gain, and the fallback exactly where plain Newton + Coulomb gains.
TEST(CollisionImpulse, NeverAddsKineticEnergyAndClampsOnlyWhereNewtonCoulombWould) {
  Rng rng(5);
  int clamped = 0;
  int would_gain = 0;
  int clamped_to_zero = 0;
  int clamped_sliding = 0;
  int clamped_switching = 0;  // lowering ε moved the impulse between sticking and sliding
  int sticking = 0;
  int cases = 0;
  double worst_gain = -std::numeric_limits<double>::infinity();
  double worst_clamped_residual = 0.0;
  for (int i = 0; i < 50000; ++i) {
    const Case c = random_case(rng, true);
    if (c.friction == 0.0 && c.restitution == 1.0) continue;
    ++cases;
    const Outcome out = collide(c);
    const double before = c.a.kinetic_energy() + c.b.kinetic_energy();
    const double change = out.a.kinetic_energy() + out.b.kinetic_energy() - before;
    worst_gain = std::max(worst_gain, change / before);
    ASSERT_LE(change, 1e-12 * before)
        << "case " << i << " ma " << c.a.mass << " ia " << c.a.inertia << " mb " << c.b.mass
        << " ib " << c.b.inertia << " e " << c.restitution << " mu " << c.friction << " stick "
        << out.result.sticking << " clamp " << out.result.energy_clamped << " formula "
        << out.result.energy_change << " vn " << out.result.vn << " vt " << out.result.vt;
    EXPECT_NEAR(change, out.result.energy_change, 1e-9 * before);

    // Plain Newton + Coulomb, applied to copies of the bodies.
    bool plain_sticks = false;
    const Vec2 plain = plain_newton_coulomb(c, &plain_sticks);
    ContactBodyState pa = c.a.at(c.point);
    ContactBodyState pb = c.b.at(c.point);
    apply_impulse(plain, pa, pb);
    const double plain_change = kinetic_energy(pa) + kinetic_energy(pb) - before;
    const double band = 1e-10 * before;  // cases this close to zero may go either way
    if (plain_change > band) ++would_gain;
    if (out.result.energy_clamped) {
      ++clamped;
      if (!out.result.sticking) ++clamped_sliding;
      if (out.result.sticking != plain_sticks) ++clamped_switching;
      EXPECT_GT(plain_change, -band) << "case " << i;
      EXPECT_LT(out.result.restitution, c.restitution);
      EXPECT_GE(out.result.restitution, 0.0);
      // Lowered just enough: the bounce stops where the energy balance reaches zero (aiming a
      // relative 1e-9 of ε below it against rounding), unless even ε = 0 dissipates.
      // ... and no larger ε would do: Newton + Coulomb gains energy all the way above ε_eff.
      for (int step = 1; step <= 16; ++step) {
        Case higher = c;
        const double e_eff = out.result.restitution;
        higher.restitution = e_eff + (c.restitution - e_eff) * step / 16.0;
        ContactBodyState ha = c.a.at(c.point);
        ContactBodyState hb = c.b.at(c.point);
        apply_impulse(plain_newton_coulomb(higher), ha, hb);
        EXPECT_GT(kinetic_energy(ha) + kinetic_energy(hb) - before, -band) << "case " << i;
      }
      if (out.result.restitution > 0.0) {
        worst_clamped_residual = std::max(worst_clamped_residual, std::abs(change) / before);
        EXPECT_LE(std::abs(change), 1e-8 * before) << "case " << i;
      } else {
        ++clamped_to_zero;
      }
    } else {
      EXPECT_LT(plain_change, band) << "case " << i;
      // Unclamped, the impulse is exactly plain Newton + Coulomb.
      EXPECT_LE((out.result.impulse - plain).norm(), 1e-8 * (plain.norm() + 1e-300)) << i;
      if (out.result.sticking) ++sticking;
    }
  }
  std::printf(
      "%d collisions with friction or eps < 1: %d clamped (%d of them sliding, %d switching "
      "mode, %d to eps = 0), "
      "%d where Newton-Coulomb gains energy, %d unclamped sticking; worst dKE/KE %.3g; worst "
      "clamped |dKE|/KE %.3g\n",
      cases, clamped, clamped_sliding, clamped_switching, clamped_to_zero, would_gain, sticking,
      worst_gain, worst_clamped_residual);
  EXPECT_GE(cases, 10000);
  EXPECT_EQ(clamped, would_gain);
  // The random cases do reach the configurations that need the guard, in both modes.
  EXPECT_GT(clamped, 0);
  EXPECT_GT(clamped_sliding, 0);
  EXPECT_GT(clamped_switching, 0);
  EXPECT_GT(sticking, 0);
}

TEST(CollisionImpulse, ObeysNewtonRestitutionAndTheCoulombRule) {
  Rng rng(6);
  int sliding = 0;
  int reversed = 0;
  double worst_normal = 0.0;
  double worst_stick = 0.0;
  for (int i = 0; i < 30000; ++i) {
    const Case c = random_case(rng, true);
    const ContactBodyState sa = c.a.at(c.point);
    const ContactBodyState sb = c.b.at(c.point);
    const ImpulseResult r = collision_impulse(sa, sb, c.normal, c.restitution, c.friction);
    const Mat2 k = collision_matrix(sa, sb);
    const Vec2 n = c.normal;
    const Vec2 t = perp(n);
    const Vec2 u = relative_contact_velocity(sa, sb);
    const Vec2 after = u + k * r.impulse;
    const double scale = u.norm();
    const double jscale = r.impulse.norm();

    EXPECT_NEAR(r.vn, u.dot(n), 1e-15 * scale);
    EXPECT_NEAR(r.vt, u.dot(t), 1e-15 * scale);
    EXPECT_NEAR(r.jn, r.impulse.dot(n), 1e-12 * jscale);
    EXPECT_NEAR(r.jt, r.impulse.dot(t), 1e-12 * jscale);
    EXPECT_GT(r.jn, 0.0);
    if (!r.energy_clamped) {
      EXPECT_EQ(r.restitution, c.restitution);
    }
    const double normal_error = std::abs(after.dot(n) + r.restitution * r.vn) / scale;
    worst_normal = std::max(worst_normal, normal_error);
    EXPECT_LE(normal_error, 1e-9) << "case " << i;
    EXPECT_LE(std::abs(r.jt), c.friction * r.jn * (1.0 + 1e-12) + 1e-15 * jscale);

    const double slip = after.dot(t);
    if (r.sticking) {
      worst_stick = std::max(worst_stick, std::abs(slip) / scale);
      EXPECT_LE(std::abs(slip), 1e-9 * scale) << "case " << i;
    } else {
      ++sliding;
      EXPECT_NEAR(std::abs(r.jt), c.friction * r.jn, 1e-12 * jscale);
      // Friction opposes the slip that remains.
      EXPECT_LE(r.jt * slip, 0.0) << "case " << i;
      // It can stop a slip, never reverse it: a reversal is the normal impulse's doing, and the
      // frictionless impulse reverses it as well.
      if (slip * r.vt < 0.0) {
        ++reversed;
        EXPECT_GE(r.jt * r.vt, 0.0) << "case " << i;
        const Vec2 frictionless = -(1.0 + r.restitution) * r.vn / n.dot(k * n) * n;
        EXPECT_LT((u + k * frictionless).dot(t) * r.vt, 0.0) << "case " << i;
      }
    }
  }
  std::printf(
      "worst |u_n+ + eps u_n|/|u| %.3g, worst sticking |u_t+|/|u| %.3g; %d sliding, "
      "%d reversed by the normal impulse\n",
      worst_normal, worst_stick, sliding, reversed);
  EXPECT_GT(sliding, 1000);
  EXPECT_GT(reversed, 0);
}

ContactBodyState fixed_floor() {
  return ContactBodyState{};
}

TEST(CollisionImpulse, BallReboundsFromAFixedFloorWithTheRestitutionSpeed) {
  for (const double e : {0.0, 0.3, 0.75, 1.0}) {
    ContactBodyState ball;  // a point mass: no rotation
    ball.inverse_mass = 1.0 / 2.5;
    ball.velocity = Vec2(0.0, -4.0);
    ball.arm = Vec2(0.0, -0.1);
    ContactBodyState floor = fixed_floor();
    const ImpulseResult r = collision_impulse(ball, floor, Vec2::UnitY(), e, 0.5);
    apply_impulse(r.impulse, ball, floor);
    EXPECT_NEAR(ball.velocity.y(), 4.0 * e, 1e-14);
    EXPECT_NEAR(ball.velocity.x(), 0.0, 1e-14);
    EXPECT_NEAR(r.jn, 2.5 * 4.0 * (1.0 + e), 1e-12);
    EXPECT_EQ(floor.velocity, Vec2::Zero());
    EXPECT_FALSE(r.energy_clamped);
  }
}

// A disk (I = ½ m R²) hitting a fixed floor while sliding at v0 with no spin. The arm is
// (0, −R), parallel to n, so the normal and tangential problems decouple: J_n = (1 + ε) m v_n,
// and the tangential response of the contact point is 3/m (1/m + R²/I).
struct DiskOnFloor {
  double mass = 2.0;
  double radius = 0.5;
  double v0 = 3.0;  // m/s, along +x
  double vn = 1.0;  // m/s, downwards
  double e = 0.4;

  ContactBodyState disk() const {
    ContactBodyState s;
    s.inverse_mass = 1.0 / mass;
    s.inverse_inertia = 2.0 / (mass * radius * radius);
    s.velocity = Vec2(v0, -vn);
    s.arm = Vec2(0.0, -radius);
    return s;
  }
};

TEST(CollisionImpulse, DiskWithLargeFrictionStartsRollingAtTwoThirdsOfItsSpeed) {
  const DiskOnFloor d;
  ContactBodyState disk = d.disk();
  ContactBodyState floor = fixed_floor();
  const ImpulseResult r = collision_impulse(disk, floor, Vec2::UnitY(), d.e, 5.0);
  apply_impulse(r.impulse, disk, floor);
  EXPECT_TRUE(r.sticking);
  EXPECT_NEAR(disk.velocity.x(), 2.0 / 3.0 * d.v0, 1e-13);
  EXPECT_NEAR(disk.angular_velocity, -2.0 / 3.0 * d.v0 / d.radius, 1e-13);        // clockwise
  EXPECT_NEAR(disk.velocity.x() + disk.angular_velocity * d.radius, 0.0, 1e-13);  // rolling
  EXPECT_NEAR(disk.velocity.y(), d.e * d.vn, 1e-13);
  EXPECT_NEAR(contact_point_velocity(disk).x(), 0.0, 1e-13);
  // t = (−1, 0): friction points along −x, i.e. +t, with magnitude m v0 / 3.
  EXPECT_NEAR(r.jt, d.mass * d.v0 / 3.0, 1e-13);
  EXPECT_NEAR(r.vt, -d.v0, 1e-15);
}

TEST(CollisionImpulse, DiskWithSmallFrictionKeepsSlidingByTheCoulombClosedForm) {
  const DiskOnFloor d;
  const double mu = 0.2;  // sticking would need μ ≥ v0 / (3 (1 + ε) v_n) = 5/7
  ContactBodyState disk = d.disk();
  ContactBodyState floor = fixed_floor();
  const ImpulseResult r = collision_impulse(disk, floor, Vec2::UnitY(), d.e, mu);
  apply_impulse(r.impulse, disk, floor);
  EXPECT_FALSE(r.sticking);
  const double dvn = (1.0 + d.e) * d.vn;
  EXPECT_NEAR(disk.velocity.y(), d.e * d.vn, 1e-13);
  EXPECT_NEAR(disk.velocity.x(), d.v0 - mu * dvn, 1e-13);                 // Δv_t = μ Δv_n
  EXPECT_NEAR(disk.angular_velocity, -2.0 * mu * dvn / d.radius, 1e-13);  // Δω = −2μΔv_n/R
  EXPECT_NEAR(contact_point_velocity(disk).x(), d.v0 - 3.0 * mu * dvn, 1e-13);
  EXPECT_NEAR(r.jt, mu * r.jn, 1e-13);
}

// A rod's end struck while it slides slowly: with μ = 1 Newton's ε = 1 plus sticking would
// leave KE 0.625 J + 0.089 J. The guard lowers ε to the value with ΔKE = 0.
TEST(CollisionImpulse, RodEndThatNewtonRestitutionWouldSpeedUpIsClampedToZeroEnergyChange) {
  ContactBodyState rod;
  rod.inverse_mass = 1.0;
  rod.inverse_inertia = 3.0;
  rod.velocity = Vec2(-0.5, -1.0);
  rod.arm = Vec2(0.8, -0.6);
  ContactBodyState floor = fixed_floor();
  const double before = kinetic_energy(rod);
  const ImpulseResult r = collision_impulse(rod, floor, Vec2::UnitY(), 1.0, 1.0);
  EXPECT_TRUE(r.energy_clamped);
  EXPECT_TRUE(r.sticking);
  EXPECT_GT(r.restitution, 0.0);
  EXPECT_LT(r.restitution, 1.0);
  apply_impulse(r.impulse, rod, floor);
  EXPECT_NEAR(kinetic_energy(rod), before, 1e-8 * before);
  EXPECT_LE(kinetic_energy(rod), before);
  EXPECT_NEAR(contact_point_velocity(rod).y(), -r.restitution * r.vn, 1e-12);
  EXPECT_NEAR(contact_point_velocity(rod).x(), 0.0, 1e-12);

  // Plain sticking Newton with ε = 1, for the record: K⁻¹ in (n, t) is [[0.52, 0.36], [0.36,
  // 0.73]], J = (0.86, 0.355), and ΔKE = −u_n u_t M_nt − ½ u_t² M_tt = 0.18 − 0.09125.
  ContactBodyState plain_rod = rod;
  plain_rod.velocity = Vec2(-0.5, -1.0);
  plain_rod.angular_velocity = 0.0;
  const Vec2 plain(-0.355, 0.86);  // world: J_n n + J_t t with t = (−1, 0)
  apply_impulse(plain, plain_rod, floor);
  EXPECT_NEAR(kinetic_energy(plain_rod) - before, 0.08875, 1e-12);
}

TEST(CollisionImpulse, ZeroTangentialVelocityCanStillSlide) {
  // The same rod with no slip and small μ: the normal impulse alone drives a slip through
  // K_nt, and friction opposes that slip.
  ContactBodyState rod;
  rod.inverse_mass = 1.0;
  rod.inverse_inertia = 3.0;
  rod.velocity = Vec2(0.0, -1.0);
  rod.arm = Vec2(0.8, -0.6);
  ContactBodyState floor = fixed_floor();
  const ImpulseResult r = collision_impulse(rod, floor, Vec2::UnitY(), 0.5, 0.1);
  EXPECT_EQ(r.vt, 0.0);
  EXPECT_FALSE(r.sticking);
  const Vec2 after =
      relative_contact_velocity(rod, floor) + collision_matrix(rod, floor) * r.impulse;
  const double slip = after.dot(perp(Vec2::UnitY()));
  EXPECT_NE(slip, 0.0);
  EXPECT_LT(r.jt * slip, 0.0);
  EXPECT_NEAR(std::abs(r.jt), 0.1 * r.jn, 1e-14);
  EXPECT_LE(r.energy_change, 0.0);
}

TEST(CollisionImpulse, ContactThroughTheCentreActsOnAParticle) {
  ContactBodyState a;
  a.inverse_mass = 0.5;
  a.inverse_inertia = 4.0;
  a.velocity = Vec2(1.0, -2.0);
  a.angular_velocity = 0.0;
  a.arm = Vec2::Zero();
  ContactBodyState floor = fixed_floor();
  const ImpulseResult r = collision_impulse(a, floor, Vec2::UnitY(), 0.5, 10.0);
  apply_impulse(r.impulse, a, floor);
  EXPECT_TRUE(r.sticking);
  EXPECT_NEAR(a.velocity.x(), 0.0, 1e-15);
  EXPECT_NEAR(a.velocity.y(), 1.0, 1e-15);
  EXPECT_EQ(a.angular_velocity, 0.0);  // no lever arm, no spin
}

TEST(CollisionImpulse, BothBodiesFixedGiveAZeroImpulseWithoutNaN) {
  ContactBodyState a = fixed_floor();
  a.velocity = Vec2(0.0, -1.0);  // a moving kinematic body: no finite impulse can change it
  ContactBodyState b = fixed_floor();
  const ImpulseResult r = collision_impulse(a, b, Vec2::UnitY(), 0.5, 0.5);
  EXPECT_TRUE(r.degenerate);
  EXPECT_FALSE(r.collision);
  EXPECT_EQ(r.impulse, Vec2::Zero());
  EXPECT_EQ(r.vn, -1.0);
}

TEST(CollisionImpulse, SingularCollisionMatrixGivesAFiniteImpulse) {
  // A wheel pinned at its centre (infinite mass, finite inertia) against a fixed body:
  // K = perp(r)perp(r)ᵀ/I has rank one, so no impulse can set both u_n and u_t.
  Rng rng(7);
  for (int i = 0; i < 2000; ++i) {
    ContactBodyState wheel;
    wheel.inverse_inertia = std::pow(10.0, rng.uniform(-2.0, 2.0));
    wheel.angular_velocity = rng.normal();
    wheel.arm = Vec2(rng.normal(), rng.normal());
    ContactBodyState b = fixed_floor();
    const double angle = rng.uniform(0.0, 2.0 * std::numbers::pi);
    Vec2 n(std::cos(angle), std::sin(angle));
    if (relative_contact_velocity(wheel, b).dot(n) > 0.0) n = -n;
    const double e = rng.uniform();
    const double mu = rng.uniform(0.0, 2.0);
    const ImpulseResult r = collision_impulse(wheel, b, n, e, mu);
    ASSERT_TRUE(r.impulse.allFinite());
    const double before = kinetic_energy(wheel);
    apply_impulse(r.impulse, wheel, b);
    ASSERT_TRUE(std::isfinite(wheel.angular_velocity));
    EXPECT_LE(kinetic_energy(wheel), before * (1.0 + 1e-12));
    EXPECT_NEAR(contact_point_velocity(wheel).dot(n), -r.restitution * r.vn, 1e-9 * std::abs(r.vn));
  }
}

TEST(CollisionImpulse, SeparatingContactGetsNoImpulse) {
  ContactBodyState a;
  a.inverse_mass = 1.0;
  a.inverse_inertia = 1.0;
  a.velocity = Vec2(1.0, 0.5);
  const ImpulseResult r = collision_impulse(a, fixed_floor(), Vec2::UnitY(), 0.5, 0.5);
  EXPECT_FALSE(r.collision);
  EXPECT_EQ(r.impulse, Vec2::Zero());
  EXPECT_EQ(r.vn, 0.5);
  EXPECT_EQ(r.vt, -1.0);
}

TEST(CollisionImpulse, RejectsInvalidArguments) {
  ContactBodyState a;
  a.inverse_mass = 1.0;
  a.velocity = Vec2(0.0, -1.0);
  const ContactBodyState b = fixed_floor();
  EXPECT_THROW(collision_impulse(a, b, Vec2::UnitY(), 1.5, 0.5), std::invalid_argument);
  EXPECT_THROW(collision_impulse(a, b, Vec2::UnitY(), -0.1, 0.5), std::invalid_argument);
  EXPECT_THROW(collision_impulse(a, b, Vec2::UnitY(), 0.5, -1.0), std::invalid_argument);
  EXPECT_THROW(collision_impulse(a, b, Vec2(0.0, 2.0), 0.5, 0.5), std::invalid_argument);
  ContactBodyState bad = a;
  bad.inverse_mass = -1.0;
  EXPECT_THROW(collision_impulse(bad, b, Vec2::UnitY(), 0.5, 0.5), std::invalid_argument);
  bad = a;
  bad.velocity.x() = std::nan("");
  EXPECT_THROW(collision_impulse(bad, b, Vec2::UnitY(), 0.5, 0.5), std::invalid_argument);
}

}  // namespace
}  // namespace rugosim
