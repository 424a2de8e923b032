// Many robots at once: one tree's algorithm over the states of N robots, L robots per
// instruction stream (ctga::pack<T, L>, support/pack.hpp), on as many threads as asked.
//
//   struct robot { ch::configuration<Tree> q; ch::joint_vector<Tree> qd, qdd, tau; ctga::error_code error; };
//   std::vector<robot> robots(1000);                          // the layout users keep
//   const auto lanes = ch::model_cast<ctga::pack<double, 8>>(m);   // the model in every lane, once
//   std::size_t failed = ch::batch_call(ch::rnea, lanes, robots, &robot::tau, &robot::error, 1,  // 1 thread
//                                       &robot::q, &robot::qd, &robot::qdd);
//
// The algorithms are the scalar ones with pack<T, L> as the scalar: one instruction stream, each
// lane its own robot, no lane reading another's numbers. A robot's inputs are gathered into its
// lane from the array of structures (`load`), its results scattered back (`store`); the last pack of
// a batch whose N is not a multiple of L fills its spare lanes with copies of its last robot
// (finite numbers, results never stored).
//
// Checked, lane by lane. The packs are plain arithmetic: a NaN in one robot's q gives NaNs in that
// lane only. batch_call checks each robot's inputs and results as checked_call does
// (checked_call.hpp: non_finite, not_a_motor), writes each robot's error_code and returns the
// number of robots that failed; the others' results are those of the algorithm on their inputs.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#include "ctga/chains/checked_call.hpp"
#include "ctga/chains/motion.hpp"
#include "ctga/chains/tree.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/integrators/model.hpp"
#include "ctga/support/pack.hpp"

namespace ctga::chains {

namespace batch_detail {
// out = x with every pack replaced by its lane l: a number, or an array of them (nested: a
// matrix), written in place (no temporary of the robot's size)
template <class T, std::size_t L>
constexpr void get_lane(T& out, const pack<T, L>& x, std::size_t l) noexcept {
    out = x[l];
}
template <class Y, class X, std::size_t K>
constexpr void get_lane(std::array<Y, K>& out, const std::array<X, K>& x, std::size_t l) noexcept {
    for (std::size_t k = 0; k < K; ++k) get_lane(out[k], x[k], l);
}
template <class T, std::size_t L>
constexpr void set_lane(pack<T, L>& x, std::size_t l, const T& v) noexcept {
    x.set(l, v);
}
template <class X, class Y, std::size_t K>
constexpr void set_lane(std::array<X, K>& x, std::size_t l, const std::array<Y, K>& v) noexcept {
    for (std::size_t k = 0; k < K; ++k) set_lane(x[k], l, v[k]);
}
// x's first number: a pack (x a pack, or nested std::arrays of packs)
template <class X>
constexpr const X& first_number(const X& x) noexcept {
    return x;
}
template <class X, std::size_t K>
constexpr const auto& first_number(const std::array<X, K>& x) noexcept {
    return first_number(x[0]);
}
// The same structure with pack<T, L> for every number T (std::array nests).
template <class X, std::size_t L>
struct packed {
    using type = pack<X, L>;
};
template <class X, std::size_t K, std::size_t L>
struct packed<std::array<X, K>, L> {
    using type = std::array<typename packed<X, L>::type, K>;
};

// Numbers of L robots, K ≥ L each (nested std::arrays of T, contiguous), to and from K packs, L
// numbers at a time: L rows of L numbers (one vector load each), transposed in registers (log2 L
// stages of shuffles), one vector store each. (Lane by lane, a pack's number is an extract and
// a scalar store: the tree's CRBA in 8 lanes spent more time storing H than computing it.)
// Fewer than L numbers (a short q) go lane by lane.
template <class T, class X>
inline constexpr std::size_t count_of = sizeof(X) / sizeof(T);  // the numbers of X (nested arrays of T)
template <class X, class T>
inline constexpr bool flat_numbers = false;  // X is T or nested std::arrays of T: contiguous, no padding
template <class T>
inline constexpr bool flat_numbers<T, T> = true;
template <class X, std::size_t K, class T>
inline constexpr bool flat_numbers<std::array<X, K>, T> = flat_numbers<X, T> && sizeof(std::array<X, K>) == K * sizeof(X);

// rows r[0 … L): afterwards r[j] lane e is the former r[e] lane j. Transposing swaps each bit of
// the row index with that bit of the lane index. The first stage interleaves rows i and i + 1
// (bit 0; unpcklpd/unpckhpd); every further stage, pairing rows i and i + H (H = 2, 4, …),
// gathers the even pairs of lanes of both rows into row i and the odd pairs into row i + H,
// which moves row bit H to the top lane bit and shifts the lane bits above bit 0 down, so after
// the last stage every bit has been swapped (one 128-bit-chunk shuffle each, vshuff64x2, where a
// general two-row permute would be slower).
template <std::size_t H, class V, std::size_t L, std::size_t... E>
CTGA_ALWAYS_INLINE void transpose(std::array<V, L>& r, std::index_sequence<E...> lanes) noexcept {
    // lane E of the new row i (Odd = 0) or i + H (Odd = 1), as an index into (row i, row i + H)
    constexpr auto from = [](std::size_t e, std::size_t odd) {
        if constexpr (H == 1) {
            return (e & 1) ? L + e - 1 + odd : e + odd;
        } else {
            const std::size_t pair = e / 2, source = pair < L / 4 ? 0 : L;
            return source + 2 * (2 * (pair % (L / 4)) + odd) + e % 2;
        }
    };
    for (std::size_t block = 0; block < L; block += 2 * H)
        for (std::size_t i = block; i < block + H; ++i) {
            const V a = r[i], b = r[i + H];
            r[i] = __builtin_shufflevector(a, b, from(E, 0)...);
            r[i + H] = __builtin_shufflevector(a, b, from(E, 1)...);
        }
    if constexpr (2 * H < L) transpose<2 * H>(r, lanes);
}
// (K ≥ L: the blocks start at 0, L, 2L, … and, for the last K mod L numbers, at K − L, which
// moves some numbers twice rather than lane by lane)
template <std::size_t L, std::size_t K>
inline constexpr auto block_starts = [] {
    std::array<std::size_t, (K + L - 1) / L> first{};
    for (std::size_t b = 0; b < first.size(); ++b) first[b] = b * L + L <= K ? b * L : K - L;
    return first;
}();
template <class T, std::size_t L, std::size_t K>
CTGA_ALWAYS_INLINE void gather(pack<T, L>* out, const std::array<const T*, L>& robot) noexcept {
    using V = typename pack<T, L>::vector;
    for (const std::size_t k : block_starts<L, K>) {
        std::array<V, L> r;
        for (std::size_t j = 0; j < L; ++j) __builtin_memcpy(&r[j], robot[j] + k, sizeof(V));
        transpose<1>(r, std::make_index_sequence<L>{});
        for (std::size_t e = 0; e < L; ++e) out[k + e].v = r[e];
    }
}
template <class T, std::size_t L, std::size_t K>
CTGA_ALWAYS_INLINE void scatter(const pack<T, L>* x, const std::array<T*, L>& robot) noexcept {
    using V = typename pack<T, L>::vector;
    for (const std::size_t k : block_starts<L, K>) {
        std::array<V, L> r;
        for (std::size_t e = 0; e < L; ++e) r[e] = x[k + e].v;
        transpose<1>(r, std::make_index_sequence<L>{});
        for (std::size_t j = 0; j < L; ++j) __builtin_memcpy(robot[j] + k, &r[j], sizeof(V));
    }
}
}  // namespace batch_detail

// Robots first … first + L − 1 of `robots` (a random-access range of structures) as packs:
// lane l holds std::invoke(member, robots[first + l]) (a pointer to an array member, or a
// function returning one); past robots.size() a lane repeats the last robot.
template <std::size_t L, class Robots, class Member>
[[nodiscard]] constexpr auto load(const Robots& robots, std::size_t first, Member member) noexcept {
    using scalar_value = std::remove_cvref_t<decltype(std::invoke(member, robots[0]))>;
    using out_type = typename batch_detail::packed<scalar_value, L>::type;
    out_type out;
    const std::size_t n = std::size(robots);
    using T = typename std::remove_cvref_t<decltype(batch_detail::first_number(out))>::value_type;
    if constexpr (L > 1 && batch_detail::flat_numbers<scalar_value, T> && batch_detail::count_of<T, scalar_value> >= L &&
                  std::is_lvalue_reference_v<decltype(std::invoke(member, robots[0]))>) {
        if (!std::is_constant_evaluated() && first + L <= n) {
            std::array<const T*, L> robot;
            for (std::size_t l = 0; l < L; ++l) robot[l] = reinterpret_cast<const T*>(&std::invoke(member, robots[first + l]));
            batch_detail::gather<T, L, batch_detail::count_of<T, scalar_value>>(reinterpret_cast<pack<T, L>*>(&out), robot);
            return out;
        }
    }
    for (std::size_t l = 0; l < L; ++l)
        batch_detail::set_lane(out, l, std::invoke(member, robots[first + l < n ? first + l : n - 1]));
    return out;
}

// The lanes of x back into robots first … (those that exist): std::invoke(member, robots[first + l]) = lane l.
template <std::size_t L, class X, class Robots, class Member>
constexpr void store(const X& x, Robots& robots, std::size_t first, Member member) noexcept {
    const std::size_t n = std::size(robots);
    using scalar_value = std::remove_cvref_t<decltype(std::invoke(member, robots[0]))>;
    using T = typename std::remove_cvref_t<decltype(batch_detail::first_number(x))>::value_type;
    if constexpr (L > 1 && batch_detail::flat_numbers<scalar_value, T> && batch_detail::flat_numbers<X, pack<T, L>> &&
                  batch_detail::count_of<T, scalar_value> >= L) {
        if (!std::is_constant_evaluated() && first + L <= n) {
            std::array<T*, L> robot;
            for (std::size_t l = 0; l < L; ++l) robot[l] = reinterpret_cast<T*>(&std::invoke(member, robots[first + l]));
            batch_detail::scatter<T, L, batch_detail::count_of<T, scalar_value>>(reinterpret_cast<const pack<T, L>*>(&x), robot);
            return;
        }
    }
    for (std::size_t l = 0; l < L && first + l < n; ++l) batch_detail::get_lane(std::invoke(member, robots[first + l]), x, l);
}

// f(first) for first = 0, L, 2L, … < n: every pack of a batch of n robots, the last one
// possibly partial. With threads > 1 the packs are cut into that many contiguous runs, each run
// on its own std::thread (0: std::thread::hardware_concurrency()); f must then write only its
// own robots.
template <std::size_t L, class F>
void for_each_pack(std::size_t n, unsigned threads, F&& f) {
    const std::size_t packs = (n + L - 1) / L;
    if (threads == 0) threads = std::thread::hardware_concurrency();
    if (threads <= 1 || packs <= 1) {
        for (std::size_t p = 0; p < packs; ++p) f(p * L);
        return;
    }
    if (threads > packs) threads = static_cast<unsigned>(packs);
    const auto run = [&](std::size_t begin, std::size_t end) {
        for (std::size_t p = begin; p < end; ++p) f(p * L);
    };
    std::vector<std::thread> pool;
    pool.reserve(threads - 1);
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back(run, packs * t / threads, packs * (t + 1) / threads);
    run(0, packs / threads);
    for (auto& th : pool) th.join();
}

// out = algorithm(model, in…) for every robot of `robots`, L at a time (lanes: the model cast to
// pack<T, L>, model_cast.hpp), each robot's error_code in its `error` member (none, or why its
// inputs or results are not acceptable, as checked_call). Returns the number of robots that failed.
// The inputs are members or functions giving q and then the algorithm's further arguments.
template <class Algorithm, class Tree, class T, std::size_t L, class Robots, class Out, class Error, class Q, class... In>
std::size_t batch_call(const Algorithm& algorithm, const model<Tree, pack<T, L>>& lanes, Robots& robots, Out out, Error error,
                       unsigned threads, Q q, In... in) {
    const std::size_t n = std::size(robots);
    std::size_t total = 0;
    for_each_pack<L>(n, threads, [&](std::size_t first) {
        const auto result = algorithm(lanes, load<L>(robots, first, q), load<L>(robots, first, in)...);
        store<L>(result, robots, first, out);
        for (std::size_t i = first; i < first + L && i < n; ++i) {
            auto& r = robots[i];
            error_code e = algorithm_detail::check_configuration<Tree>(std::invoke(q, r));
            if (e == error_code::none && !(algorithm_detail::finite_all<T>(std::invoke(in, r)) && ...)) e = error_code::non_finite;
            if (e == error_code::none && !algorithm_detail::finite_all<T>(std::invoke(out, r))) e = error_code::non_finite;
            std::invoke(error, r) = e;
        }
    });
    for (const auto& r : robots) total += std::invoke(error, r) != error_code::none;
    return total;
}

// `steps` steps of `method` (integrators/methods.hpp) for every robot of `robots`, L at a time
// (sim: a tree_motion in pack<T, L>, chains/motion.hpp), from and back into the members q and qd.
// Lane by lane as ctga::integrate does for one robot: a robot whose input is not finite (or whose
// floating base is no motor) is not stepped; a robot whose step fails (did_not_converge, a
// non-finite state) stops at its last good state; each robot's error_code (none, or why it
// stopped) goes to its `error` member. Returns the number of robots that stopped early.
template <class Method, class Tree, class T, std::size_t L, class Actuation, class Robots, class Q, class V, class Error>
std::size_t batch_integrate(const Method& method, const tree_motion<Tree, pack<T, L>, Actuation>& sim, Robots& robots, Q q, V qd,
                            Error error, const T& h, long steps, unsigned threads) {
    using P = pack<T, L>;
    using model_t = tree_motion<Tree, P, Actuation>;
    const std::size_t n = std::size(robots);
    for_each_pack<L>(n, threads, [&](std::size_t first) {
        state_of<model_t> x;
        x.g.x = load<L>(robots, first, q);
        x.s.x = load<L>(robots, first, qd);
        lane_errors<L> e;
        for (std::size_t l = 0; l < L && first + l < n; ++l) {
            const auto& r = robots[first + l];
            e[l] = algorithm_detail::check_configuration<Tree>(std::invoke(q, r));
            if (e[l] == error_code::none && !algorithm_detail::finite_all<T>(std::invoke(qd, r))) e[l] = error_code::non_finite;
        }
        const auto running = [&] {
            return P::generate([&](std::size_t l) { return e[l] == error_code::none ? T(0) : T(1); }) == P(T(0));
        };
        for (long k = 0; k < steps && any(running()); ++k) {
            const auto next = method.step(sim, x, P(h));
            for (std::size_t l = 0; l < L; ++l)
                if (e[l] == error_code::none && next.error[l] != error_code::none) e[l] = next.error[l];
            auto finite = finite_lanes(next.value.g[0]);
            for (const P& c : next.value.g.x) finite = finite && finite_lanes(c);
            for (const P& c : next.value.s.x) finite = finite && finite_lanes(c);
            for (std::size_t l = 0; l < L; ++l)
                if (e[l] == error_code::none && !finite[l]) e[l] = error_code::non_finite;
            const auto ok = running();
            x = {select(ok, next.value.g, x.g), select(ok, next.value.s, x.s)};
        }
        store<L>(x.g.x, robots, first, q);
        store<L>(x.s.x, robots, first, qd);
        for (std::size_t l = 0; l < L && first + l < n; ++l) std::invoke(error, robots[first + l]) = e[l];
    });
    std::size_t failed = 0;
    for (const auto& r : robots) failed += std::invoke(error, r) != error_code::none;
    return failed;
}

}  // namespace ctga::chains
