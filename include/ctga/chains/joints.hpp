// Joints of a kinematic tree (paper §7: bodies joined by joints; Featherstone, "Rigid Body
// Dynamics Algorithms" (2008), ch. 4). A joint is a type: how many configuration numbers it
// reads (nq), how many velocity numbers (nv), its motion and its free directions.
//
// Each free direction k < nv is a screw (§3) in the body frame, the joint's motion subspace
// column S_k. For a joint about or along a coordinate axis it is one blade known at compile
// time, e1e2 for a revolute joint about z, e1e for a prismatic joint along x, so every formula
// it enters (the joint velocity S q̇, the bracket v × S q̇, the momentum N S of the mass matrix,
// the pairing τ = f(S) = f ∨ (Q0 ∧ S) of §5) is evaluated by the engine on that one blade:
// the other five components are structural zeros and cost nothing.
//
//   revolute<axis::z>       rotation by q about the joint frame's z axis    nq = nv = 1
//   prismatic<axis::x>      translation by q along x                        nq = nv = 1
//   revolute<axis::minus_y> rotation by q about −y: S = −e3e1, still one blade
//   prismatic<axis::minus_z> translation by q along −z: S = −e3e
//   revolute_about          rotation about a unit axis u given at run time  nq = nv = 1
//   prismatic_along         translation along a unit axis u (run time)      nq = nv = 1
//   fixed                   no motion                                       nq = nv = 0
//   floating                a motor g (§3) relative to the joint frame      nq = 8, nv = 6
//   mimic<J, M>             J (one dof) at q = r q_M + o, body M's joint    nq = nv = 0
//   aligned<J>              J whose joint frame is aligned with the parent's: its placement a
//                           pure translation (URDF rpy = 0, most joints of real robots)
//   turned<turn{...}, J>    J whose joint frame is turned from the parent's by multiples of π/2
//                           (a signed permutation: URDF rpy "1.5707963267948966 0 0", the other
//                           joints of real robots); aligned<J> is turned<turn{}, J>
//   with_armature<J>        J (one dof) with a rotor inertia reflected onto it (H_ii + a)
//
// The body frame is the joint frame moved by the joint: its map in the parent's frame is
// placement ∘ motion(q), a motor_map (R, t) (motor.hpp). For an aligned joint R is the joint's own
// rotation, whose shape (linear3.hpp) the type knows: a turn about coordinate axis k has
// R_kk = 1 and four more zeros, so a screw or co-screw moves across the joint with 4m 2a per
// 3-vector instead of 9m 6a (Featherstone's X_J X_T split, §4.1), and the map costs no product.
// A turned joint's R = P R_J, P a signed permutation, has as many zeros, in other places, and −1
// among its known entries: it costs the same.
// The floating joint's velocity numbers are the body's screw relative to the joint frame in body
// coordinates, (ω, v), and its configuration the eight coefficients of the motor in ctga::motor's
// order; it moves as dg/dt = ½ g s (§3, body-frame velocity).
#pragma once

#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <string_view>
#include <type_traits>

#include "ctga/mechanics/algebras.hpp"
#include "ctga/mechanics/linear3.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/mechanics/screw.hpp"
#include "ctga/support/inline.hpp"
#include "ctga/support/math.hpp"

namespace ctga::chains {

// A coordinate axis of the joint frame, either way round.
enum class axis { x, y, z, minus_x, minus_y, minus_z };

namespace joint_detail {

// The bivector of Cl(0,3,1) of a rotation about coordinate axis A and of a translation along
// it (screw.hpp: s = ωx e2e3 + ωy e3e1 + ωz e1e2 + vx e1e + vy e2e + vz e3e).
constexpr int index_of(axis a) { return static_cast<int>(a) % 3; }
constexpr int sign_of(axis a) { return static_cast<int>(a) < 3 ? 1 : -1; }

// (The blade of −x is e2e3 too: the sign goes into the joint's S = −1·e2e3.)
template <axis A>
inline constexpr fixed_string rotation_blade = index_of(A) == 0 ? fixed_string{"e2e3"} : index_of(A) == 1 ? fixed_string{"e3e1"} : fixed_string{"e1e2"};
template <axis A>
inline constexpr fixed_string translation_blade = index_of(A) == 0 ? fixed_string{"e1e"} : index_of(A) == 1 ? fixed_string{"e2e"} : fixed_string{"e3e"};

// placement ∘ (rotation by angle q about coordinate axis k): R' = R Rₖ(q), t' = t. With
// (a, b) = (k + 1, k + 2) mod 3, Rₖ(q) turns column a of R towards column b:
// col_a' = c col_a + s col_b, col_b' = −s col_a + c col_b (12m 6a). Every entry is written once,
// in one initialiser: a copy of P overwritten in part leaves pairs of entries half written that
// the next read of the pair must wait for (a store-forwarding stall; measured: the 7-dof arm's
// seven maps 165 → 99 ns, the legged tree's thirteen 333 → 195 ns).
template <int K, class T>
CTGA_ALWAYS_INLINE constexpr motor_map<T> rotate_about_axis(const motor_map<T>& P, const T& c, const T& s) noexcept {
    constexpr int a = (K + 1) % 3, b = (K + 2) % 3;
    const auto entry = [&](int r, int j) CTGA_INLINE_LAMBDA -> T {
        return j == a ? c * P.R[r][a] + s * P.R[r][b] : j == b ? c * P.R[r][b] - s * P.R[r][a] : P.R[r][j];
    };
    return {{{{entry(0, 0), entry(0, 1), entry(0, 2)}, {entry(1, 0), entry(1, 1), entry(1, 2)}, {entry(2, 0), entry(2, 1), entry(2, 2)}}},
            P.t};
}

// The turn about coordinate axis K itself, R_K(q) (no flops): rotate_about_axis of the identity.
template <int K, class T>
CTGA_ALWAYS_INLINE constexpr mat3<T> axis_rotation(const T& c, const T& s) noexcept {
    constexpr int a = (K + 1) % 3, b = (K + 2) % 3;
    const auto entry = [&](int r, int j) CTGA_INLINE_LAMBDA -> T {
        return r == K && j == K ? T(1) : r == K || j == K ? T(0) : r == j ? c : r == b && j == a ? s : -s;
    };
    return {{{entry(0, 0), entry(0, 1), entry(0, 2)}, {entry(1, 0), entry(1, 1), entry(1, 2)}, {entry(2, 0), entry(2, 1), entry(2, 2)}}};
}
// Its shape: entry (K, K) is 1, the rest of row and column K are 0.
template <int K>
inline constexpr linear3::shape axis_rotation_shape = [] {
    linear3::shape out = linear3::dense;
    for (std::size_t j = 0; j < 3; ++j) {
        out.e[static_cast<std::size_t>(3 * K + j)] = j == K ? linear3::entry::one : linear3::entry::zero;
        out.e[static_cast<std::size_t>(3 * j + K)] = j == K ? linear3::entry::one : linear3::entry::zero;
    }
    return out;
}();
template <class T>
constexpr mat3<T> identity3() noexcept {
    return {{{T(1), T(0), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), T(1)}}};
}

// R u for the parameters' unit axis (column combination), and R·R_u(q) by Rodrigues' formula
// R_u(q) = 1 + s û + (1 − c) û².
template <class T>
constexpr mat3<T> rodrigues(const vec3<T>& u, const T& c, const T& s) noexcept {
    const T d = T(1) - c;
    return {{{c + d * u[0] * u[0], d * u[0] * u[1] - s * u[2], d * u[0] * u[2] + s * u[1]},
             {d * u[1] * u[0] + s * u[2], c + d * u[1] * u[1], d * u[1] * u[2] - s * u[0]},
             {d * u[2] * u[0] - s * u[1], d * u[2] * u[1] + s * u[0], c + d * u[2] * u[2]}}};
}
template <class T>
constexpr mat3<T> multiply(const mat3<T>& A, const mat3<T>& B) noexcept {
    mat3<T> C{};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) C[i][j] = A[i][0] * B[0][j] + A[i][1] * B[1][j] + A[i][2] * B[2][j];
    return C;
}

struct no_parameters {};

// A run-time unit axis: ‖u‖ = 1 to rounding (checked by the tree's parameters, tree.hpp).
template <class T>
struct unit_axis {
    vec3<T> u{T(0), T(0), T(1)};
};

}  // namespace joint_detail

namespace joint_detail {

// One degree of freedom along a single blade known at compile time (an axis joint):
// S = Sign·Blade, Sign = ±1.
template <fixed_string Blade, int Sign>
struct one_blade {
    static constexpr std::size_t nq = 1, nv = 1;
    // the screw component S lies on (screw.hpp's order: ω then v), e.g. 2 for e1e2
    static constexpr std::size_t component = [] {
        constexpr std::string_view names[6] = {"e2e3", "e3e1", "e1e2", "e1e", "e2e", "e3e"};
        for (std::size_t k = 0; k < 6; ++k)
            if (names[k] == Blade.view()) return k;
        return std::size_t(6);
    }();
    template <class T>
    using parameters = no_parameters;
    template <class T>
    using subspace_type = cl031::mv<T, Blade>;
    template <std::size_t K, class T>
    static constexpr subspace_type<T> subspace(const parameters<T>&) noexcept {
        return subspace_type<T>{T(Sign)};
    }
};

// One degree of freedom along a run-time unit axis u on three blades: S = u1 B1 + u2 B2 + u3 B3.
template <fixed_string B1, fixed_string B2, fixed_string B3>
struct unit_axis_dof {
    static constexpr std::size_t nq = 1, nv = 1;
    template <class T>
    using parameters = unit_axis<T>;
    template <class T>
    using subspace_type = cl031::mv<T, B1, B2, B3>;
    template <std::size_t K, class T>
    static constexpr subspace_type<T> subspace(const parameters<T>& p) noexcept {
        return subspace_type<T>{p.u[0], p.u[1], p.u[2]};
    }
};

}  // namespace joint_detail

// Rotation about a coordinate axis of the joint frame (about −e_k: by −q about e_k).
template <axis A>
struct revolute : joint_detail::one_blade<joint_detail::rotation_blade<A>, joint_detail::sign_of(A)> {
    template <class T>
    using parameters = joint_detail::no_parameters;  // (the base is dependent: named again here)
    template <class T>
    static constexpr motor_map<T> motion(const motor_map<T>& placement, const parameters<T>&, const T* q) noexcept {
        const math::cos_sin_pair<T> cs = math::cos_sin(q[0]);
        if constexpr (joint_detail::sign_of(A) > 0)
            return joint_detail::rotate_about_axis<joint_detail::index_of(A)>(placement, cs.cos, cs.sin);
        else
            return joint_detail::rotate_about_axis<joint_detail::index_of(A)>(placement, cs.cos, -cs.sin);
    }
    // its own motion in the joint frame (turned<P, revolute<A>>): the turn R_k(±q), no translation
    static constexpr linear3::shape own_shape = joint_detail::axis_rotation_shape<joint_detail::index_of(A)>;
    static constexpr std::array<bool, 3> own_translation{false, false, false};
    template <class T>
    static constexpr motor_map<T> own_motion(const parameters<T>&, const T* q) noexcept {
        const math::cos_sin_pair<T> cs = math::cos_sin(q[0]);
        const T s = joint_detail::sign_of(A) > 0 ? cs.sin : -cs.sin;
        return {joint_detail::axis_rotation<joint_detail::index_of(A)>(cs.cos, s), {}};
    }
};

// Translation along a coordinate axis of the joint frame: t' = t ± q R e_k (3m 3a).
template <axis A>
struct prismatic : joint_detail::one_blade<joint_detail::translation_blade<A>, joint_detail::sign_of(A)> {
    template <class T>
    using parameters = joint_detail::no_parameters;
    template <class T>
    static constexpr motor_map<T> motion(const motor_map<T>& placement, const parameters<T>&, const T* q) noexcept {
        constexpr int k = joint_detail::index_of(A);
        const T d = joint_detail::sign_of(A) > 0 ? q[0] : -q[0];
        return {placement.R, {placement.t[0] + d * placement.R[0][k], placement.t[1] + d * placement.R[1][k], placement.t[2] + d * placement.R[2][k]}};
    }
    // its own motion: the translation ±q e_k
    static constexpr linear3::shape own_shape = linear3::identity;
    static constexpr std::array<bool, 3> own_translation{joint_detail::index_of(A) == 0, joint_detail::index_of(A) == 1,
                                                         joint_detail::index_of(A) == 2};
    template <class T>
    static constexpr motor_map<T> own_motion(const parameters<T>&, const T* q) noexcept {
        vec3<T> d{};
        d[joint_detail::index_of(A)] = joint_detail::sign_of(A) > 0 ? q[0] : -q[0];
        return {joint_detail::identity3<T>(), d};
    }
};

// Rotation about a unit axis u of the joint frame given at run time.
struct revolute_about : joint_detail::unit_axis_dof<"e2e3", "e3e1", "e1e2"> {
    template <class T>
    static constexpr motor_map<T> motion(const motor_map<T>& placement, const parameters<T>& p, const T* q) noexcept {
        const math::cos_sin_pair<T> cs = math::cos_sin(q[0]);
        return {joint_detail::multiply(placement.R, joint_detail::rodrigues(p.u, cs.cos, cs.sin)), placement.t};
    }
    static constexpr linear3::shape own_shape = linear3::dense;
    static constexpr std::array<bool, 3> own_translation{false, false, false};
    template <class T>
    static constexpr motor_map<T> own_motion(const parameters<T>& p, const T* q) noexcept {
        const math::cos_sin_pair<T> cs = math::cos_sin(q[0]);
        return {joint_detail::rodrigues(p.u, cs.cos, cs.sin), {}};
    }
};

// Translation along a unit axis u of the joint frame given at run time: t' = t + q R u.
struct prismatic_along : joint_detail::unit_axis_dof<"e1e", "e2e", "e3e"> {
    template <class T>
    static constexpr motor_map<T> motion(const motor_map<T>& placement, const parameters<T>& p, const T* q) noexcept {
        const vec3<T> d = linear3::apply(placement.R, p.u);
        return {placement.R, {placement.t[0] + q[0] * d[0], placement.t[1] + q[0] * d[1], placement.t[2] + q[0] * d[2]}};
    }
    static constexpr linear3::shape own_shape = linear3::identity;
    static constexpr std::array<bool, 3> own_translation{true, true, true};
    template <class T>
    static constexpr motor_map<T> own_motion(const parameters<T>& p, const T* q) noexcept {
        return {joint_detail::identity3<T>(), {q[0] * p.u[0], q[0] * p.u[1], q[0] * p.u[2]}};
    }
};

// A rigid connection: the body frame is the joint frame.
struct fixed {
    static constexpr std::size_t nq = 0, nv = 0;
    template <class T>
    using parameters = joint_detail::no_parameters;
    template <class T>
    using subspace_type = screw<T>;  // never formed: nv = 0
    template <std::size_t K, class T>
    static constexpr screw<T> subspace(const parameters<T>&) noexcept {
        static_assert(K != K, "ctga::chains::fixed: a fixed joint has no free direction");
        return {};
    }
    template <class T>
    static constexpr motor_map<T> motion(const motor_map<T>& placement, const parameters<T>&, const T*) noexcept {
        return placement;
    }
    static constexpr linear3::shape own_shape = linear3::identity;
    static constexpr std::array<bool, 3> own_translation{false, false, false};
    template <class T>
    static constexpr motor_map<T> own_motion(const parameters<T>&, const T*) noexcept {
        return {joint_detail::identity3<T>(), {}};
    }
};

// Six degrees of freedom: the body's motor g relative to the joint frame (a mobile or legged
// base). Free direction k is the k-th blade of a screw, so S = 1 in body coordinates.
struct floating {
    static constexpr std::size_t nq = 8, nv = 6;
    template <class T>
    using parameters = joint_detail::no_parameters;
    template <class T, std::size_t K>
    using blade_screw = std::conditional_t<(K < 3), cl031::mv<T, joint_detail::rotation_blade<axis(K % 3)>>,
                                           cl031::mv<T, joint_detail::translation_blade<axis(K % 3)>>>;
    template <std::size_t K, class T>
    static constexpr blade_screw<T, K> subspace(const parameters<T>&) noexcept {
        return blade_screw<T, K>{T(1)};
    }
    // placement ∘ map_of(g): R' = R R_g, t' = R t_g + t.
    template <class T>
    static constexpr motor_map<T> motion(const motor_map<T>& placement, const parameters<T>&, const T* q) noexcept {
        const motor_map<T> J = map_of(motor<T>{q[0], q[1], q[2], q[3], q[4], q[5], q[6], q[7]});
        return {joint_detail::multiply(placement.R, J.R), linear3::add(linear3::apply(placement.R, J.t), placement.t)};
    }
    static constexpr linear3::shape own_shape = linear3::dense;
    static constexpr std::array<bool, 3> own_translation{true, true, true};
    template <class T>
    static constexpr motor_map<T> own_motion(const parameters<T>&, const T* q) noexcept {
        return map_of(motor<T>{q[0], q[1], q[2], q[3], q[4], q[5], q[6], q[7]});
    }
};

// The coupling of a mimic joint to the joint it follows: q = multiplier · q_master + offset.
template <class T = double>
struct coupling {
    T multiplier{1};
    T offset{0};
};

// A joint J of one degree of freedom that follows body Master's joint (URDF's <mimic>: gripper
// fingers, hands): q = r q_M + o, q̇ = r q̇_M, q̈ = r q̈_M. It has no coordinates of its own
// (nq = nv = 0) and reads its master's; its velocity is S (r q̇_M). With G the matrix taking the
// independent velocities to every joint's (1 in the independent joints' own places, r in the
// mimic's row, master's column), the algorithms give the reduced τ = Gᵀ τ_all (the mimic's torque
// goes to its master), H = Gᵀ H_all G and J = J_all G.
template <class J, std::size_t Master>
struct mimic {
    static_assert(J::nq == 1 && J::nv == 1,
                  "ctga::chains::mimic: the mimicking joint has one degree of freedom (revolute, prismatic)");
    static constexpr std::size_t nq = 0, nv = 0;
    static constexpr std::size_t master = Master;
    using followed_joint = J;
    template <class T>
    struct parameters {
        typename J::template parameters<T> joint{};  // J's own parameters (e.g. the axis of revolute_about)
        T multiplier{1};
        T offset{0};
    };
    template <class T>
    using subspace_type = typename J::template subspace_type<T>;
    template <std::size_t K, class T>
    static constexpr subspace_type<T> subspace(const parameters<T>& p) noexcept {
        return J::template subspace<K, T>(p.joint);
    }
    // q_master: the master's coordinate.
    template <class T>
    static constexpr motor_map<T> motion(const motor_map<T>& placement, const parameters<T>& p, const T* q_master) noexcept {
        const T q = p.multiplier * q_master[0] + p.offset;
        return J::motion(placement, p.joint, &q);
    }
};

template <class J>
inline constexpr bool is_mimic = false;
template <class J, std::size_t M>
inline constexpr bool is_mimic<mimic<J, M>> = true;

// The turn of a joint frame from its parent's by multiples of π/2 about coordinate axes: the
// parent's axes along which the joint frame's x, y and z axes lie, so that its rotation P is a
// signed permutation (column j of P is ±e_k for the j-th axis). turn{} leaves the axes as they are.
struct turn {
    axis x = axis::x, y = axis::y, z = axis::z;
    [[nodiscard]] constexpr axis column(std::size_t j) const noexcept { return j == 0 ? x : j == 1 ? y : z; }
    // the column whose axis is the parent's k-th, so that row k of P R is ±row column_along(k) of R
    [[nodiscard]] constexpr std::size_t column_along(std::size_t k) const noexcept {
        for (std::size_t j = 0; j < 3; ++j)
            if (static_cast<std::size_t>(joint_detail::index_of(column(j))) == k) return j;
        return 3;
    }
    // a rotation: the three axes distinct and right-handed (x × y = z)
    [[nodiscard]] constexpr bool is_rotation() const noexcept {
        const int i = joint_detail::index_of(x), j = joint_detail::index_of(y), k = joint_detail::index_of(z);
        if (i == j || j == k || i == k) return false;
        const int parity = (j - i + 3) % 3 == 1 ? 1 : -1;  // (i, j, k) cyclic: an even permutation
        return parity * joint_detail::sign_of(x) * joint_detail::sign_of(y) * joint_detail::sign_of(z) == 1;
    }
    friend constexpr bool operator==(const turn&, const turn&) = default;
};
// P as a matrix (for checks and references).
template <class T>
[[nodiscard]] constexpr mat3<T> turn_matrix(const turn& P) noexcept {
    mat3<T> out{};
    for (std::size_t j = 0; j < 3; ++j)
        out[static_cast<std::size_t>(joint_detail::index_of(P.column(j)))][j] = T(joint_detail::sign_of(P.column(j)));
    return out;
}

namespace joint_detail {
// The shape of P R for R of shape S: row k is ±row column_along(k) of S, so an entry known to be 1
// becomes ±1 and the zeros stay.
constexpr linear3::shape turned_shape(const turn& P, const linear3::shape& S) noexcept {
    linear3::shape out = S;
    for (std::size_t k = 0; k < 3; ++k) {
        const std::size_t j = P.column_along(k);
        const bool minus = sign_of(P.column(j)) < 0;
        for (std::size_t c = 0; c < 3; ++c) {
            const linear3::entry e = S.at(j, c);
            out.e[3 * k + c] = e == linear3::entry::any || e == linear3::entry::zero ? e
                               : (e == linear3::entry::one) != minus                ? linear3::entry::one
                                                                                    : linear3::entry::minus_one;
        }
    }
    return out;
}
// ±x: x, or −x (one negation; none for a plus sign).
template <int Sign, class T>
CTGA_ALWAYS_INLINE constexpr T signed_entry(const T& x) noexcept {
    if constexpr (Sign > 0) return x;
    else return -x;
}
}  // namespace joint_detail

// A joint J whose joint frame is turned from its parent's by P (its placement's rotation is P,
// checked by make_link: not_aligned), so that the body's map is (P R_J, t + P t_J) for J's own
// motion (R_J, t_J) in the joint frame (own_motion) and the placement's translation t: P only moves
// and negates entries (none for turn{}, aligned<J>), and R's shape (linear3.hpp) is own_shape's
// rows moved, which the algorithms' transforms use: a turned revolute joint crosses a screw at an
// aligned one's cost. A mimic joint follows a turned one as mimic<turned<P, J>, M>.
template <turn P, class J>
struct turned : J {
    static_assert(P.is_rotation(), "ctga::chains::turned: the joint frame's axes turn{x, y, z} must be the parent's "
                                   "axes, each once, right-handed (a rotation by multiples of pi/2)");
    static_assert(!is_mimic<J>, "ctga::chains::turned: for a mimic joint write mimic<turned<P, J>, Master>");
    static constexpr linear3::shape shape = joint_detail::turned_shape(P, J::own_shape);
    template <class T>
    static constexpr motor_map<T> motion(const motor_map<T>& placement, const typename J::template parameters<T>& p,
                                         const T* q) noexcept {
        const motor_map<T> own = J::own_motion(p, q);
        // row k of P R_J is ±row j of R_J and entry k of P t_J is ±entry j of t_J (j = column_along(k))
        const auto row = [&]<std::size_t k>() CTGA_INLINE_LAMBDA -> vec3<T> {
            constexpr std::size_t j = P.column_along(k);
            constexpr int sign = joint_detail::sign_of(P.column(j));
            return {joint_detail::signed_entry<sign>(own.R[j][0]), joint_detail::signed_entry<sign>(own.R[j][1]),
                    joint_detail::signed_entry<sign>(own.R[j][2])};
        };
        const auto translation = [&]<std::size_t k>() CTGA_INLINE_LAMBDA -> T {
            constexpr std::size_t j = P.column_along(k);
            if constexpr (J::own_translation[j])
                return placement.t[k] + joint_detail::signed_entry<joint_detail::sign_of(P.column(j))>(own.t[j]);
            else return placement.t[k];
        };
        return {{row.template operator()<0>(), row.template operator()<1>(), row.template operator()<2>()},
                {translation.template operator()<0>(), translation.template operator()<1>(), translation.template operator()<2>()}};
    }
};
template <class J>
using aligned = turned<turn{}, J>;
// Whether J's placement rotation is known at compile time (turned, aligned, or a mimic of one).
template <class J>
inline constexpr bool is_turned = false;
template <turn P, class J>
inline constexpr bool is_turned<turned<P, J>> = true;
template <class J, std::size_t M>
inline constexpr bool is_turned<mimic<J, M>> = is_turned<J>;
// The turn of a turned joint's placement (turn{} for the others, whose placement is general).
template <class J>
inline constexpr turn placement_turn = turn{};
template <turn P, class J>
inline constexpr turn placement_turn<turned<P, J>> = P;
template <class J, std::size_t M>
inline constexpr turn placement_turn<mimic<J, M>> = placement_turn<J>;

// A joint J of one degree of freedom driven through a gear: the inertia of its motor's rotor,
// reflected (J_rotor · ratio²), its armature, a run-time parameter (link_parameters::armature),
// adds to the joint's own entry of the mass matrix, H_ii + a. Its type says so, because ABA's
// articulated inertia N^A − U Uᵀ/D keeps S's component zero only without it (N^a S = U a/D): a
// joint without armature keeps that structure and pays nothing. With an aligned placement:
// aligned<with_armature<J>>.
template <class J>
struct with_armature : J {
    static_assert(J::nq == 1 && J::nv == 1 && !is_mimic<J>,
                  "ctga::chains::with_armature: a joint with an armature has one degree of freedom of its own (revolute, "
                  "prismatic; a mimic joint's rotor belongs to its master)");
};
template <class J>
inline constexpr bool has_armature = false;
template <class J>
inline constexpr bool has_armature<with_armature<J>> = true;
template <turn P, class J>
inline constexpr bool has_armature<turned<P, J>> = has_armature<J>;

// The shape of R in a body's map placement ∘ motion(q) (linear3.hpp): dense unless the joint is
// turned (or aligned).
template <class J>
inline constexpr linear3::shape map_shape = linear3::dense;
template <turn P, class J>
inline constexpr linear3::shape map_shape<turned<P, J>> = turned<P, J>::shape;
template <class J, std::size_t M>
inline constexpr linear3::shape map_shape<mimic<J, M>> = map_shape<J>;

// Whether a joint moves its body relative to the parent: it has velocity numbers, or it mimics.
template <class J>
inline constexpr bool moves = J::nv > 0 || is_mimic<J>;

// Whether a joint's type leaves its axis to run time (revolute_about, prismatic_along, or a mimic
// of one): make_link then takes the axis, and refuses one for every other joint, whose axis its
// type fixes.
namespace joint_detail {
template <class J>
struct axis_owner {
    using type = J;
};
template <class J, std::size_t M>
struct axis_owner<mimic<J, M>> {
    using type = J;
};
}  // namespace joint_detail
template <class J>
inline constexpr bool has_run_time_axis =
    std::is_same_v<typename joint_detail::axis_owner<J>::type::template parameters<double>, joint_detail::unit_axis<double>>;

using revolute_x = revolute<axis::x>;
using revolute_y = revolute<axis::y>;
using revolute_z = revolute<axis::z>;
using prismatic_x = prismatic<axis::x>;
using prismatic_y = prismatic<axis::y>;
using prismatic_z = prismatic<axis::z>;

template <class J>
concept joint = requires {
    { J::nq } -> std::convertible_to<std::size_t>;
    { J::nv } -> std::convertible_to<std::size_t>;
    typename J::template parameters<double>;
};

}  // namespace ctga::chains
