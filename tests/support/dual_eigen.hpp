// Eigen's traits for the forward-mode dual numbers of support/dual.hpp: with this header,
// Eigen::Matrix<ctga_test::dual<N, T>, ...> is a matrix of duals (sums, products, blocks,
// transposes, casts from T with .cast<dual<N, T>>()). Tests only; used by the Featherstone
// reference on duals (support/featherstone_derivatives.hpp).
//
// Mixed expressions of dual and T matrices are not declared (no ScalarBinaryOpTraits): convert
// the T matrix with .cast<dual<N, T>>(). A T scalar times a dual matrix works (Literal = T).
// The costs tell Eigen's unroller that a dual operation is N + 1 operations of T, so products of
// dual matrices are unrolled less than those of T (a shorter compile).
#pragma once

#include <cstddef>

#include <Eigen/Core>

#include "support/dual.hpp"

namespace Eigen {

template <std::size_t N, class T>
struct NumTraits<ctga_test::dual<N, T>> : NumTraits<T> {
    using Real = ctga_test::dual<N, T>;
    using NonInteger = ctga_test::dual<N, T>;
    using Nested = ctga_test::dual<N, T>;
    using Literal = T;
    enum {
        IsComplex = 0,
        IsInteger = 0,
        IsSigned = 1,
        RequireInitialization = 1,
        ReadCost = static_cast<int>(N + 1) * NumTraits<T>::ReadCost,
        AddCost = static_cast<int>(N + 1) * NumTraits<T>::AddCost,
        MulCost = static_cast<int>(2 * N + 1) * NumTraits<T>::MulCost
    };
    // the limits are T's, as constants (zero partials)
    static Real epsilon() { return Real(NumTraits<T>::epsilon()); }
    static Real dummy_precision() { return Real(NumTraits<T>::dummy_precision()); }
    static Real highest() { return Real(NumTraits<T>::highest()); }
    static Real lowest() { return Real(NumTraits<T>::lowest()); }
    static Real infinity() { return Real(NumTraits<T>::infinity()); }
    static Real quiet_NaN() { return Real(NumTraits<T>::quiet_NaN()); }
};

}  // namespace Eigen
