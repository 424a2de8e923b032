// The paper's worked examples of §4 and identities 1–4 of shared conventions, exactly.
// The engine is constexpr, so each identity is first a static_assert on integer-valued
// coefficients (exact in floating point), then checked at run time on random inputs against
// the dense reference.
#include <random>

#include <ctga/ctga.hpp>
#include <ctga/reference/dense.hpp>

#include "support/catch.hpp"
#include "support/properties.hpp"

namespace {

using namespace ctga;

using G = cl062;
// Paper §5: screws on the e's, co-screws on the a's, written as the paper writes them.
using screw6 = G::mv<double, "e2e3", "e3e1", "e1e2", "e1e", "e2e", "e3e">;   // (ω, v)
using coscrew = G::mv<double, "a2a3", "a3a1", "a1a2", "a1a", "a2a", "a3a">;  // (p, l)
using Q0_type = G::mv<double, "a2a3e1e", "a3a1e2e", "a1a2e3e", "a1ae2e3", "a2ae3e1", "a3ae1e2">;

constexpr Q0_type Q0{1, 1, 1, 1, 1, 1};
constexpr auto A = G::blade<"a1a2a3a">();
constexpr auto E = G::blade<"e1e2e3e">();

constexpr double wx = 2, wy = -3, wz = 5, vx = 7, vy = -11, vz = 13;
constexpr double px = 17, py = 19, pz = -23, lx = 29, ly = 31, lz = -37;
constexpr screw6 s{wx, wy, wz, vx, vy, vz};
constexpr coscrew P{px, py, pz, lx, ly, lz};

TEST_CASE("§4: e1e2 ∨ e3e = 1 in Cl(0,3,1)", "[paper][shuffle]") {
    constexpr auto r = cl031::blade<"e1e2">() & cl031::blade<"e3e">();
    static_assert(r == cl031::blade<"1">());
    static_assert(decltype(r)::size() == 1);
    CHECK(scalar_part(r) == 1.0);
}

TEST_CASE("§4: a1a2a3a ∨ a3a1e1e2e3e = a3a1 in Cl(0,6,2)", "[paper][shuffle]") {
    constexpr auto r = G::blade<"a1a2a3a">() & G::blade<"a3a1e1e2e3e">();
    static_assert(r == G::blade<"a3a1">());
    static_assert(r.get<"a3a1">() == 1.0 && r.get<"a1a3">() == -1.0);
    CHECK(get<"a3a1">(r) == 1.0);
}

TEST_CASE("identity 2: Q0 ∧ s = (ωx a2a3 + ωy a3a1 + ωz a1a2 + vx a1a + vy a2a + vz a3a) e1e2e3e",
          "[paper][identities]") {
    constexpr auto lhs = Q0 ^ s;
    constexpr coscrew s_on_a{wx, wy, wz, vx, vy, vz};
    constexpr auto rhs = eval(s_on_a * E);
    static_assert(lhs == rhs);
    static_assert(decltype(lhs)::size() == 6, "Q0 ∧ s has exactly six blades");
    CHECK(lhs == rhs);
}

TEST_CASE("identity 3: P ∨ (Q0 ∧ s) = (P ∧ Q0) ∨ s = ω·l + v·p", "[paper][identities]") {
    constexpr double evaluation = wx * lx + wy * ly + wz * lz + vx * px + vy * py + vz * pz;
    constexpr auto left = P & (Q0 ^ s);
    constexpr auto right = (P ^ Q0) & s;
    static_assert(decltype(left)::size() == 1 && decltype(right)::size() == 1, "a scalar and nothing else");
    static_assert(scalar_part(left) == evaluation);
    static_assert(scalar_part(right) == evaluation);

    std::mt19937_64 rng(3);
    for (int trial = 0; trial < 100; ++trial) {
        const auto sr = test::random_fill<screw6>(rng);
        const auto pr = test::random_fill<coscrew>(rng);
        const double dot = get<"e2e3">(sr) * get<"a1a">(pr) + get<"e3e1">(sr) * get<"a2a">(pr) +
                           get<"e1e2">(sr) * get<"a3a">(pr) + get<"e1e">(sr) * get<"a2a3">(pr) +
                           get<"e2e">(sr) * get<"a3a1">(pr) + get<"e3e">(sr) * get<"a1a2">(pr);
        // inputs in [-1, 1]: the six products sum to at most 6 in magnitude
        CHECK(scalar_part(pr & (Q0 ^ sr)) == Approx(dot).margin(1e-14));
        CHECK(scalar_part((pr ^ Q0) & sr) == Approx(dot).margin(1e-14));
        test::check_close("P ∨ (Q0 ∧ s) against dense", pr & (Q0 ^ sr),
                          dense::shuffle(dense::to_dense(pr), dense::wedge(dense::to_dense(Q0), dense::to_dense(sr))));
    }
}

TEST_CASE("identity 4: A ∨ (Q0 ∧ s) = s̄, and Ā = E", "[paper][identities]") {
    static_assert((A & (Q0 ^ s)) == bar(s));
    static_assert(bar(A) == E);
    static_assert(bar(E) == A);
    std::mt19937_64 rng(4);
    for (int trial = 0; trial < 100; ++trial) {
        const auto sr = test::random_fill<screw6>(rng);
        CHECK((A & (Q0 ^ sr)) == bar(sr));
        test::check_close("s̄ against dense", bar(sr), dense::bar(dense::to_dense(sr)));
    }
}

}  // namespace
