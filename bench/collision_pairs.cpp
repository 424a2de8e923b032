// The pair rows of ctga_collision_bench (collision_bench.hpp): one narrowphase query per call on one
// of 64 pose pairs in memory, cycling, in ctga and, when CMake found them, FCL 0.7 and Bullet 3.24
// (double precision):
//   collision_<pair>/<implementation>  the signed distance with its normal and witness points, what
//                                      a physics engine asks of each pair each step
//   contact_<pair>/<implementation>    the contact manifold (margin 0: the overlapping points)
//   collision_<pair>/bullet_algorithm  Bullet's own algorithm for the pair (sphere_sphere, sphere_box,
//                                      capsule_capsule: the closed forms its dispatcher picks)
// for pair = sphere_sphere, sphere_box, capsule_capsule, box_box, box_half_space (contact rows:
// box_box and box_half_space), and the peers' side of hull_hull and sphere_mesh (their ctga rows
// come with ctga's hulls and meshes: the marked places in register_hull_hull, register_sphere_mesh).
//
// Poses: 32 separated (gap 0.005–0.25 m) and 32 overlapping (depth 0.005–0.1 m) in a random order,
// shapes 0.2–1 m across (sphere radius 0.1–0.5, capsule radius 0.1–0.25 and half height 0.1–0.4,
// box half extents 0.1–0.5), uniform random rotations, B moved along a random direction from A until
// ctga's distance is the drawn target (bisection; only the placement, not the answer); the same
// poses for every implementation.
// Each row carries Google Benchmark counters, from a check of every pose before timing:
//   max_err     max |distance − exact| over the poses the row answers (contact rows: the deepest
//               point's separation over the overlapping poses; a separated pose must give no point)
//   normal_err  max |n − n_exact| (the normal from A to B), over the poses where the row gives one
//   answered    the poses with a distance, when not all 64
//   points      contact rows: mean points per query
// exact: closed forms in long double written here (spheres, sphere–box, capsules by the closest
// points of the two segments, box–half-space, sphere–triangle mesh) and, for box–box and hulls,
// collision_ref::signed_distance (tests/support/collision_reference.hpp: the brute-force long-double
// reference). A row further than 1e-6 from them (distance or normal) is printed on stderr at start.
//
// How the peers are called (conventions converted to ctga's: distance < 0 overlapping, normal A → B):
// FCL: fcl::distance(geometry, tf, geometry, tf) with DistanceRequest(enable_nearest_points = true,
//   enable_signed_distance = true) and its default solver (GST_LIBCCD: libccd's GJK, EPA when they
//   overlap) on Sphered, Boxd (full side lengths), Capsuled (the segment's full length); FCL gives
//   no normal, so n = (p_B − p_A)/distance from its nearest points. box–half-space: FCL's distance
//   has no half-space support (libccd has no support function for it: a null pointer, FCL issues
//   383 and 623), so fcl::collide(CollisionRequest(1 contact, enable_contact)): penetration depth and
//   normal (o1 → o2) when they overlap, nothing when apart (answered 32). Contact rows:
//   fcl::collide with up to 4 contacts (deepest: the largest penetration_depth).
// Bullet: shapes with no margin of their own: btBoxShape and btConvexHullShape setMargin(0) (the
//   geometry is the box, not a box grown by 0.04); btSphereShape and btCapsuleShapeZ (height = 2h)
//   are their point and segment with the radius as margin, which is their geometry. Distance rows:
//   btGjkPairDetector with a btVoronoiSimplexSolver and a btGjkEpaPenetrationDepthSolver (made once
//   per row; the detector per query, as btConvexConvexAlgorithm does) into a Result that keeps the
//   deepest point: distance, normalOnB (from B to A: n = −normalOnB). box–box: btBoxBoxDetector
//   (ODE's dBoxBox, Bullet's box–box algorithm) reports only overlapping boxes (a manifold of up to
//   4 points, the distance its deepest), so a pair it leaves without points goes on to
//   btGjkPairDetector for its distance. box–half-space: btStaticPlaneShape is concave, not a
//   btConvexShape, so not for btGjkPairDetector: btConvexPlaneCollisionAlgorithm::processCollision
//   (Bullet's convex–plane algorithm, no perturbation) into a result that keeps the point, with a
//   manifold whose breaking threshold is BT_LARGE_FLOAT so that it reports separated boxes too.
//   bullet_algorithm rows: btSphereSphereCollisionAlgorithm, btSphereBoxCollisionAlgorithm and
//   btConvexConvexAlgorithm (its capsule–capsule case), processCollision into the same kind of result.
//   Contact rows: btBoxBoxDetector into a Result collecting its points; the convex–plane algorithm
//   with Bullet's setPlaneConvexMultipointIterations() defaults (3 perturbations while fewer than 3
//   points) into a btManifoldResult and a btPersistentManifold cleared per query, breaking threshold
//   1e-9 (margin 0, as ctga's row).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>

#include <ctga/collision/box.hpp>
#include <ctga/collision/capsule.hpp>
#include <ctga/collision/half_space.hpp>
#include <ctga/collision/hull.hpp>
#include <ctga/collision/mesh.hpp>
#include <ctga/collision/narrowphase.hpp>
#include <ctga/collision/sphere.hpp>

#include "collision_bench.hpp"
#include "support/collision_reference.hpp"

#ifdef CTGA_BENCH_FCL
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/geometry/shape/halfspace.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>
#endif
#ifdef CTGA_BENCH_BULLET
#include <btBulletCollisionCommon.h>
#include <BulletCollision/CollisionDispatch/btBoxBoxDetector.h>
#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <BulletCollision/CollisionDispatch/btConvexConvexAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btConvexPlaneCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>
#include <BulletCollision/CollisionDispatch/btSphereBoxCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btSphereSphereCollisionAlgorithm.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>
#endif

namespace bench::collision {
namespace {

namespace co = ctga::collision;
using map = ctga::motor_map<double>;
using v3 = ctga::vec3<double>;
using m3 = ctga::mat3<double>;
using real = long double;
using rv3 = std::array<real, 3>;

constexpr std::size_t poses = 64;

// ---- random draws: own uniforms, one draw per statement (argument order differs by compiler) ----

struct draws {
    std::mt19937_64 rng;
    explicit draws(std::uint64_t seed) : rng(seed) {}
    double uniform() { return std::ldexp(static_cast<double>(rng() >> 11), -53); }  // [0, 1)
    double in(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    v3 direction() {
        const double z = in(-1, 1);
        const double phi = in(0, 2 * std::numbers::pi);
        const double s = std::sqrt(1 - z * z);
        return {s * std::cos(phi), s * std::sin(phi), z};
    }
    v3 point(double half) {
        const double x = in(-half, half);
        const double y = in(-half, half);
        const double z = in(-half, half);
        return {x, y, z};
    }
    // uniform rotation (Shoemake's quaternion)
    m3 rotation() {
        const double u1 = uniform();
        const double u2 = uniform();
        const double u3 = uniform();
        const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
        const double x = a * std::sin(2 * std::numbers::pi * u2), y = a * std::cos(2 * std::numbers::pi * u2);
        const double z = b * std::sin(2 * std::numbers::pi * u3), w = b * std::cos(2 * std::numbers::pi * u3);
        return {{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                 {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                 {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
    }
};

// The targets: 32 gaps in [0.005, 0.25] m and 32 depths in [0.005, 0.1] m (negative), shuffled.
std::array<double, poses> targets(draws& d) {
    std::array<double, poses> t{};
    for (std::size_t i = 0; i < poses; ++i) t[i] = i < poses / 2 ? d.in(0.005, 0.25) : -d.in(0.005, 0.1);
    for (std::size_t i = poses - 1; i > 0; --i) std::swap(t[i], t[static_cast<std::size_t>(d.rng() % (i + 1))]);
    return t;
}

v3 add_scaled(const v3& a, double s, const v3& u) { return {a[0] + s * u[0], a[1] + s * u[1], a[2] + s * u[2]}; }

// B (rotation Rb) moved from A's origin along u until ctga's distance is `target` (bisection; the
// distance grows along the ray, which starts at the centre of the centrally symmetric A − B).
template <class A, class B>
map placed(const A& a, const map& pa, const B& b, const m3& Rb, const v3& u, double target) {
    double lo = 0, hi = 4;
    for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
        const double mid = (lo + hi) / 2;
        if (co::separation_of(a, pa, b, map{Rb, add_scaled(pa.t, mid, u)}).distance < target) lo = mid;
        else hi = mid;
    }
    return {Rb, add_scaled(pa.t, (lo + hi) / 2, u)};
}

// ---- the exact answers, long double ----------------------------------------------------------

struct exact {
    real distance;
    rv3 normal;  // unit, from A to B
};

rv3 lift(const v3& x) { return {x[0], x[1], x[2]}; }
rv3 sub(const rv3& a, const rv3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
rv3 add(const rv3& a, const rv3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
rv3 scale(real s, const rv3& a) { return {s * a[0], s * a[1], s * a[2]}; }
real dot(const rv3& a, const rv3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
rv3 cross(const rv3& a, const rv3& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
real norm(const rv3& a) { return std::sqrt(dot(a, a)); }
rv3 column(const map& p, std::size_t i) { return {p.R[0][i], p.R[1][i], p.R[2][i]}; }
rv3 to_world(const map& p, const rv3& x) {  // R x + t
    rv3 out = lift(p.t);
    for (std::size_t i = 0; i < 3; ++i) out = add(out, scale(x[i], column(p, i)));
    return out;
}
rv3 to_body(const map& p, const rv3& x) {  // Rᵀ (x − t)
    const rv3 d = sub(x, lift(p.t));
    return {dot(column(p, 0), d), dot(column(p, 1), d), dot(column(p, 2), d)};
}
// two balls (centres a, b, radii): the closest-point form
exact balls(const rv3& a, real ra, const rv3& b, real rb) {
    const rv3 d = sub(b, a);
    const real l = norm(d);
    return {l - ra - rb, scale(1 / l, d)};
}

exact exact_of(const co::sphere<double>& a, const map& pa, const co::sphere<double>& b, const map& pb) {
    return balls(lift(pa.t), a.radius, lift(pb.t), b.radius);
}

// sphere A, box B: the centre in the box's frame; outside, the box's closest point is the clamped
// centre; inside, the nearest face.
exact exact_of(const co::sphere<double>& a, const map& pa, const co::box<double>& b, const map& pb) {
    const rv3 c = to_body(pb, lift(pa.t));
    rv3 q = c;
    bool inside = true;
    for (std::size_t i = 0; i < 3; ++i) {
        const real h = b.half[i];
        if (c[i] > h) q[i] = h, inside = false;
        else if (c[i] < -h) q[i] = -h, inside = false;
    }
    if (!inside) return balls(lift(pa.t), a.radius, to_world(pb, q), 0);
    std::size_t k = 0;
    for (std::size_t i = 1; i < 3; ++i)
        if (b.half[i] - std::abs(c[i]) < b.half[k] - std::abs(c[k])) k = i;
    const real side = c[k] < 0 ? -1 : 1;
    return {-(b.half[k] - std::abs(c[k]) + a.radius), scale(-side, column(pb, k))};  // B's face normal reversed: A → B
}

// The closest points of segments P(s) = p0 + s d1, Q(t) = q0 + t d2 on [0, 1]²: the minimum of the
// convex quadratic |P − Q|² is its stationary point when inside the square, else on an edge, where
// the 1-D minimiser is the clamped one; every candidate is evaluated and the least kept.
std::pair<rv3, rv3> closest_on_segments(const rv3& p0, const rv3& d1, const rv3& q0, const rv3& d2) {
    const rv3 r = sub(p0, q0);
    const real a = dot(d1, d1), b = dot(d1, d2), e = dot(d2, d2), c = dot(d1, r), f = dot(d2, r);
    const auto clamp01 = [](real x) { return x < 0 ? real(0) : x > 1 ? real(1) : x; };
    std::vector<std::pair<real, real>> cand;
    const real det = a * e - b * b;
    if (det > 0) {
        const real s = (b * f - c * e) / det, t = (a * f - b * c) / det;
        if (s >= 0 && s <= 1 && t >= 0 && t <= 1) cand.push_back({s, t});
    }
    for (real s : {real(0), real(1)}) cand.push_back({s, clamp01((b * s + f) / e)});
    for (real t : {real(0), real(1)}) cand.push_back({clamp01((b * t - c) / a), t});
    std::pair<rv3, rv3> best{};
    real best_d = -1;
    for (const auto& [s, t] : cand) {
        const rv3 P = add(p0, scale(s, d1)), Q = add(q0, scale(t, d2));
        const real d = dot(sub(Q, P), sub(Q, P));
        if (best_d < 0 || d < best_d) best = {P, Q}, best_d = d;
    }
    return best;
}

exact exact_of(const co::capsule<double>& a, const map& pa, const co::capsule<double>& b, const map& pb) {
    const rv3 za = scale(a.half_height, column(pa, 2)), zb = scale(b.half_height, column(pb, 2));
    const auto [p, q] = closest_on_segments(sub(lift(pa.t), za), scale(2, za), sub(lift(pb.t), zb), scale(2, zb));
    return balls(p, a.radius, q, b.radius);
}

// box A, half-space B (z ≤ 0 in its frame): the box's corner lowest along the plane's normal n.
exact exact_of(const co::box<double>& a, const map& pa, const co::half_space<double>&, const map& pb) {
    const rv3 n = column(pb, 2);
    rv3 s = lift(pa.t);
    for (std::size_t i = 0; i < 3; ++i) {
        const rv3 e = column(pa, i);
        s = add(s, scale(dot(n, e) > 0 ? -real(a.half[i]) : real(a.half[i]), e));
    }
    return {dot(n, sub(s, lift(pb.t))), scale(-1, n)};
}

collision_ref::pose ref_pose(const map& p) {
    collision_ref::pose out{};
    for (std::size_t i = 0; i < 3; ++i) {
        for (std::size_t j = 0; j < 3; ++j) out.R[i][j] = p.R[i][j];
        out.t[i] = p.t[i];
    }
    return out;
}

exact exact_of(const co::box<double>& a, const map& pa, const co::box<double>& b, const map& pb) {
    const collision_ref::distance_result r = collision_ref::signed_distance(collision_ref::box{lift(a.half)}, ref_pose(pa),
                                                                            collision_ref::box{lift(b.half)}, ref_pose(pb));
    return {r.distance, r.normal};
}

// ---- a row's check: its answers against the exact ones ------------------------------------

struct answer {
    bool has_distance = false;  // a distance (contact rows: at least one point)
    double distance = 0;        // contact rows: the deepest point's separation
    bool has_normal = false;
    v3 normal{};  // from A to B
    int points = 0;
};

struct accuracy {
    double max_err = 0, normal_err = 0, points = 0;
    int answered = 0, with_normal = 0;
    bool contact = false;
};

const char* kind(const exact& e) { return e.distance > 0 ? "separated" : "overlapping"; }

accuracy assess(const std::string& row, const std::vector<exact>& ex, const std::vector<answer>& got, bool contact) {
    accuracy acc;
    acc.contact = contact;
    int far = 0, far_normal = 0, missing_sep = 0, missing_ovl = 0, spurious = 0;
    std::size_t worst = 0, worst_normal = 0;
    double worst_normal_err = 0;
    for (std::size_t i = 0; i < ex.size(); ++i) {
        const answer& g = got[i];
        acc.points += g.points;
        if (contact && ex[i].distance > 0) {  // a separated pair: no point at margin 0
            if (g.has_distance) ++spurious;
            continue;
        }
        if (!g.has_distance) {
            ++(ex[i].distance > 0 ? missing_sep : missing_ovl);
            continue;
        }
        ++acc.answered;
        const double err = static_cast<double>(std::abs(g.distance - ex[i].distance));
        if (err > 1e-6) ++far;
        if (acc.answered == 1 || err > acc.max_err) acc.max_err = err, worst = i;
        if (g.has_normal) {
            ++acc.with_normal;
            const rv3 d = sub(lift(g.normal), ex[i].normal);
            const double ne = static_cast<double>(norm(d));
            if (ne > 1e-6) ++far_normal;
            if (ne > worst_normal_err || acc.with_normal == 1) worst_normal_err = ne, worst_normal = i;
        }
    }
    acc.normal_err = worst_normal_err;
    acc.points /= static_cast<double>(ex.size());
    const int n = static_cast<int>(ex.size());
    if (far > 0)
        std::fprintf(stderr,
                     "ctga_collision_bench: %s: distance off the exact one by more than 1e-6 at %d of %d poses (worst: pose %zu, %s, "
                     "%.9f against %.9Lf, error %.1e)\n",
                     row.c_str(), far, acc.answered, worst, kind(ex[worst]), got[worst].distance, ex[worst].distance, acc.max_err);
    if (far_normal > 0)
        std::fprintf(stderr,
                     "ctga_collision_bench: %s: normal off the exact one by more than 1e-6 at %d of %d poses (worst: pose %zu, %s, "
                     "|n - n_exact| = %.1e)\n",
                     row.c_str(), far_normal, acc.with_normal, worst_normal, kind(ex[worst_normal]), worst_normal_err);
    if (missing_sep + missing_ovl > 0)
        std::fprintf(stderr, "ctga_collision_bench: %s: no distance at %d of %d poses (%d separated, %d overlapping)\n", row.c_str(),
                     missing_sep + missing_ovl, n, missing_sep, missing_ovl);
    if (spurious > 0)
        std::fprintf(stderr, "ctga_collision_bench: %s: contact points for %d separated poses (margin 0: none expected)\n", row.c_str(),
                     spurious);
    return acc;
}

// Registers a row: `query(k)` answers pose k (one call, its result kept by DoNotOptimize).
template <class Query>
void add_row(const std::string& name, Query query, const accuracy& acc) {
    benchmark::RegisterBenchmark(name.c_str(), [query, acc](benchmark::State& st) {
        std::size_t k = 0;
        for (auto _ : st) {
            query(k);
            k = (k + 1) % poses;
        }
        st.counters["max_err"] = acc.max_err;
        if (acc.with_normal > 0) st.counters["normal_err"] = acc.normal_err;
        if (!acc.contact && acc.answered != static_cast<int>(poses)) st.counters["answered"] = acc.answered;
        if (acc.contact) st.counters["points"] = acc.points;
    });
}

// ---- the pose sets -----------------------------------------------------------------------

template <class A, class B>
struct pair_set {
    std::vector<A> a;
    std::vector<B> b;
    std::vector<map> pa, pb;
    std::vector<exact> ex;
};

// Shapes drawn by draw_a, draw_b; A at a random place, B placed at the target distance.
template <class A, class B, class DrawA, class DrawB>
std::shared_ptr<const pair_set<A, B>> make_set(std::uint64_t seed, DrawA draw_a, DrawB draw_b) {
    draws d(seed);
    const std::array<double, poses> t = targets(d);
    auto s = std::make_shared<pair_set<A, B>>();
    for (std::size_t i = 0; i < poses; ++i) {
        const A a = draw_a(d);
        const B b = draw_b(d);
        const m3 Ra = d.rotation();
        const v3 ta = d.point(2);
        const m3 Rb = d.rotation();
        const v3 u = d.direction();
        const map pa{Ra, ta};
        const map pb = placed(a, pa, b, Rb, u, t[i]);
        s->a.push_back(a);
        s->b.push_back(b);
        s->pa.push_back(pa);
        s->pb.push_back(pb);
        s->ex.push_back(exact_of(a, pa, b, pb));
    }
    return s;
}

co::sphere<double> draw_sphere(draws& d) { return {d.in(0.1, 0.5)}; }
co::capsule<double> draw_capsule(draws& d) {
    const double r = d.in(0.1, 0.25);
    const double h = d.in(0.1, 0.4);
    return {r, h};
}
co::box<double> draw_box(draws& d) {
    const double x = d.in(0.1, 0.5);
    const double y = d.in(0.1, 0.5);
    const double z = d.in(0.1, 0.5);
    return {{x, y, z}};
}

// A box on a tilted half-space: the plane's pose at random, the box over a random point of the
// plane at the target distance (its centre n·(t − o) = target + its extent along n).
std::shared_ptr<const pair_set<co::box<double>, co::half_space<double>>> make_box_half_space(std::uint64_t seed) {
    draws d(seed);
    const std::array<double, poses> t = targets(d);
    auto s = std::make_shared<pair_set<co::box<double>, co::half_space<double>>>();
    for (std::size_t i = 0; i < poses; ++i) {
        const co::box<double> a = draw_box(d);
        const m3 Rp = d.rotation();
        const v3 tp = d.point(2);
        const m3 Ra = d.rotation();
        const double x = d.in(-1, 1);
        const double y = d.in(-1, 1);
        const map pp{Rp, tp};
        const v3 e1{Rp[0][0], Rp[1][0], Rp[2][0]}, e2{Rp[0][1], Rp[1][1], Rp[2][1]}, n{Rp[0][2], Rp[1][2], Rp[2][2]};
        double extent = 0;
        for (std::size_t k = 0; k < 3; ++k) extent += a.half[k] * std::abs(n[0] * Ra[0][k] + n[1] * Ra[1][k] + n[2] * Ra[2][k]);
        const map pa{Ra, add_scaled(add_scaled(add_scaled(tp, x, e1), y, e2), t[i] + extent, n)};
        s->a.push_back(a);
        s->b.push_back({});
        s->pa.push_back(pa);
        s->pb.push_back(pp);
        s->ex.push_back(exact_of(a, pa, co::half_space<double>{}, pp));
    }
    return s;
}

// ---- ctga ----------------------------------------------------------------------------------

template <class A, class B>
[[gnu::noinline]] co::separation<double> ctga_separation(const A& a, const map& pa, const B& b, const map& pb) {
    return co::separation_of(a, pa, b, pb);
}
template <class A, class B>
[[gnu::noinline]] co::manifold<double> ctga_contact(const A& a, const map& pa, const B& b, const map& pb) {
    return co::contact_of(a, pa, b, pb, 0.0);
}

template <class A, class B>
void add_ctga(const std::string& pair, const std::shared_ptr<const pair_set<A, B>>& s) {
    std::vector<answer> got;
    for (std::size_t k = 0; k < poses; ++k) {
        const co::separation<double> r = co::separation_of(s->a[k], s->pa[k], s->b[k], s->pb[k]);
        got.push_back({true, r.distance, true, r.normal, 0});
    }
    const std::string name = "collision_" + pair + "/ctga";
    add_row(name, [s](std::size_t k) {
        co::separation<double> r = ctga_separation(s->a[k], s->pa[k], s->b[k], s->pb[k]);
        benchmark::DoNotOptimize(r);
    }, assess(name, s->ex, got, false));
}

template <class A, class B>
void add_ctga_contact(const std::string& pair, const std::shared_ptr<const pair_set<A, B>>& s) {
    std::vector<answer> got;
    for (std::size_t k = 0; k < poses; ++k) {
        const co::manifold<double> m = co::contact_of(s->a[k], s->pa[k], s->b[k], s->pb[k], 0.0);
        answer g;
        g.points = static_cast<int>(m.count);
        for (std::size_t i = 0; i < m.count; ++i)
            if (i == 0 || m.points[i].separation < g.distance) g.distance = m.points[i].separation;
        g.has_distance = g.has_normal = m.count > 0;
        g.normal = m.normal;
        got.push_back(g);
    }
    const std::string name = "contact_" + pair + "/ctga";
    add_row(name, [s](std::size_t k) {
        co::manifold<double> m = ctga_contact(s->a[k], s->pa[k], s->b[k], s->pb[k]);
        benchmark::DoNotOptimize(m);
    }, assess(name, s->ex, got, true));
}

// ---- FCL -----------------------------------------------------------------------------------
#ifdef CTGA_BENCH_FCL
using fcl_geometry = std::unique_ptr<fcl::CollisionGeometryd>;

fcl::Transform3d fcl_pose(const map& p) {
    fcl::Transform3d tf = fcl::Transform3d::Identity();
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) tf.linear()(i, j) = p.R[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
        tf.translation()(i) = p.t[static_cast<std::size_t>(i)];
    }
    return tf;
}
fcl_geometry fcl_shape(const co::sphere<double>& x) { return std::make_unique<fcl::Sphered>(x.radius); }
fcl_geometry fcl_shape(const co::box<double>& x) { return std::make_unique<fcl::Boxd>(2 * x.half[0], 2 * x.half[1], 2 * x.half[2]); }
fcl_geometry fcl_shape(const co::capsule<double>& x) { return std::make_unique<fcl::Capsuled>(x.radius, 2 * x.half_height); }
fcl_geometry fcl_shape(const co::half_space<double>&) { return std::make_unique<fcl::Halfspaced>(fcl::Vector3d(0, 0, 1), 0.0); }
v3 from_fcl(const fcl::Vector3d& x) { return {x[0], x[1], x[2]}; }

struct fcl_set {
    std::vector<fcl_geometry> a, b;
    std::vector<fcl::Transform3d> ta, tb;
};
template <class A, class B>
std::shared_ptr<fcl_set> to_fcl(const pair_set<A, B>& s) {
    auto f = std::make_shared<fcl_set>();
    for (std::size_t k = 0; k < poses; ++k) {
        f->a.push_back(fcl_shape(s.a[k]));
        f->b.push_back(fcl_shape(s.b[k]));
        f->ta.push_back(fcl_pose(s.pa[k]));
        f->tb.push_back(fcl_pose(s.pb[k]));
    }
    return f;
}

const fcl::DistanceRequestd fcl_signed_request(true, true);  // nearest points, signed; GST_LIBCCD

[[gnu::noinline]] double fcl_distance(const fcl_set& f, std::size_t k, fcl::DistanceResultd& r) {
    r.clear();
    return fcl::distance(f.a[k].get(), f.ta[k], f.b[k].get(), f.tb[k], fcl_signed_request, r);
}
[[gnu::noinline]] std::size_t fcl_collide(const fcl_set& f, std::size_t k, const fcl::CollisionRequestd& q, fcl::CollisionResultd& r) {
    r.clear();
    return fcl::collide(f.a[k].get(), f.ta[k], f.b[k].get(), f.tb[k], q, r);
}

// FCL's distance: n = (p_B − p_A)/distance from its nearest points (it gives no normal).
answer from_fcl_distance(const fcl::DistanceResultd& r, bool a_first = true) {
    answer g;
    g.has_distance = true;
    g.distance = r.min_distance;
    const v3 pa = from_fcl(r.nearest_points[a_first ? 0 : 1]), pb = from_fcl(r.nearest_points[a_first ? 1 : 0]);
    const v3 d{pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
    const double l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (l > 0 && g.distance != 0) {
        const double s = (g.distance > 0 ? 1 : -1) / l;
        g.has_normal = true;
        g.normal = {s * d[0], s * d[1], s * d[2]};
    }
    return g;
}
// FCL's collide: the deepest contact (normal from o1 to o2).
answer from_fcl_contacts(const fcl::CollisionResultd& r) {
    answer g;
    g.points = static_cast<int>(r.numContacts());
    for (std::size_t i = 0; i < r.numContacts(); ++i) {
        const fcl::Contactd& c = r.getContact(i);
        if (!g.has_distance || -c.penetration_depth < g.distance) {
            g.has_distance = g.has_normal = true;
            g.distance = -c.penetration_depth;
            g.normal = from_fcl(c.normal);
        }
    }
    return g;
}

template <class A, class B>
void add_fcl(const std::string& pair, const std::shared_ptr<const pair_set<A, B>>& s) {
    const std::shared_ptr<const fcl_set> f = to_fcl(*s);
    std::vector<answer> got;
    for (std::size_t k = 0; k < poses; ++k) {
        fcl::DistanceResultd r;
        fcl_distance(*f, k, r);
        got.push_back(from_fcl_distance(r));
    }
    const std::string name = "collision_" + pair + "/fcl";
    add_row(name, [f](std::size_t k) {
        fcl::DistanceResultd r;
        benchmark::DoNotOptimize(fcl_distance(*f, k, r));
        benchmark::DoNotOptimize(r);
    }, assess(name, s->ex, got, false));
}

// fcl::collide with enable_contact: `contacts` at most (box–half-space distance row: 1; contact rows: 4).
template <class A, class B>
void add_fcl_collide(const std::string& name, const std::shared_ptr<const pair_set<A, B>>& s, std::size_t contacts, bool contact_row) {
    const std::shared_ptr<const fcl_set> f = to_fcl(*s);
    const fcl::CollisionRequestd q(contacts, true);
    std::vector<answer> got;
    for (std::size_t k = 0; k < poses; ++k) {
        fcl::CollisionResultd r;
        fcl_collide(*f, k, q, r);
        got.push_back(from_fcl_contacts(r));
    }
    add_row(name, [f, q](std::size_t k) {
        fcl::CollisionResultd r;
        benchmark::DoNotOptimize(fcl_collide(*f, k, q, r));
        benchmark::DoNotOptimize(r);
    }, assess(name, s->ex, got, contact_row));
}
#endif

// ---- Bullet --------------------------------------------------------------------------------
#ifdef CTGA_BENCH_BULLET
using bt_shape = std::unique_ptr<btConvexShape>;

btTransform bt_pose(const map& p) {
    const m3& R = p.R;
    return btTransform(btMatrix3x3(R[0][0], R[0][1], R[0][2], R[1][0], R[1][1], R[1][2], R[2][0], R[2][1], R[2][2]),
                       btVector3(p.t[0], p.t[1], p.t[2]));
}
v3 from_bt(const btVector3& x) { return {x.x(), x.y(), x.z()}; }
bt_shape bt_convex(const co::sphere<double>& x) { return std::make_unique<btSphereShape>(x.radius); }
bt_shape bt_convex(const co::capsule<double>& x) { return std::make_unique<btCapsuleShapeZ>(x.radius, 2 * x.half_height); }
bt_shape bt_convex(const co::box<double>& x) {
    auto b = std::make_unique<btBoxShape>(btVector3(x.half[0], x.half[1], x.half[2]));
    b->setMargin(0);  // the box itself (the default 0.04 rounds its edges and corners)
    return b;
}

// Bullet's Result: the deepest point (normalOnB from B to A, the point on B, the signed distance)
// and the count of points.
struct bt_points : btDiscreteCollisionDetectorInterface::Result {
    int count = 0;
    btScalar distance = BT_LARGE_FLOAT;
    btVector3 normal_on_b{0, 0, 0}, point_on_b{0, 0, 0};
    void setShapeIdentifiersA(int, int) override {}
    void setShapeIdentifiersB(int, int) override {}
    void addContactPoint(const btVector3& normalOnBInWorld, const btVector3& pointInWorld, btScalar depth) override {
        ++count;
        if (depth < distance) distance = depth, normal_on_b = normalOnBInWorld, point_on_b = pointInWorld;
    }
};
answer from_bt(const bt_points& r) {
    answer g;
    g.points = r.count;
    if (r.count > 0) {
        g.has_distance = g.has_normal = true;
        g.distance = r.distance;
        g.normal = from_bt(-r.normal_on_b);  // ctga: from A to B
    }
    return g;
}

struct bt_set {
    std::vector<bt_shape> a, b;
    std::vector<btTransform> ta, tb;
    btVoronoiSimplexSolver simplex;  // made once per row, as a collision configuration holds them
    btGjkEpaPenetrationDepthSolver epa;
};
template <class A, class B>
std::shared_ptr<bt_set> to_bt(const pair_set<A, B>& s) {
    auto f = std::make_shared<bt_set>();
    for (std::size_t k = 0; k < poses; ++k) {
        f->a.push_back(bt_convex(s.a[k]));
        f->b.push_back(bt_convex(s.b[k]));
        f->ta.push_back(bt_pose(s.pa[k]));
        f->tb.push_back(bt_pose(s.pb[k]));
    }
    return f;
}

void bt_gjk(bt_set& f, std::size_t k, bt_points& out) {
    btGjkPairDetector detector(f.a[k].get(), f.b[k].get(), &f.simplex, &f.epa);
    btDiscreteCollisionDetectorInterface::ClosestPointInput input;
    input.m_transformA = f.ta[k];
    input.m_transformB = f.tb[k];
    detector.getClosestPoints(input, out, nullptr);
}
[[gnu::noinline]] void bt_gjk_query(bt_set& f, std::size_t k, bt_points& out) { bt_gjk(f, k, out); }

// box–box: btBoxBoxDetector; when it reports nothing (the boxes are apart), GJK for the distance.
void bt_box_box(bt_set& f, std::size_t k, bt_points& out) {
    btBoxBoxDetector detector(static_cast<const btBoxShape*>(f.a[k].get()), static_cast<const btBoxShape*>(f.b[k].get()));
    btDiscreteCollisionDetectorInterface::ClosestPointInput input;
    input.m_transformA = f.ta[k];
    input.m_transformB = f.tb[k];
    detector.getClosestPoints(input, out, nullptr);
}
[[gnu::noinline]] void bt_box_box_distance(bt_set& f, std::size_t k, bt_points& out) {
    bt_box_box(f, k, out);
    if (out.count == 0) bt_gjk(f, k, out);
}
[[gnu::noinline]] void bt_box_box_contact(bt_set& f, std::size_t k, bt_points& out) { bt_box_box(f, k, out); }

enum class bt_query { gjk, box_box_distance, box_box_contact };

template <bt_query Q, class A, class B>
void add_bt(const std::string& name, const std::shared_ptr<const pair_set<A, B>>& s) {
    const std::shared_ptr<bt_set> f = to_bt(*s);
    const auto query = [](bt_set& set, std::size_t k, bt_points& out) {
        if constexpr (Q == bt_query::gjk) bt_gjk_query(set, k, out);
        else if constexpr (Q == bt_query::box_box_distance) bt_box_box_distance(set, k, out);
        else bt_box_box_contact(set, k, out);
    };
    std::vector<answer> got;
    for (std::size_t k = 0; k < poses; ++k) {
        bt_points r;
        query(*f, k, r);
        got.push_back(from_bt(r));
    }
    add_row(name, [f, query](std::size_t k) {
        bt_points r;
        query(*f, k, r);
        benchmark::DoNotOptimize(r);
    }, assess(name, s->ex, got, Q == bt_query::box_box_contact));
}

// Bullet's own algorithm for the pair, the one its dispatcher picks (btDefaultCollisionConfiguration):
// btSphereSphereCollisionAlgorithm, btSphereBoxCollisionAlgorithm (closed forms), and for capsules
// btConvexConvexAlgorithm, whose capsule–capsule case is a closed form too (capsuleCapsuleDistance).
// processCollision (made once per row, on our manifold: breaking threshold BT_LARGE_FLOAT, and the
// result's closest-point threshold BT_LARGE_FLOAT, so that separated pairs are reported) into a
// result that keeps the point, as for the half-space below.
struct bt_deepest_result : btManifoldResult {  // the point, no manifold bookkeeping
    bt_points points;
    bt_deepest_result(const btCollisionObjectWrapper* a, const btCollisionObjectWrapper* b) : btManifoldResult(a, b) {}
    void addContactPoint(const btVector3& normalOnBInWorld, const btVector3& pointInWorld, btScalar depth) override {
        points.addContactPoint(normalOnBInWorld, pointInWorld, depth);
    }
};
struct bt_algorithm_set {
    std::shared_ptr<bt_set> shapes;
    btCollisionObject object;  // (the wrappers' object; nothing here reads it)
    btPersistentManifold manifold;
    btDispatcherInfo info;
    std::unique_ptr<btCollisionAlgorithm> algorithm;
};
[[gnu::noinline]] void bt_pair_algorithm(bt_algorithm_set& f, std::size_t k, bt_points& out) {
    btCollisionObjectWrapper wa(nullptr, f.shapes->a[k].get(), &f.object, f.shapes->ta[k], -1, -1);
    btCollisionObjectWrapper wb(nullptr, f.shapes->b[k].get(), &f.object, f.shapes->tb[k], -1, -1);
    bt_deepest_result r(&wa, &wb);
    r.m_closestPointDistanceThreshold = BT_LARGE_FLOAT;
    f.algorithm->processCollision(&wa, &wb, f.info, &r);
    out = r.points;
}
// make(manifold, construction info, wrapper A, wrapper B, shapes): the algorithm
template <class A, class B, class Make>
void add_bt_algorithm(const std::string& pair, const std::shared_ptr<const pair_set<A, B>>& s, Make make) {
    auto f = std::make_shared<bt_algorithm_set>();
    f->shapes = to_bt(*s);
    f->manifold.setContactBreakingThreshold(BT_LARGE_FLOAT);
    btCollisionAlgorithmConstructionInfo ci;
    btCollisionObjectWrapper wa(nullptr, f->shapes->a[0].get(), &f->object, f->shapes->ta[0], -1, -1);
    btCollisionObjectWrapper wb(nullptr, f->shapes->b[0].get(), &f->object, f->shapes->tb[0], -1, -1);
    f->algorithm = make(&f->manifold, ci, &wa, &wb, *f->shapes);
    std::vector<answer> got;
    for (std::size_t k = 0; k < poses; ++k) {
        bt_points r;
        bt_pair_algorithm(*f, k, r);
        got.push_back(from_bt(r));
    }
    const std::string name = "collision_" + pair + "/bullet_algorithm";
    add_row(name, [f](std::size_t k) {
        bt_points r;
        bt_pair_algorithm(*f, k, r);
        benchmark::DoNotOptimize(r);
    }, assess(name, s->ex, got, false));
}

// box–half-space: btConvexPlaneCollisionAlgorithm::processCollision on the box (body 0) and a
// btStaticPlaneShape z = 0 (body 1) posed like ctga's half-space.
struct bt_plane_set {
    std::vector<std::unique_ptr<btBoxShape>> box;
    std::vector<btTransform> tbox, tplane;
    std::vector<std::unique_ptr<btCollisionObject>> obox, oplane;  // (what a btManifoldResult reads)
    btStaticPlaneShape plane{btVector3(0, 0, 1), 0};
    btCollisionObject dummy;
    btPersistentManifold manifold;
    btDispatcherInfo info;
    std::unique_ptr<btConvexPlaneCollisionAlgorithm> algorithm;
};
std::shared_ptr<bt_plane_set> to_bt_plane(const pair_set<co::box<double>, co::half_space<double>>& s, bool contact) {
    auto f = std::make_shared<bt_plane_set>();
    for (std::size_t k = 0; k < poses; ++k) {
        auto b = std::make_unique<btBoxShape>(btVector3(s.a[k].half[0], s.a[k].half[1], s.a[k].half[2]));
        b->setMargin(0);
        f->box.push_back(std::move(b));
        f->tbox.push_back(bt_pose(s.pa[k]));
        f->tplane.push_back(bt_pose(s.pb[k]));
        f->obox.push_back(std::make_unique<btCollisionObject>());
        f->obox.back()->setCollisionShape(f->box.back().get());
        f->obox.back()->setWorldTransform(f->tbox.back());
        f->oplane.push_back(std::make_unique<btCollisionObject>());
        f->oplane.back()->setCollisionShape(&f->plane);
        f->oplane.back()->setWorldTransform(f->tplane.back());
    }
    // distance: every pair reported (breaking threshold BT_LARGE_FLOAT), no perturbation (Bullet's
    // CreateFunc defaults: 1 iteration below 0 points); contact: margin 0, Bullet's multipoint defaults
    f->manifold.setContactBreakingThreshold(contact ? btScalar(1e-9) : btScalar(BT_LARGE_FLOAT));
    btCollisionAlgorithmConstructionInfo ci;
    btCollisionObjectWrapper wa(nullptr, f->box[0].get(), &f->dummy, f->tbox[0], -1, -1);
    btCollisionObjectWrapper wb(nullptr, &f->plane, &f->dummy, f->tplane[0], -1, -1);
    f->algorithm = std::make_unique<btConvexPlaneCollisionAlgorithm>(&f->manifold, ci, &wa, &wb, false, contact ? 3 : 1, contact ? 3 : 0);
    return f;
}
[[gnu::noinline]] void bt_box_plane_distance(bt_plane_set& f, std::size_t k, bt_points& out) {
    btCollisionObjectWrapper wa(nullptr, f.box[k].get(), f.obox[k].get(), f.tbox[k], -1, -1);
    btCollisionObjectWrapper wb(nullptr, &f.plane, f.oplane[k].get(), f.tplane[k], -1, -1);
    bt_deepest_result r(&wa, &wb);
    f.algorithm->processCollision(&wa, &wb, f.info, &r);
    out = r.points;
}
[[gnu::noinline]] int bt_box_plane_contact(bt_plane_set& f, std::size_t k) {
    btCollisionObjectWrapper wa(nullptr, f.box[k].get(), f.obox[k].get(), f.tbox[k], -1, -1);
    btCollisionObjectWrapper wb(nullptr, &f.plane, f.oplane[k].get(), f.tplane[k], -1, -1);
    f.manifold.setBodies(f.obox[k].get(), f.oplane[k].get());
    f.manifold.clearManifold();
    btManifoldResult r(&wa, &wb);
    f.algorithm->processCollision(&wa, &wb, f.info, &r);
    return f.manifold.getNumContacts();
}

void add_bt_box_half_space(const std::shared_ptr<const pair_set<co::box<double>, co::half_space<double>>>& s) {
    {
        const std::shared_ptr<bt_plane_set> f = to_bt_plane(*s, false);
        std::vector<answer> got;
        for (std::size_t k = 0; k < poses; ++k) {
            bt_points r;
            bt_box_plane_distance(*f, k, r);
            got.push_back(from_bt(r));
        }
        const std::string name = "collision_box_half_space/bullet";
        add_row(name, [f](std::size_t k) {
            bt_points r;
            bt_box_plane_distance(*f, k, r);
            benchmark::DoNotOptimize(r);
        }, assess(name, s->ex, got, false));
    }
    {
        const std::shared_ptr<bt_plane_set> f = to_bt_plane(*s, true);
        std::vector<answer> got;
        for (std::size_t k = 0; k < poses; ++k) {
            bt_points r;
            const int n = bt_box_plane_contact(*f, k);
            for (int i = 0; i < n; ++i) {
                const btManifoldPoint& p = f->manifold.getContactPoint(i);
                r.addContactPoint(p.m_normalWorldOnB, p.m_positionWorldOnB, p.getDistance());
            }
            got.push_back(from_bt(r));
        }
        const std::string name = "contact_box_half_space/bullet";
        add_row(name, [f](std::size_t k) { benchmark::DoNotOptimize(bt_box_plane_contact(*f, k)); }, assess(name, s->ex, got, true));
    }
}
#endif

// ---- the pair kinds ------------------------------------------------------------------------

template <class A, class B>
void add_distance_rows(const std::string& pair, const std::shared_ptr<const pair_set<A, B>>& s) {
    add_ctga(pair, s);
#ifdef CTGA_BENCH_FCL
    add_fcl(pair, s);
#endif
#ifdef CTGA_BENCH_BULLET
    add_bt<bt_query::gjk>("collision_" + pair + "/bullet", s);
#endif
}

void register_sphere_sphere() {
    const auto s = make_set<co::sphere<double>, co::sphere<double>>(0xc011'0001, draw_sphere, draw_sphere);
    add_distance_rows("sphere_sphere", s);
#ifdef CTGA_BENCH_BULLET
    add_bt_algorithm("sphere_sphere", s, [](btPersistentManifold* m, const btCollisionAlgorithmConstructionInfo& ci, auto* wa, auto* wb, bt_set&) {
        return std::make_unique<btSphereSphereCollisionAlgorithm>(m, ci, wa, wb);
    });
#endif
}
void register_sphere_box() {
    const auto s = make_set<co::sphere<double>, co::box<double>>(0xc011'0002, draw_sphere, draw_box);
    add_distance_rows("sphere_box", s);
#ifdef CTGA_BENCH_BULLET
    add_bt_algorithm("sphere_box", s, [](btPersistentManifold* m, const btCollisionAlgorithmConstructionInfo& ci, auto* wa, auto* wb, bt_set&) {
        return std::make_unique<btSphereBoxCollisionAlgorithm>(m, ci, wa, wb, false);  // (the sphere is body 0)
    });
#endif
}
void register_capsule_capsule() {
    const auto s = make_set<co::capsule<double>, co::capsule<double>>(0xc011'0003, draw_capsule, draw_capsule);
    add_distance_rows("capsule_capsule", s);
#ifdef CTGA_BENCH_BULLET
    add_bt_algorithm("capsule_capsule", s, [](btPersistentManifold* m, const btCollisionAlgorithmConstructionInfo& ci, auto* wa, auto* wb, bt_set& shapes) {
        // (btConvexConvexAlgorithm::CreateFunc's defaults: no perturbation, 3 points)
        return std::make_unique<btConvexConvexAlgorithm>(m, ci, wa, wb, &shapes.epa, 0, 3);
    });
#endif
}
void register_box_box() {
    const auto s = make_set<co::box<double>, co::box<double>>(0xc011'0004, draw_box, draw_box);
    add_ctga("box_box", s);
    add_ctga_contact("box_box", s);
#ifdef CTGA_BENCH_FCL
    add_fcl("box_box", s);
    add_fcl_collide("contact_box_box/fcl", s, 4, true);
#endif
#ifdef CTGA_BENCH_BULLET
    add_bt<bt_query::box_box_distance>("collision_box_box/bullet", s);
    add_bt<bt_query::box_box_contact>("contact_box_box/bullet", s);
#endif
}
void register_box_half_space() {
    const auto s = make_box_half_space(0xc011'0005);
    add_ctga("box_half_space", s);
    add_ctga_contact("box_half_space", s);
#ifdef CTGA_BENCH_FCL
    add_fcl_collide("collision_box_half_space/fcl", s, 1, false);  // (fcl::distance: no half-space support)
    add_fcl_collide("contact_box_half_space/fcl", s, 4, true);
#endif
#ifdef CTGA_BENCH_BULLET
    add_bt_box_half_space(s);
#endif
}

// ---- hull_hull: convex hulls of 20–30 points ---------------------------------------------
// The points: on an ellipsoid (semi-axes 0.15–0.5 m) at random directions, so every point is a
// vertex of the hull and (in general position) every face a triangle, found here by brute force
// (the triples whose plane has every other point on one side), oriented outward for FCL.
struct hull_shape {
    std::vector<v3> points;
    std::vector<std::array<int, 3>> faces;  // counter-clockwise seen from outside
};
hull_shape draw_hull(draws& d) {
    const std::size_t n = 20 + static_cast<std::size_t>(d.rng() % 11);
    const double ax = d.in(0.15, 0.5);
    const double ay = d.in(0.15, 0.5);
    const double az = d.in(0.15, 0.5);
    hull_shape h;
    for (std::size_t i = 0; i < n; ++i) {
        const v3 u = d.direction();
        h.points.push_back({ax * u[0], ay * u[1], az * u[2]});
    }
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j)
            for (std::size_t k = j + 1; k < n; ++k) {
                const rv3 a = lift(h.points[i]), nrm = cross(sub(lift(h.points[j]), a), sub(lift(h.points[k]), a));
                int above = 0, below = 0;
                for (std::size_t m = 0; m < n; ++m) {
                    if (m == i || m == j || m == k) continue;
                    const real s = dot(nrm, sub(lift(h.points[m]), a));
                    above += s > 0;
                    below += s < 0;
                }
                if (above == 0) h.faces.push_back({static_cast<int>(i), static_cast<int>(j), static_cast<int>(k)});
                else if (below == 0) h.faces.push_back({static_cast<int>(i), static_cast<int>(k), static_cast<int>(j)});
            }
    if (h.faces.size() != 2 * n - 4)
        std::fprintf(stderr, "ctga_collision_bench: hull of %zu points with %zu faces (expected %zu: not in general position)\n", n,
                     h.faces.size(), 2 * n - 4);
    return h;
}
collision_ref::hull ref_hull(const hull_shape& h) {
    collision_ref::hull out;
    for (const v3& p : h.points) out.points.push_back(lift(p));
    return out;
}
exact exact_of(const hull_shape& a, const map& pa, const hull_shape& b, const map& pb) {
    const collision_ref::distance_result r = collision_ref::signed_distance(ref_hull(a), ref_pose(pa), ref_hull(b), ref_pose(pb));
    return {r.distance, r.normal};
}
// B placed along u at the target gap between the hulls' extents along u (a lower bound of the
// distance: separated targets are separated; an overlapping one is kept only if the exact distance
// says so, else drawn again).
std::shared_ptr<const pair_set<hull_shape, hull_shape>> make_hull_hull(std::uint64_t seed) {
    draws d(seed);
    const std::array<double, poses> t = targets(d);
    auto s = std::make_shared<pair_set<hull_shape, hull_shape>>();
    for (std::size_t i = 0; i < poses; ++i) {
        for (int attempt = 0;; ++attempt) {
            hull_shape a = draw_hull(d);
            hull_shape b = draw_hull(d);
            const m3 Ra = d.rotation();
            const v3 ta = d.point(2);
            const m3 Rb = d.rotation();
            const v3 u = d.direction();
            const auto extent = [&u](const hull_shape& h, const m3& R, double sign) {
                double e = -1e300;
                for (const v3& p : h.points) {
                    double x = 0;
                    for (std::size_t r = 0; r < 3; ++r) x += sign * u[r] * (R[r][0] * p[0] + R[r][1] * p[1] + R[r][2] * p[2]);
                    e = std::max(e, x);
                }
                return e;
            };
            const map pa{Ra, ta};
            const map pb{Rb, add_scaled(ta, t[i] + extent(a, Ra, 1) + extent(b, Rb, -1), u)};
            const exact e = exact_of(a, pa, b, pb);
            if ((e.distance > 0) == (t[i] > 0) || attempt == 20) {
                s->a.push_back(std::move(a));
                s->b.push_back(std::move(b));
                s->pa.push_back(pa);
                s->pb.push_back(pb);
                s->ex.push_back(e);
                break;
            }
        }
    }
    return s;
}

void register_hull_hull() {
    const auto s = make_hull_hull(0xc011'0006);
    {
        // ctga: the hulls of the same points (hull.hpp, capacity 32), GJK apart and EPA overlapping
        using hull = co::convex_hull<double, 32>;
        auto c = std::make_shared<pair_set<hull, hull>>();
        for (std::size_t k = 0; k < poses; ++k) {
            c->a.push_back(*co::make_hull<32, double>(s->a[k].points));
            c->b.push_back(*co::make_hull<32, double>(s->b[k].points));
        }
        c->pa = s->pa, c->pb = s->pb, c->ex = s->ex;
        add_ctga("hull_hull", std::shared_ptr<const pair_set<hull, hull>>(c));
    }
#ifdef CTGA_BENCH_FCL
    {
        // fcl::Convexd from the points and the triangular faces ([3, i, j, k] each); FCL's distance
        // as for the primitives (libccd GJK, EPA overlapping)
        auto f = std::make_shared<fcl_set>();
        const auto convex = [](const hull_shape& h) {
            auto vertices = std::make_shared<std::vector<fcl::Vector3d>>();
            for (const v3& p : h.points) vertices->emplace_back(p[0], p[1], p[2]);
            auto faces = std::make_shared<std::vector<int>>();
            for (const auto& fc : h.faces) faces->insert(faces->end(), {3, fc[0], fc[1], fc[2]});
            return std::make_unique<fcl::Convexd>(vertices, static_cast<int>(h.faces.size()), faces);
        };
        for (std::size_t k = 0; k < poses; ++k) {
            f->a.push_back(convex(s->a[k]));
            f->b.push_back(convex(s->b[k]));
            f->ta.push_back(fcl_pose(s->pa[k]));
            f->tb.push_back(fcl_pose(s->pb[k]));
        }
        std::vector<answer> got;
        for (std::size_t k = 0; k < poses; ++k) {
            fcl::DistanceResultd r;
            fcl_distance(*f, k, r);
            got.push_back(from_fcl_distance(r));
        }
        const std::string name = "collision_hull_hull/fcl";
        add_row(name, [f](std::size_t k) {
            fcl::DistanceResultd r;
            benchmark::DoNotOptimize(fcl_distance(*f, k, r));
            benchmark::DoNotOptimize(r);
        }, assess(name, s->ex, got, false));
    }
#endif
#ifdef CTGA_BENCH_BULLET
    {
        // btConvexHullShape of the points, margin 0; btGjkPairDetector as for the primitives
        auto f = std::make_shared<bt_set>();
        const auto convex = [](const hull_shape& h) {
            std::vector<btVector3> points;
            for (const v3& p : h.points) points.emplace_back(p[0], p[1], p[2]);
            auto c = std::make_unique<btConvexHullShape>(&points[0].x(), static_cast<int>(points.size()), static_cast<int>(sizeof(btVector3)));
            c->setMargin(0);
            return c;
        };
        for (std::size_t k = 0; k < poses; ++k) {
            f->a.push_back(convex(s->a[k]));
            f->b.push_back(convex(s->b[k]));
            f->ta.push_back(bt_pose(s->pa[k]));
            f->tb.push_back(bt_pose(s->pb[k]));
        }
        std::vector<answer> got;
        for (std::size_t k = 0; k < poses; ++k) {
            bt_points r;
            bt_gjk_query(*f, k, r);
            got.push_back(from_bt(r));
        }
        const std::string name = "collision_hull_hull/bullet";
        add_row(name, [f](std::size_t k) {
            bt_points r;
            bt_gjk_query(*f, k, r);
            benchmark::DoNotOptimize(r);
        }, assess(name, s->ex, got, false));
    }
#endif
    (void)s;
}

// ---- sphere_mesh: a sphere on a triangle-mesh terrain ------------------------------------
// The terrain: a height field over [−4, 4]² m, 32 × 32 cells of two triangles (2,048 triangles,
// 1,089 vertices), z = 0.25 sin(0.9x + 0.3) cos(0.7y) + 0.1 sin(1.9x − 1.3y) (slopes below 0.5).
// The spheres (radius 0.15–0.5) above it, centres over [−3, 3]², at the target distance (the
// mesh's closest point: min over the triangles of the centre's distance, less the radius; the
// centre stays above the surface, so an overlap's depth is the radius less that distance).
struct terrain {
    std::vector<v3> vertices;
    std::vector<std::array<int, 3>> triangles;
};
terrain make_terrain() {
    constexpr int cells = 32;
    terrain t;
    for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i) {
            const double x = -4 + 8.0 * i / cells, y = -4 + 8.0 * j / cells;
            t.vertices.push_back({x, y, 0.25 * std::sin(0.9 * x + 0.3) * std::cos(0.7 * y) + 0.1 * std::sin(1.9 * x - 1.3 * y)});
        }
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            const int v = j * (cells + 1) + i;  // counter-clockwise from above (normals up)
            t.triangles.push_back({v, v + 1, v + cells + 2});
            t.triangles.push_back({v, v + cells + 2, v + cells + 1});
        }
    return t;
}
// The terrain's height at (x, y): the linear interpolation on the cell's triangle below it.
double height_at(const terrain& t, double x, double y) {
    constexpr int cells = 32;
    const double u = (x + 4) / 8 * cells, w = (y + 4) / 8 * cells;
    const int i = std::clamp(static_cast<int>(u), 0, cells - 1), j = std::clamp(static_cast<int>(w), 0, cells - 1);
    const double fx = u - i, fy = w - j;
    const auto z = [&t](int v) { return t.vertices[static_cast<std::size_t>(v)][2]; };
    const int v = j * (cells + 1) + i;
    const double z00 = z(v), z10 = z(v + 1), z01 = z(v + cells + 1), z11 = z(v + cells + 2);
    return fx >= fy ? z00 + fx * (z10 - z00) + fy * (z11 - z10) : z00 + fy * (z01 - z00) + fx * (z11 - z01);
}
// The closest point of triangle abc to p: the foot on the plane when inside, else the nearest of
// the three edges' clamped projections. Templated: double for the placement, long double exact.
template <class R>
std::array<R, 3> closest_on_triangle(const std::array<R, 3>& p, const std::array<R, 3>& a, const std::array<R, 3>& b,
                                     const std::array<R, 3>& c) {
    using V = std::array<R, 3>;
    const auto sb = [](const V& x, const V& y) { return V{x[0] - y[0], x[1] - y[1], x[2] - y[2]}; };
    const auto dt = [](const V& x, const V& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
    const auto cr = [](const V& x, const V& y) { return V{x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]}; };
    const V n = cr(sb(b, a), sb(c, a));
    const R h = dt(sb(p, a), n) / dt(n, n);
    const V q{p[0] - h * n[0], p[1] - h * n[1], p[2] - h * n[2]};
    if (dt(cr(sb(b, a), sb(q, a)), n) >= 0 && dt(cr(sb(c, b), sb(q, b)), n) >= 0 && dt(cr(sb(a, c), sb(q, c)), n) >= 0) return q;
    V best{};
    R best_d = -1;
    for (const auto& [u, v] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
        const V e = sb(v, u);
        R s = dt(sb(p, u), e) / dt(e, e);
        s = s < 0 ? R(0) : s > 1 ? R(1) : s;
        const V x{u[0] + s * e[0], u[1] + s * e[1], u[2] + s * e[2]};
        const R d = dt(sb(p, x), sb(p, x));
        if (best_d < 0 || d < best_d) best = x, best_d = d;
    }
    return best;
}
template <class R>
std::array<R, 3> closest_on_terrain(const terrain& t, const std::array<R, 3>& p) {
    std::array<R, 3> best{};
    R best_d = -1;
    const auto at = [&t](int i) {
        const v3& x = t.vertices[static_cast<std::size_t>(i)];
        return std::array<R, 3>{x[0], x[1], x[2]};
    };
    for (const auto& tr : t.triangles) {
        const std::array<R, 3> q = closest_on_triangle<R>(p, at(tr[0]), at(tr[1]), at(tr[2]));
        const R d = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]);
        if (best_d < 0 || d < best_d) best = q, best_d = d;
    }
    return best;
}

struct sphere_mesh_set {
    terrain mesh;
    std::vector<co::sphere<double>> sphere;
    std::vector<map> pose;  // the spheres' (the terrain's is the identity)
    std::vector<exact> ex;  // A the sphere, B the terrain
};
std::shared_ptr<const sphere_mesh_set> make_sphere_mesh(std::uint64_t seed) {
    draws d(seed);
    const std::array<double, poses> t = targets(d);
    auto s = std::make_shared<sphere_mesh_set>();
    s->mesh = make_terrain();
    for (std::size_t i = 0; i < poses; ++i) {
        const double r = d.in(0.15, 0.5);
        const double x = d.in(-3, 3);
        const double y = d.in(-3, 3);
        const m3 R = d.rotation();
        const double ground = height_at(s->mesh, x, y);
        double lo = ground + 1e-3, hi = ground + r + 1;
        for (int k = 0; k < 200 && hi - lo > 1e-15; ++k) {
            const double mid = (lo + hi) / 2;
            const v3 c{x, y, mid};
            const v3 q = closest_on_terrain<double>(s->mesh, c);
            const double dist = std::sqrt((c[0] - q[0]) * (c[0] - q[0]) + (c[1] - q[1]) * (c[1] - q[1]) + (c[2] - q[2]) * (c[2] - q[2]));
            if (dist - r < t[i]) lo = mid;
            else hi = mid;
        }
        const map p{R, {x, y, (lo + hi) / 2}};
        const rv3 c = lift(p.t);
        const rv3 q = closest_on_terrain<real>(s->mesh, c);
        const exact e = balls(c, r, q, 0);
        s->sphere.push_back({r});
        s->pose.push_back(p);
        s->ex.push_back(e);
    }
    return s;
}

#ifdef CTGA_BENCH_BULLET
struct bt_closest : btCollisionWorld::ContactResultCallback {
    bt_points points;
    btScalar addSingleResult(btManifoldPoint& cp, const btCollisionObjectWrapper*, int, int, const btCollisionObjectWrapper*, int, int) override {
        points.addContactPoint(cp.m_normalWorldOnB, cp.m_positionWorldOnB, cp.getDistance());
        return 0;
    }
};
struct bt_mesh_set {
    std::vector<int> indices;
    std::vector<btScalar> vertices;
    std::unique_ptr<btTriangleIndexVertexArray> arrays;
    std::unique_ptr<btBvhTriangleMeshShape> shape;
    btCollisionObject mesh;
    std::vector<std::unique_ptr<btSphereShape>> spheres;
    std::vector<std::unique_ptr<btCollisionObject>> objects;
    btDefaultCollisionConfiguration configuration;
    std::unique_ptr<btCollisionDispatcher> dispatcher;
    btDbvtBroadphase broadphase;
    std::unique_ptr<btCollisionWorld> world;
};
// contactPairTest finds the closest-points algorithm (convex–concave: the triangles in the sphere's
// box grown by the threshold, sphere–triangle on each) and reports a point per triangle within
// the threshold: 0.3 m, above every separated target (0.25 m).
[[gnu::noinline]] void bt_sphere_mesh(bt_mesh_set& f, std::size_t k, bt_closest& out) {
    out.m_closestDistanceThreshold = 0.3;
    f.world->contactPairTest(f.objects[k].get(), &f.mesh, out);
}
#endif

void register_sphere_mesh() {
    const auto s = make_sphere_mesh(0xc011'0007);
    {
        // ctga: the terrain as a triangle mesh (mesh.hpp: its hierarchy in storage kept here), the
        // separation of the sphere at s->pose[k] from the mesh at the identity (A the sphere)
        struct ctga_mesh {
            std::vector<std::array<std::uint32_t, 3>> triangles;
            std::vector<co::bvh_node<double>> nodes;
            std::vector<std::uint32_t> order;
            co::triangle_mesh<double> mesh;
            std::vector<co::sphere<double>> sphere;
        };
        auto c = std::make_shared<ctga_mesh>();
        for (const auto& t : s->mesh.triangles)
            c->triangles.push_back({static_cast<std::uint32_t>(t[0]), static_cast<std::uint32_t>(t[1]), static_cast<std::uint32_t>(t[2])});
        c->nodes.resize(co::bvh_nodes_for(c->triangles.size()));
        c->order.resize(c->triangles.size());
        c->mesh = *co::make_triangle_mesh<double>(s->mesh.vertices, c->triangles, c->nodes, c->order);
        for (std::size_t k = 0; k < poses; ++k) c->sphere.push_back(*co::make_sphere(s->sphere[k].radius));
        const map identity{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {0, 0, 0}};
        std::vector<answer> got;
        for (std::size_t k = 0; k < poses; ++k) {
            const co::separation<double> r = co::separation_of(c->sphere[k], s->pose[k], c->mesh, identity);
            got.push_back({true, r.distance, true, r.normal, 0});
        }
        const std::string name = "collision_sphere_mesh/ctga";
        add_row(name, [c, s, identity](std::size_t k) {
            co::separation<double> r = ctga_separation(c->sphere[k], s->pose[k], c->mesh, identity);
            benchmark::DoNotOptimize(r);
        }, assess(name, s->ex, got, false));
    }
#ifdef CTGA_BENCH_FCL
    {
        // fcl::BVHModel<OBBRSSd> of the terrain against fcl::Sphered. FCL 0.7's mesh–sphere distance
        // is undefined when they overlap (its sphere–triangle distance returns false and leaves the
        // distance unset: values like 7e-321 come back, and FCL's own fallback for a negative
        // distance does not run), so a query is fcl::collide(mesh, sphere, enable_contact, all
        // contacts) first: if it finds contacts, the deepest (FCL 0.7's sphereTriangleIntersect
        // gives penetration_depth = −(r − distance), sphere_triangle-inl.h; normal from o1, the
        // mesh, to o2); if not, fcl::distance(mesh, sphere), signed, nearest points requested
        // (nearest_points[0] on the mesh in the world, [1] on the sphere in the sphere's own frame:
        // FCL 0.7's mesh–shape traversal).
        struct fcl_mesh_set {
            fcl::BVHModel<fcl::OBBRSSd> mesh;
            std::vector<std::unique_ptr<fcl::Sphered>> sphere;
            std::vector<fcl::Transform3d> pose;
            fcl::Transform3d identity = fcl::Transform3d::Identity();  // the terrain's pose
            fcl::CollisionRequestd contacts{std::size_t(1000), true};
        };
        auto f = std::make_shared<fcl_mesh_set>();
        std::vector<fcl::Vector3d> vertices;
        for (const v3& v : s->mesh.vertices) vertices.emplace_back(v[0], v[1], v[2]);
        std::vector<fcl::Triangle> triangles;
        for (const auto& t : s->mesh.triangles)
            triangles.emplace_back(static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]), static_cast<std::size_t>(t[2]));
        f->mesh.beginModel();
        f->mesh.addSubModel(vertices, triangles);
        f->mesh.endModel();
        for (std::size_t k = 0; k < poses; ++k) {
            f->sphere.push_back(std::make_unique<fcl::Sphered>(s->sphere[k].radius));
            f->pose.push_back(fcl_pose(s->pose[k]));
        }
        struct fcl_mesh_answer {
            fcl::DistanceResultd distance;
            fcl::CollisionResultd contacts;
        };
        const auto query = [](const fcl_mesh_set& m, std::size_t k, fcl_mesh_answer& r) {
            const auto* mesh = static_cast<const fcl::CollisionGeometryd*>(&m.mesh);
            const auto* sphere = static_cast<const fcl::CollisionGeometryd*>(m.sphere[k].get());
            r.contacts.clear();
            if (fcl::collide(mesh, m.identity, sphere, m.pose[k], m.contacts, r.contacts) > 0) return true;
            r.distance.clear();
            fcl::distance(mesh, m.identity, sphere, m.pose[k], fcl_signed_request, r.distance);
            return false;
        };
        std::vector<answer> got;
        for (std::size_t k = 0; k < poses; ++k) {
            fcl_mesh_answer r;
            answer g;
            if (!query(*f, k, r)) {
                fcl::DistanceResultd w = r.distance;
                w.nearest_points[1] = f->pose[k] * w.nearest_points[1];  // (the sphere's point, from its frame)
                g = from_fcl_distance(w, false);                          // nearest_points[0] on the mesh (B)
            } else {
                for (std::size_t i = 0; i < r.contacts.numContacts(); ++i) {
                    const fcl::Contactd& c = r.contacts.getContact(i);
                    if (!g.has_distance || c.penetration_depth < g.distance) {
                        g.has_distance = g.has_normal = true;
                        g.distance = c.penetration_depth;
                        g.normal = from_fcl(-c.normal);
                    }
                }
            }
            got.push_back(g);
        }
        const std::string name = "collision_sphere_mesh/fcl";
        add_row(name, [f, query](std::size_t k) {
            fcl_mesh_answer r;
            benchmark::DoNotOptimize(query(*f, k, r));
            benchmark::DoNotOptimize(r);
        }, assess(name, s->ex, got, false));
    }
#endif
#ifdef CTGA_BENCH_BULLET
    {
        // btBvhTriangleMeshShape (quantized BVH, margin 0) and btSphereShape through
        // btCollisionWorld::contactPairTest (the simplest public way; it makes and frees the
        // convex–concave algorithm per call, as a query outside a simulation step does)
        auto f = std::make_shared<bt_mesh_set>();
        for (const auto& t : s->mesh.triangles) f->indices.insert(f->indices.end(), {t[0], t[1], t[2]});
        for (const v3& v : s->mesh.vertices) f->vertices.insert(f->vertices.end(), {v[0], v[1], v[2]});
        f->arrays = std::make_unique<btTriangleIndexVertexArray>(static_cast<int>(s->mesh.triangles.size()), f->indices.data(),
                                                                 static_cast<int>(3 * sizeof(int)), static_cast<int>(s->mesh.vertices.size()),
                                                                 f->vertices.data(), static_cast<int>(3 * sizeof(btScalar)));
        f->shape = std::make_unique<btBvhTriangleMeshShape>(f->arrays.get(), true);
        f->shape->setMargin(0);
        f->mesh.setCollisionShape(f->shape.get());
        for (std::size_t k = 0; k < poses; ++k) {
            f->spheres.push_back(std::make_unique<btSphereShape>(s->sphere[k].radius));
            f->objects.push_back(std::make_unique<btCollisionObject>());
            f->objects.back()->setCollisionShape(f->spheres.back().get());
            f->objects.back()->setWorldTransform(bt_pose(s->pose[k]));
        }
        f->dispatcher = std::make_unique<btCollisionDispatcher>(&f->configuration);
        f->world = std::make_unique<btCollisionWorld>(f->dispatcher.get(), &f->broadphase, &f->configuration);
        std::vector<answer> got;
        for (std::size_t k = 0; k < poses; ++k) {
            bt_closest r;
            bt_sphere_mesh(*f, k, r);
            got.push_back(from_bt(r.points));
        }
        const std::string name = "collision_sphere_mesh/bullet";
        add_row(name, [f](std::size_t k) {
            bt_closest r;
            bt_sphere_mesh(*f, k, r);
            benchmark::DoNotOptimize(r.points);
        }, assess(name, s->ex, got, false));
    }
#endif
    (void)s;
}

}  // namespace

void register_pairs() {
    register_sphere_sphere();
    register_sphere_box();
    register_capsule_capsule();
    register_box_box();
    register_box_half_space();
    register_hull_hull();    // the peers only, for now
    register_sphere_mesh();  // the peers only, for now
}

}  // namespace bench::collision
