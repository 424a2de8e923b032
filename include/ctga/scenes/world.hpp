// A world of bodies that touch: moving bodies with shapes, grouped by kind, static shapes around
// them, gravity, and a step that makes them push, rub, bounce and rest (issue 44).
//
//   using cube = ctga::body_kind<ctga::subspace::full, ctga::inertia_kind::diagonal, collision::box<double>>;
//   ctga::physics_world<double, collision::half_space<double>, cube> w({5050}, {.statics = 1, .contacts = 40000, .pairs = 20000});
//   w.add_static(collision::half_space<double>{}, ground_pose, {.friction = 0.6});
//   w.add_body<0>(*collision::make_box(0.5, 0.5, 0.5), 100.0 /* density */, pose, {});
//   ctga::step_report<double> r = w.step(1.0 / 60);     // r.contact.residual, r.penetration, …
//
// The kinds are types: body_kind<subspace, inertia structure, shape> (body_kinds.hpp; the shape
// may be a collision::shape variant). Bodies of one kind are stored together, as arrays; a pair of
// kinds compiles its own narrowphase routine, and a body's response (its mobility) is its kind's.
// Static shapes (a ground, walls, a mesh: few) are one shape type, met by every moving body whose
// box reaches theirs; they have no side in a contact's rows. A kinematic one moves at a velocity
// given to it (a conveyor, a turntable): its surface's velocity k enters the rows as an offset,
// u = J s + k, and nothing pushes it. Joints (joints.hpp:
// spherical, revolute, prismatic, fixed, distance) hold two bodies, or a body and the ground,
// together: one to three blocks of three rows each (constraints/joint_rows.hpp), solved with the
// contacts in one problem (joints first in each sweep); jointed bodies do not collide. Elastic
// couplings (couplings.hpp, §7: K and D) push with −K ξ − D s, applied as the step starts; the
// same elements make a static shape soft (set_compliance): its contacts' normal rows become
// springs and dampers, in the contact problem.
//
// The step, in its stages (each a member function of that name):
//   collide         poses' maps, broadphase boxes, manifolds within the speculative reach
//   build_rows      each manifold point's three rows (constraints/contact_rows.hpp): lines,
//                   responses, Delassus block, the normal row's offset (below); the free
//                   velocities s + h (gravity, §6's gyroscopic term)
//   warm_start      the impulses of the contacts (pair, point id) the last step ended with
//   solve           the frictional contact problem to the settings' tolerance
//                   (constraints/contact_problem.hpp), then the normal-only problem of position
//                   correction on pseudo-velocities
//   soft_solve      instead of solve when settings.substeps > 0: the soft step
//                   (constraints/soft_step.hpp), cheaper, to no tolerance (the step below is the
//                   exact way's; the soft step's impulses are a substep's)
//   integrate       poses from the velocities (the soft step's: from the displacements)
//   store_impulses  the impulses by contact, sorted, for the next warm start
// begin (collide … warm_start), correct (solve's position correction) and end (integrate,
// store_impulses) let a stepper solve the world's rows with its own (constrained/robot_world.hpp:
// a robot's), reading and writing them through rows(), impulses(), velocities() and mobilities().
//
// Time stepping (Moreau–Jean with θ = ½ for positions): velocities jump to s⁺ = s_free + N⁻¹ Jᵀ r,
// positions move with the average (s⁻ + s⁺)/2, the centre of mass by h (v⁻ + v⁺)/2 and the
// rotation by exp(h (ω⁻ + ω⁺)/2) on the left. Under a force constant over the step this is exact
// (free fall, a block sliding down an incline: the energy lost is the friction's work to
// rounding); a gap then closes as φ⁺ = φ + h (u⁻ + u⁺)/2 to first order. A contact's normal row:
//   closing this step (free flight would give φ + h (u⁻ + u_free)/2 ≤ 0): Newton's impact law
//       u⁺ ≥ −e u⁻ (e = 0 below the restitution threshold speed); with e = 1 the body leaves
//       at −u⁻ from where it was, so the step keeps its energy;
//   otherwise speculative: u⁺ ≥ −u⁻ − 2φ / h, the gap may close but not be crossed.
// Penetration left over is removed by a second, frictionless problem on pseudo-velocities that
// move positions only (split impulse): the velocities, and so the energy, are not changed by it.
// Its contact lines pass through the bodies' centres of mass: it moves bodies without turning them.
// It removes all the penetration the step's own motion makes (an inelastic impact's body moves on
// by h u⁻/2: at 1,000 m/s, through a 2 cm wall, measured) and the fraction β of what the step
// started with, less the slop. The same problem closes the joints' gaps (all of each, no slop).
//
// No body sleeps: every one is stepped every step (a resting pyramid's warm-started steps cost
// 0–4 sweeps, measured), and the rows are one problem, not islands.
//
// Storage: allocated by the constructor from a std::pmr::memory_resource, nothing afterwards;
// more bodies, contacts or pairs than the capacities is capacity_exceeded. A step that goes
// non-finite returns non_finite and keeps the state it started from.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory_resource>
#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "ctga/collision/broadphase.hpp"
#include "ctga/collision/manifold.hpp"
#include "ctga/collision/narrowphase.hpp"
#include "ctga/collision/shape_set.hpp"
#include "ctga/constraints/contact_problem.hpp"
#include "ctga/constraints/contact_rows.hpp"
#include "ctga/constraints/joint_rows.hpp"
#include "ctga/constraints/newton_polish.hpp"
#include "ctga/constraints/soft_step.hpp"
#include "ctga/mechanics/mass_properties.hpp"
#include "ctga/mechanics/motor.hpp"
#include "ctga/scenes/body_kinds.hpp"
#include "ctga/scenes/couplings.hpp"
#include "ctga/scenes/joints.hpp"
#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"
#include "ctga/support/team.hpp"
#include "ctga/support/unit_direction.hpp"

namespace ctga {

template <class S, class K, class Shape>
struct body_kind {
    using subspace_type = S;
    using inertia_type = K;
    using shape_type = Shape;
};

// A surface's friction coefficient and restitution; a contact takes √(μ_A μ_B) and max(e_A, e_B).
template <class T = double>
struct material {
    T friction = T(0.5);
    T restitution = T(0);
};

template <class T = double>
struct world_settings {
    vec3<T> gravity{T(0), T(0), T(-9.81)};
    T margin = T(0.02);                  // speculative distance: points this far apart are rows
    T fat_margin = T(0.1);               // the broadphase's boxes are this much larger (Box2D's): a body moving
                                         // less keeps its place in the tree (≥ margin)
    T restitution_threshold = T(0.05);   // slower impacts are inelastic (m/s)
    T slop = T(1e-4);                    // penetration left alone (m)
    T correction = T(0.2);               // fraction of a penetration found at a step's start removed by the step
    std::size_t correction_sweeps = 10;  // at most, for the position correction
    constraints::contact_settings<T> solver{T(1e-8), 200, constraints::local_solve::projected};
    bool conjugate = true;               // sweeps accelerated by conjugate directions (contact_problem.hpp)
    std::size_t threads = 1;             // the solver's sweeps on this many threads (the same results for any number)
    std::size_t partitions = 1;          // parts the sweeps split the bodies into (1 … 64, a larger number is taken
                                         // as 64): the results depend on it, not on the threads; one part sweeps in
                                         // row order, which converges best (joint_grid, 4 sweeps: joint gap 6.2 cm
                                         // with one part, 2.2 m with two slabs), more let threads share the sweeps
    std::size_t parallel_rows = 2048;    // fewer rows are swept by the caller's thread alone (the same schedule, the
                                         // same results: a fork and join costs more than a sweep of a few hundred rows)
    std::size_t polish_limit = 64;       // sweeps short of the tolerance are finished by Newton
                                         // (newton_polish.hpp) on problems of at most this many contacts
    // The soft step instead (constraints/soft_step.hpp) when substeps > 0: that many substeps of two
    // sweeps each, the gaps springs; no tolerance, no residual (NaN in the report), no correction
    std::size_t substeps = 0;
    T contact_hertz = T(0);  // the contacts' springs: at most a quarter of the substeps' rate, that when 0
                             // (Box2D's limit; measured, the stiffest stood best); the joints' twice it, as
                             // far as the same limit
    T contact_damping = T(10), joint_damping = T(2);  // their damping ratios
    T push_speed = T(3);                              // the fastest a contact's spring pushes out (m/s)
};

struct world_capacity {
    std::size_t statics = 1;
    std::size_t contacts = 1024;  // manifold points per step
    std::size_t pairs = 1024;     // broadphase pairs
    std::size_t joints = 0;
    std::size_t couplings = 0;  // elastic couplings (couplings.hpp)
};

template <class T>
struct step_report {
    error_code error = error_code::none;
    constraints::contact_report<T> contact;     // the frictional problem's solve
    constraints::contact_report<T> correction;  // the position correction's
    std::size_t contacts = 0;                   // manifold points
    T penetration = T(0);                       // the largest at the step's start (m)
    T joint_error = T(0);                       // the largest gap of a joint's point, line or distance at the step's start (m)
    T joint_angle = T(0);                       // the largest of a joint's hinge or weld (sin of the angle)
};

namespace world_detail {
// A body kind's data from the mass properties of its shape: the inertia structure must hold them
// (centre of mass at the body origin, principal axes along the body's; sphere: three equal moments).
template <class K, class T>
[[nodiscard]] constexpr error_code kind_holds(const mass_properties<T>& p) noexcept {
    static_assert(std::is_same_v<K, inertia_kind::sphere> || std::is_same_v<K, inertia_kind::axisymmetric> ||
                      std::is_same_v<K, inertia_kind::diagonal>,
                  "ctga::physics_world: a moving body's inertia structure is sphere, axisymmetric or diagonal (its centre of "
                  "mass at its origin, on principal axes)");
    const mat3<T>& I = p.inertia_c;
    const T tiny = T(64) * std::numeric_limits<T>::epsilon() * (I[0][0] + I[1][1] + I[2][2]);
    const auto off = [&](const T& x) { return x > tiny || -x > tiny; };
    // (the centre within rounding of the origin: a hull moved there, on_principal_axes, keeps ~ε of its size)
    const T reach = math::sqrt((I[0][0] + I[1][1] + I[2][2]) / p.mass);
    const T c2 = linear3::dot(p.com, p.com), near = T(64) * std::numeric_limits<T>::epsilon() * reach;
    const bool centred = c2 <= near * near;
    bool ok = centred && !off(I[0][1]) && !off(I[0][2]) && !off(I[1][2]);
    if constexpr (std::is_same_v<K, inertia_kind::sphere>) ok = ok && !off(I[0][0] - I[1][1]) && !off(I[0][0] - I[2][2]);
    if constexpr (std::is_same_v<K, inertia_kind::axisymmetric>) ok = ok && !off(I[0][0] - I[1][1]);
    return ok ? error_code::none : error_code::not_aligned;
}
template <class K, class T>
[[nodiscard]] constexpr typename K::template data<T> data_from(const mass_properties<T>& p) noexcept {
    const mat3<T>& I = p.inertia_c;
    if constexpr (std::is_same_v<K, inertia_kind::sphere>) return {p.mass, I[0][0]};
    else if constexpr (std::is_same_v<K, inertia_kind::axisymmetric>) return {p.mass, I[0][0], I[2][2]};
    else return {p.mass, I[0][0], I[1][1], I[2][2]};
}

// A shape's mass properties at a density; a shape variant's by its kind.
template <class Shape, class T>
[[nodiscard]] constexpr checked<mass_properties<T>> mass_of_shape(const Shape& shape, const T& density) noexcept {
    if constexpr (requires { shape.index(); }) return std::visit([&](const auto& x) { return mass_of(x, density); }, shape);
    else return mass_of(shape, density);
}

// The body-frame inverse moments (the diagonal of I_b⁻¹).
template <class K, class T>
[[nodiscard]] constexpr vec3<T> inverse_moments(const typename K::template data<T>& d) noexcept {
    if constexpr (std::is_same_v<K, inertia_kind::sphere>) return {d.reciprocal(1)[0], d.reciprocal(1)[0], d.reciprocal(1)[0]};
    else if constexpr (std::is_same_v<K, inertia_kind::axisymmetric>)
        return {d.reciprocal(1)[0], d.reciprocal(1)[0], d.reciprocal(2)[0]};
    else return {d.reciprocal(1)[0], d.reciprocal(2)[0], d.reciprocal(3)[0]};
}

// I_w⁻¹ = R diag(k) Rᵀ; a sphere's is k·1 (no rotation needed).
template <class K, class T>
[[nodiscard]] constexpr constraints::mobility<T> world_mobility(const typename K::template data<T>& d, const mat3<T>& R) noexcept {
    const vec3<T> k = inverse_moments<K, T>(d);
    constraints::mobility<T> M{d.reciprocal(0)[0], {}};
    if constexpr (std::is_same_v<K, inertia_kind::sphere>) {
        M.inverse_inertia = {{{k[0], T(0), T(0)}, {T(0), k[0], T(0)}, {T(0), T(0), k[0]}}};
    } else {
        for (std::size_t i = 0; i < 3; ++i)
            for (std::size_t j = i; j < 3; ++j)
                M.inverse_inertia[i][j] = M.inverse_inertia[j][i] =
                    R[i][0] * k[0] * R[j][0] + R[i][1] * k[1] * R[j][1] + R[i][2] * k[2] * R[j][2];
    }
    return M;
}

template <class T>
[[nodiscard]] constexpr T norm(const vec3<T>& x) noexcept {
    return math::sqrt(linear3::dot(x, x));
}

// A contact's identity from one step to the next: its two bodies (a static shape as
// statics_bit | index) and the point's feature id.
inline constexpr std::uint32_t statics_bit = std::uint32_t{1} << 31;
struct contact_key {
    std::uint32_t a, b, id;
    friend constexpr bool operator<(const contact_key& x, const contact_key& y) noexcept {
        return x.a != y.a ? x.a < y.a : x.b != y.b ? x.b < y.b : x.id < y.id;
    }
    friend constexpr bool operator==(const contact_key&, const contact_key&) = default;
};
template <class T>
struct stored_impulse {
    contact_key key;
    vec3<T> r;      // the impulse in the world's axes (the tangents of a frame need not be the next step's)
    vec3<T> local;  // the point in body a's frame
};

// A moving body's coordinate along the axis the sweeps' slabs divide (partition).
template <class T>
struct ranked {
    T at;
    std::uint32_t body;
};

// An elastic coupling as the world keeps it: global body ids (no_body for the ground).
template <class T>
struct coupling_record {
    std::uint32_t a, b;
    elastic_coupling<T> coupling;
};

// A manifold found by collide, between moving body a and moving body b or static shape b.
template <class T>
struct found_manifold {
    std::uint32_t a, b;  // b: a body, or statics_bit | static index
    collision::manifold<T> m;
};
}  // namespace world_detail

template <class T, class Static, class... Kinds>
class physics_world {
    static_assert(sizeof...(Kinds) > 0, "ctga::physics_world: name at least one body kind");
    static_assert((std::is_same_v<typename Kinds::subspace_type, subspace::full> && ...),
                  "ctga::physics_world: moving bodies with contact move in full space (subspace::full)");

    template <class Kind>
    struct group {
        using K = typename Kind::inertia_type;
        std::pmr::vector<typename Kind::shape_type> shape;
        std::pmr::vector<typename K::template data<T>> data;
        std::size_t offset = 0, capacity = 0, count = 0;
    };
    static constexpr std::size_t kinds = sizeof...(Kinds);
    static constexpr std::size_t max_partitions = 64;
    // the soft step's colours and lanes (constraints/row_colours.hpp)
    static constexpr std::size_t max_colours = 64, lanes = native_lanes<T>;
    using lane_group = constraints::row_group<T, lanes>;
    static constexpr std::uint32_t no_row = ~std::uint32_t{0};

public:
    using scalar_type = T;
    template <std::size_t I>
    using kind = std::tuple_element_t<I, std::tuple<Kinds...>>;

    physics_world(const std::array<std::size_t, kinds>& bodies, const world_capacity& capacity, const world_settings<T>& settings = {},
          std::pmr::memory_resource* storage = std::pmr::get_default_resource())
        : settings_(settings),
          groups_{group<Kinds>{std::pmr::vector<typename Kinds::shape_type>(storage),
                               std::pmr::vector<typename Kinds::inertia_type::template data<T>>(storage)}...},
          total_(sum(bodies)),
          pose_(total_, storage), before_pose_(total_, storage), map_(total_, storage), velocity_(total_ + 1, storage),
          before_(total_, storage), pseudo_(total_, storage), displacement_(total_ + 1, storage), free_(total_, storage), substep_start_(total_, storage), force_(total_, storage), torque_(total_, storage), mobility_(total_, storage), material_(total_, storage),
          reach_(total_, storage), radius_(total_, storage), box_(total_, storage), proxy_(total_, storage), static_shape_(storage),
          static_pose_(capacity.statics, storage), static_map_(capacity.statics, storage), static_velocity_(capacity.statics, storage),
          static_box_(capacity.statics, storage), static_material_(capacity.statics, storage),
          static_bounded_(capacity.statics, storage), static_moving_(capacity.statics, storage), static_soft_(capacity.statics, storage),
          static_softness_(capacity.statics, storage), found_(capacity.contacts, storage),
          by_key_(capacity.contacts, storage), first_of_body_(total_ + 1, storage), stored_from_(rows_for(capacity), storage), rows_(rows_for(capacity), storage),
          keys_(rows_for(capacity), storage), separation_(rows_for(capacity), storage), before_normal_(rows_for(capacity), storage),
          surface_(rows_for(capacity), storage),
          impulse_(3 * rows_for(capacity), storage), correction_(3 * rows_for(capacity), storage), mu_(rows_for(capacity), storage), restitution_(rows_for(capacity), storage), spring_rate_(rows_for(capacity), storage), arm_(rows_for(capacity), storage),
          colour_used_(total_, storage), colour_of_(rows_for(capacity), storage),
          colour_order_(rows_for(capacity), storage), colour_start_(max_colours + 2, storage), lane_group_start_(max_colours + 1, storage),
          lane_groups_(rows_for(capacity) / lanes + 2 * max_colours, storage), lane_bilateral_(rows_for(capacity) / lanes + 2 * max_colours, storage),
          lane_first_(rows_for(capacity) / lanes + 2 * max_colours, storage), lane_count_(rows_for(capacity) / lanes + 2 * max_colours, storage),
          singles_(max_colours * (lanes / 4), storage), single_bilateral_(max_colours * (lanes / 4), storage), single_start_(max_colours + 1, storage),
          stored_(capacity.contacts, storage),
          conjugate_(6 * rows_for(capacity), storage), dense_(9 * settings.polish_limit * settings.polish_limit + 6 * settings.polish_limit, storage),
          scratch_(constraints::newton_scratch_size(settings.polish_limit), storage),
          joints_(3 * capacity.joints, storage), joint_impulse_(3 * capacity.joints, storage), joint_error_(3 * capacity.joints, storage),
          joint_before_(3 * capacity.joints, storage), joined_(capacity.joints, storage), couplings_(capacity.couplings, storage),
          coupled_(total_, storage),
          kind_(settings.polish_limit, storage), bounds_(settings.polish_limit, storage), order_(rows_for(capacity), storage),
          part_start_(max_partitions + 2, storage), phase_start_(3, storage),
          part_of_row_(rows_for(capacity), storage), slab_of_body_(total_, storage), ranked_(total_, storage), partial_(rows_for(capacity), storage),
          by_after_(total_, 0, storage),
          crew_(settings.threads),
          broadphase_(total_ > 0 ? total_ : 1, capacity.pairs, settings.fat_margin, storage) {
        settings_.partitions = settings_.partitions < 1 ? 1 : (settings_.partitions > max_partitions ? max_partitions : settings_.partitions);
        std::size_t offset = 0, k = 0;
        for_each_group([&](auto& g) {
            g.offset = offset, g.capacity = bodies[k++], offset += g.capacity;
            g.shape.reserve(g.capacity), g.data.reserve(g.capacity);
        });
        static_shape_.reserve(capacity.statics);
    }

    // ---- building ----

    // A static shape at a pose. Reported: not_a_motor, non_finite, negative_friction (μ < 0,
    // restitution outside [0, 1]), capacity_exceeded.
    checked<std::size_t> add_static(const Static& shape, const motor<T>& pose, const material<T>& m = {}) noexcept {
        return add_kinematic(shape, pose, screw<T>{}, m);
    }
    // A kinematic shape: a static one that moves at a prescribed velocity (ω, v: world axes, v
    // the velocity of the pose's origin), kept until set_kinematic_velocity changes it: a
    // conveyor, a turntable, a moving platform. Bodies feel its surface's velocity; it feels
    // nothing. Reported as add_static, and non_finite for the velocity.
    checked<std::size_t> add_kinematic(const Static& shape, const motor<T>& pose, const screw<T>& velocity, const material<T>& m = {}) noexcept {
        if (const error_code e = check_material(m); e != error_code::none) return {0, e};
        if (!near_unit(pose)) return {0, error_code::not_a_motor};
        const std::size_t i = static_shape_.size();
        if (i == static_map_.size()) return {0, error_code::capacity_exceeded};
        static_shape_.push_back(shape);
        static_pose_[i] = pose, static_material_[i] = m, static_soft_[i] = false;
        place_static(i);
        if (const error_code e = set_kinematic_velocity(i, velocity); e != error_code::none) {
            static_shape_.pop_back();
            return {0, e};
        }
        return {i, error_code::none};
    }
    error_code set_kinematic_velocity(std::size_t s, const screw<T>& velocity) noexcept {
        if (s >= static_shape_.size()) return error_code::bad_index;
        for (std::size_t c = 0; c < 6; ++c)
            if (!is_finite(velocity[c])) return error_code::non_finite;
        static_velocity_[s] = velocity;
        static_moving_[s] = false;
        for (std::size_t c = 0; c < 6; ++c) static_moving_[s] = static_moving_[s] || velocity[c] != T(0);
        return error_code::none;
    }

    // Static shape s made soft (couplings.hpp: K and D in its frame; its contacts' normal rows
    // become springs and dampers, taken implicitly). Reported: bad_index, non_finite,
    // not_symmetric, not_positive_definite (K's translation block not positive definite, or D's
    // not positive semi-definite).
    error_code set_compliance(std::size_t s, const contact_compliance<T>& c) noexcept {
        if (s >= static_shape_.size()) return error_code::bad_index;
        if (const error_code e = check_elements(c.stiffness, c.damping); e != error_code::none) return e;
        const auto translation = [](const matrix6<T>& M) {
            mat3<T> B;
            for (std::size_t i = 0; i < 3; ++i)
                for (std::size_t j = 0; j < 3; ++j) B[i][j] = M[3 + i][3 + j];
            return linear3::eigen_symmetric(B).d;
        };
        const vec3<T> k = translation(c.stiffness), d = translation(c.damping);
        for (std::size_t i = 0; i < 3; ++i)
            if (!(k[i] > T(0)) || d[i] < T(0)) return error_code::not_positive_definite;
        static_softness_[s] = c, static_soft_[s] = true;
        return error_code::none;
    }

    // A moving body of kind I: its shape, density (its mass properties are the shape's), pose and
    // velocity (ω, v of its centre of mass, in the world's axes). Returns its index among kind I's.
    // Reported: non_finite, non_positive_mass, not_a_motor, not_aligned (the shape's centre of
    // mass is not its origin, or its principal axes are not the body's: the kind cannot hold it),
    // negative_friction, capacity_exceeded.
    template <std::size_t I>
    checked<std::size_t> add_body(const typename kind<I>::shape_type& shape, const T& density, const motor<T>& pose,
                                  const material<T>& m = {}, const screw<T>& velocity = {}, const collision::filter& f = {}) noexcept {
        using K = typename kind<I>::inertia_type;
        auto& g = std::get<I>(groups_);
        if (g.count == g.capacity) return {0, error_code::capacity_exceeded};
        if (const error_code e = check_material(m); e != error_code::none) return {0, e};
        if (!is_finite(density)) return {0, error_code::non_finite};
        if (!(density > T(0))) return {0, error_code::non_positive_mass};
        if (!near_unit(pose)) return {0, error_code::not_a_motor};
        for (std::size_t c = 0; c < 6; ++c)
            if (!is_finite(velocity[c])) return {0, error_code::non_finite};
        const checked<mass_properties<T>> props = world_detail::mass_of_shape(shape, density);
        if (!props) return {0, props.error};
        if (const error_code e = world_detail::kind_holds<K>(*props); e != error_code::none) return {0, e};
        const std::size_t i = g.count++, b = g.offset + i;
        g.shape.push_back(shape), g.data.push_back(world_detail::data_from<K>(*props));
        pose_[b] = pose, velocity_[b] = velocity, material_[b] = m;
        map_[b] = map_of(pose);
        const collision::aabb<T> box = bounds_of(shape, motor_map<T>{{{{T(1), T(0), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), T(1)}}}, {}});
        radius_[b] = world_detail::norm(linear3::scale(T(0.5), linear3::sub(box.upper, box.lower)));
        reach_[b] = T(0);
        const checked<collision::proxy_id> p = broadphase_.create_proxy(bounds_of(shape, map_[b]), b, f);
        if (!p) return {0, p.error};
        proxy_[b] = *p;
        return {i, error_code::none};
    }

    // A joint (joints.hpp) between two bodies, or a body and the ground; its first block's index
    // (joint_impulse). Reported: bad_index (a body not added), joint_to_itself, non_finite (an
    // anchor, axis, length, limit, speed or effort; a limit may be infinite), zero_direction (a
    // zero axis), non_positive_size (a length ≤ 0), limits_reversed, negative_limit (an effort
    // < 0), capacity_exceeded (three blocks a joint at most). The two bodies no longer collide.
    template <class J>
    checked<std::size_t> add_joint(const J& j) noexcept {
        static_assert(is_joint_v<J, T>, "ctga::physics_world::add_joint: a joint is a spherical_, revolute_, prismatic_, fixed_ or distance_joint of the world's scalar");
        const std::uint32_t a = global(j.a), b = global(j.b);
        if ((a == bad_ref && j.a != ground) || (b == bad_ref && j.b != ground)) return {0, error_code::bad_index};
        if (a == b) return {0, error_code::joint_to_itself};
        if (!all_finite(j.anchor_a[0], j.anchor_a[1], j.anchor_a[2], j.anchor_b[0], j.anchor_b[1], j.anchor_b[2]))
            return {0, error_code::non_finite};
        J unit = j;
        const auto normalise = [](vec3<T>& axis) {
            const checked<std::array<T, 3>> u = unit_direction(axis[0], axis[1], axis[2]);
            if (u) axis = u.value;
            return u.error;
        };
        error_code e = error_code::none;
        if constexpr (requires { unit.axis_a; }) e = normalise(unit.axis_a);
        if constexpr (requires { unit.axis_b; })
            if (e == error_code::none) e = normalise(unit.axis_b);
        if constexpr (requires { unit.length; })
            if (e == error_code::none) e = !is_finite(unit.length) ? error_code::non_finite : !(unit.length > T(0)) ? error_code::non_positive_size : e;
        if constexpr (requires { unit.limits; })
            if (e == error_code::none) {
                const joint_limits<T>& l = unit.limits;
                const joint_motor<T>& m = unit.motor;
                if (l.lower != l.lower || l.upper != l.upper || !is_finite(m.speed) || !is_finite(m.effort)) e = error_code::non_finite;
                else if (l.lower > l.upper) e = error_code::limits_reversed;
                else if (m.effort < T(0)) e = error_code::negative_limit;
            }
        if (e != error_code::none) return {0, e};
        const auto rotation = [&](std::uint32_t x) { return x == constraints::no_body ? identity3() : map_of(pose_[x]).R; };
        std::array<constraints::joint_block<T>, 3> blocks;
        const std::size_t n = joint_detail::blocks_of<T>(unit, a, b, rotation(a), rotation(b), blocks);
        const std::size_t first = blocks_;
        if (first + n > joints_.size()) return {0, error_code::capacity_exceeded};
        for (std::size_t k = 0; k < n; ++k) joints_[first + k] = blocks[k], joint_impulse_[first + k] = {};
        blocks_ += n;
        if (a != constraints::no_body && b != constraints::no_body) {
            const std::uint64_t key = pair_key(a, b);
            std::uint64_t* end = joined_.data() + joined_count_;
            std::uint64_t* at = std::lower_bound(joined_.data(), end, key);
            if (at == end || *at != key) {
                std::move_backward(at, end, end + 1);
                *at = key, ++joined_count_;
            }
        }
        return {first, error_code::none};
    }

    // An elastic coupling (couplings.hpp, §7) between two bodies, or a body and the ground; its
    // index. Reported: bad_index, joint_to_itself, not_a_motor (a frame), non_finite (K or D),
    // not_symmetric (K or D), capacity_exceeded.
    checked<std::size_t> add_coupling(const elastic_coupling<T>& c) noexcept {
        const std::uint32_t a = global(c.a), b = global(c.b);
        if ((a == bad_ref && c.a != ground) || (b == bad_ref && c.b != ground)) return {0, error_code::bad_index};
        if (a == b) return {0, error_code::joint_to_itself};
        if (!near_unit(c.frame_a) || !near_unit(c.frame_b)) return {0, error_code::not_a_motor};
        if (const error_code e = check_elements(c.stiffness, c.damping); e != error_code::none) return {0, e};
        if (couplings_count_ == couplings_.size()) return {0, error_code::capacity_exceeded};
        couplings_[couplings_count_] = {a, b, c};
        return {couplings_count_++, error_code::none};
    }

    // ---- the step ----

    step_report<T> step(const T& h) noexcept {
        step_report<T> report;
        if (!is_finite(h) || !(h > T(0))) return report.error = error_code::non_finite, report;
        if (settings_.substeps > 0) {
            const world_settings<T>& s = settings_;
            if (!all_finite(s.contact_hertz, s.contact_damping, s.joint_damping, s.push_speed)) return report.error = error_code::non_finite, report;
            if (s.contact_hertz < T(0) || s.contact_damping < T(0) || s.joint_damping < T(0) || !(s.push_speed > T(0)))
                return report.error = error_code::negative_limit, report;
        }
        if ((report.error = begin(h, report)) != error_code::none) return report;
        if (settings_.substeps > 0) soft_solve(h, report);
        else solve(h, report);
        report.error = end(h);
        return report;
    }

    // ---- the stages ----

    // The step up to its solve: the state kept (restore), collide, the manifolds in order,
    // build_rows, partition, warm_start.
    error_code begin(const T& h, step_report<T>& report) noexcept {
        for_each_body([&](auto&, std::size_t, std::size_t b) { before_pose_[b] = pose_[b], before_[b] = velocity_[b]; });
        if (const error_code e = collide(h); e != error_code::none) return e;
        order_manifolds();
        if (const error_code e = build_rows(h, report); e != error_code::none) return e;
        if (settings_.substeps == 0) partition();  // (the soft step's rows go in colours instead: soft_solve)
        warm_start();
        return error_code::none;
    }
    // The step after its solve: integrate and store_impulses, or, if the state went non-finite,
    // restore (and non_finite).
    error_code end(const T& h) noexcept {
        integrate(h);
        if (!state_finite()) return restore(), error_code::non_finite;
        store_impulses();
        return error_code::none;
    }
    // The poses and velocities the step began with.
    void restore() noexcept {
        for_each_body([&](auto&, std::size_t, std::size_t b) { pose_[b] = before_pose_[b], velocity_[b] = before_[b]; });
    }

    // The bodies' maps and boxes (grown by how far they may move in h), the broadphase's pairs
    // and every static shape a body's box meets; their manifolds, within the margin plus both
    // bodies' reach.
    error_code collide(const T& h) noexcept {
        manifolds_ = 0;
        for_each_body_at_once([&](auto& g, std::size_t i, std::size_t b) {
            map_[b] = map_of(pose_[b]);
            const vec3<T> w{velocity_[b][0], velocity_[b][1], velocity_[b][2]}, v{velocity_[b][3], velocity_[b][4], velocity_[b][5]};
            reach_[b] = h * (world_detail::norm(v) + world_detail::norm(w) * radius_[b]);
            collision::aabb<T> box = bounds_of(g.shape[i], map_[b]);
            const T grow = h * world_detail::norm(w) * radius_[b];
            for (std::size_t c = 0; c < 3; ++c) box.lower[c] -= grow, box.upper[c] += grow;
            box_[b] = box;
        });
        for_each_body([&](auto&, std::size_t, std::size_t b) {
            const vec3<T> v{velocity_[b][3], velocity_[b][4], velocity_[b][5]};
            broadphase_.move_proxy(proxy_[b], box_[b], linear3::scale(h, v));
        });
        bool full = false;
        const error_code e = broadphase_.for_each_pair([&](collision::proxy_id pa, collision::proxy_id pb) {
            const auto a = static_cast<std::uint32_t>(broadphase_.user_of(pa)), b = static_cast<std::uint32_t>(broadphase_.user_of(pb));
            if (joined(a, b)) return;
            with_body(a, [&](auto& ga, std::size_t ia) {
                with_body(b, [&](auto& gb, std::size_t ib) {
                    const T margin = settings_.margin + reach_[a] + reach_[b];
                    keep(a, b, contact_of(ga.shape[ia], map_[a], gb.shape[ib], map_[b], margin), full);
                });
            });
        });
        if (e != error_code::none) return e;
        for_each_body([&](auto& g, std::size_t i, std::size_t b) {
            const T margin = settings_.margin + reach_[b];
            collision::aabb<T> box = bounds_of(g.shape[i], map_[b]);
            for (std::size_t c = 0; c < 3; ++c) box.lower[c] -= margin, box.upper[c] += margin;
            for (std::size_t s = 0; s < static_shape_.size(); ++s) {
                if (static_bounded_[s] && !collision::overlaps(box, static_box_[s])) continue;
                keep(static_cast<std::uint32_t>(b), world_detail::statics_bit | static_cast<std::uint32_t>(s),
                     contact_of(g.shape[i], map_[b], static_shape_[s], static_map_[s], margin), full);
            }
        });
        return full ? error_code::capacity_exceeded : error_code::none;
    }

    // The manifolds in the order of their keys (a, b): counted by body a (a is always a moving
    // body), then each a's few put in order of b by insertion. The rows, and so the impulses
    // stored for the next step, come out in key order: no sort of the contacts.
    void order_manifolds() noexcept {
        std::uint32_t* first = first_of_body_.data();
        for (std::size_t b = 0; b <= total_; ++b) first[b] = 0;
        for (std::size_t f = 0; f < manifolds_; ++f) ++first[found_[f].a + 1];
        for (std::size_t b = 0; b < total_; ++b) first[b + 1] += first[b];
        for (std::size_t f = 0; f < manifolds_; ++f) by_key_[first[found_[f].a]++] = static_cast<std::uint32_t>(f);
        for (std::size_t k = 1; k < manifolds_; ++k) {
            const std::uint32_t f = by_key_[k];
            std::size_t j = k;
            for (; j > 0 && found_[by_key_[j - 1]].a == found_[f].a && found_[by_key_[j - 1]].b > found_[f].b; --j) by_key_[j] = by_key_[j - 1];
            by_key_[j] = f;
        }
    }

    // The free velocities (gravity; the gyroscopic term of §6's equation of motion, in the body
    // frame, by the kind's own formula), each body's mobility in the world's axes, and each
    // manifold point's rows.
    error_code build_rows(const T& h, step_report<T>& report) noexcept {
        couple();
        for_each_body_at_once([&](auto& g, std::size_t i, std::size_t b) {
            using G = std::remove_cvref_t<decltype(g)>;
            using K = typename G::K;
            const mat3<T>& R = map_[b].R;
            const screw<T>& s = velocity_[b];
            const vec3<T> wb = linear3::apply_transposed(R, vec3<T>{s[0], s[1], s[2]});
            const screw<T> sb{wb[0], wb[1], wb[2], T(0), T(0), T(0)};
            const screw<T> ab = body_acceleration<subspace::full, K, T>(g.data[i], sb);
            const vec3<T> dw = linear3::apply(R, vec3<T>{ab[0], ab[1], ab[2]});
            mobility_[b] = world_detail::world_mobility<K, T>(g.data[i], R);
            // the applied wrench's and the couplings' share: h N⁻¹ (τ, f)
            const coscrew<T>& c = coupled_[b];
            const screw<T> dv = constraints::respond(
                mobility_[b], coscrew<T>{h * (torque_[b][0] + c[0]), h * (torque_[b][1] + c[1]), h * (torque_[b][2] + c[2]),
                                         h * (force_[b][0] + c[3]), h * (force_[b][1] + c[4]), h * (force_[b][2] + c[5])});
            velocity_[b] = screw<T>{s[0] + h * dw[0] + dv[0], s[1] + h * dw[1] + dv[1], s[2] + h * dw[2] + dv[2],
                                    s[3] + h * settings_.gravity[0] + dv[3], s[4] + h * settings_.gravity[1] + dv[4],
                                    s[5] + h * settings_.gravity[2] + dv[5]};
            pseudo_[b] = screw<T>{};
        });
        contacts_ = 0;
        T deepest = T(0), worst = T(0);
        if (blocks_ > rows_.size()) return error_code::capacity_exceeded;
        at_once(blocks_, [&](std::size_t j) {
            const constraints::joint_block<T>& J = joints_[j];
            constraints::contact_row<T>& row = rows_[j];
            joint_error_[j] = constraints::joint_row<T>(J, map_[J.a], J.b == constraints::no_body ? motor_map<T>{identity3(), {}} : map_[J.b],
                                                        mobilities(), row);
            joint_before_[j] = constraints::row_velocity(row, bodies(before_));
            if (row.bounded)
                constraints::limit_and_motor<T>(J, joint_error_[j], joint_before_[j], constraints::row_velocity(row, bodies(velocity_)), h, row);
            mu_[j] = T(0);
        });
        T turned = T(0);
        for (std::size_t j = 0; j < blocks_; ++j) {
            using constraints::joint_block_kind;
            const joint_block_kind kind = joints_[j].kind;
            if (kind == joint_block_kind::twist || kind == joint_block_kind::slide) continue;  // (its gaps: distances to its limits)
            const T gap = math::sqrt(linear3::dot(joint_error_[j], joint_error_[j]));
            const bool angular = kind == joint_block_kind::hinge || kind == joint_block_kind::weld;
            (angular ? turned : worst) = std::max(angular ? turned : worst, gap);
        }
        report.joint_angle = turned;
        contacts_ = blocks_;
        for (std::size_t f = 0; f < manifolds_; ++f) {
            const world_detail::found_manifold<T>& fm = found_[by_key_[f]];
            const bool fixed = (fm.b & world_detail::statics_bit) != 0;
            const material<T>& ma = material_[fm.a];
            const material<T>& mb = fixed ? static_material_[fm.b & ~world_detail::statics_bit] : material_[fm.b];
            const T mu = math::sqrt(ma.friction * mb.friction);
            const T e = ma.restitution > mb.restitution ? ma.restitution : mb.restitution;
            const std::array<vec3<T>, 2> t = constraints::tangents(fm.m.normal);
            const std::array<vec3<T>, 3> dir{fm.m.normal, t[0], t[1]};
            for (std::size_t p = 0; p < fm.m.count; ++p) {
                if (contacts_ == rows_.size()) return error_code::capacity_exceeded;
                const collision::contact_point<T>& cp = fm.m.points[p];
                const vec3<T> x = linear3::scale(T(0.5), linear3::add(cp.point_a, cp.point_b));
                constraints::contact_row<T>& row = rows_[contacts_];
                row.direction = dir;
                row.a = constraints::make_side(fm.a, map_[fm.a].t, x, dir);
                row.b = fixed ? constraints::row_side<T>{} : constraints::make_side(fm.b, map_[fm.b].t, x, dir);
                row.block = constraints::delassus_block<T>(row, mobility_);
                row.mu = mu, row.bilateral = false;
                // a kinematic shape's surface velocity, in every row: u = J s + k
                const std::size_t s = fm.b & ~world_detail::statics_bit;
                const vec3<T> k = fixed ? static_speed(s, x, dir) : vec3<T>{};
                // u⁻ and u_free along n
                const T before = constraints::row_velocity(row, bodies(before_))[0] + k[0];
                const T free = constraints::row_velocity(row, bodies(velocity_))[0] + k[0];
                const T phi = cp.separation;
                const bool closing = phi + h * (before + free) / T(2) <= T(0);
                row.bias = k;
                row.compliance = T(0);
                spring_rate_[contacts_] = T(0);
                if (fixed && static_soft_[s]) {  // a spring and a damper along n (couplings.hpp), over a substep in the soft step
                    const vec3<T> n = linear3::apply_transposed(static_map_[s].R, fm.m.normal);
                    const T over = settings_.substeps > 0 ? h / T(settings_.substeps) : h;
                    const soft_row<T> soft = soften(static_softness_[s], n, phi, over);
                    row.block[0][0] += soft.compliance, row.compliance = soft.compliance;
                    if (settings_.substeps == 0) row.bias[0] += soft.offset;  // (the soft step's from the gap as it moves)
                    spring_rate_[contacts_] = soften(static_softness_[s], n, T(1), over).offset;  // b / φ
                } else if (settings_.substeps == 0) {
                    row.bias[0] += closing ? (before < -settings_.restitution_threshold ? e * before : T(0)) : before + T(2) * phi / h;
                }
                restitution_[contacts_] = closing && before < -settings_.restitution_threshold ? e : T(0);
                row.step_length = constraints::step_lengths(row.block);
                separation_[contacts_] = phi, before_normal_[contacts_] = before, surface_[contacts_] = k[0];
                arm_[contacts_] = linear3::sub(x, map_[fm.a].t);
                mu_[contacts_] = mu;
                keys_[contacts_] = {fm.a, fm.b, cp.id};
                deepest = -phi > deepest ? -phi : deepest;
                ++contacts_;
            }
        }
        report.contacts = contacts_ - blocks_, report.penetration = deepest, report.joint_error = worst;
        return error_code::none;
    }

    // The rows in parts for the sweeps (contact_problem.hpp's sweep_schedule): the moving bodies
    // are split in space into `partitions` slabs of as many bodies each, across the axis along
    // which their centres spread most (by rank: the order of their coordinates, ties by index);
    // a row whose bodies lie in one slab goes to that slab's part, in row order, and the parts
    // are swept at once; a row across two slabs goes to the seam, swept after them. The parts
    // depend on the partitions and the positions, not on the threads. (Slabs of body indices
    // instead put most of a pile's rows on the seam: a world stores its bodies kind by kind, and
    // a pile's kinds share its space; measured, 1,000 mixed bodies ran slower on two threads.)
    void partition() noexcept {
        const std::size_t P = settings_.partitions > 0 ? settings_.partitions : 1;
        if (P > 1 && total_ > 0) {
            vec3<T> low = map_[0].t, high = map_[0].t;
            for (std::size_t b = 1; b < total_; ++b)
                for (std::size_t c = 0; c < 3; ++c) low[c] = std::min(low[c], map_[b].t[c]), high[c] = std::max(high[c], map_[b].t[c]);
            std::size_t axis = 0;
            for (std::size_t c = 1; c < 3; ++c)
                if (high[c] - low[c] > high[axis] - low[axis]) axis = c;
            for (std::size_t b = 0; b < total_; ++b) ranked_[b] = {map_[b].t[axis], static_cast<std::uint32_t>(b)};
            const auto before = [](const world_detail::ranked<T>& x, const world_detail::ranked<T>& y) {
                return x.at != y.at ? x.at < y.at : x.body < y.body;
            };
            for (std::size_t p = 0, first = 0; p < P; ++p) {  // slab p: ranks [p n / P, (p + 1) n / P)
                const std::size_t end = (p + 1) * total_ / P;
                if (p + 1 < P) std::nth_element(ranked_.data() + first, ranked_.data() + end, ranked_.data() + total_, before);
                for (std::size_t k = first; k < end; ++k) slab_of_body_[ranked_[k].body] = static_cast<std::uint16_t>(p);
                first = end;
            }
        }
        const auto slab_of = [&](std::uint32_t body) { return P > 1 ? std::size_t{slab_of_body_[body]} : std::size_t{0}; };
        std::array<std::uint32_t, max_partitions + 2> count{};
        for (std::size_t i = 0; i < contacts_; ++i) {
            const constraints::contact_row<T>& row = rows_[i];
            const std::size_t a = slab_of(row.a.body);
            const std::size_t p = row.b.body == constraints::no_body || slab_of(row.b.body) == a ? a : P;
            part_of_row_[i] = static_cast<std::uint16_t>(p);
            ++count[p + 1];
        }
        for (std::size_t p = 0; p <= P; ++p) count[p + 1] += count[p];
        for (std::size_t p = 0; p <= P + 1; ++p) part_start_[p] = count[p];
        for (std::size_t i = 0; i < contacts_; ++i) order_[count[part_of_row_[i]]++] = static_cast<std::uint32_t>(i);
        phase_start_[0] = 0, phase_start_[1] = static_cast<std::uint32_t>(P), phase_start_[2] = static_cast<std::uint32_t>(P + 1);
    }
    constraints::sweep_schedule<T> schedule() noexcept {
        const std::size_t P = settings_.partitions > 0 ? settings_.partitions : 1;
        return {std::span<const std::uint32_t>(order_.data(), contacts_), std::span<const std::uint32_t>(part_start_.data(), P + 2),
                std::span<const std::uint32_t>(phase_start_.data(), 3), contacts_ >= settings_.parallel_rows ? &crew_ : nullptr,
                std::span<T>(partial_.data(), contacts_)};
    }

    // Each contact starts from the impulse the same contact ended the last step with, applied to
    // the bodies' velocities: among the stored contacts of the same two bodies within the margin
    // of it (in body a's frame), the one with the same feature id, else the nearest; a new
    // contact from zero. Ids alone do not do: where faces lie exactly on each other rounding
    // decides which lines a clipped point lies on, and an id moved from one corner to another
    // between steps (a 210-cube pyramid: every other step's warm start set a cube turning at
    // 2e-3 rad/s, and 60 sweeps a step went to putting it right, measured).
    void warm_start() noexcept {
        const constraints::rows_delassus<T> W{rows(), mobilities(), velocities()};
        const world_detail::stored_impulse<T>*first = stored_.data(), *end = first + stored_count_;
        // (rows and stored impulses are both in key order: one merge finds each row's pair)
        const auto pair_before = [](const world_detail::contact_key& x, const world_detail::contact_key& y) {
            return x.a != y.a ? x.a < y.a : x.b < y.b;
        };
        for (std::size_t c = blocks_, at = 0; c < contacts_; ++c) {
            while (at < stored_count_ && pair_before(stored_[at].key, keys_[c])) ++at;
            stored_from_[c] = static_cast<std::uint32_t>(at);
        }
        at_once(blocks_, [&](std::size_t j) {
            for (std::size_t k = 0; k < 3; ++k) impulse_[3 * j + k] = joint_impulse_[j][k];
        });
        at_once(contacts_ - blocks_, [&](std::size_t n) {
            const std::size_t c = blocks_ + n;
            const world_detail::contact_key& key = keys_[c];
            const vec3<T> local = local_point(c);
            const world_detail::stored_impulse<T>* match = nullptr;
            T nearest = settings_.margin * settings_.margin;
            bool same_id = false;
            for (const world_detail::stored_impulse<T>* at = first + stored_from_[c];
                 at != end && at->key.a == key.a && at->key.b == key.b; ++at) {
                const vec3<T> d = linear3::sub(at->local, local);
                const T distance = linear3::dot(d, d);
                if (distance >= settings_.margin * settings_.margin || same_id) continue;
                if (at->key.id == key.id) same_id = true, match = at;
                else if (distance < nearest) nearest = distance, match = at;
            }
            vec3<T> r{};
            if (match)
                for (std::size_t k = 0; k < 3; ++k) r[k] = linear3::dot(rows_[c].direction[k], match->r);
            for (std::size_t k = 0; k < 3; ++k) impulse_[3 * c + k] = r[k];
        });
        // applied part by part (rows of one part share no body with another's); the soft step
        // applies them at each substep
        if (settings_.substeps > 0) return;
        const constraints::sweep_schedule<T> plan = schedule();
        constraints::for_each_row(&plan, contacts_, [&](std::size_t c) {
            W.apply(c, vec3<T>{impulse_[3 * c], impulse_[3 * c + 1], impulse_[3 * c + 2]});
        });
    }

    // The frictional contact problem to the settings' tolerance: a problem of at most
    // polish_limit contacts by Newton from the warm start (measured: a stack of ten boxes of mass
    // ratio 1:1000 in 0.8 Newton steps per step on average, where a few sweeps first left Newton
    // too far to converge), then, if short of the tolerance, sweeps and Newton again; a larger
    // one by sweeps. Then the position correction: a
    // normal-only problem on pseudo-velocities for the gaps the step would end with,
    // φ⁺ = φ + h (u⁻ + u⁺)/2, asking φ⁺ + h u_p ≥ −(1 − β) max(0, −φ) − slop.
    void solve(const T& h, step_report<T>& report) noexcept {
        constraints::rows_delassus<T> W{rows(), mobilities(), velocities()};
        const bool small = contacts_ <= settings_.polish_limit;
        const std::span<T> r(impulse_.data(), 3 * contacts_);
        if (small) polish(W, r, report.contact);
        if (!small || !report.contact.converged) {
            const std::size_t steps = report.contact.polish_steps;
            const constraints::sweep_schedule<T> plan = schedule();
            report.contact = constraints::solve_contacts<T>(
                W, std::span<const T>(mu_.data(), contacts_), std::span<T>(impulse_.data(), 3 * contacts_), settings_.solver,
                settings_.conjugate ? std::span<T>(conjugate_.data(), 6 * contacts_) : std::span<T>{}, &plan);
            if (small && !report.contact.converged && report.contact.error == error_code::none) polish(W, r, report.contact);
            report.contact.polish_steps += steps;
        }
        correct(h, report);
    }
    // The position correction (above) after the impulses: on the velocities they left.
    void correct(const T& h, step_report<T>& report) noexcept {
        // (each row's flag in partial_, read in row order after)
        at_once(contacts_, [&](std::size_t c) {
            correction_[3 * c] = correction_[3 * c + 1] = correction_[3 * c + 2] = T(0);
            bool needed = false;
            if (c < blocks_) {
                // the joint's gap at the step's end, φ⁺ = φ + h (u⁻ + u⁺)/2 on each axis, all of it
                // removed (a joint has no slop); a limit's only where it is passed, a motor's not at all
                const vec3<T> after = constraints::row_velocity(rows_[c], bodies(velocity_));
                for (std::size_t k = 0; k < 3; ++k) {
                    const T gap = joint_error_[c][k] + h * (joint_before_[c][k] + after[k]) / T(2);
                    rows_[c].bias[k] = gap / h;  // the pseudo-velocities add no energy
                    needed = needed || (rows_[c].bounded ? gap < T(0) && k != 1 && rows_[c].upper[k] > T(0) : gap != T(0));
                }
                if (rows_[c].bounded) rows_[c].lower[1] = rows_[c].upper[1] = T(0);
            } else {
                // the gap allowed at the end: the penetration the step started with, less the
                // fraction `correction` of it, and the slop; what this step's own motion would
                // push in is removed whole (a fast body stopped by an inelastic impact would
                // otherwise go on by h u⁻/2, through a thin wall)
                const T after = constraints::row_velocity(rows_[c], bodies(velocity_))[0] + surface_[c];
                const T start = separation_[c] < T(0) ? -separation_[c] : T(0);
                const T allowed = (T(1) - settings_.correction) * start + settings_.slop;
                // (a soft contact's penetration is its spring's: the correction only keeps it from deepening)
                const T gap = rows_[c].compliance > T(0) ? T(0) : separation_[c] + h * (before_normal_[c] + after) / T(2) + allowed;
                rows_[c].compliance = T(0);
                rows_[c].bias[0] = gap / h;
                needed = gap < T(0);
                mu_[c] = T(0);
                // the correction's contact lines through the bodies' centres: it moves them
                // without turning them (turning them, a frictionless correction tilts stacked
                // cubes, which then slide off each other: a pyramid of 210 cubes at 10 sweeps a
                // step fell, its top 47 m away after 60 s; through the centres, 0.68 m)
                // (so W_jk = Σ_sides e_j·e_k / m = δ_jk Σ 1/m: the directions are orthonormal)
                T inverse_mass = T(0);
                for (constraints::row_side<T>* side : {&rows_[c].a, &rows_[c].b})
                    if (side->moment = {}; side->body != constraints::no_body) inverse_mass += mobility_[side->body].inverse_mass;
                rows_[c].block = {{{inverse_mass, T(0), T(0)}, {T(0), inverse_mass, T(0)}, {T(0), T(0), inverse_mass}}};
                rows_[c].step_length = constraints::step_lengths(rows_[c].block);
            }
            partial_[c] = needed ? T(1) : T(0);
        });
        bool any = false;
        for (std::size_t c = 0; c < contacts_ && !any; ++c) any = partial_[c] != T(0);
        if (!any) return;
        constraints::rows_delassus<T> P{rows(), mobilities(), std::span<screw<T>>(pseudo_.data(), total_)};
        constraints::contact_settings<T> correcting = settings_.solver;
        correcting.max_sweeps = settings_.correction_sweeps;
        const constraints::sweep_schedule<T> plan = schedule();
        const std::span<T> shift(correction_.data(), 3 * contacts_);
        report.correction = constraints::solve_contacts<T>(P, std::span<const T>(mu_.data(), contacts_), shift, correcting, {}, &plan);
        // (a joint's limit and its point sweep slowly against each other: a pendulum stopped at its
        // limit, 0.98 a sweep, measured; Newton finishes a small problem)
        if (contacts_ <= settings_.polish_limit && !report.correction.converged && report.correction.error == error_code::none)
            polish(P, shift, report.correction);
    }

    // The soft step (constraints/soft_step.hpp): the rows in colours and groups of lanes
    // (group_rows), then n substeps, each the free velocity's share, the warm start, a sweep with
    // the springs, the displacements moved on, a sweep without; then Newton's impact law once,
    // u⁺_n ≥ −e u⁻_n, for the rows that close fast enough to bounce.
    void soft_solve(const T& h, step_report<T>& report) noexcept {
        const std::size_t n = settings_.substeps;
        const T hs = h / T(n), quarter = T(0.25) / hs;
        // (a joint's spring faster than a quarter of the substeps' rate made a chain ring and grow:
        // a 10 × 10 joint grid at 4 substeps, joints at 120 Hz: gap 23 cm after 100 steps; at 60 Hz 1.1 mm)
        const T hertz = settings_.contact_hertz > T(0) && settings_.contact_hertz < quarter ? settings_.contact_hertz : quarter;
        constraints::soft_sweep_settings<T> s{constraints::make_soft(hertz, settings_.contact_damping, hs),
                                              constraints::make_soft(std::min(T(2) * hertz, quarter), settings_.joint_damping, hs),
                                              settings_.push_speed, hs, false};
        for_each_body_at_once([&](auto&, std::size_t, std::size_t b) {
            for (std::size_t c = 0; c < 6; ++c) free_[b][c] = (velocity_[b][c] - before_[b][c]) / T(n);
            velocity_[b] = before_[b], displacement_[b] = screw<T>{};
        });
        group_rows();
        constraints::rows_delassus<T> W{rows(), mobilities(), velocities()};
        const std::span<T> r(impulse_.data(), 3 * contacts_);
        screw<T>* const v = velocity_.data();
        screw<T>* const d = displacement_.data();
        v[total_] = d[total_] = screw<T>{};  // no body
        T elapsed = T(0);
        // a group's sweep: in the relaxing one its gaps measured first (just after the positions
        // moved: the next substep's first sweep finds them unchanged)
        const auto sweep_group = [&](auto& g, bool bilateral) {
            if (s.relax) constraints::measure_gaps(g, constraints::gather(d, g.a), constraints::gather(d, g.b), elapsed);
            auto sa = constraints::gather(v, g.a), sb = constraints::gather(v, g.b);
            constraints::soft_group(g, bilateral, sa, sb, s);
            constraints::scatter(v, g.a, sa), constraints::scatter(v, g.b, sb);
        };
        // a row left over (its body in more rows than there are colours) as a group of one lane,
        // its gaps measured afresh; a joint's limits and motor by the exact way's bounded step
        const auto sweep_left = [&](std::size_t i) {
            if (rows_[i].bounded) {
                const vec3<T> old{r[3 * i], r[3 * i + 1], r[3 * i + 2]};
                const vec3<T> next = constraints::bounded_step(rows_[i].block, W.velocity(i, r), {rows_[i].lower, rows_[i].upper}, old);
                for (std::size_t k = 0; k < 3; ++k) r[3 * i + k] = next[k];
                return W.apply(i, linear3::sub(next, old));
            }
            constraints::row_group<T, 1> g = single_group(i);
            constraints::measure_gaps(g, constraints::gather(d, g.a), constraints::gather(d, g.b), elapsed);
            constraints::lane_screws<T, 1> sa = constraints::gather(v, g.a), sb = constraints::gather(v, g.b);
            constraints::soft_group(g, rows_[i].bilateral, sa, sb, s);
            constraints::scatter(v, g.a, sa), constraints::scatter(v, g.b, sb);
            for (std::size_t k = 0; k < 3; ++k) r[3 * i + k] = g.r[k][0];
        };
        const auto sweep = [&](bool relax) {
            s.relax = relax;
            each_colour(sweep_group);
            for (std::size_t k = coloured_; k < contacts_; ++k) sweep_left(colour_order_[k]);
        };
        for (std::size_t k = 0; k < n; ++k) {
            // the warm start: the impulses the last substep ended with, applied again. In the first
            // substep those of the last step, row by row; after it, each body's share of them is
            // the change of its velocity over the last substep, s_end − s_start (the free velocity
            // added before it): s ← s_end + free + (s_end − s_start), body by body
            for_each_body_at_once([&](auto&, std::size_t, std::size_t b) {
                const screw<T> pushed = k == 0 ? screw<T>{} : screw<T>(velocity_[b] - substep_start_[b]);
                substep_start_[b] = screw<T>(velocity_[b] + free_[b]);
                velocity_[b] = screw<T>(substep_start_[b] + pushed);
            });
            if (k == 0) {
                each_colour([&](auto& g, bool) {
                    auto sa = constraints::gather(v, g.a), sb = constraints::gather(v, g.b);
                    constraints::group_apply(g, g.r, sa, sb);
                    constraints::scatter(v, g.a, sa), constraints::scatter(v, g.b, sb);
                });
                for (std::size_t m = coloured_; m < contacts_; ++m) {
                    const std::size_t i = colour_order_[m];
                    W.apply(i, vec3<T>{r[3 * i], r[3 * i + 1], r[3 * i + 2]});
                }
            }
            sweep(false);
            for_each_body_at_once([&](auto&, std::size_t, std::size_t b) {
                for (std::size_t c = 0; c < 6; ++c) displacement_[b][c] += hs * velocity_[b][c];
            });
            elapsed += hs;
            sweep(true);
        }
        each_colour([&](const auto& g, bool) {
            for (std::size_t l = 0; l < g.row.size(); ++l)
                if (const std::uint32_t i = g.row[l]; i != no_row)
                    for (std::size_t k = 0; k < 3; ++k) r[3 * i + k] = g.r[k][l];
        });
        for (std::size_t c = blocks_; c < contacts_; ++c) {
            if (restitution_[c] == T(0) || impulse_[3 * c] == T(0) || rows_[c].compliance > T(0)) continue;
            const T u = W.velocity(c, r)[0];
            const T rn = std::max(impulse_[3 * c] - (u + restitution_[c] * before_normal_[c]) * rows_[c].step_length[0], T(0));
            W.apply(c, vec3<T>{rn - impulse_[3 * c], T(0), T(0)});
            impulse_[3 * c] = rn;
        }
        report.contact.sweeps = 2 * n;
        report.contact.residual = std::numeric_limits<T>::quiet_NaN();
        report.contact.converged = false;
    }

    // The rows in colours (constraints/row_colours.hpp; a joint's limits and motor left over),
    // each colour's joints then its contacts in groups of `lanes`, with their impulses (the warm
    // start), gaps at the start and surfaces' speeds.
    void group_rows() noexcept {
        coloured_ = constraints::colour_rows<T>(rows(), max_colours, std::span<std::uint64_t>(colour_used_.data(), total_),
                                                std::span<std::uint32_t>(colour_of_), std::span<std::uint32_t>(colour_order_),
                                                std::span<std::uint32_t>(colour_start_), [&](std::size_t i) { return rows_[i].bounded; });
        // the groups, colour by colour (a colour lists its rows in row order: the joints' blocks,
        // the first rows, come first; a group holds joints or contacts): each its first row's
        // place in the order and its rows; then filled, group by group, shared among the threads
        // (a colour of a few rows, a quarter of the lanes or fewer, goes one row at a time: a
        // pinched box's 8 rows are 8 colours of one, and groups of 8 lanes swept 7 of nothing)
        lane_group_count_ = single_count_ = 0;
        for (std::size_t c = 0; c < max_colours; ++c) {
            lane_group_start_[c] = static_cast<std::uint32_t>(lane_group_count_), single_start_[c] = static_cast<std::uint32_t>(single_count_);
            if (4 * (colour_start_[c + 1] - colour_start_[c]) <= lanes) {
                for (std::size_t k = colour_start_[c]; k < colour_start_[c + 1]; ++k) {
                    const std::uint32_t i = colour_order_[k];
                    fill_row(singles_[single_count_], 0, i), single_bilateral_[single_count_++] = i < blocks_;
                }
                continue;
            }
            for (std::size_t k = colour_start_[c]; k < colour_start_[c + 1]; ++k) {
                const bool joint = colour_order_[k] < blocks_;
                const std::size_t j = lane_group_count_ - 1;
                if (lane_group_count_ == lane_group_start_[c] || lane_count_[j] == lanes || joint != (lane_bilateral_[j] != 0)) {
                    lane_first_[lane_group_count_] = static_cast<std::uint32_t>(k), lane_count_[lane_group_count_] = 0;
                    lane_bilateral_[lane_group_count_++] = joint;
                }
                ++lane_count_[lane_group_count_ - 1];
            }
        }
        lane_group_start_[max_colours] = static_cast<std::uint32_t>(lane_group_count_), single_start_[max_colours] = static_cast<std::uint32_t>(single_count_);
        at_once(lane_group_count_, [&](std::size_t j) {
            for (std::size_t l = 0; l < lanes; ++l) {
                if (l < lane_count_[j]) fill_row(lane_groups_[j], l, colour_order_[lane_first_[j] + l]);
                else constraints::empty_lane(lane_groups_[j], l, static_cast<std::uint32_t>(total_), no_row);
            }
        });
    }
    template <std::size_t L>
    void fill_row(constraints::row_group<T, L>& g, std::size_t l, std::uint32_t i) noexcept {
        constraints::fill_lane(g, l, i, rows_[i], mobilities(), static_cast<std::uint32_t>(total_));
        const bool joint = i < blocks_;
        const vec3<T> start = joint ? joint_error_[i] : vec3<T>{separation_[i], T(0), T(0)};
        const vec3<T> surface = joint ? vec3<T>{} : vec3<T>{surface_[i], rows_[i].bias[1], rows_[i].bias[2]};
        for (std::size_t k = 0; k < 3; ++k)
            g.start[k].set(l, start[k]), g.gap[k].set(l, start[k]), g.surface[k].set(l, surface[k]), g.r[k].set(l, impulse_[3 * i + k]);
        g.spring_rate.set(l, joint ? T(0) : spring_rate_[i]);
    }
    constraints::row_group<T, 1> single_group(std::size_t i) noexcept {
        constraints::row_group<T, 1> g;
        fill_row(g, 0, static_cast<std::uint32_t>(i));
        return g;
    }
    // f(group, bilateral) for each group, colour by colour, a colour's groups of lanes shared among
    // the team's threads when it has many rows (they share no body: the same result for any number
    // of threads), then its rows that go one at a time
    template <class F>
    void each_colour(F&& f) {
        for (std::size_t c = 0; c < max_colours; ++c) {
            const std::size_t first = lane_group_start_[c], count = lane_group_start_[c + 1] - first;
            const auto chunk = [&](std::size_t begin, std::size_t end) {
                for (std::size_t j = first + begin; j < first + end; ++j) f(lane_groups_[j], lane_bilateral_[j] != 0);
            };
            if (count * lanes >= settings_.parallel_rows / 2) crew_.run(count, chunk);
            else chunk(0, count);
            for (std::size_t k = single_start_[c]; k < single_start_[c + 1]; ++k) f(singles_[k], single_bilateral_[k] != 0);
        }
    }

    // Newton on the problem held densely: W_ij = Σ over the bodies contacts i and j share of
    // ± L_i(N⁻¹ L_j), q = u − W r at the impulses r the sweeps reached (the step's, or the
    // correction's); the change of impulse is then applied to the bodies.
    void polish(constraints::rows_delassus<T>& W, std::span<T> r, constraints::contact_report<T>& report) noexcept {
        const std::size_t n = 3 * contacts_;
        std::span<T> D(dense_.data(), n * n), q(dense_.data() + n * n, n), before(dense_.data() + n * n + n, n);
        const auto block = [&](const constraints::row_side<T>& x, const constraints::row_side<T>& y, T sign, std::size_t i, std::size_t j) {
            if (x.body == constraints::no_body || x.body != y.body) return;
            for (std::size_t a = 0; a < 3; ++a)
                for (std::size_t b = 0; b < 3; ++b)
                    D[(3 * i + a) * n + 3 * j + b] += sign * constraints::coupling(mobility_[x.body], rows_[i], x, a, rows_[j], y, b);
        };
        for (T& x : D) x = T(0);
        for (std::size_t i = 0; i < contacts_; ++i)
            for (std::size_t j = 0; j < contacts_; ++j) {
                const constraints::contact_row<T>&ri = rows_[i], &rj = rows_[j];
                block(ri.a, rj.a, T(1), i, j), block(ri.b, rj.b, T(1), i, j);
                block(ri.a, rj.b, T(-1), i, j), block(ri.b, rj.a, T(-1), i, j);
            }
        for (std::size_t i = 0; i < contacts_; ++i) D[3 * i * n + 3 * i] += rows_[i].compliance;  // a soft contact's c
        for (std::size_t i = 0; i < contacts_; ++i) {
            const vec3<T> u = W.velocity(i, r);
            for (std::size_t a = 0; a < 3; ++a) {
                T s = u[a];
                for (std::size_t k = 0; k < n; ++k) s -= D[(3 * i + a) * n + k] * r[k];
                q[3 * i + a] = s;
            }
        }
        for (std::size_t k = 0; k < n; ++k) before[k] = r[k];
        for (std::size_t i = 0; i < contacts_; ++i) {
            const constraints::contact_row<T>& row = rows_[i];
            kind_[i] = row.bounded ? constraints::bounded_block : row.bilateral ? constraints::bilateral_block : constraints::contact_block;
            bounds_[i] = {row.lower, row.upper};
        }
        const constraints::contact_report<T> newton = constraints::newton_polish<T>(
            D, q, std::span<const T>(mu_.data(), contacts_), r, std::span<T>(scratch_), settings_.solver.tolerance, 30,
            std::span<const unsigned char>(kind_.data(), contacts_), std::span<const std::array<vec3<T>, 2>>(bounds_.data(), contacts_));
        for (std::size_t i = 0; i < contacts_; ++i)
            W.apply(i, vec3<T>{r[3 * i] - before[3 * i], r[3 * i + 1] - before[3 * i + 1], r[3 * i + 2] - before[3 * i + 2]});
        report.residual = newton.residual, report.converged = newton.converged, report.error = newton.error;
        report.polish_steps += newton.sweeps;
    }

    // Poses from the average of the velocities before and after the jump, plus the pseudo-velocity
    // (a body marked by move_by_velocity_after: from the velocity after). The kinematic shapes move
    // as prescribed, by their own velocity.
    void integrate(const T& h) noexcept {
        for_each_body_at_once([&](auto&, std::size_t, std::size_t b) {
            screw<T> m;
            const T w = by_after_[b] ? T(0) : T(0.5);  // the weight of the velocity before
            for (std::size_t c = 0; c < 6; ++c)
                m[c] = settings_.substeps > 0 ? displacement_[b][c] / h : w * before_[b][c] + (T(1) - w) * velocity_[b][c] + pseudo_[b][c];
            pose_[b] = advance(pose_[b], map_[b].t, m, h);
            by_after_[b] = 0;
        });
        for (std::size_t s = 0; s < static_shape_.size(); ++s) {
            if (!static_moving_[s]) continue;
            static_pose_[s] = advance(static_pose_[s], static_map_[s].t, static_velocity_[s], h);
            place_static(s);
        }
    }

    // The impulses of this step by contact, in order of their pairs' keys, for the next warm start.
    void store_impulses() noexcept {
        for (std::size_t j = 0; j < blocks_; ++j) joint_impulse_[j] = {impulse_[3 * j], impulse_[3 * j + 1], impulse_[3 * j + 2]};
        for (std::size_t c = blocks_; c < contacts_; ++c) {
            vec3<T> r{};
            for (std::size_t k = 0; k < 3; ++k) r = linear3::add_scaled(r, impulse_[3 * c + k], rows_[c].direction[k]);
            stored_[c - blocks_] = {keys_[c], r, local_point(c)};
        }
        stored_count_ = contacts_ - blocks_;  // (in key order: build_rows went through the manifolds so)
    }

    // ---- a stepper's view of the stages (constrained/robot_world.hpp: a robot's rows solved with these) ----

    // The rows a step may have: the contact points and the joints' blocks (at most three a joint).
    static constexpr std::size_t rows_for(const world_capacity& c) noexcept { return c.contacts + 3 * c.joints; }

    // The step's rows (the joints' blocks, then the contacts), their impulses and friction
    // coefficients, the bodies' velocities and mobilities (build_rows': in the world's axes at each centre).
    [[nodiscard]] std::span<const constraints::contact_row<T>> rows() const noexcept { return {rows_.data(), contacts_}; }
    [[nodiscard]] std::span<T> impulses() noexcept { return {impulse_.data(), 3 * contacts_}; }
    [[nodiscard]] std::span<const T> friction() const noexcept { return {mu_.data(), contacts_}; }
    [[nodiscard]] std::span<screw<T>> velocities() noexcept { return {velocity_.data(), total_}; }
    [[nodiscard]] std::span<const constraints::mobility<T>> mobilities() const noexcept { return {mobility_.data(), total_}; }
    [[nodiscard]] const vec3<T>& centre(std::uint32_t body) const noexcept { return map_[body].t; }
    // This step, body b moves by its velocity after the jump (semi-implicit Euler, as a tree
    // does: constrained/impulse_dynamics.hpp), not by the average: so a gap between it and a
    // robot closes as their rows assumed (u⁺ ≥ −φ/h), not by half the body's change of velocity less.
    void move_by_velocity_after(std::uint32_t body) noexcept { by_after_[body] = 1; }
    // f(body, shape, map, margin) for each moving body whose box (collide's: grown by its reach)
    // may meet `box`; margin: the settings' plus the body's reach over the step.
    template <class F>
    void for_each_body_near(const collision::aabb<T>& box, F&& f) noexcept {
        broadphase_.query(box, [&](collision::proxy_id p) {
            const auto b = static_cast<std::uint32_t>(broadphase_.user_of(p));
            with_body(b, [&](auto& g, std::size_t i) { f(b, g.shape[i], map_[b], settings_.margin + reach_[b]); });
        });
    }
    // f(index, shape, map) for each static shape (a kinematic or soft one as if fixed and rigid).
    template <class F>
    void for_each_static(F&& f) const noexcept {
        for (std::size_t s = 0; s < static_shape_.size(); ++s) f(s, static_shape_[s], static_map_[s]);
    }

    // ---- reading ----

    [[nodiscard]] const world_settings<T>& settings() const noexcept { return settings_; }
    [[nodiscard]] world_settings<T>& settings() noexcept { return settings_; }
    template <std::size_t I>
    [[nodiscard]] std::size_t count() const noexcept { return std::get<I>(groups_).count; }
    template <std::size_t I>
    [[nodiscard]] const motor<T>& pose(std::size_t i) const noexcept { return pose_[std::get<I>(groups_).offset + i]; }
    template <std::size_t I>
    [[nodiscard]] const screw<T>& velocity(std::size_t i) const noexcept { return velocity_[std::get<I>(groups_).offset + i]; }
    template <std::size_t I>
    void set_velocity(std::size_t i, const screw<T>& s) noexcept { velocity_[std::get<I>(groups_).offset + i] = s; }
    // A force f through body i's centre of mass and a torque τ (world axes, N and N m) on every
    // step from now on, besides gravity; zeros to remove them. A non-finite one shows as a
    // non-finite step.
    template <std::size_t I>
    void set_wrench(std::size_t i, const vec3<T>& f, const vec3<T>& tau = {}) noexcept {
        force_[std::get<I>(groups_).offset + i] = f, torque_[std::get<I>(groups_).offset + i] = tau;
    }
    template <std::size_t I>
    [[nodiscard]] const typename kind<I>::inertia_type::template data<T>& body(std::size_t i) const noexcept {
        return std::get<I>(groups_).data[i];
    }
    // This step's contact points: rows and impulses (normal, t1, t2). The rows are as the step's
    // last problem left them: its position correction's lines pass through the bodies' centres.
    [[nodiscard]] std::span<const constraints::contact_row<T>> contact_rows() const noexcept {
        return {rows_.data() + blocks_, contacts_ - blocks_};
    }
    // (the soft step's: its last substep's times the substeps)
    [[nodiscard]] vec3<T> contact_impulse(std::size_t c) const noexcept {
        const std::size_t i = blocks_ + c;
        const T n = settings_.substeps > 0 ? T(settings_.substeps) : T(1);
        return {n * impulse_[3 * i], n * impulse_[3 * i + 1], n * impulse_[3 * i + 2]};
    }
    // Joint block j's impulses over the last step along its three rows (joint_rows.hpp: the world's
    // axes for a point or weld, the rows' directions otherwise), on body b; body a felt their opposite.
    [[nodiscard]] vec3<T> joint_impulse(std::size_t j) const noexcept {
        return linear3::scale(settings_.substeps > 0 ? T(settings_.substeps) : T(1), joint_impulse_[j]);
    }

private:
    template <class F>
    void for_each_group(F&& f) {
        std::apply([&](auto&... g) { (f(g), ...); }, groups_);
    }
    // f(group, index in it, body) for every moving body
    template <class F>
    void for_each_body(F&& f) {
        for_each_group([&](auto& g) {
            for (std::size_t i = 0; i < g.count; ++i) f(g, i, g.offset + i);
        });
    }
    // The same, the bodies of each kind shared among the team's threads (a body's work touches that
    // body only; a few bodies are done by the caller alone).
    template <class F>
    void for_each_body_at_once(F&& f) {
        for_each_group([&](auto& g) {
            const auto chunk = [&](std::size_t begin, std::size_t end) {
                for (std::size_t i = begin; i < end; ++i) f(g, i, g.offset + i);
            };
            if (g.count >= settings_.parallel_rows / 2) crew_.run(g.count, chunk);
            else chunk(0, g.count);
        });
    }
    // f(i) for i in [0, n), shared among the team's threads when n is large
    template <class F>
    void at_once(std::size_t n, F&& f) {
        const auto chunk = [&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) f(i);
        };
        if (n >= settings_.parallel_rows / 2) crew_.run(n, chunk);
        else chunk(0, n);
    }
    template <class F>
    void with_body(std::uint32_t b, F&& f) {
        for_each_group([&](auto& g) {
            if (b >= g.offset && b < g.offset + g.capacity) f(g, b - g.offset);
        });
    }
    static constexpr std::size_t sum(const std::array<std::size_t, kinds>& a) noexcept {
        std::size_t s = 0;
        for (std::size_t x : a) s += x;
        return s;
    }
    // §7's K and D: finite and symmetric.
    static error_code check_elements(const matrix6<T>& K, const matrix6<T>& D) noexcept {
        for (const matrix6<T>* M : {&K, &D})
            for (std::size_t i = 0; i < 6; ++i)
                for (std::size_t j = 0; j < 6; ++j) {
                    if (!is_finite((*M)[i][j])) return error_code::non_finite;
                    const T d = (*M)[i][j] - (*M)[j][i], size = (*M)[i][i] + (*M)[j][j];
                    if ((d < T(0) ? -d : d) > T(1e-12) * (size < T(0) ? -size : size)) return error_code::not_symmetric;
                }
        return error_code::none;
    }
    static error_code check_material(const material<T>& m) noexcept {
        if (!all_finite(m.friction, m.restitution)) return error_code::non_finite;
        if (m.friction < T(0) || m.restitution < T(0) || m.restitution > T(1)) return error_code::negative_friction;
        return error_code::none;
    }
    void keep(std::uint32_t a, std::uint32_t b, const collision::manifold<T>& m, bool& full) noexcept {
        if (m.count == 0) return;
        if (manifolds_ == found_.size()) return void(full = true);
        found_[manifolds_++] = {a, b, m};
    }
    // A pose moved by a screw m (ω, v: world axes, v the velocity of the point at t) over h: the
    // point t by h v, the rotation by exp(h ω) on the left. A non-finite m gives a motor
    // renormalize cannot mend: its NaNs are kept, and step() then returns to the state it started from.
    static motor<T> advance(const motor<T>& pose, const vec3<T>& at, const screw<T>& m, const T& h) noexcept {
        const translator<T> t = make_translator(at[0] + h * m[3], at[1] + h * m[4], at[2] + h * m[5]);
        const rotor<T> turn = project<rotor<T>>(ctga::exp(screw<T>{h * m[0], h * m[1], h * m[2], T(0), T(0), T(0)}));
        const rotor<T> r0 = project<rotor<T>>(pose * conj(make_translator(at[0], at[1], at[2])));
        const checked<motor<T>> g = renormalize_checked(motor<T>(t * (turn * r0)));
        motor<T> out = g ? g.value : motor<T>(t * (turn * r0));
        if (!g) out[0] = std::numeric_limits<T>::quiet_NaN();
        return out;
    }
    // A static shape's map and box from its pose.
    void place_static(std::size_t s) noexcept {
        static_map_[s] = map_of(static_pose_[s]);
        if constexpr (requires { collision::bounds_of(static_shape_[s], static_map_[s]); })
            static_bounded_[s] = true, static_box_[s] = collision::bounds_of(static_shape_[s], static_map_[s]);
        else static_bounded_[s] = false;
    }
    // The velocity of static shape s's point x along the directions e (zero for a static one).
    vec3<T> static_speed(std::size_t s, const vec3<T>& x, const std::array<vec3<T>, 3>& e) const noexcept {
        if (!static_moving_[s]) return {};
        const screw<T>& m = static_velocity_[s];
        const vec3<T> w{m[0], m[1], m[2]};
        const vec3<T> v = linear3::add(vec3<T>{m[3], m[4], m[5]}, linear3::cross(w, linear3::sub(x, static_map_[s].t)));
        return {linear3::dot(e[0], v), linear3::dot(e[1], v), linear3::dot(e[2], v)};
    }
    // Each body's wrench from the couplings (about its centre, world axes), at the step's start:
    // W = −K ξ − D s on b at its frame's origin p (couplings.hpp), −W on a along the same line.
    void couple() noexcept {
        for (std::size_t b = 0; b < total_; ++b) coupled_[b] = coscrew<T>{};
        for (std::size_t k = 0; k < couplings_count_; ++k) {
            const world_detail::coupling_record<T>& c = couplings_[k];
            const auto frame = [&](std::uint32_t body, const motor<T>& f) { return body == constraints::no_body ? f : motor<T>(pose_[body] * f); };
            const motor<T> A = frame(c.a, c.coupling.frame_a), B = frame(c.b, c.coupling.frame_b);
            const screw<T> xi = ctga::log(motor<T>(conj(A) * B));
            const motor_map<T> MA = map_of(A), MB = map_of(B);
            const vec3<T>& p = MB.t;
            // the velocity of body x's point at p, and its angular velocity
            const auto at_p = [&](std::uint32_t x) -> std::array<vec3<T>, 2> {
                if (x == constraints::no_body) return {};
                const screw<T>& s = velocity_[x];
                const vec3<T> w{s[0], s[1], s[2]};
                return {w, linear3::add(vec3<T>{s[3], s[4], s[5]}, linear3::cross(w, linear3::sub(p, map_[x].t)))};
            };
            const std::array<vec3<T>, 2> va = at_p(c.a), vb = at_p(c.b);
            const vec3<T> w = linear3::apply_transposed(MA.R, linear3::sub(vb[0], va[0])), v = linear3::apply_transposed(MA.R, linear3::sub(vb[1], va[1]));
            const coscrew<T> W = coupling_wrench(c.coupling.stiffness, c.coupling.damping, xi, screw<T>{w[0], w[1], w[2], v[0], v[1], v[2]});
            const vec3<T> tau = linear3::apply(MA.R, vec3<T>{W[0], W[1], W[2]}), f = linear3::apply(MA.R, vec3<T>{W[3], W[4], W[5]});
            const auto push = [&](std::uint32_t x, const T& sign) {
                if (x == constraints::no_body) return;
                const vec3<T> moment = linear3::add(tau, linear3::cross(linear3::sub(p, map_[x].t), f));
                for (std::size_t i = 0; i < 3; ++i) coupled_[x][i] += sign * moment[i], coupled_[x][3 + i] += sign * f[i];
            };
            push(c.b, T(1));
            push(c.a, T(-1));
        }
    }
    static constexpr std::uint32_t bad_ref = ~std::uint32_t{0} - 1;
    static constexpr mat3<T> identity3() noexcept { return {vec3<T>{T(1), T(0), T(0)}, vec3<T>{T(0), T(1), T(0)}, vec3<T>{T(0), T(0), T(1)}}; }
    // A body_ref's global id: no_body for the ground, bad_ref for a body that was not added.
    std::uint32_t global(const body_ref& r) noexcept {
        if (r == ground) return constraints::no_body;
        std::uint32_t out = bad_ref;
        std::size_t k = 0;
        for_each_group([&](auto& g) {
            if (k++ == r.kind && r.index < g.count) out = static_cast<std::uint32_t>(g.offset + r.index);
        });
        return out;
    }
    static std::uint64_t pair_key(std::uint32_t a, std::uint32_t b) noexcept {
        return a < b ? (std::uint64_t{a} << 32) | b : (std::uint64_t{b} << 32) | a;
    }
    bool joined(std::uint32_t a, std::uint32_t b) const noexcept {
        if (joined_count_ == 0) return false;
        return std::binary_search(joined_.data(), joined_.data() + joined_count_, pair_key(a, b));
    }
    std::span<const screw<T>> bodies(const std::pmr::vector<screw<T>>& s) const noexcept { return {s.data(), total_}; }
    // Contact c's point in its body a's frame (at the step's start pose).
    vec3<T> local_point(std::size_t c) const noexcept {
        const constraints::contact_row<T>& row = rows_[c];
        const motor_map<T>& G = map_[row.a.body];
        // the line's moment is (x − c) × n; the point is kept as the contact point's offset from a's centre
        return linear3::apply_transposed(G.R, arm_[c]);
    }
    bool state_finite() noexcept {
        bool ok = true;
        for_each_body([&](auto&, std::size_t, std::size_t b) {
            for (std::size_t c = 0; c < 8; ++c) ok = ok && is_finite(pose_[b][c]);
            for (std::size_t c = 0; c < 6; ++c) ok = ok && is_finite(velocity_[b][c]);
        });
        return ok;
    }

    world_settings<T> settings_;
    std::tuple<group<Kinds>...> groups_;
    std::size_t total_;
    std::pmr::vector<motor<T>> pose_, before_pose_;
    std::pmr::vector<motor_map<T>> map_;
    std::pmr::vector<screw<T>> velocity_, before_, pseudo_;
    std::pmr::vector<screw<T>> displacement_, free_, substep_start_;  // the soft step's: each body's d = Σ h_s s, its free
                                                                      // velocity's share, its velocity as a substep starts
    // (velocity_ and displacement_ have a slot past the last body, zero: the soft step's "no body")
    std::pmr::vector<vec3<T>> force_, torque_;
    std::pmr::vector<constraints::mobility<T>> mobility_;
    std::pmr::vector<material<T>> material_;
    std::pmr::vector<T> reach_, radius_;
    std::pmr::vector<collision::aabb<T>> box_;  // this step's grown boxes
    std::pmr::vector<collision::proxy_id> proxy_;
    std::pmr::vector<Static> static_shape_;
    std::pmr::vector<motor<T>> static_pose_;
    std::pmr::vector<motor_map<T>> static_map_;
    std::pmr::vector<screw<T>> static_velocity_;  // a kinematic shape's (zero for a static one)
    std::pmr::vector<collision::aabb<T>> static_box_;
    std::pmr::vector<material<T>> static_material_;
    std::pmr::vector<bool> static_bounded_, static_moving_, static_soft_;
    std::pmr::vector<contact_compliance<T>> static_softness_;  // a soft static shape's K and D (couplings.hpp)
    std::pmr::vector<world_detail::found_manifold<T>> found_;
    std::pmr::vector<std::uint32_t> by_key_, first_of_body_;  // the manifolds in key order; a counting sort's buckets
    std::pmr::vector<std::uint32_t> stored_from_;  // each row's first stored impulse of its pair
    std::pmr::vector<constraints::contact_row<T>> rows_;
    std::pmr::vector<world_detail::contact_key> keys_;
    std::pmr::vector<T> separation_, before_normal_, surface_, impulse_, correction_, mu_, restitution_, spring_rate_;  // surface_: a kinematic shape's normal speed
    std::pmr::vector<vec3<T>> arm_;  // contact point − body a's centre
    // the soft step's rows in colours and groups (constraints/row_colours.hpp)
    std::pmr::vector<std::uint64_t> colour_used_;
    std::pmr::vector<std::uint32_t> colour_of_, colour_order_, colour_start_, lane_group_start_;
    std::pmr::vector<lane_group> lane_groups_;
    std::pmr::vector<unsigned char> lane_bilateral_;
    std::pmr::vector<std::uint32_t> lane_first_;  // each group's first row's place in colour_order_
    std::pmr::vector<unsigned char> lane_count_;   // and its rows
    std::pmr::vector<constraints::row_group<T, 1>> singles_;  // the rows of colours of few rows, one at a time
    std::pmr::vector<unsigned char> single_bilateral_;
    std::pmr::vector<std::uint32_t> single_start_;
    std::size_t single_count_ = 0;
    std::size_t coloured_ = 0, lane_group_count_ = 0;
    std::pmr::vector<world_detail::stored_impulse<T>> stored_;
    std::pmr::vector<T> conjugate_;       // the conjugate directions' scratch
    std::pmr::vector<T> dense_, scratch_;  // W and q of a problem to polish, Newton's scratch
    std::pmr::vector<constraints::joint_block<T>> joints_;  // the joints' blocks (each joint one or two)
    std::pmr::vector<vec3<T>> joint_impulse_, joint_error_, joint_before_;
    std::pmr::vector<std::uint64_t> joined_;  // pairs of jointed bodies, sorted
    std::pmr::vector<world_detail::coupling_record<T>> couplings_;
    std::pmr::vector<coscrew<T>> coupled_;  // each body's wrench from the couplings this step
    std::pmr::vector<unsigned char> kind_;  // a problem to polish: its blocks' kinds and bounds (newton_polish.hpp)
    std::pmr::vector<std::array<vec3<T>, 2>> bounds_;
    std::pmr::vector<std::uint32_t> order_, part_start_, phase_start_;  // rows by part (sweep_schedule)
    std::pmr::vector<std::uint16_t> part_of_row_, slab_of_body_;
    std::pmr::vector<world_detail::ranked<T>> ranked_;  // the bodies by their coordinate across the slabs
    std::pmr::vector<T> partial_;
    std::pmr::vector<unsigned char> by_after_;  // move_by_velocity_after's bodies, this step (bytes: set and cleared by threads)
    team crew_;
    std::size_t blocks_ = 0, joined_count_ = 0, couplings_count_ = 0;  // blocks_: the joints' blocks, the rows' first
    std::size_t manifolds_ = 0, contacts_ = 0, stored_count_ = 0;  // contacts_: rows in use, the joints' first
    collision::broadphase<T> broadphase_;
};

}  // namespace ctga
