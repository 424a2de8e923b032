// A step's rows in colours, swept L at a time (Box2D v3's graph colouring): no two rows of a
// colour share a moving body, so the rows of a colour can be solved in any order, or together
// in the lanes of a vector register (ctga::pack), or on several threads, with the same result bit
// for bit; the colours follow one another as a Gauss–Seidel sweep's rows do. A row that finds no
// colour among the first `colours` (a body in more rows than that) is left to the caller's
// sweep, after the colours.
//
// A colour's rows are stored in groups of L, each member a pack of L lanes (structure of arrays):
// the directions e_k, both sides' moments x × e_k and responses to them (the angular part of N⁻¹
// L_k, I_w⁻¹ (x × e_k); the linear part is e_k / m), the step's constants, and the impulses and
// gaps, kept in the group through the sweeps. A lane left over at a colour's end is a row of
// nothing: its bodies the slot past the last body, its responses zero.
//
// A group's velocities u_k = L_k^B(s_B) − L_k^A(s_A) (contact_rows.hpp) and the change an impulse
// dr makes, s_B += N_B⁻¹ Σ dr_k L_k, s_A −= N_A⁻¹ Σ dr_k L_k, are `group_velocity` and `group_apply`,
// on the bodies' screws gathered into lanes (`gather`) and put back (`scatter`).
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>

#include "ctga/constraints/contact_rows.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/support/pack.hpp"

namespace ctga::constraints {

// The colours (at most 64): order holds the rows colour by colour, colour c being order[start[c]
// .. start[c + 1]); start[colours] .. the end are the rows left over. A row takes the lowest
// colour neither of its moving bodies is in yet (each body's colours a bit mask in `used`, one
// word per body); a row `skip` says so goes with the leftovers. Returns the rows in colours.
template <class T, class Skip>
std::size_t colour_rows(std::span<const contact_row<T>> rows, std::size_t colours, std::span<std::uint64_t> used,
                        std::span<std::uint32_t> colour_of, std::span<std::uint32_t> order, std::span<std::uint32_t> start, Skip&& skip) noexcept {
    for (std::uint64_t& w : used) w = 0;
    const std::uint64_t all = colours >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << colours) - 1;
    const auto in = [&](std::uint32_t body) { return body == no_body ? std::uint64_t{0} : used[body]; };
    for (std::size_t c = 0; c <= colours + 1; ++c) start[c] = 0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const std::uint64_t free = skip(i) ? 0 : all & ~(in(rows[i].a.body) | in(rows[i].b.body));
        const std::size_t c = free == 0 ? colours : static_cast<std::size_t>(std::countr_zero(free));
        if (c < colours)
            for (std::uint32_t body : {rows[i].a.body, rows[i].b.body})
                if (body != no_body) used[body] |= std::uint64_t{1} << c;
        colour_of[i] = static_cast<std::uint32_t>(c);
        ++start[c + 1];
    }
    for (std::size_t c = 0; c < colours; ++c) start[c + 1] += start[c];
    for (std::size_t i = 0; i < rows.size(); ++i) order[start[colour_of[i]]++] = static_cast<std::uint32_t>(i);
    for (std::size_t c = colours; c > 0; --c) start[c] = start[c - 1];
    start[0] = 0;
    return start[colours];  // rows in colours; the leftovers are order[start[colours] .. rows.size())
}

template <class T, std::size_t L>
struct row_group {
    using P = pack<T, L>;
    std::array<std::uint32_t, L> row{}, a{}, b{};  // a lane's row and bodies (a body past the last: none)
    std::array<std::array<P, 3>, 3> direction, moment_a, moment_b, turn_a, turn_b;  // e_k, x × e_k, I_w⁻¹ (x × e_k)
    P inverse_mass_a, inverse_mass_b;
    std::array<P, 6> inverse;       // a bilateral block's W⁻¹ (upper triangle, row by row)
    std::array<P, 2> step_length;   // 1/W_nn, 2/(W_t1t1 + W_t2t2)
    P coupling_1, coupling_2;       // W_t1n, W_t2n
    P compliance, spring_rate, mu;  // a soft surface's c and k/(h k + d); μ
    std::array<P, 3> surface, start, r, gap;  // a kinematic surface's speed; gaps at the start; impulses; gaps now
};

// The bodies' screws (ω, v) in lanes, and back. The slot past the last body stands for none: the
// caller keeps it zero, and a lane of none writes it back unchanged (its responses are zero).
// (Through a buffer of L numbers: loops a compiler can make gathers and scatters of.)
template <class T, std::size_t L>
struct lane_screws {
    std::array<pack<T, L>, 3> w, v;
};
template <class T, std::size_t L>
[[nodiscard]] CTGA_ALWAYS_INLINE lane_screws<T, L> gather(const screw<T>* s, const std::array<std::uint32_t, L>& body) noexcept {
    lane_screws<T, L> out;
    alignas(sizeof(T) * L) T x[L];
    for (std::size_t c = 0; c < 6; ++c) {
        for (std::size_t l = 0; l < L; ++l) x[l] = s[body[l]][c];
        (c < 3 ? out.w[c] : out.v[c - 3]) = pack<T, L>::load(x);
    }
    return out;
}
template <class T, std::size_t L>
CTGA_ALWAYS_INLINE void scatter(screw<T>* s, const std::array<std::uint32_t, L>& body, const lane_screws<T, L>& y) noexcept {
    alignas(sizeof(T) * L) T x[L];
    for (std::size_t c = 0; c < 6; ++c) {
        (c < 3 ? y.w[c] : y.v[c - 3]).store(x);
        for (std::size_t l = 0; l < L; ++l) s[body[l]][c] = x[l];
    }
}

template <class T, std::size_t L>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr pack<T, L> dot3(const std::array<pack<T, L>, 3>& x, const std::array<pack<T, L>, 3>& y) noexcept {
    return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}
// u_k = L_k^B(s_B) − L_k^A(s_A), the offsets not included.
template <class T, std::size_t L>
[[nodiscard]] CTGA_ALWAYS_INLINE constexpr std::array<pack<T, L>, 3> group_velocity(const row_group<T, L>& g, const lane_screws<T, L>& sa,
                                                                                    const lane_screws<T, L>& sb) noexcept {
    std::array<pack<T, L>, 3> dv, u;
    for (std::size_t c = 0; c < 3; ++c) dv[c] = sb.v[c] - sa.v[c];
    for (std::size_t k = 0; k < 3; ++k) u[k] = dot3(g.moment_b[k], sb.w) - dot3(g.moment_a[k], sa.w) + dot3(g.direction[k], dv);
    return u;
}
// s_B += N_B⁻¹ Σ dr_k L_k, s_A −= N_A⁻¹ Σ dr_k L_k.
template <class T, std::size_t L>
CTGA_ALWAYS_INLINE constexpr void group_apply(const row_group<T, L>& g, const std::array<pack<T, L>, 3>& dr, lane_screws<T, L>& sa,
                                              lane_screws<T, L>& sb) noexcept {
    for (std::size_t c = 0; c < 3; ++c) {
        const pack<T, L> f = dr[0] * g.direction[0][c] + dr[1] * g.direction[1][c] + dr[2] * g.direction[2][c];
        sb.v[c] += f * g.inverse_mass_b, sa.v[c] -= f * g.inverse_mass_a;
        sb.w[c] += dr[0] * g.turn_b[0][c] + dr[1] * g.turn_b[1][c] + dr[2] * g.turn_b[2][c];
        sa.w[c] -= dr[0] * g.turn_a[0][c] + dr[1] * g.turn_a[1][c] + dr[2] * g.turn_a[2][c];
    }
}

// Lane l of group g from row i (its side's mobility's responses); `none` is the body index of no body.
template <class T, std::size_t L>
constexpr void fill_lane(row_group<T, L>& g, std::size_t l, std::uint32_t i, const contact_row<T>& row, std::span<const mobility<T>> M,
                         std::uint32_t none) noexcept {
    g.row[l] = i;
    const auto side = [&](const row_side<T>& s, std::uint32_t& body, std::array<std::array<pack<T, L>, 3>, 3>& moment,
                          std::array<std::array<pack<T, L>, 3>, 3>& turn, pack<T, L>& inverse_mass) {
        body = s.body == no_body ? none : s.body;
        for (std::size_t k = 0; k < 3; ++k) {
            const vec3<T> response = s.body == no_body ? vec3<T>{} : linear3::apply(M[s.body].inverse_inertia, s.moment[k]);
            for (std::size_t c = 0; c < 3; ++c) moment[k][c].set(l, s.body == no_body ? T(0) : s.moment[k][c]), turn[k][c].set(l, response[c]);
        }
        inverse_mass.set(l, s.body == no_body ? T(0) : M[s.body].inverse_mass);
    };
    side(row.a, g.a[l], g.moment_a, g.turn_a, g.inverse_mass_a);
    side(row.b, g.b[l], g.moment_b, g.turn_b, g.inverse_mass_b);
    for (std::size_t k = 0; k < 3; ++k)
        for (std::size_t c = 0; c < 3; ++c) g.direction[k][c].set(l, row.direction[k][c]);
    g.step_length[0].set(l, row.step_length[0]), g.step_length[1].set(l, row.step_length[1]);
    g.coupling_1.set(l, row.block[1][0]), g.coupling_2.set(l, row.block[2][0]);
    g.compliance.set(l, row.compliance), g.mu.set(l, row.mu);
    for (std::size_t j = 0, n = 0; j < 3; ++j)
        for (std::size_t k = j; k < 3; ++k) g.inverse[n++].set(l, row.bilateral ? row.inverse[j][k] : T(0));
}
// A lane of nothing (past a colour's last row).
template <class T, std::size_t L>
constexpr void empty_lane(row_group<T, L>& g, std::size_t l, std::uint32_t none, std::uint32_t no_row) noexcept {
    g.row[l] = no_row, g.a[l] = g.b[l] = none;
    for (auto* m : {&g.direction, &g.moment_a, &g.moment_b, &g.turn_a, &g.turn_b})
        for (auto& x : *m)
            for (auto& y : x) y.set(l, T(0));
    for (auto* p : {&g.inverse_mass_a, &g.inverse_mass_b, &g.coupling_1, &g.coupling_2, &g.compliance, &g.spring_rate, &g.mu}) p->set(l, T(0));
    for (auto& p : g.inverse) p.set(l, T(0));
    g.step_length[0].set(l, T(0)), g.step_length[1].set(l, T(0));
    for (auto* a : {&g.surface, &g.start, &g.r, &g.gap})
        for (auto& p : *a) p.set(l, T(0));
}

}  // namespace ctga::constraints
