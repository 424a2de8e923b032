// Tests of the naive dense reference (ctga::dense), the oracle of the sparse engine.
// Every expectation is an independent, hand-known fact (quaternion rules, the paper's worked
// examples, the paper's identities of §5–6), never the oracle against itself.
#include "support/catch.hpp"

#include <array>
#include <bit>
#include <cstddef>
#include <stdexcept>
#include <string_view>

#include "ctga/reference/dense.hpp"

namespace {

using ctga::blade_mask;
namespace dense = ctga::dense;

using cl020 = ctga::algebra<"e1 e2", -1, -1>;
using cl030 = ctga::algebra<"e1 e2 e3", -1, -1, -1>;
using cl300 = ctga::algebra<"e1 e2 e3", 1, 1, 1>;
using cl031 = ctga::algebra<"e1 e2 e3 e", -1, -1, -1, 0>;
using cl062 = ctga::algebra<"a1 a2 a3 a e1 e2 e3 e", -1, -1, -1, 0, -1, -1, -1, 0>;
using cl532 = ctga::algebra<"e1 e2 e3 e4 e5 e6 e7 e8 e9 e10", 1, 1, 1, 1, 1, -1, -1, -1, 0, 0>;

template <class Alg, class T = double>
using mv = dense::multivector<Alg, T>;

// coef * (blade as written)
template <class Alg, class T = double>
mv<Alg, T> B(std::string_view name, T coef = T(1)) {
    return mv<Alg, T>::blade(name, coef);
}

template <class Alg, class T = double>
mv<Alg, T> S(T value) {
    return mv<Alg, T>::scalar(value);
}

struct vec3 {
    double x, y, z;
};
vec3 cross(vec3 a, vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
vec3 operator-(vec3 a, vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
vec3 operator+(vec3 a, vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
double dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// s = ωx e2e3 + ωy e3e1 + ωz e1e2 + vx e1e + vy e2e + vz e3e (in Cl(0,3,1) or in the e-half of Cl(0,6,2))
template <class Alg>
mv<Alg> screw(vec3 w, vec3 v) {
    return B<Alg>("e2e3", w.x) + B<Alg>("e3e1", w.y) + B<Alg>("e1e2", w.z) + B<Alg>("e1e", v.x) +
           B<Alg>("e2e", v.y) + B<Alg>("e3e", v.z);
}

// P = px a2a3 + py a3a1 + pz a1a2 + lx a1a + ly a2a + lz a3a (Cl(0,6,2))
mv<cl062> coscrew(vec3 l, vec3 p) {
    return B<cl062>("a2a3", p.x) + B<cl062>("a3a1", p.y) + B<cl062>("a1a2", p.z) + B<cl062>("a1a", l.x) +
           B<cl062>("a2a", l.y) + B<cl062>("a3a", l.z);
}

mv<cl062> Q0() {
    return B<cl062>("a2a3e1e") + B<cl062>("a3a1e2e") + B<cl062>("a1a2e3e") + B<cl062>("a1ae2e3") +
           B<cl062>("a2ae3e1") + B<cl062>("a3ae1e2");
}

// N = dx a1ae1e + dy a2ae2e + dz a3ae3e + m a2a3e2e3 + m a3a1e3e1 + m a1a2e1e2
mv<cl062> diagonal_inertia(vec3 d, double m) {
    return B<cl062>("a1ae1e", d.x) + B<cl062>("a2ae2e", d.y) + B<cl062>("a3ae3e", d.z) + B<cl062>("a2a3e2e3", m) +
           B<cl062>("a3a1e3e1", m) + B<cl062>("a1a2e1e2", m);
}

// A user-defined coefficient type: exact integers with only +, -, *, unary -, == and < and
// construction from int, plus an ADL-found abs for max_abs.
struct exact {
    long long v = 0;
    exact() = default;
    exact(int i) : v(i) {}  // NOLINT: implicit on purpose, like a number type
    friend exact operator+(exact a, exact b) { return fromll(a.v + b.v); }
    friend exact operator-(exact a, exact b) { return fromll(a.v - b.v); }
    friend exact operator*(exact a, exact b) { return fromll(a.v * b.v); }
    friend exact operator-(exact a) { return fromll(-a.v); }
    friend bool operator==(exact a, exact b) { return a.v == b.v; }
    friend bool operator<(exact a, exact b) { return a.v < b.v; }
    friend exact abs(exact a) { return fromll(a.v < 0 ? -a.v : a.v); }
    static exact fromll(long long x) {
        exact e;
        e.v = x;
        return e;
    }
};

// A stand-in for a sparse-engine multivector (the interface to_dense relies on).
struct mock_layout {
    std::array<blade_mask, 3> masks;
    std::array<signed char, 3> signs;
};
struct mock_sparse {
    using algebra_type = cl031;
    static constexpr mock_layout layout{{0b0011u, 0b1001u, 0b0000u}, {-1, 1, 1}};  // e2e1, e1e, 1
    std::array<double, 3> values;
    const double& operator[](std::size_t i) const { return values[i]; }
    static constexpr std::size_t size() { return 3; }
};

}  // namespace

TEST_CASE("blade names: orientation as written, invalid names throw", "[dense]") {
    const auto x = B<cl031>("e3e1", 2.0);
    CHECK(x[0b0101u] == -2.0);  // mask of e1e3
    CHECK(B<cl031>("e1e3", 2.0)[0b0101u] == 2.0);
    CHECK(B<cl031>("e2e3e1", 1.0)[0b0111u] == 1.0);  // cyclic: even permutation
    CHECK(B<cl031>("e2e1e3", 1.0)[0b0111u] == -1.0);
    CHECK(B<cl031>("1", 5.0)[0] == 5.0);
    CHECK(B<cl062>("a3a1e1e2e3e")[0b11110101u] == -1.0);
    CHECK_THROWS_AS(B<cl031>("e4"), std::invalid_argument);
    CHECK_THROWS_AS(B<cl031>("e1e1"), std::invalid_argument);
    CHECK_THROWS_AS(B<cl031>("e1x"), std::invalid_argument);
    // longest match: "e10" is one generator of the 10-generator algebra
    CHECK(B<cl532>("e10e1")[(1u << 9) | 1u] == -1.0);
}

TEMPLATE_TEST_CASE("quaternions in Cl(0,3,0): i = e2e3, j = e3e1, k = e1e2", "[dense]", float, double, long double) {
    using T = TestType;
    const auto i = B<cl030, T>("e2e3"), j = B<cl030, T>("e3e1"), k = B<cl030, T>("e1e2");
    const auto minus_one = S<cl030, T>(T(-1));
    CHECK(dense::gp(i, i) == minus_one);
    CHECK(dense::gp(j, j) == minus_one);
    CHECK(dense::gp(k, k) == minus_one);
    CHECK(dense::gp(dense::gp(i, j), k) == minus_one);  // ijk = -1
    CHECK(dense::gp(i, j) == k);                        // Hamilton: ij = k, jk = i, ki = j
    CHECK(dense::gp(j, k) == i);
    CHECK(dense::gp(k, i) == j);
    CHECK(dense::gp(j, i) == -k);
}

TEST_CASE("quaternions in Cl(0,2,0): i = e1, j = e2, k = e1e2", "[dense]") {
    const auto i = B<cl020>("e1"), j = B<cl020>("e2"), k = B<cl020>("e1e2");
    const auto minus_one = S<cl020>(-1.0);
    CHECK(dense::gp(i, i) == minus_one);
    CHECK(dense::gp(j, j) == minus_one);
    CHECK(dense::gp(k, k) == minus_one);
    CHECK(dense::gp(dense::gp(i, j), k) == minus_one);
    CHECK(dense::gp(i, j) == k);
}

TEST_CASE("Euclidean Cl(3,0,0): e1e2e1e2 = -1, contractions", "[dense]") {
    const auto e1 = B<cl300>("e1"), e2 = B<cl300>("e2"), e12 = B<cl300>("e1e2");
    CHECK(dense::gp(e1, e1) == S<cl300>(1.0));
    CHECK(dense::gp(e12, e12) == S<cl300>(-1.0));
    CHECK(dense::gp(dense::gp(e1, e2), dense::gp(e1, e2)) == S<cl300>(-1.0));
    CHECK(dense::gp(e2, e1) == B<cl300>("e2e1"));
    CHECK(dense::gp(e2, e1) == -e12);
    // contractions of a vector and a bivector
    CHECK(dense::lcont(e1, e12) == e2);
    CHECK(dense::lcont(e2, e12) == -e1);
    CHECK(dense::lcont(e12, e1) == mv<cl300>{});
    CHECK(dense::rcont(e12, e2) == e1);
    CHECK(dense::rcont(e12, e1) == -e2);
    CHECK(dense::rcont(e1, e12) == mv<cl300>{});
    CHECK(dense::lcont(e1, e1) == S<cl300>(1.0));
    CHECK(dense::scalar_product(e12, e12) == S<cl300>(-1.0));
    CHECK(dense::scalar_product(e1, e12) == mv<cl300>{});
    // wedge: shared factor kills, disjoint factors anticommute
    CHECK(dense::wedge(e1, e1) == mv<cl300>{});
    CHECK(dense::wedge(e2, e1) == -e12);
    CHECK(dense::wedge(e12, B<cl300>("e3")) == B<cl300>("e1e2e3"));
    // vector product = contraction + wedge
    const auto a = B<cl300>("e1", 2.0) + B<cl300>("e2", 3.0), b = B<cl300>("e2", 5.0) + B<cl300>("e3", 7.0);
    CHECK(dense::gp(a, b) == dense::lcont(a, b) + dense::wedge(a, b));
    CHECK(dense::lcont(a, b) == S<cl300>(15.0));
}

TEST_CASE("degenerate squares in Cl(0,3,1)", "[dense]") {
    const auto e = B<cl031>("e"), e1 = B<cl031>("e1"), e1e = B<cl031>("e1e");
    const mv<cl031> zero;
    CHECK(dense::gp(e, e) == zero);
    CHECK(dense::gp(e1e, e1e) == zero);
    CHECK(dense::gp(e1, e1) == S<cl031>(-1.0));
    CHECK(dense::gp(e, e1) == -e1e);
    CHECK(dense::gp(e1, e1e) == -e);  // e1 e1 e = -e
    CHECK(dense::gp(e1e, e1) == e);   // e1 e e1 = -e1 e1 e = e
    CHECK(dense::lcont(e, e1e) == zero);
    CHECK(dense::lcont(e1, e1e) == -e);
    CHECK(dense::wedge(e, e) == zero);
    CHECK(dense::scalar_product(e, e) == zero);
}

TEST_CASE("shuffle product: the paper's two examples and basic facts", "[dense]") {
    // e1e2 ∨ e3e = det(e1, e2, e3, e) = 1 in Cl(0,3,1)
    CHECK(dense::shuffle(B<cl031>("e1e2"), B<cl031>("e3e")) == S<cl031>(1.0));
    // e3e ∨ e1e2 = det(e3, e, e1, e2) = +1 (an even permutation)
    CHECK(dense::shuffle(B<cl031>("e3e"), B<cl031>("e1e2")) == S<cl031>(1.0));
    // grades summing to less than n: zero
    CHECK(dense::shuffle(B<cl031>("e1"), B<cl031>("e2e3")) == mv<cl031>{});
    // a1a2a3a ∨ a3a1e1e2e3e = a3a1 (= -a1a3) in Cl(0,6,2)
    const auto r = dense::shuffle(B<cl062>("a1a2a3a"), B<cl062>("a3a1e1e2e3e"));
    CHECK(r == B<cl062>("a3a1"));
    CHECK(r[0b0101u] == -1.0);
    // the pseudoscalar I = a1...e (= AE) is the unit of ∨ on both sides, for every basis blade
    // (identity 11, AE ∨ c = c)
    const auto I = B<cl062>("a1a2a3ae1e2e3e");
    CHECK(dense::gp(B<cl062>("a1a2a3a"), B<cl062>("e1e2e3e")) == I);
    for (blade_mask m = 0; m < cl062::blade_count; ++m) {
        mv<cl062> c;
        c[m] = 3.0;
        CHECK(dense::shuffle(I, c) == c);
        CHECK(dense::shuffle(c, I) == c);
    }
}

TEST_CASE("Cl(0,6,2) identities 2-6 of the paper with concrete numbers", "[dense]") {
    const vec3 w{2, 3, 5}, v{7, 11, 13}, l{17, 19, 23}, p{29, 31, 37}, d{41, 43, 47};
    const double m = 53;
    const auto s = screw<cl062>(w, v);
    const auto P = coscrew(l, p);
    const auto q0s = dense::wedge(Q0(), s);

    // 2. Q0 ∧ s = (ωx a2a3 + ωy a3a1 + ωz a1a2 + vx a1a + vy a2a + vz a3a) e1e2e3e
    const auto expected2 = B<cl062>("a2a3e1e2e3e", w.x) + B<cl062>("a3a1e1e2e3e", w.y) +
                           B<cl062>("a1a2e1e2e3e", w.z) + B<cl062>("a1ae1e2e3e", v.x) +
                           B<cl062>("a2ae1e2e3e", v.y) + B<cl062>("a3ae1e2e3e", v.z);
    CHECK(q0s == expected2);
    const auto sbar_e = coscrew(v, w);  // ωx a2a3 + ... + vz a3a
    CHECK(q0s == dense::gp(sbar_e, B<cl062>("e1e2e3e")));

    // 3. P ∨ (Q0 ∧ s) = (P ∧ Q0) ∨ s = ω·l + v·p
    const double pairing = dot(w, l) + dot(v, p);
    CHECK(dense::shuffle(P, q0s) == S<cl062>(pairing));
    CHECK(dense::shuffle(dense::wedge(P, Q0()), s) == S<cl062>(pairing));

    // 4. A ∨ (Q0 ∧ s) = s̄, and Ā = E
    const auto A = B<cl062>("a1a2a3a"), E = B<cl062>("e1e2e3e");
    CHECK(dense::shuffle(A, q0s) == dense::bar(s));
    CHECK(dense::shuffle(A, q0s) == sbar_e);
    CHECK(dense::bar(A) == E);

    // 5. A ∨ (N ∧ s) = m vx a2a3 + m vy a3a1 + m vz a1a2 + dx ωx a1a + dy ωy a2a + dz ωz a3a
    const auto N = diagonal_inertia(d, m);
    const auto momentum = dense::shuffle(A, dense::wedge(N, s));
    CHECK(momentum == coscrew({d.x * w.x, d.y * w.y, d.z * w.z}, {m * v.x, m * v.y, m * v.z}));

    // 6. s̄ ∨ (N ∧ s) = 2 E_k = dx ωx² + dy ωy² + dz ωz² + m |v|²
    const double two_ek = d.x * w.x * w.x + d.y * w.y * w.y + d.z * w.z * w.z + m * dot(v, v);
    CHECK(dense::shuffle(dense::bar(s), dense::wedge(N, s)) == S<cl062>(two_ek));
}

TEST_CASE("Cl(0,6,2) identities 9-10 of the paper (co-adjoint action)", "[dense]") {
    const vec3 w{2, -3, 5}, v{7, 11, -13}, l{17, 19, 23}, p{-29, 31, 37}, d{41, 43, 47};
    const double m = 53;
    const auto s = screw<cl062>(w, v);
    const auto sbar = dense::bar(s);
    const auto P = coscrew(l, p);
    const auto bracket = [&](const mv<cl062>& q) { return 0.5 * (dense::gp(sbar, q) - dense::gp(q, sbar)); };

    // 9. {s, P} = ½(s̄P − Ps̄) = (ω×l + v×p, ω×p)
    CHECK(bracket(P) == coscrew(cross(w, l) + cross(v, p), cross(w, p)));

    // 10. (sN − Ns) ∧ s = 0, and ½ A ∨ ((s̄N − Ns̄) ∧ s) = {s, A ∨ (N ∧ s)}
    const auto N = diagonal_inertia(d, m);
    const auto A = B<cl062>("a1a2a3a");
    CHECK(dense::wedge(dense::gp(s, N) - dense::gp(N, s), s) == mv<cl062>{});
    const auto lhs = 0.5 * dense::shuffle(A, dense::wedge(dense::gp(sbar, N) - dense::gp(N, sbar), s));
    CHECK(lhs == bracket(dense::shuffle(A, dense::wedge(N, s))));
}

TEST_CASE("Cl(0,3,1) screws: Lie bracket, rotor and translator actions", "[dense]") {
    // 8. [s1, s2] = ½(s1 s2 − s2 s1) = (ω1×ω2, ω1×v2 − ω2×v1)
    const vec3 w1{2, 3, -5}, v1{7, -11, 13}, w2{-17, 19, 23}, v2{29, 31, -37};
    const auto s1 = screw<cl031>(w1, v1), s2 = screw<cl031>(w2, v2);
    const auto commutator = 0.5 * (dense::gp(s1, s2) - dense::gp(s2, s1));
    CHECK(commutator == screw<cl031>(cross(w1, w2), cross(w1, v2) - cross(w2, v1)));

    // Rotor r = cos(θ/2) + sin(θ/2) e1e2 rotates by +θ about z: r s r* = (Rω, Rv).
    // cos(θ/2) = 3/5, sin(θ/2) = 4/5: cos θ = -7/25, sin θ = 24/25.
    const auto r = S<cl031>(0.6) + B<cl031>("e1e2", 0.8);
    CHECK(dense::max_abs_diff(dense::gp(r, dense::conjugate(r)), S<cl031>(1.0)) < 1e-15);
    const double c = -7.0 / 25, sn = 24.0 / 25;
    const auto rot = [&](vec3 x) { return vec3{c * x.x - sn * x.y, sn * x.x + c * x.y, x.z}; };
    const auto rotated = dense::gp(dense::gp(r, s1), dense::conjugate(r));
    CHECK(dense::max_abs_diff(rotated, screw<cl031>(rot(w1), rot(v1))) < 1e-12);

    // Translator t = 1 + ½(t·e_ie): t s t* = (ω, v + t×ω), g g* = 1.
    const vec3 t{3, -2, 4};
    const auto tr = S<cl031>(1.0) + B<cl031>("e1e", 0.5 * t.x) + B<cl031>("e2e", 0.5 * t.y) + B<cl031>("e3e", 0.5 * t.z);
    CHECK(dense::gp(tr, dense::conjugate(tr)) == S<cl031>(1.0));
    CHECK(dense::gp(dense::gp(tr, s1), dense::conjugate(tr)) == screw<cl031>(w1, v1 + cross(t, w1)));
}

TEST_CASE("reverse, grade involution, Clifford conjugation signs by grade", "[dense]") {
    // grades 0..4: reverse + + - - +, involution + - + - +, conjugation + - - + +
    constexpr std::array<double, 5> rev{1, 1, -1, -1, 1}, inv{1, -1, 1, -1, 1}, conj{1, -1, -1, 1, 1};
    for (blade_mask mask = 0; mask < cl031::blade_count; ++mask) {
        const auto k = static_cast<std::size_t>(std::popcount(mask));
        mv<cl031> x;
        x[mask] = 2.0;
        CHECK(dense::reverse(x) == rev[k] * x);
        CHECK(dense::involute(x) == inv[k] * x);
        CHECK(dense::conjugate(x) == conj[k] * x);
    }
    CHECK(dense::reverse(B<cl031>("e1e2")) == B<cl031>("e2e1"));
    CHECK(dense::reverse(B<cl031>("e1e2e3")) == B<cl031>("e3e2e1"));
    CHECK(dense::involute(B<cl031>("e1e2e3")) == -B<cl031>("e1e2e3"));
    // the paper's β0 blade e e1e2e3 (grade 4) is fixed by conjugation and is -e1e2e3e
    CHECK(dense::conjugate(B<cl031>("ee1e2e3")) == B<cl031>("ee1e2e3"));
    CHECK(B<cl031>("ee1e2e3") == -B<cl031>("e1e2e3e"));
}

TEST_CASE("grade projection", "[dense]") {
    const auto x = S<cl031>(1.0) + B<cl031>("e1", 2.0) + B<cl031>("e2e3", 3.0) + B<cl031>("e3e", 4.0) +
                   B<cl031>("e1e2e3e", 5.0);
    CHECK(dense::grade(x, 0) == S<cl031>(1.0));
    CHECK(dense::grade(x, 1) == B<cl031>("e1", 2.0));
    CHECK(dense::grade(x, 2) == B<cl031>("e2e3", 3.0) + B<cl031>("e3e", 4.0));
    CHECK(dense::grade(x, 3) == mv<cl031>{});
    CHECK(dense::grade(x, 4) == B<cl031>("e1e2e3e", 5.0));
    CHECK(dense::grade(x, 5) == mv<cl031>{});
    CHECK(dense::grade(x, -1) == mv<cl031>{});
}

TEST_CASE("bar: a_i <-> e_i, a <-> e", "[dense]") {
    CHECK(dense::bar(B<cl062>("a1a2a3a")) == B<cl062>("e1e2e3e"));
    CHECK(dense::bar(B<cl062>("a3a1")) == B<cl062>("e3e1"));
    CHECK(dense::bar(B<cl062>("a1e2")) == B<cl062>("e1a2"));
    CHECK(dense::bar(B<cl062>("a2a3e1e")) == B<cl062>("e2e3a1a"));
    const auto x = S<cl062>(2.0) + B<cl062>("a3ae1", 3.0) + B<cl062>("e2e3a", -5.0);
    CHECK(dense::bar(dense::bar(x)) == x);
    // a general automorphism: e1 -> e2 -> e3 -> e1 in Cl(0,3,1)
    const std::array<int, 4> cycle{1, 2, 0, 3};
    CHECK(dense::automorphism(B<cl031>("e1e2"), cycle) == B<cl031>("e2e3"));
    CHECK(dense::automorphism(B<cl031>("e3e"), cycle) == B<cl031>("e1e"));
    CHECK(dense::automorphism(B<cl031>("e2e3"), cycle) == B<cl031>("e3e1"));
    CHECK_THROWS_AS(dense::automorphism(B<cl031>("e1"), {3, 1, 2, 0}), std::invalid_argument);  // e1 <-> e: squares differ
    CHECK_THROWS_AS(dense::automorphism(B<cl031>("e1"), {0, 0, 2, 3}), std::invalid_argument);  // not a permutation
}

TEST_CASE("metric-free complements: B ∧ rc(B) = I, lc(B) ∧ B = I", "[dense]") {
    // hand examples in Cl(0,3,1): e2 ∧ e3e1e = e1e2e3e, e1e3e ∧ e2 = e1e2e3e
    CHECK(dense::right_complement(B<cl031>("e1")) == B<cl031>("e2e3e"));
    CHECK(dense::right_complement(B<cl031>("e2")) == B<cl031>("e3e1e"));
    CHECK(dense::left_complement(B<cl031>("e2")) == B<cl031>("e1e3e"));
    CHECK(dense::right_complement(S<cl031>(1.0)) == B<cl031>("e1e2e3e"));
    CHECK(dense::right_complement(B<cl031>("e1e2e3e")) == S<cl031>(1.0));
    const auto check_all = [](auto tag) {
        using Alg = decltype(tag);
        const auto I = dense::right_complement(S<Alg>(1.0));
        for (blade_mask m = 0; m < Alg::blade_count; ++m) {
            mv<Alg> b;
            b[m] = 1.0;
            CHECK(dense::wedge(b, dense::right_complement(b)) == I);
            CHECK(dense::wedge(dense::left_complement(b), b) == I);
        }
    };
    check_all(cl031{});
    check_all(cl062{});
}

TEST_CASE("paper §5: the translated inertia (g ḡ) N (g ḡ)*, term by term", "[dense]") {
    const double tx = 2, m = 3;
    const vec3 d{5, 7, 11};
    const auto g = S<cl062>(1.0) + B<cl062>("e1e", 0.5 * tx);
    const auto gbar = dense::bar(g);
    CHECK(gbar == S<cl062>(1.0) + B<cl062>("a1a", 0.5 * tx));
    const auto G = dense::gp(g, gbar);
    // g ḡ = 1 + ½tx a1a + ½tx e1e + ¼tx² a1ae1e
    CHECK(G == S<cl062>(1.0) + B<cl062>("a1a", 0.5 * tx) + B<cl062>("e1e", 0.5 * tx) +
                   B<cl062>("a1ae1e", 0.25 * tx * tx));
    CHECK(dense::conjugate(G) == dense::gp(dense::conjugate(gbar), dense::conjugate(g)));

    const auto N = diagonal_inertia(d, m);
    const auto transformed = dense::gp(dense::gp(G, N), dense::conjugate(G));
    const auto expected = B<cl062>("a1ae1e", d.x) + B<cl062>("a2ae2e", d.y + m * tx * tx) +
                          B<cl062>("a3ae3e", d.z + m * tx * tx)                       //
                          + B<cl062>("a3ae3e1", m * tx) - B<cl062>("a2ae1e2", m * tx)  //
                          + B<cl062>("a3a1e3e", m * tx) - B<cl062>("a1a2e2e", m * tx)  //
                          + B<cl062>("a2a3e2e3", m) + B<cl062>("a3a1e3e1", m) + B<cl062>("a1a2e1e2", m);
    CHECK(transformed == expected);

    // Through A ∨ (· ∧ s) it is the paper's 6x6 matrix acting on (ω, v), giving (l, p).
    const vec3 w{13, 17, 19}, v{23, 29, 31};
    const auto P = dense::shuffle(B<cl062>("a1a2a3a"), dense::wedge(transformed, screw<cl062>(w, v)));
    const vec3 l{d.x * w.x, (d.y + m * tx * tx) * w.y - m * tx * v.z, (d.z + m * tx * tx) * w.z + m * tx * v.y};
    const vec3 p{m * v.x, m * tx * w.z + m * v.y, -m * tx * w.y + m * v.z};
    CHECK(P == coscrew(l, p));
}

TEST_CASE("a 10-generator algebra Cl(5,3,2)", "[dense]") {
    using A10 = cl532;
    STATIC_REQUIRE(A10::blade_count == 1024);
    CHECK(dense::gp(B<A10>("e1"), B<A10>("e1")) == S<A10>(1.0));
    CHECK(dense::gp(B<A10>("e6"), B<A10>("e6")) == S<A10>(-1.0));
    CHECK(dense::gp(B<A10>("e9"), B<A10>("e9")) == mv<A10>{});
    CHECK(dense::gp(B<A10>("e10"), B<A10>("e1")) == -B<A10>("e1e10"));
    // I8 = e1...e8: I8² = (-1)^(8·7/2) · (+1)^5 (-1)^3 = -1; the full pseudoscalar squares to 0
    const auto I8 = B<A10>("e1e2e3e4e5e6e7e8");
    CHECK(dense::gp(I8, I8) == S<A10>(-1.0));
    const auto I10 = B<A10>("e1e2e3e4e5e6e7e8e9e10");
    CHECK(dense::gp(I10, I10) == mv<A10>{});
    // one dense product of full multivectors (1,048,576 blade pairs), checked for associativity
    // with small integers (exact in double)
    mv<A10> x, y, z;
    for (blade_mask m = 0; m < A10::blade_count; ++m) {
        x[m] = static_cast<double>(static_cast<int>(m * 7u % 5u) - 2);
        y[m] = static_cast<double>(static_cast<int>(m * 3u % 7u) - 3);
        z[m] = (m % 97u == 0) ? static_cast<double>(m % 5u) - 2.0 : 0.0;
    }
    CHECK(dense::gp(dense::gp(x, y), z) == dense::gp(x, dense::gp(y, z)));
    CHECK(dense::shuffle(I10, x) == x);
}

TEST_CASE("generic coefficient types", "[dense]") {
    // a user type: quaternion rules and degenerate square, exactly
    const auto i = B<cl031, exact>("e2e3"), j = B<cl031, exact>("e3e1"), k = B<cl031, exact>("e1e2");
    CHECK(dense::gp(i, j) == k);
    CHECK(dense::gp(dense::gp(i, j), k) == S<cl031, exact>(exact(-1)));
    CHECK(dense::gp(B<cl031, exact>("e"), B<cl031, exact>("e")) == mv<cl031, exact>{});
    const auto x = B<cl031, exact>("e1e", exact(-7)) + B<cl031, exact>("e2", exact(3));
    CHECK(dense::max_abs(x).v == 7);
    CHECK(dense::max_abs_diff(x, B<cl031, exact>("e2", exact(3))).v == 7);
    CHECK(dense::shuffle(B<cl031, exact>("e1e2"), B<cl031, exact>("e3e")) == S<cl031, exact>(exact(1)));
}

TEST_CASE("max_abs, to_string, to_dense", "[dense]") {
    const auto x = B<cl062>("a2a3", 3.0) + B<cl062>("e1e", 2.0);
    CHECK(dense::to_string(x) == "3*a2a3 + 2*e1e");
    CHECK(dense::to_string(B<cl062>("a3a2", 3.0)) == "-3*a2a3");
    CHECK(dense::to_string(mv<cl062>{}) == "0");
    CHECK(dense::to_string(S<cl031>(1.5) + B<cl031>("e", 0.25)) == "1.5 + 0.25*e");
    CHECK(dense::max_abs(x - B<cl062>("a", 4.0)) == 4.0);
    CHECK(dense::max_abs_diff(x, B<cl062>("a2a3", 3.0)) == 2.0);
    CHECK(x / 2.0 == 0.5 * x);
    CHECK(x * 2.0 == x + x);

    const mock_sparse sparse{{3.0, 5.0, 7.0}};  // 3 e2e1 + 5 e1e + 7
    const auto dense_copy = dense::to_dense(sparse);
    static_assert(std::is_same_v<std::remove_cvref_t<decltype(dense_copy)>, mv<cl031, double>>);
    CHECK(dense_copy == B<cl031>("e2e1", 3.0) + B<cl031>("e1e", 5.0) + S<cl031>(7.0));
}
