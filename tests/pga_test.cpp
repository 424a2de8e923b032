// ctga::pga, the ready-made Cl(3,0,1), against references written here independently of it:
// rotation matrices by Rodrigues' formula, 4×4 homogeneous matrices, cross products, 3×3 systems
// solved by Cramer's rule, parametric line–plane intersections, and the naive dense algebra
// (reference/dense.hpp). Every sign convention stated in geometry/pga.hpp is checked here.
//
// Tolerance: results are compared component by component, |x − y| ≤ 1e-12 · max(1, |y|) with
// inputs of size about 1 (a few roundings of double).
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <type_traits>

#include <ctga/geometry/pga.hpp>
#include <ctga/reference/dense.hpp>

#include "support/catch.hpp"
#include "support/published.hpp"

namespace {

namespace pga = ctga::pga;
using vec3 = std::array<double, 3>;
using mat3 = std::array<vec3, 3>;
constexpr double pi = 3.14159265358979323846;
constexpr double tol = 1e-12;

// ---- the independent references ----------------------------------------------------------

vec3 add(const vec3& a, const vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
vec3 sub(const vec3& a, const vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
vec3 scale(double s, const vec3& a) { return {s * a[0], s * a[1], s * a[2]}; }
double dot(const vec3& a, const vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
vec3 cross(const vec3& a, const vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
vec3 mat_vec(const mat3& m, const vec3& v) { return {dot(m[0], v), dot(m[1], v), dot(m[2], v)}; }
double det(const vec3& r0, const vec3& r1, const vec3& r2) { return dot(r0, cross(r1, r2)); }

// Rodrigues: the rotation by +θ about unit u (right-hand rule), R = I + sin θ K + (1 − cos θ) K².
mat3 rodrigues(double theta, vec3 u) {
    u = scale(1.0 / std::sqrt(dot(u, u)), u);
    const mat3 K{{{0, -u[2], u[1]}, {u[2], 0, -u[0]}, {-u[1], u[0], 0}}};
    mat3 R{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double k2 = 0;
            for (int l = 0; l < 3; ++l) k2 += K[i][l] * K[l][j];
            R[i][j] = (i == j ? 1.0 : 0.0) + std::sin(theta) * K[i][j] + (1 - std::cos(theta)) * k2;
        }
    return R;
}

// x = A⁻¹ b by Cramer's rule, A given by its rows.
vec3 solve(const mat3& A, const vec3& b) {
    const double d = det(A[0], A[1], A[2]);
    vec3 x{};
    for (int k = 0; k < 3; ++k) {
        mat3 Ak = A;
        for (int i = 0; i < 3; ++i) Ak[i][k] = b[i];
        x[k] = det(Ak[0], Ak[1], Ak[2]) / d;
    }
    return x;
}

bool near(double x, double y) { return std::abs(x - y) <= tol * std::max(1.0, std::abs(y)); }
bool near(const vec3& x, const vec3& y) { return near(x[0], y[0]) && near(x[1], y[1]) && near(x[2], y[2]); }

// ---- reading pga values (the storage order the types document) ---------------------------

vec3 coordinates(const pga::point<>& p) { return {p[0] / p[3], p[1] / p[3], p[2] / p[3]}; }
vec3 normal(const pga::plane<>& e) { return {e[0], e[1], e[2]}; }
vec3 line_direction(const pga::line<>& l) { return {l[3], l[4], l[5]}; }
vec3 line_moment(const pga::line<>& l) { return {l[0], l[1], l[2]}; }
pga::point<> at(const vec3& x) { return pga::make_point(x[0], x[1], x[2]); }

template <class X>
bool all_zero(const X& x) {
    for (std::size_t i = 0; i < X::size(); ++i)
        if (std::abs(x[i]) > tol) return false;
    return true;
}

struct random_source {
    std::mt19937_64 rng{26};
    std::uniform_real_distribution<double> u{-1.0, 1.0};
    double operator()() { return u(rng); }
    vec3 vec() { return {u(rng), u(rng), u(rng)}; }
};

// ---- types: what each operation returns is part of its type -----------------------------

static_assert(std::is_same_v<pga::algebra, ctga::algebra<"e0 e1 e2 e3", 0, 1, 1, 1>>);
static_assert(std::is_same_v<decltype(pga::sandwich(pga::motor<>{}, pga::point<>{})), pga::point<>>);
static_assert(std::is_same_v<decltype(pga::sandwich(pga::rotor<>{}, pga::line<>{})), pga::line<>>);
static_assert(std::is_same_v<decltype(pga::sandwich(pga::translator<>{}, pga::direction<>{})), pga::direction<>>);
static_assert(std::is_same_v<decltype(pga::join(pga::point<>{}, pga::point<>{})), pga::line<>>);
static_assert(std::is_same_v<decltype(pga::join(pga::point<>{}, pga::point<>{}, pga::point<>{})), pga::plane<>>);
static_assert(std::is_same_v<decltype(pga::join(pga::point<>{}, pga::plane<>{})), double>);
static_assert(std::is_same_v<decltype(pga::meet(pga::plane<>{}, pga::plane<>{})), pga::line<>>);
static_assert(std::is_same_v<decltype(pga::meet(pga::plane<>{}, pga::line<>{})), pga::point<>>);
static_assert(std::is_same_v<decltype(pga::meet(pga::plane<>{}, pga::plane<>{}, pga::plane<>{})), pga::point<>>);
static_assert(std::is_same_v<decltype(pga::make_point<float>(1, 2, 3)), pga::point<float>>);
// the clipping step of a contact manifold in the algebra (docs/design.md §9b, bench/collision_algebra.cpp):
// the line through two points, and its meet with a plane
static_assert(ctga::cost_of<decltype(pga::join.formula(std::declval<const pga::point<>&>(), std::declval<const pga::point<>&>())),
                            pga::line<>> == ctga::test::published<12, 6>);
static_assert(ctga::cost_of<decltype(pga::meet.formula(std::declval<const pga::plane<>&>(), std::declval<const pga::line<>&>())),
                            pga::point<>> == ctga::test::published<12, 8>);

// A translation at compile time, exactly: (0, 0, 0) moved by (1, 2, 3).
static_assert([] {
    constexpr pga::point<> q = pga::sandwich(pga::make_translator(1, 2, 3), pga::make_point(0, 0, 0));
    return q[0] == 1 && q[1] == 2 && q[2] == 3 && q[3] == 1;
}());

// The composition of two translators is a translator, of two rotors a rotor (the engine proves
// the other blades zero, or these would not compile).
static_assert([] {
    constexpr pga::translator<> t = pga::make_translator(1, 0, 0) * pga::make_translator(0, 2, 0);
    return t[0] == 1 && t[1] == -0.5 && t[2] == -1 && t[3] == 0;
}());

// ---- rotors --------------------------------------------------------------------------------

TEST_CASE("pga: +90° about each axis turns counter-clockwise seen from the axis' tip", "[pga]") {
    const pga::point<> qz = pga::sandwich(pga::make_rotor(pi / 2, 0, 0, 1), pga::make_point(1, 0, 0));
    CHECK(near(coordinates(qz), vec3{0, 1, 0}));
    CHECK(qz[3] == 1.0);
    const pga::point<> qx = pga::sandwich(pga::make_rotor(pi / 2, 3, 0, 0), pga::make_point(0, 1, 0));
    CHECK(near(coordinates(qx), vec3{0, 0, 1}));
    const pga::point<> qy = pga::sandwich(pga::make_rotor(pi / 2, 0, 0.5, 0), pga::make_point(0, 0, 1));
    CHECK(near(coordinates(qy), vec3{1, 0, 0}));
}

TEST_CASE("pga: rotors move points, directions, planes and lines as Rodrigues' matrix does", "[pga]") {
    random_source r;
    for (int trial = 0; trial < 20; ++trial) {
        const double theta = 3 * r();
        const vec3 axis = r.vec();
        const mat3 Rm = rodrigues(theta, axis);
        const pga::rotor<> R = pga::make_rotor(theta, axis[0], axis[1], axis[2]);
        CHECK(near(pga::norm(R), 1.0));

        const vec3 x = r.vec();
        CHECK(near(coordinates(pga::sandwich(R, at(x))), mat_vec(Rm, x)));

        const pga::direction<> d = pga::sandwich(R, pga::make_direction(x[0], x[1], x[2]));
        CHECK(near(vec3{d[0], d[1], d[2]}, mat_vec(Rm, x)));

        // the plane n·y + c = 0 becomes (R n)·y + c = 0
        const vec3 n = r.vec();
        const double c = r();
        const pga::plane<> e = pga::sandwich(R, pga::make_plane(n[0], n[1], n[2], c));
        CHECK(near(normal(e), mat_vec(Rm, n)));
        CHECK(near(e[3], c));

        // the line through x along v: direction R v, moment (R x) × (R v)
        const vec3 v = r.vec();
        const pga::line<> l = pga::sandwich(R, pga::make_line(at(x), pga::make_direction(v[0], v[1], v[2])));
        CHECK(near(line_direction(l), mat_vec(Rm, v)));
        CHECK(near(line_moment(l), cross(mat_vec(Rm, x), mat_vec(Rm, v))));
    }
}

TEST_CASE("pga: make_rotor reports a zero or non-finite axis instead of making a rotor", "[pga]") {
    CHECK(pga::make_rotor_checked(1.0, 0, 0, 0).error == ctga::error_code::zero_direction);
    CHECK(pga::make_rotor_checked(1.0, -0.0, 0, 0).error == ctga::error_code::zero_direction);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    CHECK(pga::make_rotor_checked(1.0, nan, 0, 1).error == ctga::error_code::non_finite);
    CHECK(pga::make_rotor_checked(1.0, inf, 0, 0).error == ctga::error_code::non_finite);
    CHECK(pga::make_rotor_checked(nan, 0, 0, 1).error == ctga::error_code::non_finite);
    // tiny and huge axes are directions all the same (no underflow to a zero length, no overflow)
    for (double s : {1e-300, 1e300}) {
        const auto R = pga::make_rotor_checked(pi / 2, 0, 0, s);
        REQUIRE(R);
        CHECK(near(coordinates(pga::sandwich(*R, pga::make_point(1, 0, 0))), vec3{0, 1, 0}));
    }
#ifdef NDEBUG
    // without assertions, make_rotor returns NaNs, which every later result shows
    const pga::rotor<> bad = pga::make_rotor(1.0, 0, 0, 0);
    for (std::size_t i = 0; i < bad.size(); ++i) CHECK(std::isnan(bad[i]));
    CHECK(std::isnan(pga::sandwich(bad, pga::make_point(1, 2, 3))[0]));
#endif
}

// ---- translators, motors, composition -----------------------------------------------------

TEST_CASE("pga: a translator by d adds d to points and moves planes and lines along", "[pga]") {
    random_source r;
    for (int trial = 0; trial < 10; ++trial) {
        const vec3 d = r.vec(), x = r.vec(), n = r.vec(), v = r.vec();
        const double c = r();
        const pga::translator<> T = pga::make_translator(d[0], d[1], d[2]);
        const pga::point<> q = pga::sandwich(T, at(x));
        CHECK(near(coordinates(q), add(x, d)));
        CHECK(q[3] == 1.0);
        // a direction does not move
        const pga::direction<> dv = pga::sandwich(T, pga::make_direction(v[0], v[1], v[2]));
        CHECK(near(vec3{dv[0], dv[1], dv[2]}, v));
        // n·y + c = 0 moved by d: n·(y − d) + c = 0
        const pga::plane<> e = pga::sandwich(T, pga::make_plane(n[0], n[1], n[2], c));
        CHECK(near(normal(e), n));
        CHECK(near(e[3], c - dot(n, d)));
        // the line through x along v, moved: through x + d along v
        const pga::line<> l = pga::sandwich(T, pga::make_line(at(x), pga::make_direction(v[0], v[1], v[2])));
        CHECK(near(line_direction(l), v));
        CHECK(near(line_moment(l), cross(add(x, d), v)));
    }
}

TEST_CASE("pga: M2 * M1 applies M1 first, T * R rotates, then translates", "[pga]") {
    random_source r;
    const vec3 d = r.vec(), axis = r.vec(), x = r.vec();
    const double theta = 2.0;
    const pga::translator<> T = pga::make_translator(d[0], d[1], d[2]);
    const pga::rotor<> R = pga::make_rotor(theta, axis[0], axis[1], axis[2]);
    const mat3 Rm = rodrigues(theta, axis);

    const pga::motor<> TR = T * R;
    const pga::motor<> RT = R * T;
    CHECK(near(coordinates(pga::sandwich(TR, at(x))), add(mat_vec(Rm, x), d)));
    CHECK(near(coordinates(pga::sandwich(RT, at(x))), mat_vec(Rm, add(x, d))));

    // three rotors: sandwich(R3 * R2 * R1, p) = R3(R2(R1(p)))
    const pga::rotor<> R1 = pga::make_rotor(0.3, 1, 0, 0), R2 = pga::make_rotor(-1.1, 0, 1, 1), R3 = pga::make_rotor(2.5, 1, 2, 3);
    const pga::rotor<> R321 = R3 * R2 * R1;
    const vec3 expected = mat_vec(rodrigues(2.5, {1, 2, 3}), mat_vec(rodrigues(-1.1, {0, 1, 1}), mat_vec(rodrigues(0.3, {1, 0, 0}), x)));
    CHECK(near(coordinates(pga::sandwich(R321, at(x))), expected));
    CHECK(near(coordinates(pga::sandwich(R3, pga::sandwich(R2, pga::sandwich(R1, at(x))))), expected));
}

TEST_CASE("pga: a motor acts on a point as its 4x4 homogeneous matrix", "[pga]") {
    random_source r;
    for (int trial = 0; trial < 10; ++trial) {
        const vec3 t = r.vec(), axis = r.vec();
        const double theta = 3 * r();
        const mat3 Rm = rodrigues(theta, axis);
        // H = [[R, t], [0, 1]], applied to (x, w): (R x + w t, w)
        std::array<std::array<double, 4>, 4> H{};
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) H[i][j] = Rm[i][j];
            H[i][3] = t[i];
        }
        H[3][3] = 1;
        const std::array<double, 4> xh{r(), r(), r(), 0.5 + r() * r()};  // w ≠ 1
        std::array<double, 4> yh{};
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) yh[i] += H[i][j] * xh[j];

        const pga::motor<> M = pga::make_translator(t[0], t[1], t[2]) * pga::make_rotor(theta, axis[0], axis[1], axis[2]);
        const pga::point<> q = pga::sandwich(M, pga::point<>{xh[0], xh[1], xh[2], xh[3]});
        for (int i = 0; i < 4; ++i) CHECK(near(q[static_cast<std::size_t>(i)], yh[static_cast<std::size_t>(i)]));
    }
}

// ---- join and meet ---------------------------------------------------------------------------

TEST_CASE("pga: join of two points is the line through both, directed from the first to the second", "[pga]") {
    random_source r;
    for (int trial = 0; trial < 10; ++trial) {
        const vec3 a = r.vec(), b = r.vec();
        const pga::line<> l = pga::join(at(a), at(b));
        CHECK(near(line_direction(l), sub(b, a)));
        CHECK(near(line_moment(l), cross(a, b)));
        CHECK(all_zero(pga::join(at(a), l)));  // incidence: the plane through a and l is zero
        CHECK(all_zero(pga::join(l, at(b))));
        // a point off the line is not incident
        const vec3 c = add(a, cross(sub(b, a), r.vec()));
        CHECK(!all_zero(pga::join(l, at(c))));
        // weights: join((w a, w), b) has direction w (b − a)
        const pga::line<> lw = pga::join(pga::point<>{2 * a[0], 2 * a[1], 2 * a[2], 2.0}, at(b));
        CHECK(near(line_direction(lw), scale(2, sub(b, a))));
        CHECK(near(line_moment(pga::make_line(at(a), at(b))), cross(a, b)));
    }
}

TEST_CASE("pga: join of three points is their plane, normal (q − p) × (r − p)", "[pga]") {
    random_source r;
    const vec3 p = r.vec(), q = r.vec(), s = r.vec();
    const pga::plane<> e = pga::join(at(p), at(q), at(s));
    const vec3 n = cross(sub(q, p), sub(s, p));
    CHECK(near(normal(e), n));
    CHECK(near(e[3], -dot(n, p)));
    const pga::plane<> e2 = pga::join(pga::join(at(p), at(q)), at(s));
    CHECK(near(normal(e2), n));
    const pga::plane<> e3 = pga::join(at(s), pga::join(at(p), at(q)));  // join(r, l) = join(l, r)
    CHECK(near(normal(e3), n));
    CHECK(near(e3[3], -dot(n, p)));
}

TEST_CASE("pga: meet of three planes is their intersection point, w = det of the normals", "[pga]") {
    random_source r;
    for (int trial = 0; trial < 10; ++trial) {
        const mat3 N{r.vec(), r.vec(), r.vec()};
        const vec3 d = r.vec();
        const pga::point<> x = pga::meet(pga::make_plane(N[0][0], N[0][1], N[0][2], d[0]),
                                         pga::make_plane(N[1][0], N[1][1], N[1][2], d[1]),
                                         pga::make_plane(N[2][0], N[2][1], N[2][2], d[2]));
        CHECK(near(x[3], det(N[0], N[1], N[2])));
        CHECK(near(coordinates(x), solve(N, scale(-1, d))));  // N y = −d
        CHECK(near(coordinates(pga::normalized(x)), solve(N, scale(-1, d))));
        CHECK(pga::normalized(x)[3] == 1.0);
    }
}

TEST_CASE("pga: meet of two planes is their line, direction n1 × n2", "[pga]") {
    random_source r;
    const vec3 n1 = r.vec(), n2 = r.vec();
    const double d1 = r(), d2 = r();
    const pga::plane<> e1 = pga::make_plane(n1[0], n1[1], n1[2], d1), e2 = pga::make_plane(n2[0], n2[1], n2[2], d2);
    const pga::line<> l = pga::meet(e1, e2);
    CHECK(near(line_direction(l), cross(n1, n2)));
    // a point of both planes (the third equation fixes it along the line) lies on l
    const vec3 y = solve({n1, n2, cross(n1, n2)}, {-d1, -d2, 0});
    CHECK(all_zero(pga::join(at(y), l)));
}

TEST_CASE("pga: meet of a plane and a line is their intersection, w = n · v", "[pga]") {
    random_source r;
    for (int trial = 0; trial < 10; ++trial) {
        const vec3 a = r.vec(), b = r.vec(), n = r.vec();
        const double c = r();
        const vec3 v = sub(b, a);
        // a + t v on n·y + c = 0
        const double t = -(dot(n, a) + c) / dot(n, v);
        const pga::line<> l = pga::join(at(a), at(b));
        const pga::point<> x = pga::meet(pga::make_plane(n[0], n[1], n[2], c), l);
        CHECK(near(x[3], dot(n, v)));
        CHECK(near(coordinates(x), add(a, scale(t, v))));
        const pga::point<> x2 = pga::meet(l, pga::make_plane(n[0], n[1], n[2], c));
        CHECK(near(x2[3], dot(n, v)));
    }
}

TEST_CASE("pga: a point lies on a plane iff their join is zero, with the join's and the meet's signs", "[pga]") {
    random_source r;
    const vec3 n = r.vec(), x = r.vec();
    const double c = r();
    const pga::plane<> e = pga::make_plane(n[0], n[1], n[2], c);
    const double value = dot(n, x) + c;  // a x + b y + c z + d
    CHECK(near(pga::join(e, at(x)), value));
    CHECK(near(pga::join(at(x), e), -value));
    CHECK(near(pga::meet(e, at(x)), value));
    CHECK(near(pga::meet(at(x), e), -value));
    // a point on the plane: move x along n onto it
    const vec3 on = sub(x, scale(value / dot(n, n), n));
    CHECK(std::abs(pga::join(at(on), e)) <= tol);
    // normalised, the join is the signed distance
    CHECK(near(pga::join(pga::normalized(e), at(x)), value / std::sqrt(dot(n, n))));
    CHECK(near(pga::norm(e), std::sqrt(dot(n, n))));
}

TEST_CASE("pga: two lines meet iff their join is zero", "[pga]") {
    random_source r;
    const vec3 a = r.vec(), b = r.vec(), c = r.vec();
    const pga::line<> l1 = pga::join(at(a), at(b));
    CHECK(std::abs(pga::join(l1, pga::join(at(b), at(c)))) <= tol);  // both through b
    CHECK(std::abs(pga::join(l1, pga::join(at(c), at(add(c, cross(sub(b, a), sub(c, a))))))) > 1e-3);
}

TEST_CASE("pga: a motor keeps incidence and distances", "[pga]") {
    random_source r;
    const vec3 n = r.vec(), x = r.vec(), y = r.vec();
    const pga::plane<> e = pga::normalized(pga::make_plane(n[0], n[1], n[2], r()));
    const pga::point<> on = pga::meet(e, pga::join(at(x), at(y)));  // a point of e
    const pga::motor<> M = pga::make_translator(0.3, -2, 1) * pga::make_rotor(1.2, 1, -1, 2);
    CHECK(std::abs(pga::join(pga::sandwich(M, on), pga::sandwich(M, e))) <= tol);
    // the signed distance of x from e is kept
    CHECK(near(pga::join(pga::sandwich(M, e), pga::sandwich(M, at(x))), pga::join(e, at(x))));
    // a line through x and y still holds both
    const pga::line<> l = pga::sandwich(M, pga::join(at(x), at(y)));
    CHECK(all_zero(pga::join(pga::sandwich(M, at(x)), l)));
    CHECK(all_zero(pga::join(pga::sandwich(M, at(y)), l)));
}

TEST_CASE("pga: norms and normalisation", "[pga]") {
    const pga::plane<> e = pga::make_plane(3, 0, 4, 10);
    CHECK(pga::norm(e) == 5.0);
    CHECK(near(pga::normalized(e)[0], 0.6));
    CHECK(near(pga::normalized(e)[3], 2.0));
    const pga::line<> l = pga::join(pga::make_point(1, 1, 1), pga::make_point(1, 3, 1));  // direction (0, 2, 0)
    CHECK(pga::norm(l) == 2.0);
    CHECK(near(line_direction(pga::normalized(l)), vec3{0, 1, 0}));
    CHECK(near(line_moment(pga::normalized(l)), cross({1, 1, 1}, {0, 1, 0})));
    const pga::direction<> d = pga::make_direction(0, 3, -4);
    CHECK(pga::norm(d) == 5.0);
    CHECK(near(pga::normalized(d)[2], -0.8));
    const pga::rotor<> R{2, 0, 0, 2};
    CHECK(near(pga::norm(R), std::sqrt(8.0)));
    CHECK(near(pga::squared_norm(pga::normalized(R)), 1.0));
    CHECK(pga::squared_norm(pga::point<>{5, 6, 7, 2}) == 4.0);  // w²
    const pga::point<> p = pga::normalized(pga::point<>{2, 4, -6, 2});
    CHECK((p[0] == 1 && p[1] == 2 && p[2] == -3 && p[3] == 1));
    // norm 0: non-finite, never a valid-looking element
    CHECK(!std::isfinite(pga::normalized(pga::make_plane(0, 0, 0, 1))[3]));
    CHECK(!std::isfinite(pga::normalized(pga::point<>{1, 0, 0, 0})[0]));
}

// ---- the dense reference ---------------------------------------------------------------------

TEST_CASE("pga: sandwich, join and meet equal the dense reference's products", "[pga][dense]") {
    namespace dense = ctga::dense;
    random_source r;
    const pga::motor<> M{r(), r(), r(), r(), r(), r(), r(), r()};  // any even element
    const pga::point<> p{r(), r(), r(), r()};
    const pga::line<> l{r(), r(), r(), r(), r(), r()};
    const pga::plane<> e{r(), r(), r(), r()};
    const auto dM = dense::to_dense(M);
    auto sandwiched = [&](const auto& x) { return dense::gp(dense::gp(dM, dense::to_dense(x)), dense::reverse(dM)); };
    CHECK(dense::max_abs_diff(dense::to_dense(pga::sandwich(M, p)), sandwiched(p)) <= tol);
    CHECK(dense::max_abs_diff(dense::to_dense(pga::sandwich(M, l)), sandwiched(l)) <= tol);
    CHECK(dense::max_abs_diff(dense::to_dense(pga::sandwich(M, e)), sandwiched(e)) <= tol);
    CHECK(dense::max_abs_diff(dense::to_dense(pga::join(p, l)), dense::shuffle(dense::to_dense(p), dense::to_dense(l))) <= tol);
    CHECK(dense::max_abs_diff(dense::to_dense(pga::meet(e, l)), dense::wedge(dense::to_dense(e), dense::to_dense(l))) <= tol);
    // the blade words themselves: e0e3e2 is −e0e2e3, e0e2e1 is −e0e1e2
    CHECK(dense::to_dense(pga::make_point(1, 0, 0)) ==
          dense::multivector<pga::algebra>::blade("e0e3e2") + dense::multivector<pga::algebra>::blade("e1e2e3"));
    CHECK(dense::to_dense(pga::point<>{0, 0, 1, 0})[0b0111] == -1.0);
}

// ---- printing --------------------------------------------------------------------------------

TEST_CASE("pga: every type prints in the blade words it declares", "[pga][io]") {
    auto text = [](const auto& x) {
        std::ostringstream os;
        os << x;
        return os.str();
    };
    CHECK(text(pga::point<>{2, 3, 4, 1}) == "2*e0e3e2 + 3*e0e1e3 + 4*e0e2e1 + e1e2e3");
    CHECK(text(pga::direction<>{2, 3, 4}) == "2*e0e3e2 + 3*e0e1e3 + 4*e0e2e1");
    CHECK(text(pga::plane<>{2, 3, 4, 5}) == "2*e1 + 3*e2 + 4*e3 + 5*e0");
    CHECK(text(pga::line<>{2, 3, 4, 5, 6, 7}) == "2*e0e1 + 3*e0e2 + 4*e0e3 + 5*e2e3 + 6*e3e1 + 7*e1e2");
    CHECK(text(pga::motor<>{2, 3, 4, 5, 6, 7, 8, 9}) ==
          "2 + 3*e2e3 + 4*e3e1 + 5*e1e2 + 6*e0e1 + 7*e0e2 + 8*e0e3 + 9*e0e1e2e3");
    CHECK(text(pga::translator<>{1, 2, 3, 4}) == "1 + 2*e0e1 + 3*e0e2 + 4*e0e3");
    CHECK(text(pga::rotor<>{1, 2, 3, 4}) == "1 + 2*e2e3 + 3*e3e1 + 4*e1e2");
    // a computed point too: the sandwich's result is a point, in the point's words
    const std::string q = text(pga::sandwich(pga::make_translator(1, 2, 3), pga::make_point(1, 1, 1)));
    CHECK(q == "2*e0e3e2 + 3*e0e1e3 + 4*e0e2e1 + e1e2e3");
}

}  // namespace
