// The time of impact of two convex shapes moving over a step: the first fraction t ∈ [0, 1] of the
// step at which their separation (separation.hpp) comes down to a target, by conservative
// advancement (B. Mirtich, "Impulse-based dynamic simulation of rigid body systems", 1996; the
// form of Bullet's btContinuousConvexCollision), so that a fast body does not pass through a thin
// one between two steps.
//
// The motion. A body moves over the step by a screw motion, its pose at s ∈ [0, 1]
//   g(s) = g₀ exp(s z)   (mechanics/motor.hpp: exp, log),
// z the body-frame screw of the whole step: z = Δt ξ for a body velocity ξ held over the step (the
// integrators' body-frame update g₁ = g₀ exp(Δt ξ), ġ = ½ g ξ: sweep_of), or z = log(g₀* g₁) from
// the poses at the ends (the screw motion turning by at most π: sweep_between). With z = (ω, v),
// dg/ds = g(s) z/2 at every s, so a body point x has the world velocity R(s)(v + ω × x) (per unit
// s), R(s) = R₀ E(s) with E(s) the turn by s|ω| about ω; ω_w = R₀ ω = R(s) ω is fixed in the world.
// Split v = v∥ + v⊥ along and across ω (v∥ = v when ω = 0): R(s) v∥ = R₀ v∥ is constant, and
// v⊥ + ω × x = ω × (x − c) with c = ω × v⊥/|ω|² (the point of the screw axis nearest the origin,
// |c| = |v⊥|/|ω|), whose image R(s)(ω × q) = ω_w × R(s) q has n·(ω_w × q') = q'·(n × ω_w). So for
// any unit n
//   n · R(s)(v + ω × x) ≥ n · R₀ v∥ − |n × ω̂_w| (|v⊥| + |ω| |x|).
// A shape is its core grown by its radius (sphere.hpp), and growing moves no point of the
// boundary by a rotation, so |x| runs over the core only: its reach ρ (ray_cast.hpp: core_reach,
// from the core's support points along ±x, ±y, ±z; 0 for a sphere, whose spin changes nothing).
// A half-space (unbounded) may translate but not turn over the step (static surroundings).
//
// The bound. Let n be the separation's normal at s₀ (from A to B) and d(s₀) the distance. For the
// fixed axis n the gap γ(s) = min_B n·y − max_A n·y is ≤ the signed distance d(s) at every s (the
// distance of convex sets is the largest gap over axes, apart and overlapping), with γ(s₀) = d(s₀).
// Every point's speed along n is bounded as above, so
//   d(s) ≥ γ(s) ≥ d(s₀) − μ (s − s₀),
//   μ = n·(R_A₀ v∥_A − R_B₀ v∥_B) + |n × ω̂_A| (|v⊥_A| + |ω_A| ρ_A) + |n × ω̂_B| (|v⊥_B| + |ω_B| ρ_B).
// Conservative advancement steps s₀ → s₀ + (d(s₀) − target)/μ: d stays ≥ target on the way, so no
// contact is passed over (for two bodies in pure translation the step is Newton's on the convex
// d(s) from the left, and ends in a step or two). μ ≤ 0: they cannot close before the end. Near
// the target each step closes the gap d − target by the ratio of the true rate to μ, so a body
// turning fast (|ω| ρ large against its approach) takes more steps, and one grazing past the other
// crawls along its near miss by steps of (d − target)/μ. Measured, boxes of sizes 0.1–1 m falling
// onto a plane turning by up to ±1 (±2) rad per step about each axis: median 7 (9), 99th
// percentile 26 (51) narrowphase calls, the rare grazing pass a few hundred; max_iterations
// defaults to 64 (as Bullet's continuous convex collision) and the state is then failed with a
// safe t.
//
// The answer: impact {state, t, the separation at t, narrowphase calls}:
//   overlapping  d(0) < 0: they overlap at the start (t = 0);
//   touching     d(t) ≤ target + tolerance, at the first t the advancement reaches (d(t) ≥ target
//                up to the narrowphase's rounding: the true first time d = target is ≥ t); also
//                at t = 0 when 0 ≤ d(0) ≤ target + tolerance;
//   separated    d > target + tolerance over the whole step (t = 1, the separation at the end);
//   failed       no answer within max_iterations (t: the fraction reached, safe to advance to:
//                d ≥ target before it), a non-finite input or separation, a non-positive target
//                or tolerance, or a turning half-space (t = 0).
// A target of a small linear slop (Box2D: 0.005 m, its tolerance a quarter of it) leaves room for
// the solver to see the contact at t without overlap.
//
// Speculative contacts (E. Catto, GDC 2013; Box2D v3): a solver that takes the contact points up to
// a margin m ahead (contact_of(a, pa, b, pb, m), narrowphase.hpp: the points with separation ≤ m)
// and lets each close by at most its separation over the step (v_n ≥ −d/Δt for d > 0) stops two
// bodies at contact without a time of impact when m is at least the distance they can close in
// the step: a point x of a body moves at most |v + ω × x| ≤ |v| + |ω| |x| per unit time (v its
// origin's velocity, ω its angular velocity), so m ≥ (|v_A| + |ω_A| ρ_A + |v_B| + |ω_B| ρ_B) Δt
// (ρ the cores' reaches; |v_A − v_B| Δt in pure translation) is enough. The points kept are those
// of the start of the step, so a large margin also keeps points the bodies never reach (a fast
// body passing by is slowed by them: ghost contacts); a margin of a few slops, and the time of
// impact for the bodies faster than that, avoid both.
#pragma once

#include <limits>
#include <type_traits>

#include "ctga/collision/half_space.hpp"
#include "ctga/collision/narrowphase.hpp"
#include "ctga/collision/ray_cast.hpp"
#include "ctga/collision/separation.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/mechanics/screw.hpp"
#include "ctga/support/math.hpp"

namespace ctga::collision {

// A body's motion over the step: the pose at s ∈ [0, 1] is start · exp(s · motion), motion the
// body-frame screw (ω, v) of the whole step.
template <class T = double>
struct sweep {
    motor<T> start;
    screw<T> motion;
};

// From the poses at the start and the end (unit motors): the screw motion log(g₀* g₁), turning by
// at most π (a body turning farther in a step: sweep_of); equal poses: no motion (exactly zero).
template <class T>
[[nodiscard]] constexpr sweep<T> sweep_between(const motor<T>& g0, const motor<T>& g1) noexcept {
    if (g0 == g1) return {g0, screw<T>{}};
    return {g0, ctga::log(motor<T>(inverse(g0) * g1))};
}
// From the body-frame velocity ξ held over the step Δt: motion Δt ξ (any angle).
template <class T>
[[nodiscard]] constexpr sweep<T> sweep_of(const motor<T>& g0, const screw<T>& xi, const T& dt) noexcept {
    return {g0, screw<T>{dt * xi[0], dt * xi[1], dt * xi[2], dt * xi[3], dt * xi[4], dt * xi[5]}};
}
// The pose's map at s.
template <class T>
[[nodiscard]] constexpr motor_map<T> pose_at(const sweep<T>& w, const T& s) noexcept {
    const screw<T>& z = w.motion;
    return map_of(motor<T>(w.start * ctga::exp(screw<T>{s * z[0], s * z[1], s * z[2], s * z[3], s * z[4], s * z[5]})));
}

enum class impact_state : unsigned char { separated, touching, overlapping, failed };

template <class T = double>
struct impact {
    impact_state state;
    T t;                  // the fraction of the step, in [0, 1]
    separation<T> at;     // the separation at t (A to B)
    int iterations;       // narrowphase calls
};

namespace impact_detail {
// A bound of a body's points' speed along any unit n over the step: n·axial ± |n × axis| spread.
template <class T>
struct speed_bound {
    vec3<T> axial;  // R₀ v∥, world
    vec3<T> axis;   // R₀ ω/|ω|, world (zero when ω = 0)
    T spread;       // |v⊥| + |ω| ρ
};
template <class S, class T>
[[nodiscard]] constexpr speed_bound<T> bound_of(const S& shape, const sweep<T>& w) noexcept {
    const screw<T>& z = w.motion;
    const mat3<T> R = map_of(w.start).R;
    const vec3<T> omega{z[0], z[1], z[2]}, v{z[3], z[4], z[5]};
    const T ww = linear3::dot(omega, omega);
    if (!(ww > T(0))) return {linear3::apply(R, v), {}, T(0)};
    const vec3<T> along = linear3::scale(linear3::dot(v, omega) / ww, omega);
    T reach = std::numeric_limits<T>::infinity();
    if constexpr (!std::is_same_v<S, half_space<T>>) reach = core_reach(shape);
    const T l = math::sqrt(ww);
    return {linear3::apply(R, along), linear3::apply(R, linear3::scale(T(1) / l, omega)), length(linear3::sub(v, along)) + l * reach};
}
// n·(v_A − v_B) over every pair of points is at most this (n from A to B: the rate d falls at).
template <class T>
[[nodiscard]] constexpr T closing(const speed_bound<T>& a, const speed_bound<T>& b, const vec3<T>& n) noexcept {
    const T ra = a.spread > T(0) ? length(linear3::cross(n, a.axis)) * a.spread : T(0);
    const T rb = b.spread > T(0) ? length(linear3::cross(n, b.axis)) * b.spread : T(0);
    return linear3::dot(n, linear3::sub(a.axial, b.axial)) + ra + rb;
}

template <class T>
[[nodiscard]] constexpr bool finite(const sweep<T>& w) noexcept {
    bool ok = true;
    for (std::size_t i = 0; i < 8; ++i) ok = ok && is_finite(w.start[i]);
    for (std::size_t i = 0; i < 6; ++i) ok = ok && is_finite(w.motion[i]);
    return ok;
}

}  // namespace impact_detail

template <class A, class B, class T>
[[nodiscard]] constexpr impact<T> time_of_impact(const A& a, const sweep<T>& wa, const B& b, const sweep<T>& wb, const T& target,
                                                 const T& tolerance, int max_iterations = 64) noexcept {
    using namespace impact_detail;
    impact<T> out{impact_state::failed, T(0), {}, 0};
    if (!finite(wa) || !finite(wb) || !is_finite(target) || !is_finite(tolerance) || !(target > T(0)) || !(tolerance > T(0)))
        return out;
    const speed_bound<T> ba = bound_of(a, wa), bb = bound_of(b, wb);
    if (!(ba.spread + bb.spread < std::numeric_limits<T>::infinity())) return out;  // a turning half-space
    T s = T(0);
    for (int k = 0; k < max_iterations; ++k) {
        const separation<T> now = separation_of(a, pose_at(wa, s), b, pose_at(wb, s));
        out.t = s, out.at = now, out.iterations = k + 1;
        const T d = now.distance;
        if (!is_finite(d)) return out;
        if (k == 0 && d < T(0)) {
            out.state = impact_state::overlapping;
            return out;
        }
        if (d <= target + tolerance) {
            out.state = impact_state::touching;
            return out;
        }
        if (s == T(1)) {
            out.state = impact_state::separated;
            return out;
        }
        const T mu = closing(ba, bb, now.normal);
        const T next = mu > T(0) ? s + (d - target) / mu : T(1);  // μ ≤ 0: they do not close
        s = next < T(1) ? next : T(1);
    }
    out.state = impact_state::failed;
    return out;
}

}  // namespace ctga::collision
