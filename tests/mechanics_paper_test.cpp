// Sections 2, 3, 5 and 6 of the paper, formula by formula: each TEST_CASE is named after the
// formula it checks. Two independent routes meet in each: the paper's algebra (sandwiches,
// wedges and shuffles evaluated by the engine) and the 6×6 / 3-vector formalism of §2 (written
// out here, or the library's structured maps, which share no code with the engine's products).
// §4 (the shuffle product) is tests/paper_examples_test.cpp; exp/log of §3 are exp_log_test.cpp;
// the 1,000-case comparison with Eigen is spatial_matrix_test.cpp.
// PARTS: 6
// (§2 and §3, §6 and four blocks of §5 are compiled as six units: support/parts.hpp)
#include <cmath>
#include <random>

#include <ctga/ctga.hpp>

#include "support/catch.hpp"
#include "support/parts.hpp"

namespace {

using namespace ctga;
using namespace ctga::invariants;
using v3 = vec3<double>;
using m3 = mat3<double>;
using m6 = mat6<double>;

constexpr auto sandwich = formula([](auto h, auto x) { return h * x * conj(h); });

// (g ḡ) x (g ḡ)* as g (ḡ x ḡ*) g*, one motor at a time ("for hand calculation it is probably
// better to perform the multiplications by g and ḡ separately", §5), kept in x's type: for a
// unit motor the parts outside it vanish.
template <class X>
X moved_by(const motor<>& g, const X& x) {
    const auto gl = eval(lift(g));
    const X half_way = project<X>(sandwich(eval(bar(gl)), x));
    return project<X>(sandwich(gl, half_way));
}

struct sampler {
    std::mt19937_64 rng{2024};
    std::uniform_real_distribution<double> u{-1, 1};
    double operator()() { return u(rng); }
    v3 unit() {
        v3 a{u(rng), u(rng), u(rng)};
        const double n = std::sqrt(linear3::dot(a, a));
        for (double& x : a) x /= n;
        return a;
    }
    motor<> pose() {
        const v3 axis = unit(), t{5 * u(rng), 5 * u(rng), 5 * u(rng)};
        return rigid_motion(make_translator(t[0], t[1], t[2]), make_rotor(3 * u(rng), axis[0], axis[1], axis[2]));
    }
    screw<> twist() { return {u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)}; }
    coscrew<> cotwist() { return {u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)}; }
    // a physically valid body: principal moments from a box of random sides, rotated, offset
    mass_properties<> body() {
        const double m = 1 + 4 * (u(rng) + 1), a = 1.2 + u(rng), b = 1.2 + u(rng), c = 1.2 + u(rng);
        const double d[3] = {m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12};
        const motor_map<> Q = map_of(pose());
        m3 I{};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                for (int k = 0; k < 3; ++k) I[i][j] += Q.R[i][k] * d[k] * Q.R[j][k];
        const auto checked_body = make_mass_properties(m, v3{u(rng), u(rng), u(rng)}, I);
        REQUIRE(checked_body);
        return *checked_body;
    }
};

template <class X, class Y>
double max_diff(const X& x, const Y& y) {
    double e = 0;
    for (std::size_t i = 0; i < x.size(); ++i) e = std::max(e, std::abs(x[i] - y[i]));
    return e;
}
[[maybe_unused]] double max_diff6(const m6& a, const m6& b) {
    double e = 0;
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) e = std::max(e, std::abs(a[i][j] - b[i][j]));
    return e;
}
[[maybe_unused]] v3 head(const screw<>& s) { return {s[0], s[1], s[2]}; }
[[maybe_unused]] v3 tail(const screw<>& s) { return {s[3], s[4], s[5]}; }
[[maybe_unused]] v3 head(const coscrew<>& P) { return {P[0], P[1], P[2]}; }
[[maybe_unused]] v3 tail(const coscrew<>& P) { return {P[3], P[4], P[5]}; }

// §2's 6×6 matrices, written out from R and t.
[[maybe_unused]] m6 H_of(const motor_map<>& G, bool inverse_transpose) {
    m6 H{};
    const m3 T = linear3::hat(G.t);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            H[i][j] = H[3 + i][3 + j] = G.R[i][j];
            double TR = 0;
            for (int k = 0; k < 3; ++k) TR += T[i][k] * G.R[k][j];
            (inverse_transpose ? H[i][3 + j] : H[3 + i][j]) = TR;
        }
    return H;
}
[[maybe_unused]] vec6<double> mul(const m6& A, const vec6<double>& x) {
    vec6<double> y{};
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) y[i] += A[i][j] * x[j];
    return y;
}
[[maybe_unused]] m6 mul(const m6& A, const m6& B) {
    m6 C{};
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j)
            for (int k = 0; k < 6; ++k) C[i][j] += A[i][k] * B[k][j];
    return C;
}
[[maybe_unused]] m6 transposed(const m6& A) {
    m6 B{};
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) B[i][j] = A[j][i];
    return B;
}

#if CTGA_TEST_PART_HOLDS(0)
// ---- §2 --------------------------------------------------------------------------------------

TEST_CASE("§2 s = (ω, v), P = (l, p): the types are the paper's 6-vectors", "[paper][section2]") {
    sampler r;
    const screw<> s = r.twist();
    const coscrew<> P = r.cotwist();
    CHECK(screw_from_vector6(to_vector6(s)) == s);
    CHECK(coscrew_from_vector6(to_vector6(P)) == P);
    CHECK(get<"e2e3">(s) == to_vector6(s)[0]);  // ωx
    CHECK(get<"e1e">(s) == to_vector6(s)[3]);   // vx
    CHECK(get<"a1a">(P) == to_vector6(P)[0]);   // lx
    CHECK(get<"a2a3">(P) == to_vector6(P)[3]);  // px
}

TEST_CASE("§2 s → H s with H = [[R, 0], [T R, R]], and g s g* is that map", "[paper][section2][section3]") {
    sampler r;
    for (int trial = 0; trial < 50; ++trial) {
        const motor<> g = r.pose();
        const screw<> s = r.twist();
        const motor_map<> G = map_of(g);
        const auto Hs = mul(H_of(G, false), to_vector6(s));
        CHECK(max_diff(to_vector6(transform(G, s)), Hs) <= 1e-13);
        CHECK(max_diff(to_vector6(screw<>(adjoint(g, s))), Hs) <= 1e-13);
    }
}

TEST_CASE("§2/§5 P → H⁻ᵀ P with H⁻ᵀ = [[R, T R], [0, R]], and ḡ P ḡ* is that map", "[paper][section2][section5]") {
    sampler r;
    for (int trial = 0; trial < 50; ++trial) {
        const motor<> g = r.pose();
        const coscrew<> P = r.cotwist();
        const motor_map<> G = map_of(g);
        const m6 H = H_of(G, false), Hit = H_of(G, true);
        // H⁻ᵀ Hᵀ = 1
        m6 one = mul(Hit, transposed(H));
        for (int i = 0; i < 6; ++i) one[i][i] -= 1;
        CHECK(max_diff6(one, m6{}) <= 1e-13);
        const auto expected = mul(Hit, to_vector6(P));
        CHECK(max_diff(to_vector6(transform(G, P)), expected) <= 1e-13);
        const coscrew<> moved = sandwich(eval(bar(lift(g))), P);
        CHECK(max_diff(to_vector6(moved), expected) <= 1e-13);
    }
}

TEST_CASE("§2 the evaluation P(s) = Pᵀ s = ω·l + v·p is invariant under rigid motions", "[paper][section2]") {
    sampler r;
    for (int trial = 0; trial < 50; ++trial) {
        const screw<> s = r.twist();
        const coscrew<> P = r.cotwist();
        const double dot = linear3::dot(head(s), head(P)) + linear3::dot(tail(s), tail(P));
        CHECK(pairing(P, s) == Approx(dot).margin(1e-14));
        const motor_map<> G = map_of(r.pose());
        CHECK(pairing(transform(G, P), transform(G, s)) == Approx(dot).margin(1e-12));
    }
}

TEST_CASE("§2 N = [[I, m C], [m Cᵀ, m 1]] maps velocities to momenta, P = N s", "[paper][section2][section5]") {
    sampler r;
    for (int trial = 0; trial < 50; ++trial) {
        const mass_properties<> b = r.body();
        const screw<> s = r.twist();
        // P = (I_c ω + c × p, p) with p = m (v + ω × c): angular momentum about the origin
        const v3 w = head(s), v = tail(s), c = b.com;
        const v3 p = {b.mass * (v[0] + linear3::cross(w, c)[0]), b.mass * (v[1] + linear3::cross(w, c)[1]),
                      b.mass * (v[2] + linear3::cross(w, c)[2])};
        const v3 l = linear3::add(linear3::apply(b.inertia_c, w), linear3::cross(c, p));
        const coscrew<> P = momentum(inertia_of(b), s);
        CHECK(max_diff(head(P), l) <= 1e-12);
        CHECK(max_diff(tail(P), p) <= 1e-12);
        // the matrix read off the element is symmetric with the blocks of §2
        const m6 N = inertia_matrix(inertia_of(b));
        CHECK(max_diff6(N, transposed(N)) <= 1e-14);
        CHECK(N[3][3] == b.mass);
        CHECK(N[0][4] == Approx(-b.mass * c[2]));  // m C = m ĉ: row x, column vy is −m cz
    }
}

TEST_CASE("§2 E_K = ½ P(s), and N → H⁻ᵀ N H⁻¹ keeps it invariant", "[paper][section2][section5]") {
    sampler r;
    for (int trial = 0; trial < 50; ++trial) {
        const rigid_inertia<> N = inertia_of(r.body());
        const screw<> s = r.twist();
        const double E = kinetic_energy(N, s);
        CHECK(E == Approx(0.5 * pairing(momentum(N, s), s)).epsilon(1e-13));
        CHECK(E > 0);
        const motor_map<> G = map_of(r.pose());
        CHECK(kinetic_energy(transform(G, N), transform(G, s)) == Approx(E).epsilon(1e-12));
        // and the law is H⁻ᵀ N H⁻¹ as matrices
        const m6 Hi = transposed(H_of(G, true));  // H⁻¹ = (H⁻ᵀ)ᵀ
        const m6 expected = mul(H_of(G, true), mul(inertia_matrix(N), Hi));
        CHECK(max_diff6(inertia_matrix(transform(G, N)), expected) <= 1e-11);
    }
}

TEST_CASE("§2 {s, P} = (ω × l + v × p, ω × p), dual to the bracket: s1ᵀ{s2, P} = [s1, s2]ᵀ P", "[paper][section2][section6]") {
    sampler r;
    for (int trial = 0; trial < 50; ++trial) {
        const screw<> s = r.twist(), s1 = r.twist();
        const coscrew<> P = r.cotwist();
        const coscrew<> C = coadjoint(s, P);
        CHECK(max_diff(head(C), linear3::add(linear3::cross(head(s), head(P)), linear3::cross(tail(s), tail(P)))) <= 1e-15);
        CHECK(max_diff(tail(C), linear3::cross(head(s), tail(P))) <= 1e-15);
        CHECK(pairing(C, s1) == Approx(pairing(P, bracket(s1, s))).margin(1e-14));
    }
}

TEST_CASE("§2 N ds/dt + {s, N s} = W: the acceleration solves the equation of motion", "[paper][section2][section6]") {
    sampler r;
    for (int trial = 0; trial < 50; ++trial) {
        const mass_properties<> b = r.body();
        const rigid_inertia<> N = inertia_of(b);
        const screw<> s = r.twist();
        const wrench<> W = r.cotwist();
        const screw<> sdot = acceleration(N, mobility_of(b), s, W);
        const coscrew<> lhs = eval(momentum(N, sdot) + coadjoint(s, momentum(N, s)));
        CHECK(max_diff(lhs, W) <= 1e-12);
    }
}

// ---- §3 --------------------------------------------------------------------------------------

TEST_CASE("§3 [s1, s2] = ½(s1 s2 − s2 s1) = (ω1 × ω2, ω1 × v2 − ω2 × v1)", "[paper][section3]") {
    sampler r;
    for (int trial = 0; trial < 50; ++trial) {
        const screw<> a = r.twist(), b = r.twist();
        const screw<> c = bracket(a, b);
        CHECK(max_diff(head(c), linear3::cross(head(a), head(b))) <= 1e-15);
        const v3 v = linear3::add(linear3::cross(head(a), tail(b)), linear3::cross(tail(b), head(a)) /* −ω2×v1 below */);
        (void)v;
        const v3 expected = linear3::add(linear3::cross(head(a), tail(b)), linear3::cross(tail(a), head(b)));
        CHECK(max_diff(tail(c), expected) <= 1e-15);
    }
}

#endif
#if CTGA_TEST_PART_HOLDS(1)
// ---- §5 --------------------------------------------------------------------------------------

TEST_CASE("§5 Q0 = (g ḡ) Q0 (g ḡ)*, but Q0 ≠ g Q0 g* and Q0 ≠ ḡ Q0 ḡ*", "[paper][section5]") {
    sampler r;
    const auto q0 = eval(Q0);
    for (int trial = 0; trial < 10; ++trial) {
        const motor<> pose = r.pose();
        const auto g = eval(lift(pose));
        const auto gb = eval(bar(g));
        CHECK(max_diff(moved_by(pose, inertia<>(q0)), inertia<>(q0)) <= 1e-13);  // via the 36 blades ḡ Q0 ḡ* needs
        CHECK(max_diff(project<decltype(q0)>(sandwich(g, q0)), q0) > 1e-3);
        CHECK(max_diff(project<decltype(q0)>(sandwich(gb, q0)), q0) > 1e-3);
    }
}

TEST_CASE("§5 A = g A g* = ḡ A ḡ*, and (g ḡ) fixes the pseudoscalar (determinants are invariant)", "[paper][section5]") {
    sampler r;
    const auto a = eval(A);
    const auto I = eval(cl062::basis<"a1a2a3ae1e2e3e">);
    for (int trial = 0; trial < 10; ++trial) {
        const motor<> pose = r.pose();
        const auto g = eval(lift(pose));
        const auto gb = eval(bar(g));
        CHECK(max_diff(project<decltype(a)>(sandwich(g, a)), a) <= 1e-14);
        CHECK(max_diff(project<decltype(a)>(sandwich(gb, a)), a) <= 1e-13);
        CHECK(max_diff(moved_by(pose, I), I) <= 1e-13);
    }
}

#endif
#if CTGA_TEST_PART_HOLDS(3)
TEST_CASE("§5 h(a ∧ b)h* = (h a h*) ∧ (h b h*) and h(a ∨ b)h* = (h a h*) ∨ (h b h*) for h = g ḡ", "[paper][section5]") {
    sampler r;
    for (int trial = 0; trial < 5; ++trial) {
        const motor<> g = r.pose();
        const inertia<> N = inertia_of(r.body());
        const auto s = eval(lift(r.twist()));
        const coscrew<> P = r.cotwist();
        // ∧: an inertia and a screw (grade 4 ∧ grade 2)
        const auto Ns = eval(N ^ s);
        const auto lhs_wedge = moved_by(g, Ns);
        const auto hN = moved_by(g, N);
        const auto hs = moved_by(g, s);
        CHECK(max_diff(lhs_wedge, project<decltype(Ns)>(hN ^ hs)) <= 1e-11);
        // ∨: a co-screw and Q0 ∧ s (grade 2 ∨ grade 6)
        const auto Qs = eval(Q0 ^ s);
        const auto hQs = moved_by(g, Qs);
        const auto hP = moved_by(g, P);
        CHECK(scalar_part(P & Qs) == Approx(scalar_part(hP & hQs)).margin(1e-11));
    }
}

TEST_CASE("§5 the diagonal inertia: A ∨ (N ∧ s) = (dx ωx, dy ωy, dz ωz, m v)", "[paper][section5]") {
    const double m = 3, dx = 0.5, dy = 0.7, dz = 0.9;
    const auto N = diagonal_inertia(m, dx, dy, dz);
    const screw<> s{2, -3, 5, 7, -11, 13};
    const coscrew<> P = momentum(N, s);
    CHECK(P == coscrew<>{dx * 2, dy * -3, dz * 5, m * 7, m * -11, m * 13});
    // the same element as inertia_of the principal-axes body
    const auto b = make_principal_mass_properties(m, dx, dy, dz);
    REQUIRE(b);
    CHECK(max_diff6(inertia_matrix(N), inertia_matrix(inertia_of(*b))) == 0);
}

#endif
#if CTGA_TEST_PART_HOLDS(4)
TEST_CASE("§5 ḡ P ḡ* = A ∨ ((g ḡ) N (g ḡ)* ∧ g s g*): the momentum is covariant", "[paper][section5]") {
    sampler r;
    for (int trial = 0; trial < 10; ++trial) {
        const motor<> g = r.pose();
        const rigid_inertia<> N = inertia_of(r.body());
        const screw<> s = r.twist();
        const auto gl = eval(lift(g));
        const inertia<> moved_N = moved_by(g, inertia<>(N));
        const coscrew<> lhs = sandwich(eval(bar(gl)), momentum(N, s));
        CHECK(max_diff(lhs, momentum(moved_N, screw<>(adjoint(g, s)))) <= 1e-11);
        // and the algebra's (g ḡ) N (g ḡ)* is the map built once from g
        CHECK(max_diff6(inertia_matrix(moved_N), inertia_matrix(transform(map_of(g), N))) <= 1e-11);
    }
}

TEST_CASE("§5 the worked translation example: (g ḡ) N (g ḡ)* for g = 1 + ½ tx e1e, term by term", "[paper][section5]") {
    const double m = 2, dx = 0.3, dy = 0.5, dz = 0.7, tx = 1.5;
    const auto N = diagonal_inertia(m, dx, dy, dz);
    const translator<> g = make_translator(tx, 0.0, 0.0);
    const auto gl = eval(lift(g));
    const inertia<> moved = project<inertia<>>(sandwich(eval(gl * bar(gl)), N));
    // the paper's result, written as it is printed
    const auto expected = eval(dx * cl062::basis<"a1ae1e"> + (dy + m * tx * tx) * cl062::basis<"a2ae2e"> +
                               (dz + m * tx * tx) * cl062::basis<"a3ae3e"> + m * tx * cl062::basis<"a3ae3e1"> -
                               m * tx * cl062::basis<"a2ae1e2"> + m * tx * cl062::basis<"a3a1e3e"> -
                               m * tx * cl062::basis<"a1a2e2e"> + m * cl062::basis<"a2a3e2e3"> +
                               m * cl062::basis<"a3a1e3e1"> + m * cl062::basis<"a1a2e1e2">);
    CHECK(max_diff(moved, project<inertia<>>(expected)) <= 1e-15);
    CHECK(max_diff(project<decltype(expected)>(moved), expected) <= 1e-15);
    // and the 6×6 matrix printed beside it
    const m6 printed{{{dx, 0, 0, 0, 0, 0},
                      {0, dy + m * tx * tx, 0, 0, 0, -m * tx},
                      {0, 0, dz + m * tx * tx, 0, m * tx, 0},
                      {0, 0, 0, m, 0, 0},
                      {0, 0, m * tx, 0, m, 0},
                      {0, -m * tx, 0, 0, 0, m}}};
    CHECK(max_diff6(inertia_matrix(moved), printed) <= 1e-15);
    CHECK(max_diff6(inertia_matrix(transform(map_of(motor<>(g)), N)), printed) <= 1e-15);
}

TEST_CASE("§5 E_k = ½ P ∨ (Q0 ∧ s) = ½ s̄ ∨ (N ∧ s), with A ∨ (Q0 ∧ s) = s̄", "[paper][section5]") {
    sampler r;
    for (int trial = 0; trial < 50; ++trial) {
        const rigid_inertia<> N = inertia_of(r.body());
        const auto s = eval(lift(r.twist()));
        const coscrew<> P = momentum.formula(N, s);
        const double via_evaluation = 0.5 * scalar_part(P & (Q0 ^ s));
        const double via_bar = 0.5 * scalar_part(bar(s) & (N ^ s));
        CHECK(via_bar == Approx(via_evaluation).epsilon(1e-13));
        CHECK(max_diff(eval(A & (Q0 ^ s)), eval(bar(s))) == 0);
    }
}

#endif
#if CTGA_TEST_PART_HOLDS(5)
TEST_CASE("§5 screws and co-screws also follow the inertia's law: x → (g ḡ) x (g ḡ)*", "[paper][section5]") {
    sampler r;
    for (int trial = 0; trial < 10; ++trial) {
        const motor<> g = r.pose();
        const screw<> s = r.twist();
        const coscrew<> P = r.cotwist();
        CHECK(max_diff(lower(moved_by(g, lifted_screw<>(lift(s)))), screw<>(adjoint(g, s))) <= 1e-12);
        CHECK(max_diff(moved_by(g, P), transform(map_of(g), P)) <= 1e-12);
    }
}

TEST_CASE("§5 the mobility M = N⁻¹ as an element: E ∨ (M ∧ (A ∨ (N ∧ s))) = s, and M → (g ḡ) M (g ḡ)*",
          "[paper][section5]") {
    sampler r;
    for (int trial = 0; trial < 20; ++trial) {
        const mass_properties<> b = r.body();
        const screw<> s = r.twist();
        CHECK(max_diff(velocity_from(mobility_of(b), momentum(inertia_of(b), s)), s) <= 1e-12);
        const motor<> g = r.pose();
        const mobility<> moved = moved_by(g, mobility_of(b));
        const motor_map<> G = map_of(g);
        CHECK(max_diff(moved, transform(G, mobility_of(b))) <= 1e-11);
        CHECK(max_diff(moved, mobility_of(transform(G, b))) <= 1e-11);
        CHECK(max_diff(velocity_from(moved, momentum(transform(G, inertia_of(b)), transform(G, s))), transform(G, s)) <= 1e-11);
    }
}

#endif
#if CTGA_TEST_PART_HOLDS(2)
// ---- §6 --------------------------------------------------------------------------------------

TEST_CASE("§6 (sN − Ns) ∧ s = 0 and ½ A ∨ ((s̄N − Ns̄) ∧ s) = {s, A ∨ (N ∧ s)}", "[paper][section6]") {
    sampler r;
    for (int trial = 0; trial < 50; ++trial) {
        const rigid_inertia<> N = inertia_of(r.body());
        const auto s = eval(lift(r.twist()));
        const auto zero = eval(formula([](auto x, auto M) { return (x * M - M * x) ^ x; })(s, N));
        static_assert(decltype(zero)::size() == 0, "structurally zero: the engine proves it");
        const coscrew<> lhs = formula([](auto x, auto M) { return half * (A & ((bar(x) * M - M * bar(x)) ^ x)); })(s, N);
        CHECK(max_diff(lhs, coscrew<>(coadjoint.formula(s, coscrew<>(momentum.formula(N, s))))) <= 1e-13);
    }
}

TEST_CASE("§6 AE ∨ c = c", "[paper][section6]") {
    sampler r;
    const rigid_inertia<> N = inertia_of(r.body());
    const coscrew<> P = r.cotwist();
    CHECK(max_diff(rigid_inertia<>((A * E) & N), N) == 0);
    CHECK(max_diff(coscrew<>((A * E) & P), P) == 0);
}

TEST_CASE("§6 dP/dt = A ∨ (N ∧ ṡ) + ½ A ∨ ((s̄N − Ns̄) ∧ s), and N ∧ ṡ + ½((s̄N − Ns̄) ∧ s) = W E", "[paper][section6]") {
    sampler r;
    for (int trial = 0; trial < 50; ++trial) {
        const rigid_body<> body = make_rigid_body(r.body());
        const motor<> g = r.pose();
        const screw<> s = r.twist();
        const wrench<> W = r.cotwist();
        // fixed frame: the inertia moved by g
        const state_rate<> rate = fixed_frame_rates(body, g, s, W);
        const rigid_inertia<> N = transform(map_of(g), body.N);
        const auto lhs = eval(motion_lhs(N, s, rate.s_dot));
        const auto rhs = eval(W * E);
        // The terms summed are of size |N||ṡ|, and the moved N has entries m|t|² (up to ~700
        // here): rounding is relative to that, not to |W| ~ 1.
        double n_max = 0, sdot_max = 0;
        for (std::size_t i = 0; i < N.size(); ++i) n_max = std::max(n_max, std::abs(N[i]));
        for (std::size_t i = 0; i < 6; ++i) sdot_max = std::max(sdot_max, std::abs(rate.s_dot[i]));
        const double bound = 4e-14 * std::max(1.0, n_max * sdot_max);
        CHECK(max_diff(lhs, project<decltype(lhs)>(rhs)) <= bound);
        CHECK(max_diff(project<decltype(rhs)>(lhs), rhs) <= bound);
        const coscrew<> dP = formula([](auto M, auto x, auto xdot) {
            return (A & (M ^ xdot)) + half * (A & ((bar(x) * M - M * bar(x)) ^ x));
        })(N, eval(lift(s)), eval(lift(rate.s_dot)));
        CHECK(max_diff(dP, W) <= bound);
    }
}

TEST_CASE("§3/§6 fixed and body frames agree: ṡ = H ṡ_b, dg/dt = ½ s g = ½ g s_b", "[paper][section3][section6]") {
    sampler r;
    for (int trial = 0; trial < 50; ++trial) {
        const rigid_body<> body = make_rigid_body(r.body());
        const motor<> g = r.pose();
        const screw<> s_b = r.twist();
        const wrench<> W_b = r.cotwist();
        const motor_map<> G = map_of(g);
        const state_rate<> in_body = body_frame_rates(body, g, s_b, W_b);
        const state_rate<> in_space = fixed_frame_rates(body, g, transform(G, s_b), transform(G, W_b));
        CHECK(max_diff(in_space.s_dot, transform(G, in_body.s_dot)) <= 1e-11);
        CHECK(max_diff(in_space.g_dot, in_body.g_dot) <= 1e-13);
    }
}

}  // namespace

namespace {

// d/dt at t = 0 by a fourth-order central difference, step h.
template <class F>
auto derivative(F f, double h) {
    const auto a = f(-2 * h), b = f(-h), c = f(h), d = f(2 * h);
    auto out = a;
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = (a[i] - 8 * b[i] + 8 * c[i] - d[i]) / (12 * h);
    return out;
}

TEST_CASE("§6 {s, P} = d/dt of the co-screw moved uniformly about s, g = e^{t s/2}", "[paper][section6]") {
    sampler r;
    for (int trial = 0; trial < 20; ++trial) {
        const screw<> s = r.twist();
        const coscrew<> P = r.cotwist();
        // the paper writes e^{ts/2} P e^{−ts/2}; on a co-screw the motor acts through its bar (§5)
        const coscrew<> rate = derivative([&](double t) { return transform(ctga::exp(screw<>(t * s)), P); }, 1e-3);
        CHECK(max_diff(rate, coadjoint(s, P)) <= 1e-10);
    }
}

TEST_CASE("§6 dN/dt = ½(sN − Ns) + ½(s̄N − Ns̄) for N moved uniformly about s", "[paper][section6]") {
    sampler r;
    for (int trial = 0; trial < 20; ++trial) {
        const screw<> s = r.twist();
        const rigid_inertia<> N = inertia_of(r.body());
        const rigid_inertia<> rate = derivative([&](double t) { return transform(ctga::exp(screw<>(t * s)), N); }, 1e-3);
        CHECK(max_diff6(inertia_matrix(rate), inertia_matrix(inertia_rate(N, s))) <= 1e-9);
    }
}

#endif
}  // namespace
