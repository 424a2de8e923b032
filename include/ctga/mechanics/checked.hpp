// Checked construction: physical inputs that can be wrong at run time (a non-finite number, a
// non-positive mass, an inertia tensor violating the triangle inequalities, a matrix that is not
// a rigid motion) are reported as a value, never propagated into a state that looks fine.
//
//   auto body = ctga::make_inertia(m, com, tensor);   // checked<spatial_inertia<double>>
//   if (!body) std::puts(ctga::describe(body.error));
//   use(*body);
//
// No exceptions and no heap: a checked<V> is the value plus an error code. Reading the value of a
// failed check is a logic error; it asserts in debug builds.
#pragma once

#include <cassert>
#include <cmath>

namespace ctga {

enum class input_error : unsigned char {
    none,
    non_finite,             // a NaN or an infinity among the inputs
    non_positive_mass,      // m ≤ 0
    not_symmetric,          // an inertia tensor with I_ij ≠ I_ji beyond rounding
    not_positive_definite,  // a principal moment ≤ 0
    triangle_inequality,    // principal moments with I_i > I_j + I_k: no mass distribution has them
    not_a_rotation,         // the 3×3 block of a homogeneous matrix is not orthonormal with det +1
    not_homogeneous,        // the bottom row of a homogeneous matrix is not (0, 0, 0, 1)
    not_a_motor,            // g g* = 1 fails beyond repair (zero or non-finite rotor part)
    not_a_rigid_inertia,    // a 6×6 inertia without the form [[I, m Ĉ], [m Ĉᵀ, m 1]] of §2
    did_not_converge,       // an implicit integration step's iteration did not converge
};

[[nodiscard]] constexpr const char* describe(input_error e) noexcept {
    switch (e) {
        case input_error::none: return "ok";
        case input_error::non_finite: return "ctga: non-finite input (NaN or infinity)";
        case input_error::non_positive_mass: return "ctga: the mass must be positive";
        case input_error::not_symmetric: return "ctga: the inertia tensor must be symmetric";
        case input_error::not_positive_definite: return "ctga: the inertia tensor must be positive definite";
        case input_error::triangle_inequality:
            return "ctga: the principal moments violate the triangle inequality I_i <= I_j + I_k";
        case input_error::not_a_rotation: return "ctga: the 3x3 block is not a rotation (orthonormal, det +1)";
        case input_error::not_homogeneous: return "ctga: the bottom row of a homogeneous matrix must be 0 0 0 1";
        case input_error::not_a_rigid_inertia:
            return "ctga: not a rigid body's inertia (mass block m*1, coupling block m*C antisymmetric)";
        case input_error::not_a_motor: return "ctga: not a rigid motion (the rotor part is zero or non-finite)";
        case input_error::did_not_converge:
            return "ctga: the implicit step did not converge (the step is too large for the angular velocity)";
    }
    return "ctga: unknown error";
}

template <class V>
struct checked {
    V value{};
    input_error error = input_error::none;

    [[nodiscard]] constexpr explicit operator bool() const noexcept { return error == input_error::none; }
    [[nodiscard]] constexpr const V& operator*() const noexcept {
        assert(error == input_error::none && "ctga: reading the value of a failed check");
        return value;
    }
    [[nodiscard]] constexpr const V* operator->() const noexcept { return &**this; }
};

// True when every argument is a finite number. Written without std::isfinite so that it is usable
// in constant expressions: NaN fails x == x, ±∞ fails the bound.
template <class T>
[[nodiscard]] constexpr bool is_finite(const T& x) noexcept {
    return x == x && x - x == x - x;
}
template <class... T>
[[nodiscard]] constexpr bool all_finite(const T&... x) noexcept {
    return (is_finite(x) && ...);
}

}  // namespace ctga
