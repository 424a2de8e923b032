// ctga::dense: the deliberately naive, run-time, dense reference implementation.
//
// It stores all 2^n components of a multivector and evaluates every product by visiting all
// 2^n x 2^n pairs of basis blades through a run-time table. It is the test oracle of the
// compile-time sparse engine and the baseline of its benchmarks, so it shares no product code
// with it: from include/ctga/algebra/ it uses only the type ctga::blade_mask and the algebra's
// description (dimension, blade_count, squares, generator_name, parse_blade). Every sign is
// derived here, independently, by manipulating words of generators:
//
//   * a basis blade is a word (ordered list) of generator indices; its canonical orientation is
//     the ascending order, and its index (mask) has bit i set iff generator i occurs;
//   * the geometric product of two blades is the concatenated word, reduced by adjacent
//     transpositions (e_i e_j = -e_j e_i for i != j: generators of an orthogonal basis
//     anticommute) and contractions (e_i e_i = square of e_i, which may be 0);
//   * the other products are read off their definitions (grade parts, disjointness, and for the
//     shuffle product the Grassmann-Cayley determinant formula of the paper's section 4).
//
// Nothing here aims at speed. Tables are std::vector, built on first use per algebra and per
// product kind (function-local statics, so thread-safe initialisation).
#pragma once

#include <array>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "ctga/algebra/blade.hpp"      // only for ctga::blade_mask
#include "ctga/algebra/algebra.hpp"  // only for the algebra's description

namespace ctga::dense {

// 2^10 blades, tables of 2^20 entries per product kind: the largest size this naive scheme targets.
inline constexpr std::size_t max_generators = 10;

namespace detail {

// ---------------------------------------------------------------------------------------------
// Words of generators
// ---------------------------------------------------------------------------------------------

// The product e_{g[0]} e_{g[1]} ... e_{g[len-1]} of generators, in the written order. The
// capacity holds the concatenation of two blades.
struct word {
    std::array<int, 2 * max_generators> g{};
    int len = 0;

    void push(int generator) {
        if (len == static_cast<int>(g.size())) throw std::logic_error("ctga::dense: word overflow");
        g[static_cast<std::size_t>(len++)] = generator;
    }
    [[nodiscard]] int operator[](int i) const { return g[static_cast<std::size_t>(i)]; }
    [[nodiscard]] int& operator[](int i) { return g[static_cast<std::size_t>(i)]; }
};

// A signed basis blade: sign * (canonical blade `mask`); sign == 0 stands for zero.
struct term {
    blade_mask mask = 0;
    int sign = 0;
};

// The canonical basis blade `m`: its generators in ascending (declared) order.
inline word word_of(blade_mask m, int n) {
    word w;
    for (int i = 0; i < n; ++i)
        if ((m >> i) & 1u) w.push(i);
    return w;
}

// The set of generators of a word (meaningful for words without repeats).
inline blade_mask mask_of(const word& w) {
    blade_mask m = 0;
    for (int i = 0; i < w.len; ++i) m |= blade_mask{1} << w[i];
    return m;
}

inline word concat(const word& a, const word& b) {
    word w = a;
    for (int i = 0; i < b.len; ++i) w.push(b[i]);
    return w;
}

inline bool contains(const word& w, int generator) {
    for (int i = 0; i < w.len; ++i)
        if (w[i] == generator) return true;
    return false;
}

// Exterior product of generators: v_1 ∧ ... ∧ v_m = sign * (the v's in ascending order), where
// sign is the sign of the permutation sorting the word, found here by bubble sort (each
// adjacent transposition of two distinct vectors flips the sign: v ∧ w = -w ∧ v); 0 when a
// generator repeats (v ∧ v = 0). This is also
//   * the sign of a permutation given as a sequence of distinct integers, and
//   * the determinant of m = n basis vectors (the matrix of unit columns): its permutation sign,
//     or 0 for a repeated column.
inline int sort_sign(word w) {
    int sign = 1;
    for (bool swapped = true; swapped;) {
        swapped = false;
        for (int i = 0; i + 1 < w.len; ++i) {
            if (w[i] == w[i + 1]) return 0;
            if (w[i] > w[i + 1]) {
                std::swap(w[i], w[i + 1]);
                sign = -sign;
                swapped = true;
            }
        }
    }
    return sign;
}

// Geometric product of generators of an orthogonal basis: reduce the word to a signed canonical
// blade using only
//   e_i e_j = -e_j e_i  (i != j)     and     e_i e_i = squares[i]  (+1, -1 or 0).
// Adjacent transpositions sort the word (bubble sort), equal neighbours contract; a zero square
// kills the whole term. Terminates: a swap removes one inversion, a contraction two letters.
inline term reduce(word w, const int* squares) {
    int sign = 1;
    for (bool changed = true; changed;) {
        changed = false;
        int i = 0;
        while (i + 1 < w.len) {
            if (w[i] == w[i + 1]) {
                sign *= squares[w[i]];
                if (sign == 0) return {};
                for (int k = i; k + 2 < w.len; ++k) w[k] = w[k + 2];
                w.len -= 2;
                changed = true;
            } else if (w[i] > w[i + 1]) {
                std::swap(w[i], w[i + 1]);
                sign = -sign;
                changed = true;
                ++i;
            } else {
                ++i;
            }
        }
    }
    // No equal neighbours and no descent left: the word is strictly ascending, i.e. canonical.
    return {mask_of(w), sign};
}

// ---------------------------------------------------------------------------------------------
// Products of two canonical basis blades a, b, each from its definition
// ---------------------------------------------------------------------------------------------

enum class product_kind { geometric, exterior, left_contraction, right_contraction, scalar, shuffle };

inline int word_grade(const word& w) { return w.len; }

inline term geometric_term(blade_mask a, blade_mask b, int n, const int* squares) {
    return reduce(concat(word_of(a, n), word_of(b, n)), squares);
}

// a ∧ b: for blades sharing no generator the factors are orthogonal, so the exterior product
// equals the geometric product; a shared generator makes it 0.
inline term exterior_term(blade_mask a, blade_mask b, int n, const int* squares) {
    const word wa = word_of(a, n), wb = word_of(b, n);
    for (int i = 0; i < wa.len; ++i)
        if (contains(wb, wa[i])) return {};
    return reduce(concat(wa, wb), squares);
}

// <ab>_k: the grade-k part of the geometric product of two basis blades (a single blade or 0).
inline term grade_part_of_product(blade_mask a, blade_mask b, int k, int n, const int* squares) {
    if (k < 0) return {};
    const term t = geometric_term(a, b, n, squares);
    if (t.sign == 0 || word_grade(word_of(t.mask, n)) != k) return {};
    return t;
}

// Left contraction a ⌋ b = <ab>_{gr(b)-gr(a)} (0 when gr(a) > gr(b)). For basis blades the
// product has grade gr(b)-gr(a) exactly when a's generators are among b's.
inline term left_contraction_term(blade_mask a, blade_mask b, int n, const int* squares) {
    const int ga = word_grade(word_of(a, n)), gb = word_grade(word_of(b, n));
    return grade_part_of_product(a, b, gb - ga, n, squares);
}

// Right contraction a ⌊ b = <ab>_{gr(a)-gr(b)} (0 when gr(b) > gr(a)).
inline term right_contraction_term(blade_mask a, blade_mask b, int n, const int* squares) {
    const int ga = word_grade(word_of(a, n)), gb = word_grade(word_of(b, n));
    return grade_part_of_product(a, b, ga - gb, n, squares);
}

// Scalar product a * b = <ab>_0.
inline term scalar_term(blade_mask a, blade_mask b, int n, const int* squares) {
    return grade_part_of_product(a, b, 0, n, squares);
}

// Shuffle product, literally the Grassmann-Cayley definition of the paper's §4.
// For b = b_1 ∧ ... ∧ b_j and c = c_1 ∧ ... ∧ c_k (here: the generators of the canonical
// blades, ascending) with j + k >= n:
//
//   b ∨ c = Σ_σ sign(σ) det(b_σ(1), ..., b_σ(n-k), c_1, ..., c_k) b_σ(n-k+1) ∧ ... ∧ b_σ(j),
//
// over the shuffles σ of 1..j (σ(1) < ... < σ(n-k) and σ(n-k+1) < ... < σ(j)), i.e. over the
// (n-k)-subsets of b's factors; and b ∨ c = 0 when j + k < n. det of n basis vectors is the sign
// of the permutation sorting them into the declared order (0 on a repeat), so no metric and no
// pseudoscalar inverse is involved.
inline term shuffle_term(blade_mask b, blade_mask c, int n) {
    const word bw = word_of(b, n), cw = word_of(c, n);
    const int j = bw.len, k = cw.len;
    if (j + k < n) return {};
    const int r = n - k;  // number of b's factors entering the determinant; 0 <= r <= j

    term result{};
    int nonzero_terms = 0;
    std::array<int, max_generators> chosen{};  // σ(1) < ... < σ(r), as 0-based positions in b
    for (int i = 0; i < r; ++i) chosen[static_cast<std::size_t>(i)] = i;
    for (;;) {
        word sigma, det_columns, rest;
        std::array<bool, max_generators> in_det{};
        for (int i = 0; i < r; ++i) {
            const int p = chosen[static_cast<std::size_t>(i)];
            in_det[static_cast<std::size_t>(p)] = true;
            sigma.push(p);
            det_columns.push(bw[p]);
        }
        for (int p = 0; p < j; ++p) {
            if (in_det[static_cast<std::size_t>(p)]) continue;
            sigma.push(p);  // σ(r+1) < ... < σ(j): the remaining positions, increasing
            rest.push(bw[p]);
        }
        for (int i = 0; i < k; ++i) det_columns.push(cw[i]);

        const int det = sort_sign(det_columns);
        if (det != 0) {
            // `rest` is an increasing subsequence of b's ascending generators, so the wedge
            // b_σ(r+1) ∧ ... ∧ b_σ(j) is its canonical blade with sign +1.
            const int sign_sigma = sort_sign(sigma);
            // Only the subset complementary to c can give distinct columns: at most one term.
            if (++nonzero_terms > 1)
                throw std::logic_error("ctga::dense: shuffle of basis blades gave several terms");
            result = {mask_of(rest), sign_sigma * det};
        }

        // next r-subset of {0, ..., j-1} in lexicographic order
        int i = r - 1;
        while (i >= 0 && chosen[static_cast<std::size_t>(i)] == j - r + i) --i;
        if (i < 0) break;
        ++chosen[static_cast<std::size_t>(i)];
        for (int t = i + 1; t < r; ++t)
            chosen[static_cast<std::size_t>(t)] = chosen[static_cast<std::size_t>(t - 1)] + 1;
    }
    return result;
}

// Table entry (a, b) at index a * blade_count + b: the product of the canonical blades a and b.
using product_table = std::vector<term>;

inline product_table build_product_table(product_kind kind, int n, const int* squares) {
    const std::size_t count = std::size_t{1} << n;
    product_table table(count * count);
    for (std::size_t a = 0; a < count; ++a) {
        for (std::size_t b = 0; b < count; ++b) {
            const auto ma = static_cast<blade_mask>(a), mb = static_cast<blade_mask>(b);
            term t;
            switch (kind) {
                case product_kind::geometric: t = geometric_term(ma, mb, n, squares); break;
                case product_kind::exterior: t = exterior_term(ma, mb, n, squares); break;
                case product_kind::left_contraction: t = left_contraction_term(ma, mb, n, squares); break;
                case product_kind::right_contraction: t = right_contraction_term(ma, mb, n, squares); break;
                case product_kind::scalar: t = scalar_term(ma, mb, n, squares); break;
                case product_kind::shuffle: t = shuffle_term(ma, mb, n); break;
            }
            table[a * count + b] = t;
        }
    }
    return table;
}

// Built on first use, once per algebra and product kind.
template <class Alg, product_kind Kind>
const product_table& table_for() {
    static const product_table table =
        build_product_table(Kind, static_cast<int>(Alg::dimension), Alg::squares.data());
    return table;
}

// ---------------------------------------------------------------------------------------------
// Maps of single basis blades
// ---------------------------------------------------------------------------------------------

enum class unary_kind { reverse, involute, conjugate };

// Reverse: b_1 b_2 ... b_k -> b_k ... b_2 b_1, re-sorted. Grade involution: every generator
// negated, b_i -> -b_i. Clifford conjugation: the reverse of the grade involution.
inline term unary_term(unary_kind kind, blade_mask m, int n) {
    const word w = word_of(m, n);
    word reversed;
    for (int i = w.len - 1; i >= 0; --i) reversed.push(w[i]);
    const int negations = (w.len % 2 == 0) ? 1 : -1;  // (-b_1)(-b_2)...(-b_k) = (-1)^k b_1...b_k
    switch (kind) {
        case unary_kind::reverse: return {m, sort_sign(reversed)};
        case unary_kind::involute: return {m, negations};
        case unary_kind::conjugate: return {m, negations * sort_sign(reversed)};
    }
    return {};
}

template <class Alg, unary_kind Kind>
const std::vector<term>& unary_table_for() {
    static const std::vector<term> table = [] {
        std::vector<term> t(Alg::blade_count);
        for (std::size_t m = 0; m < Alg::blade_count; ++m)
            t[m] = unary_term(Kind, static_cast<blade_mask>(m), static_cast<int>(Alg::dimension));
        return t;
    }();
    return table;
}

// Metric-free complements with respect to I = all generators in ascending order. For a basis
// blade B with complementary canonical blade C (the remaining generators, ascending), B ∧ C = s I
// with s = ±1, so rc(B) = s C satisfies B ∧ rc(B) = s² I = I; likewise lc(B) = s' C with
// C ∧ B = s' I gives lc(B) ∧ B = I.
inline term right_complement_term(blade_mask b, int n) {
    const blade_mask all = static_cast<blade_mask>((std::size_t{1} << n) - 1);
    const blade_mask c = all & ~b;
    return {c, sort_sign(concat(word_of(b, n), word_of(c, n)))};
}

inline term left_complement_term(blade_mask b, int n) {
    const blade_mask all = static_cast<blade_mask>((std::size_t{1} << n) - 1);
    const blade_mask c = all & ~b;
    return {c, sort_sign(concat(word_of(c, n), word_of(b, n)))};
}

// Algebra automorphism induced by the generator permutation e_i -> e_perm[i]:
// b_1 b_2 ... b_k -> e_perm[b_1] ... e_perm[b_k], re-sorted.
inline term permuted_term(blade_mask m, int n, const int* perm) {
    const word w = word_of(m, n);
    word image;
    for (int i = 0; i < w.len; ++i) image.push(perm[w[i]]);
    return {mask_of(image), sort_sign(image)};
}

// ---------------------------------------------------------------------------------------------
// Blade names
// ---------------------------------------------------------------------------------------------

// Read a blade name as the word of its generators in the written order. Generators are matched
// longest first (so "e10" is one generator when the algebra names one so); "1" or "" is the
// scalar. Throws std::invalid_argument on an unknown generator.
template <class Alg>
word read_word(std::string_view name) {
    word w;
    if (name == "1") return w;
    std::size_t pos = 0;
    while (pos < name.size()) {
        std::size_t best = Alg::dimension, best_len = 0;
        for (std::size_t g = 0; g < Alg::dimension; ++g) {
            const std::string_view gen = Alg::generator_name(g);
            if (gen.size() > best_len && name.substr(pos, gen.size()) == gen) {
                best = g;
                best_len = gen.size();
            }
        }
        if (best == Alg::dimension)
            throw std::invalid_argument("ctga::dense: unknown generator in blade name \"" + std::string(name) + "\"");
        if (w.len == static_cast<int>(max_generators))
            throw std::invalid_argument("ctga::dense: blade name too long: \"" + std::string(name) + "\"");
        w.push(static_cast<int>(best));
        pos += best_len;
    }
    return w;
}

template <class Alg>
std::string blade_name(blade_mask m) {
    std::string s;
    for (std::size_t i = 0; i < Alg::dimension; ++i)
        if ((m >> i) & 1u) s += Alg::generator_name(i);
    return s;
}

}  // namespace detail

// =============================================================================================
// The dense multivector
// =============================================================================================

template <class Alg, class T = double>
class multivector {
    static_assert(Alg::dimension <= max_generators,
                  "ctga::dense: the naive dense reference supports at most 10 generators");

public:
    using algebra_type = Alg;
    using value_type = T;
    static constexpr std::size_t blade_count = Alg::blade_count;

    // All 2^n components zero.
    multivector() { c_.fill(T(0)); }

    // Component of the canonical basis blade with bitmask m (bit i = generator i).
    T& operator[](blade_mask m) {
        assert(m < blade_count);
        return c_[m];
    }
    const T& operator[](blade_mask m) const {
        assert(m < blade_count);
        return c_[m];
    }
    [[nodiscard]] const std::array<T, Alg::blade_count>& components() const noexcept { return c_; }

    // coef * (blade as written): blade("e3e1", 2) stores -2 at the mask of e1e3.
    // Throws std::invalid_argument for an unknown or repeated generator.
    static multivector blade(std::string_view name, T coef = T(1)) {
        const detail::word w = detail::read_word<Alg>(name);
        // The written order relates to the ascending one by the sign of the sorting permutation
        // (generators anticommute); a repeated generator is not a blade name.
        const int sign = detail::sort_sign(w);
        const auto parsed = Alg::parse_blade(name);
        if (sign == 0 || parsed.status != blade_name_status::ok)
            throw std::invalid_argument("ctga::dense: invalid blade name \"" + std::string(name) + "\"");
        const blade_mask mask = detail::mask_of(w);
        if (parsed.mask != mask || parsed.sign != sign)
            throw std::logic_error("ctga::dense: parse_blade disagrees with the reference on \"" +
                                   std::string(name) + "\"");
        multivector out;
        out.c_[mask] = sign > 0 ? coef : -coef;
        return out;
    }

    static multivector scalar(T value) {
        multivector out;
        out.c_[0] = value;
        return out;
    }

    friend multivector operator+(const multivector& x, const multivector& y) {
        multivector out;
        for (std::size_t i = 0; i < blade_count; ++i) out.c_[i] = x.c_[i] + y.c_[i];
        return out;
    }
    friend multivector operator-(const multivector& x, const multivector& y) {
        multivector out;
        for (std::size_t i = 0; i < blade_count; ++i) out.c_[i] = x.c_[i] - y.c_[i];
        return out;
    }
    friend multivector operator-(const multivector& x) {
        multivector out;
        for (std::size_t i = 0; i < blade_count; ++i) out.c_[i] = -x.c_[i];
        return out;
    }
    friend multivector operator*(const T& s, const multivector& x) {
        multivector out;
        for (std::size_t i = 0; i < blade_count; ++i) out.c_[i] = s * x.c_[i];
        return out;
    }
    friend multivector operator*(const multivector& x, const T& s) {
        multivector out;
        for (std::size_t i = 0; i < blade_count; ++i) out.c_[i] = x.c_[i] * s;
        return out;
    }
    friend multivector operator/(const multivector& x, const T& s) {
        multivector out;
        for (std::size_t i = 0; i < blade_count; ++i) out.c_[i] = x.c_[i] / s;
        return out;
    }
    friend bool operator==(const multivector& x, const multivector& y) {
        for (std::size_t i = 0; i < blade_count; ++i)
            if (!(x.c_[i] == y.c_[i])) return false;
        return true;
    }

private:
    std::array<T, Alg::blade_count> c_;
};

namespace detail {

// The naive bilinear extension: every pair (a, b) of components, skipping only table zeros.
template <class Alg, class T>
multivector<Alg, T> apply_table(const product_table& table, const multivector<Alg, T>& x,
                                const multivector<Alg, T>& y) {
    constexpr std::size_t count = Alg::blade_count;
    multivector<Alg, T> out;
    for (std::size_t a = 0; a < count; ++a) {
        for (std::size_t b = 0; b < count; ++b) {
            const term& t = table[a * count + b];
            if (t.sign == 0) continue;
            const T p = x[static_cast<blade_mask>(a)] * y[static_cast<blade_mask>(b)];
            T& dst = out[t.mask];
            dst = t.sign > 0 ? dst + p : dst - p;
        }
    }
    return out;
}

// Linear extension of a map sending each basis blade to a signed basis blade.
template <class Alg, class T, class BladeMap>
multivector<Alg, T> apply_blade_map(const multivector<Alg, T>& x, BladeMap map) {
    multivector<Alg, T> out;
    for (std::size_t m = 0; m < Alg::blade_count; ++m) {
        const term t = map(static_cast<blade_mask>(m));
        if (t.sign == 0) continue;
        const T& v = x[static_cast<blade_mask>(m)];
        T& dst = out[t.mask];
        dst = t.sign > 0 ? dst + v : dst - v;
    }
    return out;
}

}  // namespace detail

// =============================================================================================
// Products
// =============================================================================================

// Geometric (Clifford) product xy.
template <class Alg, class T>
multivector<Alg, T> gp(const multivector<Alg, T>& x, const multivector<Alg, T>& y) {
    return detail::apply_table(detail::table_for<Alg, detail::product_kind::geometric>(), x, y);
}

// Exterior product x ∧ y.
template <class Alg, class T>
multivector<Alg, T> wedge(const multivector<Alg, T>& x, const multivector<Alg, T>& y) {
    return detail::apply_table(detail::table_for<Alg, detail::product_kind::exterior>(), x, y);
}

// Shuffle (Grassmann-Cayley) product x ∨ y of the paper's §4; metric-free.
template <class Alg, class T>
multivector<Alg, T> shuffle(const multivector<Alg, T>& x, const multivector<Alg, T>& y) {
    return detail::apply_table(detail::table_for<Alg, detail::product_kind::shuffle>(), x, y);
}

// Left contraction x ⌋ y.
template <class Alg, class T>
multivector<Alg, T> lcont(const multivector<Alg, T>& x, const multivector<Alg, T>& y) {
    return detail::apply_table(detail::table_for<Alg, detail::product_kind::left_contraction>(), x, y);
}

// Right contraction x ⌊ y.
template <class Alg, class T>
multivector<Alg, T> rcont(const multivector<Alg, T>& x, const multivector<Alg, T>& y) {
    return detail::apply_table(detail::table_for<Alg, detail::product_kind::right_contraction>(), x, y);
}

// Scalar product <xy>_0, returned as a multivector with only the grade-0 component.
template <class Alg, class T>
multivector<Alg, T> scalar_product(const multivector<Alg, T>& x, const multivector<Alg, T>& y) {
    return detail::apply_table(detail::table_for<Alg, detail::product_kind::scalar>(), x, y);
}

// =============================================================================================
// Involutions, projections, complements, automorphisms
// =============================================================================================

template <class Alg, class T>
multivector<Alg, T> reverse(const multivector<Alg, T>& x) {
    const auto& table = detail::unary_table_for<Alg, detail::unary_kind::reverse>();
    return detail::apply_blade_map(x, [&](blade_mask m) { return table[m]; });
}

template <class Alg, class T>
multivector<Alg, T> involute(const multivector<Alg, T>& x) {
    const auto& table = detail::unary_table_for<Alg, detail::unary_kind::involute>();
    return detail::apply_blade_map(x, [&](blade_mask m) { return table[m]; });
}

// Clifford conjugation (the paper's *): reverse of the grade involution.
template <class Alg, class T>
multivector<Alg, T> conjugate(const multivector<Alg, T>& x) {
    const auto& table = detail::unary_table_for<Alg, detail::unary_kind::conjugate>();
    return detail::apply_blade_map(x, [&](blade_mask m) { return table[m]; });
}

// Grade-k part <x>_k (zero for k outside 0..n).
template <class Alg, class T>
multivector<Alg, T> grade(const multivector<Alg, T>& x, int k) {
    constexpr int n = static_cast<int>(Alg::dimension);
    return detail::apply_blade_map(x, [&](blade_mask m) -> detail::term {
        if (detail::word_grade(detail::word_of(m, n)) != k) return {};
        return {m, 1};
    });
}

// Right complement: linear, with B ∧ rc(B) = I for every basis blade B (I canonical).
template <class Alg, class T>
multivector<Alg, T> right_complement(const multivector<Alg, T>& x) {
    constexpr int n = static_cast<int>(Alg::dimension);
    return detail::apply_blade_map(x, [](blade_mask m) { return detail::right_complement_term(m, n); });
}

// Left complement: linear, with lc(B) ∧ B = I for every basis blade B.
template <class Alg, class T>
multivector<Alg, T> left_complement(const multivector<Alg, T>& x) {
    constexpr int n = static_cast<int>(Alg::dimension);
    return detail::apply_blade_map(x, [](blade_mask m) { return detail::left_complement_term(m, n); });
}

// The algebra automorphism with generator i -> generator perm[i]. It is an automorphism only if
// perm is a permutation preserving the squares; both are checked (std::invalid_argument).
template <class Alg, class T>
multivector<Alg, T> automorphism(const multivector<Alg, T>& x, const std::array<int, Alg::dimension>& perm) {
    constexpr int n = static_cast<int>(Alg::dimension);
    std::array<bool, Alg::dimension> hit{};
    for (std::size_t i = 0; i < Alg::dimension; ++i) {
        const int p = perm[i];
        if (p < 0 || p >= n || hit[static_cast<std::size_t>(p)])
            throw std::invalid_argument("ctga::dense::automorphism: not a permutation of the generators");
        hit[static_cast<std::size_t>(p)] = true;
        if (Alg::square(i) != Alg::square(static_cast<std::size_t>(p)))
            throw std::invalid_argument("ctga::dense::automorphism: the permutation does not preserve squares");
    }
    return detail::apply_blade_map(x, [&](blade_mask m) { return detail::permuted_term(m, n, perm.data()); });
}

// The paper's bar: swaps the first and the second half of the generators (i <-> i + n/2); in
// Cl(0,6,2) ordered "a1 a2 a3 a e1 e2 e3 e" that is a_i <-> e_i, a <-> e.
template <class Alg, class T>
multivector<Alg, T> bar(const multivector<Alg, T>& x) {
    static_assert(Alg::dimension % 2 == 0, "ctga::dense::bar needs an even number of generators");
    constexpr int n = static_cast<int>(Alg::dimension);
    std::array<int, Alg::dimension> perm{};
    for (int i = 0; i < n; ++i) perm[static_cast<std::size_t>(i)] = (i + n / 2) % n;
    return dense::automorphism(x, perm);
}

// =============================================================================================
// Norms, printing, conversion
// =============================================================================================

// Largest |component|; abs is looked up by ADL for user types (with std::abs as fallback).
template <class Alg, class T>
T max_abs(const multivector<Alg, T>& x) {
    using std::abs;
    T best = T(0);
    for (const T& v : x.components()) {
        const T a = abs(v);
        if (best < a) best = a;
    }
    return best;
}

template <class Alg, class T>
T max_abs_diff(const multivector<Alg, T>& x, const multivector<Alg, T>& y) {
    return dense::max_abs(x - y);
}

// "3*a2a3 + 2*e1e": non-zero components in mask order, blades in canonical orientation,
// the scalar part as a bare number; "0" for zero.
template <class Alg, class T>
std::string to_string(const multivector<Alg, T>& x) {
    std::ostringstream out;
    if constexpr (std::numeric_limits<T>::is_specialized) out.precision(std::numeric_limits<T>::digits10);
    bool first = true;
    for (std::size_t m = 0; m < Alg::blade_count; ++m) {
        const T& v = x[static_cast<blade_mask>(m)];
        if (v == T(0)) continue;
        if (!first) out << " + ";
        first = false;
        out << v;
        if (m != 0) out << '*' << detail::blade_name<Alg>(static_cast<blade_mask>(m));
    }
    if (first) return "0";
    return out.str();
}

// Dense copy of a sparse-engine multivector X: component i of x is the coefficient of
// layout.signs[i] * (canonical blade layout.masks[i]).
template <class X>
auto to_dense(const X& x) -> multivector<typename X::algebra_type, std::remove_cvref_t<decltype(x[0])>> {
    using value = std::remove_cvref_t<decltype(x[0])>;
    multivector<typename X::algebra_type, value> out;
    constexpr auto& layout = X::layout;
    for (std::size_t i = 0; i < X::size(); ++i) {
        const value v = x[i];
        const int sign = layout.signs[i];
        value& dst = out[static_cast<blade_mask>(layout.masks[i])];
        if (sign > 0) dst = dst + v;
        else if (sign < 0) dst = dst - v;
    }
    return out;
}

}  // namespace ctga::dense
