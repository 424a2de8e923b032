// A dense symmetric positive definite system A x = b solved by Cholesky's factorisation A = L Lᵀ
// (Golub & Van Loan, Matrix Computations, §4.2): n³/6 multiply-adds, no pivoting (a positive
// definite matrix needs none). For the mass matrix of a tree with mimic joints (chains/aba.hpp)
// and the task-space quantities built from it. A matrix that is not positive definite, or a
// non-finite entry, is reported (not_positive_definite, non_finite), never answered with a number;
// for a pack of lanes (support/pack.hpp) such a lane's factor is NaN.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "ctga/support/checked.hpp"
#include "ctga/support/math.hpp"

namespace ctga {

// L with A = L Lᵀ (lower triangle; the rest zero), A row-major and symmetric (its lower triangle is read).
template <std::size_t N, class T>
[[nodiscard]] constexpr checked<std::array<std::array<T, N>, N>> cholesky(const std::array<std::array<T, N>, N>& A) noexcept {
    std::array<std::array<T, N>, N> L{};
    for (std::size_t j = 0; j < N; ++j) {
        T d = A[j][j];
        for (std::size_t k = 0; k < j; ++k) d -= L[j][k] * L[j][k];
        if constexpr (lane_wise<T>) {
            // lane by lane: a lane that is not positive definite goes on with NaN (its results all
            // NaN, reported by chains::batch_call); the others are factored
            d = select(d > T(0), d, T(std::numeric_limits<double>::quiet_NaN()));
        } else {
            if (!all_finite(d)) return {{}, error_code::non_finite};
            if (!(d > T(0))) return {{}, error_code::not_positive_definite};
        }
        L[j][j] = math::sqrt(d);
        for (std::size_t i = j + 1; i < N; ++i) {
            T s = A[i][j];
            for (std::size_t k = 0; k < j; ++k) s -= L[i][k] * L[j][k];
            L[i][j] = s / L[j][j];
        }
    }
    return {L, error_code::none};
}

// x with L Lᵀ x = b (forward, then back substitution).
template <std::size_t N, class T>
[[nodiscard]] constexpr std::array<T, N> cholesky_solve(const std::array<std::array<T, N>, N>& L, std::array<T, N> b) noexcept {
    for (std::size_t i = 0; i < N; ++i) {
        for (std::size_t k = 0; k < i; ++k) b[i] -= L[i][k] * b[k];
        b[i] /= L[i][i];
    }
    for (std::size_t i = N; i-- > 0;) {
        for (std::size_t k = i + 1; k < N; ++k) b[i] -= L[k][i] * b[k];
        b[i] /= L[i][i];
    }
    return b;
}

// A⁻¹ from A's factor L (A = L Lᵀ): W = L⁻¹ by forward substitution, the diagonal's reciprocals
// taken once (N divisions), then A⁻¹ = Wᵀ W, symmetric (the upper triangle formed, mirrored).
template <std::size_t N, class T>
[[nodiscard]] constexpr std::array<std::array<T, N>, N> cholesky_inverse(const std::array<std::array<T, N>, N>& L) noexcept {
    std::array<T, N> r{};
    for (std::size_t i = 0; i < N; ++i) r[i] = T(1) / L[i][i];
    std::array<std::array<T, N>, N> W{};
    for (std::size_t j = 0; j < N; ++j) {
        W[j][j] = r[j];
        for (std::size_t i = j + 1; i < N; ++i) {
            T s = T(0);
            for (std::size_t k = j; k < i; ++k) s -= L[i][k] * W[k][j];
            W[i][j] = s * r[i];
        }
    }
    std::array<std::array<T, N>, N> X{};
    for (std::size_t a = 0; a < N; ++a)
        for (std::size_t b = a; b < N; ++b) {
            T s = T(0);
            for (std::size_t k = b; k < N; ++k) s += W[k][a] * W[k][b];
            X[a][b] = X[b][a] = s;
        }
    return X;
}

}  // namespace ctga
