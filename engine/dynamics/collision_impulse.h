// The impulse of one collision between two rigid bodies (paper §4.3 "Impulse", eqs. (6)–(12)),
// with the signs of (6)–(7) derived once and consistently (DESIGN.md erratum), a sliding rule
// that is defined for every configuration, and a guard that keeps an impulse from ever adding
// kinetic energy, which Newton's restitution with Coulomb friction alone does not promise.
//
// Conventions (2D, angles and ω counter-clockwise):
//   n     unit normal of B at the contact, pointing from B towards A (Contact::normal);
//   t     = perp(n) = (−n_y, n_x), the tangent of events.csv;
//   r     arm of a body: contact point p minus its centre of mass;
//   u_X   = v_X + ω_X·perp(r_X), the velocity of X's material point at p;
//   u     = u_A − u_B, u_n = u·n, u_t = u·t; the contact is a collision when u_n < 0;
//   J     the impulse on A at p (world); B receives −J. J_n = J·n ≥ 0, J_t = J·t.
//
// Derivation of the collision matrix K (the erratum):
//   The torque impulse of J about A's centre is r_a × J, so Δv_a = J/m_a and
//   Δω_a = cross(r_a, J)/I_a. The paper's (6) writes L⁺ = L − r × J; that sign contradicts its
//   own (7) and is wrong. Since cross(r, J) = perp(r)·J,
//     Δu_A = Δv_a + Δω_a·perp(r_a) = [1/m_a·1 + perp(r_a)·perp(r_a)ᵀ/I_a] J.
//   B receives −J, so Δu_B = −[1/m_b·1 + perp(r_b)·perp(r_b)ᵀ/I_b] J, and Δu = K J with
//     K = (1/m_a + 1/m_b)·1 + perp(r_a)·perp(r_a)ᵀ/I_a + perp(r_b)·perp(r_b)ᵀ/I_b,
//   a sum of positive semi-definite terms with plus signs only (in the plane, −r̃ I⁻¹ r̃ of (7)
//   is exactly perp(r)·perp(r)ᵀ/I). A fixed body has 1/m = 1/I = 0.
//
// Kinetic energy: for A, ½m(v + J/m)² − ½mv² = v·J + ½|J|²/m, and likewise for the spin, so
// summing over both bodies ΔKE = J·u + ½JᵀKJ = ½J·(u + u⁺), with u⁺ = u + KJ.
//
// The impulse (x = 1 + ε; every candidate below satisfies u_n⁺ = −ε u_n):
//   - Sticking (eq. 12): J = −K⁻¹(u + ε u_n n), which makes u_t⁺ = 0; accepted when it lies in
//     the Coulomb cone J_n ≥ 0, |J_t| ≤ μ J_n.
//   - Otherwise sliding. All impulses that satisfy the restitution law lie on a line, and along
//     it u_t⁺ grows affinely with J_t (slope det K / K_nn ≥ 0). So exactly one edge of the cone
//     leaves a slip that its friction opposes: J = J_n (n − μ s t) with s = sign(u_t⁺), the edge
//     nearest the sticking impulse. J_n follows from the restitution law. When the slip keeps its
//     direction, s = sign(u_t) as in the paper's (10); the rule also decides u_t = 0, and μ = 0
//     (both edges are the frictionless impulse).
//   Guaranteed friction rule: friction opposes the slip left after the impulse; it can stop a
//   slip (that is sticking) but never reverses one. The slip after the impulse has the sign
//   opposite to the one before only when the frictionless impulse reverses it too (through the
//   coupling K_nt), and then friction acts against that reversal.
//   - K singular (det K ≈ 0, only when both inverse masses are 0): friction cannot change the
//     slip, so where the rule above needs K⁻¹ the frictionless impulse −(1 + ε) u_n n / K_nn is
//     used.
//   - K_nn = 0 (both bodies fixed, or a rotation-only body pushed through its centre): no
//     impulse can change u_n; the result is a zero impulse flagged `degenerate`.
//
// Energy guard (documented fallback): at ε = 0 every candidate above dissipates (sticking:
// ΔKE = −½wᵀK⁻¹w with w = u + ε u_n n; sliding: (1, −μs) K (1, −μs)ᵀ ≥ 0 bounds it), and ΔKE is
// continuous and piecewise convex-quadratic in ε with at most three pieces (the sticking/sliding
// switches are affine in ε). When Newton + Coulomb would add energy at the given ε, the restitution
// is lowered to the largest ε_eff < ε with ΔKE = 0, found in closed form on its piece; the result
// is flagged `energy_clamped` and reports ε_eff (aimed a relative 1e-9 below the root, so that
// rounding cannot leave a gain). Friction keeps its Coulomb law; only the bounce is reduced. This
// is the smallest change to Newton's law that is energy-safe; it is not Stronge's energetic
// restitution.
#pragma once

#include "engine/core/types.h"

namespace rugosim {

// One body's state at a contact. A fixed body has inverse_mass = inverse_inertia = 0.
struct ContactBodyState {
  double inverse_mass = 0.0;      // 1/kg
  double inverse_inertia = 0.0;   // 1/(kg·m²), about the centre of mass
  Vec2 velocity = Vec2::Zero();   // m/s, of the centre of mass
  double angular_velocity = 0.0;  // rad/s, counter-clockwise
  Vec2 arm = Vec2::Zero();        // m, contact point minus centre of mass (world axes)
};

struct ImpulseResult {
  Vec2 impulse = Vec2::Zero();  // N·s, world, applied to A at the contact (B receives −impulse)
  double jn = 0.0;              // N·s, impulse·n ≥ 0
  double jt = 0.0;              // N·s, impulse·t, t = perp(n)
  double vn = 0.0;              // m/s, u·n before the impulse
  double vt = 0.0;              // m/s, u·t before the impulse
  double restitution = 0.0;     // the ε actually used: the given one unless energy_clamped
  double energy_change = 0.0;   // J, ΔKE = J·(u + ½KJ) ≤ 0
  bool collision = false;       // an impulse was computed: vn < 0 and not degenerate
  bool sticking = false;        // eq. (12) accepted: u_t⁺ = 0, |jt| ≤ μ jn
  bool energy_clamped = false;  // Newton + Coulomb would add energy; ε was lowered
  bool degenerate = false;      // K_nn = 0: no impulse can change vn (e.g. both bodies fixed)
};

// Velocity of the body's material point at the contact: v + ω·perp(r), m/s.
Vec2 contact_point_velocity(const ContactBodyState& body);

// u = u_A − u_B, m/s.
Vec2 relative_contact_velocity(const ContactBodyState& a, const ContactBodyState& b);

// K with Δu = K J (see the derivation above), 1/kg.
Mat2 collision_matrix(const ContactBodyState& a, const ContactBodyState& b);

// ΔKE = J·(u + ½KJ) of applying `impulse` to A (and its opposite to B), J.
double kinetic_energy_change(const Mat2& k, const Vec2& relative_velocity, const Vec2& impulse);

// The collision impulse for unit `normal` (from B towards A), restitution ε ∈ [0, 1] and
// friction μ ≥ 0. A contact that is not approaching (vn ≥ 0) gets a zero impulse with
// collision = false. Throws std::invalid_argument for ε outside [0, 1], μ < 0, a normal that is
// not of unit length, negative inverse masses or inertias, or non-finite input.
ImpulseResult collision_impulse(const ContactBodyState& a, const ContactBodyState& b,
                                const Vec2& normal, double restitution, double friction);

// Applies `impulse` to A at its arm and −impulse to B at its arm (velocities only).
void apply_impulse(const Vec2& impulse, ContactBodyState& a, ContactBodyState& b);

}  // namespace rugosim
