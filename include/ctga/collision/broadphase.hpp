// The broadphase: which pairs of many moving bodies may touch, from their world boxes (aabb.hpp).
// A dynamic tree of boxes (as Box2D's b2DynamicTree): each proxy is a leaf with a fat box, its
// tight box grown by `margin` (and stretched by an optional displacement on the side it points
// to); each inner node holds its two children and their boxes, the union of all below. The boxes
// held in the tree are floats rounded outward (half a double's memory: a node is one 64-byte cache
// line; at 10⁴ m from the origin a float's spacing is 1 mm), and they are the fat boxes.
// A proxy whose new tight box stays within its fat box, and whose fat box lies within the new one
// grown by 4 margins (not grown stale), keeps its leaf; otherwise it is reinserted with a new fat
// box. Insertion seeks the sibling that least increases the total area of the inner boxes (the
// surface-area heuristic: a node is visited by a query in proportion to its area), descending
// greedily with a lower bound per subtree: placing leaf L anywhere under node C costs at least
// inherited + area(C ∪ L) + min(area(L) − area(C), 0), `inherited` being the growth of C's
// ancestors; each node above it is then refitted and rotated (a child swapped with a grandchild
// across, Kopta et al. 2012) where that shrinks the child it changes, up to the first node that
// neither changes nor rotates.
// The pairs are kept from one update to the next as keys sorted by (smaller id, larger id): the
// fat boxes of two untouched proxies have not changed, so whether they overlap has not either,
// and the new set is the old pairs between untouched proxies merged with what the fat box of each
// touched proxy (reinserted, created, destroyed, refiltered) meets in the tree now, a pair of two
// touched proxies taken from the larger id's walk. The set depends on the fat boxes only, not on
// the tree's shape: runs are bit-identical.
// Filtering (as Box2D's b2Filter): two proxies pair only if (a.category & b.mask) and
// (b.category & a.mask), unless they share a non-zero group: then always (group > 0) or never
// (group < 0). Bodies joined by a joint are left out by the scene layer's predicate given to
// pairs(), may_collide(user_a, user_b) (false for a jointed pair), applied when the pairs are written.
// Storage: allocated once, by the constructor, from a std::pmr::memory_resource (the heap by
// default; a caller's buffer for a build without one): proxy_capacity + 1 nodes, proxy_capacity
// proxies, 4 pair_capacity keys of 8 bytes; nothing allocates afterwards. The walks (pairs, query,
// ray_query) keep the nodes still to visit on a stack of 64 in the function, pushed without
// branches and fetched ahead; a tree taller than that is walked by its parent links instead.
// Chosen by measurement on bench/collision_broadphase.cpp (10,000 boxes moving each step, ~18,600
// overlapping pairs; thread CPU time per step, g++ 12 -O3): this tree with margin 0.1 m 1.7 ms,
// Bullet's btDbvtBroadphase 4.7 ms; the tree with Bullet's margin (0.05 m: twice the
// reinsertions) 2.7 ms, with 0.2 m 1.1 ms (35 % more candidates); a displacement of 4 steps' motion
// (Box2D's choice) −20 %. Sort and sweep along x (insertion sort, then a sweep of the sorted
// boxes) 7–10 ms: in a cube of bodies a box's x interval meets ~580 others. Walking the tree
// against itself, skipping pairs of subtrees without a touched proxy, took 1.5 times as long as
// one walk per touched proxy (both in a tree holding doubles).
#pragma once

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory_resource>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "ctga/collision/aabb.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"

namespace ctga::collision {

using proxy_id = std::uint32_t;

struct filter {
    std::uint64_t category = 1;              // what the proxy is
    std::uint64_t mask = ~std::uint64_t{0};  // what it pairs with
    std::int32_t group = 0;                  // equal and non-zero: > 0 always pair, < 0 never
};

[[nodiscard]] constexpr bool may_pair(const filter& a, const filter& b) noexcept {
    if (a.group == b.group && a.group != 0) return a.group > 0;
    return (a.category & b.mask) != 0 && (b.category & a.mask) != 0;
}

// A candidate pair, a < b.
struct proxy_pair {
    proxy_id a, b;
    friend constexpr bool operator==(const proxy_pair&, const proxy_pair&) = default;
};

template <std::floating_point T = double>
class broadphase {
public:
    // Room for proxy_capacity (< 2³⁰) proxies and pair_capacity pairs; fat boxes grown by margin ≥ 0.
    // The storage comes from `storage` once, here (the default: the heap); without a heap, a
    // std::pmr::monotonic_buffer_resource over a buffer of bytes_for(…) bytes with
    // std::pmr::null_memory_resource() behind it.
    broadphase(std::size_t proxy_capacity, std::size_t pair_capacity, T margin,
               std::pmr::memory_resource* storage = std::pmr::get_default_resource())
        : margin_(margin),
          nodes_(proxy_capacity + 1, storage),
          proxies_(proxy_capacity, storage),
          touched_list_(proxy_capacity, storage),
          pairs_(pair_capacity, storage),
          next_pairs_(pair_capacity, storage),
          found_(pair_capacity, storage),
          scratch_(pair_capacity, storage) {
        assert(proxy_capacity < (std::size_t{1} << 30) && margin >= T(0));
        while ((std::uint64_t{1} << id_bits_) < proxy_capacity) ++id_bits_;
        for (std::size_t i = 1; i < nodes_.size(); ++i) nodes_[i].parent = i + 1 < nodes_.size() ? static_cast<std::int32_t>(i + 1) : 0;
        free_node_ = nodes_.size() > 1 ? 1 : 0;
        for (std::size_t i = 0; i < proxies_.size(); ++i) proxies_[i].location = static_cast<std::int32_t>(i + 1);
    }

    // The bytes a broadphase of these capacities takes from its storage (with room to align each of
    // its seven arrays).
    [[nodiscard]] static constexpr std::size_t bytes_for(std::size_t proxy_capacity, std::size_t pair_capacity) noexcept {
        return (proxy_capacity + 1) * sizeof(node) + proxy_capacity * (sizeof(proxy) + sizeof(proxy_id)) +
               4 * pair_capacity * sizeof(std::uint64_t) + 7 * alignof(std::max_align_t) + 7 * alignof(node);
    }

    // ---- proxies ----

    // Reported: non_finite (a NaN or infinite bound), non_positive_size (lower > upper on an axis),
    // capacity_exceeded (proxy_capacity proxies alive).
    [[nodiscard]] checked<proxy_id> create_proxy(const aabb<T>& box, std::uint64_t user, const filter& f = {}) noexcept {
        if (const error_code e = check(box); e != error_code::none) return {{}, e};
        if (count_ == proxies_.size()) return {{}, error_code::capacity_exceeded};
        const proxy_id id = free_proxy_;
        proxy& p = proxies_[id];
        free_proxy_ = static_cast<proxy_id>(p.location);
        p = proxy{0, user, f, true, p.touched};  // (touched: destroyed and created again before an update)
        insert_leaf(id, outward(fattened(box, margin_)));
        touch(id);
        ++count_;
        return {id, error_code::none};
    }

    // The proxy's new tight box; `displacement` (optional: its expected motion over the next
    // steps) stretches a new fat box on the side it points to. Reported: non_finite,
    // non_positive_size (the proxy keeps its box).
    error_code move_proxy(proxy_id id, const aabb<T>& box, const vec3<T>& displacement = {}) noexcept {
        assert(is_alive(id));
        if (const error_code e = check(box); e != error_code::none) return e;
        if (!is_finite(displacement[0]) || !is_finite(displacement[1]) || !is_finite(displacement[2])) return error_code::non_finite;
        aabb<T> fat = fattened(box, margin_);
        for (std::size_t k = 0; k < 3; ++k) (displacement[k] < T(0) ? fat.lower[k] : fat.upper[k]) += displacement[k];
        // kept while it holds the tight box and lies within the new fat box grown by 4 margins
        const aabb<T> old = fat_box(id);
        if (contains(old, box) && contains(fattened(fat, T(4) * margin_), old)) return error_code::none;
        remove_leaf(id);
        insert_leaf(id, outward(fat));
        touch(id);
        return error_code::none;
    }

    void destroy_proxy(proxy_id id) noexcept {
        assert(is_alive(id));
        proxy& p = proxies_[id];
        remove_leaf(id);
        p.location = static_cast<std::int32_t>(free_proxy_);
        free_proxy_ = id;
        p.alive = false;
        touch(id);
        --count_;
    }

    void set_filter(proxy_id id, const filter& f) noexcept {
        assert(is_alive(id));
        proxies_[id].rules = f;
        touch(id);
    }

    // The fat box: its bounds are floats (rounded outward from the tight box ± margin).
    [[nodiscard]] aabb<T> fat_box(proxy_id id) const noexcept {
        assert(is_alive(id));
        return widened(held(proxies_[id].location));
    }
    [[nodiscard]] std::uint64_t user_of(proxy_id id) const noexcept { return proxies_[id].user; }
    [[nodiscard]] const filter& filter_of(proxy_id id) const noexcept { return proxies_[id].rules; }
    [[nodiscard]] bool is_alive(proxy_id id) const noexcept { return id < proxies_.size() && proxies_[id].alive; }
    [[nodiscard]] std::size_t proxy_count() const noexcept { return count_; }
    [[nodiscard]] std::size_t proxy_capacity() const noexcept { return proxies_.size(); }
    [[nodiscard]] std::size_t pair_capacity() const noexcept { return pairs_.size(); }
    [[nodiscard]] T margin() const noexcept { return margin_; }

    // ---- pairs ----

    // Brings the pair set up to date with the proxies' fat boxes and filters. Reported:
    // capacity_exceeded (more than pair_capacity pairs: the set is then incomplete, and rebuilt
    // from all proxies at the next update).
    error_code update_pairs() noexcept {
        if (touched_count_ == 0 && !overflowed_) return error_code::none;
        if (overflowed_) {
            for (std::size_t i = 0; i < proxies_.size(); ++i)
                if (proxies_[i].alive) touch(static_cast<proxy_id>(i));
            pair_count_ = 0;
        }
        // what each touched proxy's fat box meets: a pair of two touched proxies once, from the larger id
        std::size_t found = 0;
        bool full = false;
        for (std::size_t t = 0; t < touched_count_ && !full; ++t) {
            const proxy_id a = touched_list_[t];
            const proxy& pa = proxies_[a];
            if (!pa.alive) continue;
            const aabb<bound> box = held(pa.location);
            walk([&](const aabb<bound>& b) { return overlaps(box, b); },
                 [&](proxy_id b) {
                     const proxy& pb = proxies_[b];
                     if (b == a || (pb.touched && b > a) || !may_pair(pa.rules, pb.rules)) return true;
                     full = found == found_.size();
                     if (!full) found_[found++] = key(b, a);
                     return !full;
                 });
        }
        sort_keys(found);
        // merged with the old pairs between untouched proxies
        std::size_t i = 0, j = 0, out = 0;
        while (!full && (i < pair_count_ || j < found)) {
            if (i < pair_count_ && (proxies_[first(pairs_[i])].touched || proxies_[second(pairs_[i])].touched)) {
                ++i;
                continue;
            }
            full = out == next_pairs_.size();
            if (full) break;
            if (j == found || (i < pair_count_ && pairs_[i] < found_[j])) next_pairs_[out++] = pairs_[i++];
            else next_pairs_[out++] = found_[j++];
        }
        std::swap(pairs_, next_pairs_);
        pair_count_ = out;
        for (std::size_t t = 0; t < touched_count_; ++t) proxies_[touched_list_[t]].touched = false;
        touched_count_ = 0;
        overflowed_ = full;
        return full ? error_code::capacity_exceeded : error_code::none;
    }

    // Every unordered pair of proxies whose fat boxes overlap and whose filters let them pair, and
    // for which may_collide(user_a, user_b) holds, in order of (a, b), a < b, written to out. The
    // value is the number of such pairs; capacity_exceeded when out is too short (out then holds
    // the first out.size() of them) or the set outgrew pair_capacity.
    template <class Predicate>
    [[nodiscard]] checked<std::size_t> pairs(std::span<proxy_pair> out, Predicate&& may_collide) noexcept {
        const error_code e = update_pairs();
        std::size_t n = 0;
        for (std::size_t i = 0; i < pair_count_; ++i) {
            const proxy_id a = first(pairs_[i]), b = second(pairs_[i]);
            if (!may_collide(proxies_[a].user, proxies_[b].user)) continue;
            if (n < out.size()) out[n] = {a, b};
            ++n;
        }
        return {n, n > out.size() ? error_code::capacity_exceeded : e};
    }
    [[nodiscard]] checked<std::size_t> pairs(std::span<proxy_pair> out) noexcept {
        return pairs(out, [](std::uint64_t, std::uint64_t) { return true; });
    }

    // The same pairs, each handed to f(a, b) in that order, without a predicate. Reported as by
    // update_pairs.
    template <class F>
    error_code for_each_pair(F&& f) noexcept {
        const error_code e = update_pairs();
        for (std::size_t i = 0; i < pair_count_; ++i) f(first(pairs_[i]), second(pairs_[i]));
        return e;
    }

    // ---- queries ----

    // f(id) for each proxy whose fat box overlaps box, until f returns false.
    template <class F>
    void query(const aabb<T>& box, F&& f) const noexcept {
        walk([&](const aabb<bound>& b) { return overlaps(box, widened(b)); }, [&](proxy_id id) { return call(f, id); });
    }

    // The proxies whose fat boxes the segment origin + s direction, 0 ≤ s ≤ max_length, meets:
    // f(id, s) with s the entry, returning the limit from then on (max_length to see every box,
    // s to see only nearer ones, a negative number to stop).
    template <class F>
    void ray_query(const vec3<T>& origin, const vec3<T>& direction, const T& max_length, F&& f) const noexcept {
        const ray<T> r = make_ray(origin, direction, max_length);
        T limit = max_length;
        walk([&](const aabb<bound>& b) { return ray_entry(widened(b), r, limit) >= T(0); },
             [&](proxy_id id) {
                 const T s = ray_entry(fat_box(id), r, limit);
                 if (s >= T(0)) limit = f(id, s);
                 return !(limit < T(0));
             });
    }

    // ---- the tree, for tests ----

    // Parent and child links agree, every box held for an inner node is the union of its
    // children's and every height one more than the larger child's, the leaves are the live
    // proxies.
    [[nodiscard]] bool is_consistent() const noexcept {
        const ref root = nodes_[0].child[0];
        if (root == empty) return count_ == 0;
        std::size_t leaves = 0, inner = 0;
        bool ok = true;
        check_subtree(root, 0, leaves, inner, ok);
        return ok && leaves == count_ && inner + 1 == count_;
    }
    // Of the tree: 0 for one proxy (or none).
    [[nodiscard]] std::int32_t height() const noexcept { return height_of(nodes_[0].child[0]); }

private:
    // The bounds held in the tree: floats, half the memory of doubles for the walks.
    using bound = float;
    static bound down(const T& x) noexcept {
        bound f = static_cast<bound>(x);
        return static_cast<T>(f) > x ? std::nextafter(f, -std::numeric_limits<bound>::infinity()) : f;
    }
    static bound up(const T& x) noexcept {
        bound f = static_cast<bound>(x);
        return static_cast<T>(f) < x ? std::nextafter(f, std::numeric_limits<bound>::infinity()) : f;
    }
    static aabb<bound> outward(const aabb<T>& b) noexcept {
        return {{down(b.lower[0]), down(b.lower[1]), down(b.lower[2])}, {up(b.upper[0]), up(b.upper[1]), up(b.upper[2])}};
    }
    static aabb<T> widened(const aabb<bound>& b) noexcept {
        return {{b.lower[0], b.lower[1], b.lower[2]}, {b.upper[0], b.upper[1], b.upper[2]}};
    }

    // A child: an inner node's index (≥ 1), a proxy as −1 − id, or empty (0, the index of the
    // sentinel node, whose slot 0 holds the root and its box).
    using ref = std::int32_t;
    static constexpr ref empty = 0;
    [[nodiscard]] static constexpr ref leaf_ref(proxy_id id) noexcept { return -1 - static_cast<ref>(id); }
    [[nodiscard]] static constexpr proxy_id proxy_of(ref r) noexcept { return static_cast<proxy_id>(-1 - r); }

    // An inner node holds its two children and their boxes (a proxy's box is held only there), so
    // that a walk tests both from one cache line. A location is 2 node + slot.
    struct alignas(64) node {
        std::array<aabb<bound>, 2> box{};
        std::array<ref, 2> child{};
        std::int32_t parent = 0;  // its location; in the free list, the next free node
        std::int32_t height = 0;  // 1 + the larger child's (a proxy's is 0)
    };
    struct proxy {
        std::int32_t location = 0;  // in the free list, the next free proxy
        std::uint64_t user = 0;
        filter rules{};
        bool alive = false;
        bool touched = false;
    };

    static error_code check(const aabb<T>& box) noexcept {
        for (std::size_t k = 0; k < 3; ++k)
            if (!is_finite(box.lower[k]) || !is_finite(box.upper[k])) return error_code::non_finite;
        for (std::size_t k = 0; k < 3; ++k)
            if (box.upper[k] < box.lower[k]) return error_code::non_positive_size;
        return error_code::none;
    }

    template <class F>
    static bool call(F& f, proxy_id id) noexcept {
        if constexpr (std::is_void_v<decltype(f(id))>) {
            f(id);
            return true;
        } else {
            return static_cast<bool>(f(id));
        }
    }

    [[nodiscard]] std::uint64_t key(proxy_id a, proxy_id b) const noexcept {
        return a < b ? (std::uint64_t{a} << id_bits_) | b : (std::uint64_t{b} << id_bits_) | a;
    }
    [[nodiscard]] proxy_id first(std::uint64_t k) const noexcept { return static_cast<proxy_id>(k >> id_bits_); }
    [[nodiscard]] proxy_id second(std::uint64_t k) const noexcept {
        return static_cast<proxy_id>(k & ((std::uint64_t{1} << id_bits_) - 1));
    }

    void touch(proxy_id id) noexcept {
        proxy& p = proxies_[id];
        if (p.touched) return;
        p.touched = true;
        touched_list_[touched_count_++] = id;
    }

    // Sorts found_[0, n) (LSD radix sort, 11 bits a pass, over the 2 id_bits_ bits of the keys).
    void sort_keys(std::size_t n) noexcept {
        constexpr std::size_t bits = 11, buckets = std::size_t{1} << bits;
        std::uint64_t* from = found_.data();
        std::uint64_t* to = scratch_.data();
        for (std::size_t shift = 0; shift < 2 * id_bits_; shift += bits) {
            std::array<std::size_t, buckets> start{};
            for (std::size_t i = 0; i < n; ++i) ++start[(from[i] >> shift) & (buckets - 1)];
            std::size_t sum = 0;
            for (std::size_t& s : start) sum += std::exchange(s, sum);
            for (std::size_t i = 0; i < n; ++i) to[start[(from[i] >> shift) & (buckets - 1)]++] = from[i];
            std::swap(from, to);
        }
        if (from != found_.data()) std::copy(from, from + n, found_.data());
    }

    // ---- the tree ----

    [[nodiscard]] node& at(std::int32_t i) noexcept { return nodes_[static_cast<std::size_t>(i)]; }
    [[nodiscard]] const node& at(std::int32_t i) const noexcept { return nodes_[static_cast<std::size_t>(i)]; }
    [[nodiscard]] aabb<bound>& held(std::int32_t location) noexcept { return at(location >> 1).box[static_cast<std::size_t>(location & 1)]; }
    [[nodiscard]] const aabb<bound>& held(std::int32_t location) const noexcept {
        return at(location >> 1).box[static_cast<std::size_t>(location & 1)];
    }
    [[nodiscard]] std::int32_t height_of(ref r) const noexcept { return r > 0 ? at(r).height : 0; }

    // A hint to bring a node into the cache before it is read (GCC and Clang; elsewhere nothing).
    static void prefetch([[maybe_unused]] const node& n) noexcept {
#if defined(__GNUC__) || defined(__clang__)
        __builtin_prefetch(&n);
#endif
    }

    // Holds child r with its box at a location.
    void place(std::int32_t location, ref r, const aabb<bound>& box) noexcept {
        node& n = at(location >> 1);
        n.child[static_cast<std::size_t>(location & 1)] = r;
        n.box[static_cast<std::size_t>(location & 1)] = box;
        if (r < 0) proxies_[proxy_of(r)].location = location;
        else at(r).parent = location;
    }

    // The walk: enter(box) says whether to look inside a child's box; leaf(id) is called on each
    // proxy entered and returns whether to go on. Depth first, on a stack of the inner nodes to
    // visit (pushed without branching: a slot is written, and kept by moving the top; and fetched
    // ahead); at most one per level is pending, so a tree taller than the stack is walked without
    // one instead.
    template <class Enter, class Leaf>
    void walk(Enter&& enter, Leaf&& leaf) const noexcept {
        const ref root = nodes_[0].child[0];
        if (root == empty || !enter(nodes_[0].box[0])) return;
        if (root < 0) {
            leaf(proxy_of(root));
            return;
        }
        constexpr std::int32_t room = 64;
        if (at(root).height >= room) return walk_by_parents(root, enter, leaf);
        std::array<ref, room + 1> stack;
        std::size_t top = 0;
        stack[top++] = root;
        while (top > 0) {
            const node& x = at(stack[--top]);
            const bool e0 = enter(x.box[0]), e1 = enter(x.box[1]);
            const ref c0 = x.child[0], c1 = x.child[1];
            if (e0 && c0 < 0 && !leaf(proxy_of(c0))) return;
            if (e1 && c1 < 0 && !leaf(proxy_of(c1))) return;
            prefetch(at(c1 > 0 ? c1 : 0));
            prefetch(at(c0 > 0 ? c0 : 0));
            stack[top] = c1;
            top += e1 && c1 > 0 ? 1 : 0;
            stack[top] = c0;
            top += e0 && c0 > 0 ? 1 : 0;
        }
    }
    // The same without a stack: at the end of a node, up to its parent, on from the slot after its own.
    template <class Enter, class Leaf>
    void walk_by_parents(ref root, Enter& enter, Leaf& leaf) const noexcept {
        std::int32_t n = root;
        std::size_t s = 0;
        for (;;) {
            for (; s < 2; ++s) {
                const node& x = at(n);
                if (!enter(x.box[s])) continue;
                if (x.child[s] > 0) break;
                if (!leaf(proxy_of(x.child[s]))) return;
            }
            if (s < 2) {
                n = at(n).child[s];
                s = 0;
                continue;
            }
            if (n == root) return;
            const std::int32_t up = at(n).parent;
            n = up >> 1;
            s = static_cast<std::size_t>(up & 1) + 1;
        }
    }

    // The location of the sibling for leaf box L with the least total growth of area (see the
    // header).
    [[nodiscard]] std::int32_t best_sibling(const aabb<bound>& L) const noexcept {
        using B = bound;
        const B area_l = surface_area(L);
        std::int32_t location = 0;
        ref r = nodes_[0].child[0];
        B area = surface_area(nodes_[0].box[0]);
        B direct = surface_area(merged(nodes_[0].box[0], L));  // the new parent's area, L's sibling here
        B inherited = B(0);
        std::int32_t best = location;
        B best_cost = direct;
        while (r > 0) {
            if (direct + inherited < best_cost) best = location, best_cost = direct + inherited;
            inherited += direct - area;
            const node& x = at(r);
            std::array<B, 2> lower{}, direct_c{}, area_c{};
            for (std::size_t c = 0; c < 2; ++c) {
                direct_c[c] = surface_area(merged(x.box[c], L));
                area_c[c] = surface_area(x.box[c]);
                lower[c] = inherited + direct_c[c] + std::min(area_l - area_c[c], B(0));
                if (x.child[c] < 0 && direct_c[c] + inherited < best_cost)
                    best = 2 * r + static_cast<std::int32_t>(c), best_cost = direct_c[c] + inherited;
            }
            // into the inner child of the lower bound (the nearer centre on a tie), if it can do better
            const bool inner0 = x.child[0] > 0, inner1 = x.child[1] > 0;
            if (!inner0 && !inner1) break;
            const std::size_t c = !inner1 || (inner0 && (lower[0] < lower[1] || (lower[0] == lower[1] && nearer_first(x, L)))) ? 0 : 1;
            if (!(lower[c] < best_cost)) break;
            location = 2 * r + static_cast<std::int32_t>(c);
            r = x.child[c];
            area = area_c[c];
            direct = direct_c[c];
        }
        return best;
    }
    [[nodiscard]] static bool nearer_first(const node& x, const aabb<bound>& L) noexcept {
        std::array<bound, 2> d{};
        for (std::size_t c = 0; c < 2; ++c)
            for (std::size_t k = 0; k < 3; ++k) {
                const bound e = (x.box[c].lower[k] + x.box[c].upper[k]) - (L.lower[k] + L.upper[k]);
                d[c] += e * e;
            }
        return d[0] <= d[1];
    }

    // Refits and rotates the nodes above the new one while they change.
    void insert_leaf(proxy_id id, const aabb<bound>& L) noexcept {
        if (nodes_[0].child[0] == empty) {
            place(0, leaf_ref(id), L);
            return;
        }
        const std::int32_t sibling = best_sibling(L);
        const std::int32_t q = free_node_;
        free_node_ = at(q).parent;
        const ref s = at(sibling >> 1).child[static_cast<std::size_t>(sibling & 1)];
        const aabb<bound> sbox = held(sibling);
        place(2 * q, s, sbox);
        place(2 * q + 1, leaf_ref(id), L);
        at(q).height = 1 + height_of(s);
        place(sibling, q, merged(sbox, L));
        for (std::int32_t n = sibling >> 1; n != 0; n = at(n).parent >> 1) {
            const bool changed = refit(n);
            if (!rotate(n) && !changed) break;
        }
    }

    void remove_leaf(proxy_id id) noexcept {
        const std::int32_t location = proxies_[id].location, p = location >> 1;
        if (p == 0) {
            nodes_[0].child[0] = empty;
            return;
        }
        const std::size_t other = 1 - static_cast<std::size_t>(location & 1);
        const std::int32_t up = at(p).parent;
        place(up, at(p).child[other], at(p).box[other]);
        at(p).parent = free_node_;
        free_node_ = p;
        for (std::int32_t n = up >> 1; n != 0 && refit(n); n = at(n).parent >> 1) {
        }
    }

    // The box and height of node n from its children, written where n is held; false when
    // neither changed.
    bool refit(std::int32_t n) noexcept {
        node& x = at(n);
        const aabb<bound> box = merged(x.box[0], x.box[1]);
        const std::int32_t height = 1 + std::max(height_of(x.child[0]), height_of(x.child[1]));
        aabb<bound>& h = held(x.parent);
        if (h == box && x.height == height) return false;
        h = box;
        x.height = height;
        return true;
    }

    // At inner node n with children B, C: swaps B with a child of C (C becomes B ∪ the other
    // child) or C with a child of B, the one that most shrinks the changed child's area; n's box
    // is the same after. False when no swap shrinks it.
    bool rotate(std::int32_t n) noexcept {
        node& x = at(n);
        bound best_gain = 0;
        std::size_t stay = 2, grand = 2;  // swap slot `stay` of n with slot `grand` of the other child
        for (std::size_t s = 0; s < 2; ++s) {
            const ref o = x.child[1 - s];
            if (o <= 0) continue;
            const bound area = surface_area(x.box[1 - s]);
            for (std::size_t g = 0; g < 2; ++g) {
                const bound gain = area - surface_area(merged(x.box[s], at(o).box[1 - g]));
                if (gain > best_gain) best_gain = gain, stay = s, grand = g;
            }
        }
        if (stay == 2) return false;
        const ref o = x.child[1 - stay];
        node& y = at(o);
        const ref down_ref = x.child[stay], up_ref = y.child[grand];
        const aabb<bound> down_box = x.box[stay], up_box = y.box[grand];
        place(2 * n + static_cast<std::int32_t>(stay), up_ref, up_box);
        place(2 * o + static_cast<std::int32_t>(grand), down_ref, down_box);
        x.box[1 - stay] = merged(y.box[0], y.box[1]);
        y.height = 1 + std::max(height_of(y.child[0]), height_of(y.child[1]));
        x.height = 1 + std::max(height_of(x.child[0]), height_of(x.child[1]));
        return true;
    }

    void check_subtree(ref r, std::int32_t location, std::size_t& leaves, std::size_t& inner, bool& ok) const noexcept {
        if (r < 0) {
            const proxy& p = proxies_[proxy_of(r)];
            ok = ok && p.alive && p.location == location;
            ++leaves;
            return;
        }
        const node& x = at(r);
        ++inner;
        ok = ok && x.parent == location && held(location) == merged(x.box[0], x.box[1]) &&
             x.height == 1 + std::max(height_of(x.child[0]), height_of(x.child[1])) && x.child[0] != empty && x.child[1] != empty;
        if (!ok) return;
        check_subtree(x.child[0], 2 * r, leaves, inner, ok);
        check_subtree(x.child[1], 2 * r + 1, leaves, inner, ok);
    }

    T margin_;
    std::pmr::vector<node> nodes_;  // [0] the sentinel, the rest inner nodes
    std::pmr::vector<proxy> proxies_;
    std::pmr::vector<proxy_id> touched_list_;
    std::pmr::vector<std::uint64_t> pairs_, next_pairs_, found_, scratch_;  // pair keys: a << id_bits_ | b, a < b
    std::int32_t free_node_ = 0;
    proxy_id free_proxy_ = 0;
    std::size_t count_ = 0, touched_count_ = 0, pair_count_ = 0;
    unsigned id_bits_ = 1;
    bool overflowed_ = false;
};

}  // namespace ctga::collision
