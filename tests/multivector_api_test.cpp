// The multivector API: blades named in the paper's spelling with their written orientation,
// component access, conversion between blade sets, printing, and compile-time evaluation.
#include <complex>
#include <sstream>
#include <type_traits>

#include <ctga/ctga.hpp>
#include <ctga/reference/dense.hpp>

#include "support/catch.hpp"

namespace {

using namespace ctga;
using screw = cl031::mv<double, "e2e3", "e3e1", "e1e2", "e1e", "e2e", "e3e">;
using rotor = cl031::mv<double, "1", "e2e3", "e3e1", "e1e2">;
using motor = cl031::mv<double, "1", "e2e3", "e3e1", "e1e2", "ee1e2e3", "e1e", "e2e", "e3e">;

TEST_CASE("blade names: orientation as written, longest generator match", "[api]") {
    static_assert(cl031::parse_blade("e3e1").mask == 0b0101 && cl031::parse_blade("e3e1").sign == -1);
    static_assert(cl031::parse_blade("e1e3").sign == 1);
    static_assert(cl031::parse_blade("ee1e2e3").mask == 0b1111 && cl031::parse_blade("ee1e2e3").sign == -1);
    static_assert(cl031::parse_blade("1").mask == 0);
    static_assert(cl031::parse_blade("e4").status == blade_name_status::unknown_generator);
    static_assert(cl031::parse_blade("e1e1").status == blade_name_status::repeated_generator);
    using ten = algebra<"e1 e2 e3 e4 e5 e6 e7 e8 e9 e10", 1, 1, 1, 1, 1, 1, 1, 1, 1, 1>;
    static_assert(ten::parse_blade("e10e1").mask == ((1u << 9) | 1u) && ten::parse_blade("e10e1").sign == -1);
    static_assert(cl062::parse_blade("a1ae1e").mask == 0b10011001);
    // the dense reference reads names its own way and must agree
    CHECK(dense::multivector<cl062>::blade("a3ae3e1", 2.0)[cl062::parse_blade("a3ae3e1").mask] ==
          2.0 * cl062::parse_blade("a3ae3e1").sign);
}

TEST_CASE("components are stored as written and read under any spelling", "[api]") {
    constexpr screw s{1, 2, 3, 4, 5, 6};
    static_assert(s[1] == 2 && get<"e3e1">(s) == 2 && get<"e1e3">(s) == -2);
    static_assert(s.get<"e1e">() == 4 && s.get<"ee1">() == -4);
    static_assert(get<"e1e2e3e">(s) == 0, "a blade the type does not hold reads as zero");
    screw t = s;
    t.set<"e1e3">(7.0);
    CHECK(get<"e3e1">(t) == -7.0);
    CHECK(t[1] == -7.0);
    static_assert(cl031::blade<"e3e1">(2.0) == cl031::blade<"e1e3">(-2.0));
    static_assert(cl031::generator<3>() == cl031::blade<"e">());
    static_assert(std::is_same_v<std::remove_cvref_t<decltype(s.components())>, std::array<double, 6>>);
    static_assert(sizeof(screw) == 6 * sizeof(double), "exactly the stored blades, nothing else");
}

TEST_CASE("conversion to a wider blade set keeps values, projection drops on purpose", "[api]") {
    constexpr rotor r{0.5, 0.5, -0.5, 0.5};
    constexpr motor g = r;  // a rotor is a motor
    static_assert(get<"e3e1">(g) == -0.5 && get<"1">(g) == 0.5 && get<"e1e">(g) == 0);
    constexpr auto sq = screw{1, 2, 3, 4, 5, 6} * screw{6, 5, 4, 3, 2, 1};
    constexpr screw part = project<screw>(sq);  // grade 2 only
    static_assert(part == grade<2>(sq));
    CHECK(part == grade<2>(sq));
}

TEST_CASE("result types hold only structurally non-zero blades", "[api]") {
    constexpr screw s{1, 2, 3, 4, 5, 6};
    // two screws (bivectors of Cl(0,3,1), §3): grades 0, 2 and 4 only, 1 + 6 + 1 blades of 16
    using product = decltype(s * screw{});
    static_assert(product::size() == 8);
    static_assert([] {
        for (auto m : product::layout.masks) if (blade_grade(m) % 2) return false;
        return true;
    }());
    static_assert(decltype(s ^ screw{})::size() == 1, "two screws wedge to e1e2e3e alone");
    // a screw squared: −|ω|² and −2ω·v e1e2e3e; the zero bivector part is numerical here (the
    // plan sees two operands; merging equal leaves is the expression engine's job)
    static_assert(scalar_part(s * s) == -(1 + 4 + 9));
    static_assert(get<"e1e2e3e">(s * s) == 2 * (1 * 4 + 2 * 5 + 3 * 6));
    static_assert(grade<2>(s * s) == screw{});
    static_assert(decltype(cl031::blade<"e">() * cl031::blade<"e">())::size() == 0, "e² = 0 leaves no term");
    // sign-only maps stay within the blades: their results assign to the operand's type
    constexpr screw reversed = ~s, conjugated = conj(s), involuted = involute(s);
    static_assert(reversed == -s && conjugated == -s && involuted == s);
}

TEST_CASE("operator<< names blades in their stored orientation", "[api]") {
    const auto str = [](const auto& x) {
        std::ostringstream os;
        os << x;
        return os.str();
    };
    CHECK(str(screw{1, -2, 0, 4, 0, 6}) == "e2e3 - 2*e3e1 + 4*e1e + 6*e3e");
    CHECK(str(3.0 * cl062::blade<"a2a3">() + cl062::blade<"e1e">(2.0)) == "3*a2a3 + 2*e1e");
    CHECK(str(1.0 + cl031::blade<"e1e">(0.5)) == "1 + 0.5*e1e");
    // a coefficient of ±1 is its sign alone; the scalar keeps its number
    CHECK(str(cl062::blade<"a2a3">() + cl062::blade<"a3a">(0.3)) == "a2a3 + 0.3*a3a");
    CHECK(str(cl031::mv<double, "e1e2", "e3">{-1, 2}) == "-e1e2 + 2*e3");
    CHECK(str(cl031::mv<double, "1", "e1e", "e2e">{-1, -1, 1}) == "-1 - e1e + e2e");
    CHECK(str(screw{0, 1, 0, 0, 0, -1}) == "e3e1 - e3e");
    // zero: zero values and an empty blade set
    CHECK(str(screw{}) == "0");
    CHECK(str(motor{}) == "0");
    CHECK(str(cl031::blade<"e">() * cl031::blade<"e">()) == "0");
    // a negatively oriented blade: the canonical name with its last two generators swapped, the
    // names Cl(3,0,1) points and screws are declared with
    using pga = algebra<"e0 e1 e2 e3", 0, 1, 1, 1>;
    using point = pga::mv<double, "e0e3e2", "e0e1e3", "e0e2e1", "e1e2e3">;
    CHECK(str(point{0.5, -2, 3, 1}) == "0.5*e0e3e2 - 2*e0e1e3 + 3*e0e2e1 + e1e2e3");
    CHECK(str(pga::mv<double, "e0e3e1", "e1e2e3">{-1, 1}) == "-e0e3e1 + e1e2e3");
    CHECK(str(pga::mv<double, "e3e1", "e2e1", "e0e2">{1, -0.5, 2}) == "e3e1 - 0.5*e2e1 + 2*e0e2");
    CHECK(str(cl062::mv<double, "a3a1", "e3e1">{2, 1}) == "2*a3a1 + e3e1");
    // grade 4 follows the same rule, which need not give the declared word (motor: ee1e2e3)
    CHECK(str(motor{1, 0, 0, 0, 2, 0, 0, 0}) == "1 + 2*e1e2ee3");
    CHECK(str(cl062::mv<double, "a2ae3e1", "a3a1e2e">{1, 1}) == "a2ae3e1 + a1a3ee2");
    // a positively oriented blade prints its canonical name
    CHECK(str(cl062::mv<double, "a3a1e3e1">{2}) == "2*a1a3e1e3");
    // a scalar type that is not arithmetic: (c)*name, every component written
    CHECK(str(cl031::mv<std::complex<double>, "1", "e3e1">{1.0, 2.0}) == "((1,0)) + ((2,0))*e3e1");
}

TEST_CASE("everything is constexpr and noexcept", "[api]") {
    constexpr screw a{1, 0, 0, 0, 1, 0}, b{0, 1, 0, 0, 0, 1};
    // as a formula, a and b are one leaf each and the grade-0 and grade-4 parts cancel exactly
    constexpr auto lie_bracket = formula([](auto x, auto y) { return half * (x * y - y * x); });
    constexpr screw bracket = lie_bracket(a, b);
    // with plain operators the four operands are four leaves: the type keeps grades 0 and 4
    static_assert(decltype(0.5 * (a * b - b * a))::size() == 8 && decltype(lie_bracket(a, b))::size() == 6);
    static_assert(get<"e1e2">(bracket) == 1, "[ωx, ωy] = ωz");
    static_assert(noexcept(a * b) && noexcept(a ^ b) && noexcept(a & b) && noexcept(a | b));
    static_assert(noexcept(~a) && noexcept(conj(a)) && noexcept(bar(cl062::blade<"a1a">())));
    static_assert(std::is_trivially_copyable_v<screw>);
    CHECK(get<"e1e2">(bracket) == 1.0);
    // an expression is lazy: nothing is computed until it is assigned, evaluated or read
    static_assert(!multivector_type<decltype(a * b)> && expression_type<decltype(a * b)>);
    static_assert(multivector_type<decltype(eval(a * b))>);
}

}  // namespace
