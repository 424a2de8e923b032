// The products and involutions of the algebra, on basis blades. Every bilinear product is a
// rule  (blade a, blade b) -> ±blade or 0, and every linear map used here (involutions, grade
// projection, complements, automorphisms) is a rule  blade -> ±blade or 0. The expression
// engine (expr/) multiplies normal forms through these rules, so adding a product means adding
// a rule here and nothing else; `id` names the rule in the structural hash of expressions.
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>

#include "ctga/algebra/blade.hpp"

namespace ctga::rules {

inline constexpr signed_blade zero{0, 0};

// Every bilinear rule also has a row form: for a fixed left blade a, the right blades b it does
// not kill are those with (b & care) == want, and then
//   a ∘ b = sign · (−1)^popcount(b & parity) · blade(a ^ b ^ flip).
// Looped products (expr/looped.hpp) build their tables from it with word-wide bit operations
// over whole rows of blades instead of one rule application per pair; the engine test checks it
// against apply for every pair of several algebras.
struct row_form {
    blade_mask care = 0;
    blade_mask want = 0;  // want ⊄ care: the whole row is zero
    blade_mask parity = 0;
    int sign = 1;
    blade_mask flip = 0;
};
inline constexpr row_form dead_row{0, 1, 0, 1, 0};

// (reorder_sign(a, b) = (−1)^popcount(parity_above(a) & b) = (−1)^popcount(a & parity_below(b)),
// blade.hpp.)

// The sign of the geometric product as a parity over b: reordering, and one −1 per common
// generator squaring to −1.
template <class Alg>
constexpr row_form geometric_row(blade_mask a, blade_mask care, blade_mask want) noexcept {
    return {care, want, parity_above(a) ^ (a & Alg::negative_mask), 1, 0};
}

// Geometric product of basis blades: sort the word a·b (each swap of distinct generators flips
// the sign), then contract equal neighbours to their square. A square 0 kills the term; each
// square −1 flips the sign.
template <class Alg>
struct geometric {
    static constexpr std::uint64_t id = 1;
    static constexpr signed_blade apply(blade_mask a, blade_mask b) noexcept {
        const blade_mask common = a & b;
        if (common & Alg::null_mask) return zero;
        const int metric = (std::popcount(common & Alg::negative_mask) & 1) ? -1 : 1;
        return signed_blade{a ^ b, reorder_sign(a, b) * metric};
    }
    // b survives unless it shares a null generator with a
    static constexpr row_form row(blade_mask a) noexcept { return geometric_row<Alg>(a, a & Alg::null_mask, 0); }
};

// Exterior product: the geometric product of blades with no common generator, else 0.
template <class Alg>
struct exterior {
    static constexpr std::uint64_t id = 2;
    static constexpr signed_blade apply(blade_mask a, blade_mask b) noexcept {
        return (a & b) ? zero : signed_blade{a | b, reorder_sign(a, b)};
    }
    static constexpr row_form row(blade_mask a) noexcept { return {a, 0, parity_above(a), 1, 0}; }
};

// Left contraction a ⌋ b: the grade gr(b) − gr(a) part of ab, non-zero only when a ⊆ b.
template <class Alg>
struct left_contraction {
    static constexpr std::uint64_t id = 3;
    static constexpr signed_blade apply(blade_mask a, blade_mask b) noexcept {
        return (a & ~b) ? zero : geometric<Alg>::apply(a, b);
    }
    // a ⊆ b, so a & b = a: a null generator in a kills the row
    static constexpr row_form row(blade_mask a) noexcept {
        return (a & Alg::null_mask) ? dead_row : geometric_row<Alg>(a, a, a);
    }
};

// Right contraction a ⌊ b: the grade gr(a) − gr(b) part of ab, non-zero only when b ⊆ a.
template <class Alg>
struct right_contraction {
    static constexpr std::uint64_t id = 4;
    static constexpr signed_blade apply(blade_mask a, blade_mask b) noexcept {
        return (b & ~a) ? zero : geometric<Alg>::apply(a, b);
    }
    // b ⊆ a, and no null generator in common
    static constexpr row_form row(blade_mask a) noexcept {
        return geometric_row<Alg>(a, (Alg::pseudoscalar_mask & ~a) | (a & Alg::null_mask), 0);
    }
};

// Scalar product: the grade-0 part of ab.
template <class Alg>
struct scalar {
    static constexpr std::uint64_t id = 5;
    static constexpr signed_blade apply(blade_mask a, blade_mask b) noexcept {
        return (a != b) ? zero : geometric<Alg>::apply(a, b);
    }
    static constexpr row_form row(blade_mask a) noexcept {
        return (a & Alg::null_mask) ? dead_row : geometric_row<Alg>(a, Alg::pseudoscalar_mask, a);
    }
};

// Shuffle product ∨ (elsewhere called the regressive product), paper §4, the Grassmann–Cayley definition:
//   b ∨ c = Σ_σ sign(σ) det(b_σ(1..n−k), c_1..c_k) b_σ(n−k+1) ∧ … ∧ b_σ(j).
// For basis blades the determinant is non-zero only for the one split of b whose first part K
// is the complement of c, so b ∨ c ≠ 0 iff b ∪ c holds every generator, and then
//   b ∨ c = sign(b → K,R) · det(K, c) · R,   R = b ∩ c,
// with det(K, c) the sign that sorts the word K·c into the basis order. No metric, no
// pseudoscalar inverse: valid in degenerate algebras such as Cl(0,6,2).
template <class Alg>
struct shuffle {
    static constexpr std::uint64_t id = 6;
    static constexpr signed_blade apply(blade_mask b, blade_mask c) noexcept {
        constexpr blade_mask all = Alg::pseudoscalar_mask;
        if ((b | c) != all) return zero;
        const blade_mask k = all & ~c;
        const blade_mask r = b & c;
        return {r, reorder_sign(k, r) * reorder_sign(k, c)};
    }
    // c = K ∪ r with K = ∁b and r = b ∩ c; then k = b \ r and the sign is reorder_sign(b \ r, K)
    // = reorder_sign(b, K) · (−1)^popcount(r & parity_below(K)); the result b ∩ c = b ^ c ^ I.
    static constexpr row_form row(blade_mask b) noexcept {
        constexpr blade_mask all = Alg::pseudoscalar_mask;
        const blade_mask k = all & ~b;
        return {k, k, b & parity_below(k), reorder_sign(b, k), all};
    }
};

// ---- linear rules: blade -> ±blade or 0 ------------------------------------------------

// Reverse: a grade-k blade picks up (−1)^(k(k−1)/2).
template <class Alg>
struct reverse {
    static constexpr std::uint64_t id = 11;
    static constexpr signed_blade apply(blade_mask a) noexcept { return {a, reverse_sign(blade_grade(a))}; }
};

// Grade involution: every generator negated, (−1)^k.
template <class Alg>
struct involute {
    static constexpr std::uint64_t id = 12;
    static constexpr signed_blade apply(blade_mask a) noexcept { return {a, involute_sign(blade_grade(a))}; }
};

// Clifford conjugation, the paper's `*`: reverse of the grade involution, (−1)^(k(k+1)/2).
template <class Alg>
struct conjugate {
    static constexpr std::uint64_t id = 13;
    static constexpr signed_blade apply(blade_mask a) noexcept { return {a, conjugate_sign(blade_grade(a))}; }
};

template <class Alg, int K>
struct grade_projection {
    static constexpr std::uint64_t id = 100 + K;
    static constexpr signed_blade apply(blade_mask a) noexcept { return blade_grade(a) == K ? signed_blade{a, 1} : zero; }
};

// Metric-free complements (no pseudoscalar inverse): with I the canonical pseudoscalar,
//   a ∧ right_complement(a) = I   and   left_complement(a) ∧ a = I.
template <class Alg>
struct right_complement {
    static constexpr std::uint64_t id = 14;
    static constexpr signed_blade apply(blade_mask a) noexcept {
        const blade_mask c = Alg::pseudoscalar_mask & ~a;
        return {c, reorder_sign(a, c)};
    }
};

template <class Alg>
struct left_complement {
    static constexpr std::uint64_t id = 15;
    static constexpr signed_blade apply(blade_mask a) noexcept {
        const blade_mask c = Alg::pseudoscalar_mask & ~a;
        return {c, reorder_sign(c, a)};
    }
};

// The automorphism sending generator i to generator Perm[i] (an algebra automorphism when the
// squares agree, checked by the caller). A blade's image is the word of images, re-sorted.
template <class Alg, std::array<int, Alg::dimension> Perm>
struct permutation {
    static constexpr std::uint64_t id = [] {
        std::uint64_t h = 1000;
        for (int p : Perm) h = h * 31 + static_cast<std::uint64_t>(p);
        return h;
    }();
    static constexpr signed_blade apply(blade_mask a) noexcept {
        blade_mask image = 0;
        int sign = 1;
        for (std::size_t i = 0; i < Alg::dimension; ++i) {
            if (!(a >> i & 1u)) continue;
            const blade_mask bit = blade_mask{1} << Perm[i];
            sign *= reorder_sign(image, bit);  // appending the image of generator i on the right
            image |= bit;
        }
        return {image, sign};
    }
};

// The coefficient of one blade as a scalar: blade Mask (orientation Sign as written) → 1.
template <class Alg, blade_mask Mask, int Sign>
struct coefficient {
    static constexpr std::uint64_t id = 5000 + Mask * 2 + (Sign > 0);
    static constexpr signed_blade apply(blade_mask a) noexcept { return a == Mask ? signed_blade{0, Sign} : zero; }
};

// The embedding of an algebra whose generators are generators Offset… of a larger one, in the
// same order (Cl(0,3,1) as the e-half of Cl(0,6,2), §5): blade masks shift, orientations stay.
template <class Alg, int Offset>
struct embedding {
    static constexpr std::uint64_t id = 2000 + static_cast<std::uint64_t>(Offset);
    static constexpr signed_blade apply(blade_mask a) noexcept { return {a << Offset, 1}; }
};

// The parameterised rules as templates of the algebra alone, for the expression nodes.
template <int K>
struct grade_projection_of {
    template <class Alg>
    using rule = grade_projection<Alg, K>;
};
template <auto Perm>
struct permutation_of {
    template <class Alg>
    using rule = permutation<Alg, Perm>;
};
template <blade_mask Mask, int Sign>
struct coefficient_of {
    template <class Alg>
    using rule = coefficient<Alg, Mask, Sign>;
};

template <int Offset>
struct embedding_of {
    template <class Alg>
    using rule = embedding<Alg, Offset>;
};

}  // namespace ctga::rules
