// The arguments of the algorithms of a kinematic tree (algorithms.hpp): the numbers they read and
// return, std::arrays sized by the tree's type, and the compile errors that name an argument
// which does not fit, or a frame the tree does not have, in their first lines.
//
// Each algorithm is an object algorithm<Overloads, "name">: its overloads as they are (inherited:
// a call is the overload's own, nothing forwards), and for arguments that none of them takes one
// more overload, whose body names the problem (fixed_string.hpp's reported):
//
//   ch::rnea(m, q, qd, qdd)    with q a std::array<double, 32> where the tree has nq = 33:
//   In instantiation of 'struct report<configuration_has_the_wrong_length<argument<2>, expected<33>, given<32>>>'
//
// The problems (argument<k> counts from 1, the model being argument<1>):
//   configuration_has_the_wrong_length<argument<k>, expected<nq>, given<n>>
//   joint_vector_has_the_wrong_length<argument<k>, expected<nv>, given<n>>      q̇, q̈, τ
//   state_array_has_the_wrong_length<argument<k>, expected<nq>, given<n>>       either, where nq = nv
//   body_wrenches_have_the_wrong_length<argument<k>, expected<bodies>, given<n>>
//   state_array_has_another_scalar<argument<k>, expected_type<double>, given_type<float>>
//   state_array_is_not_a_std_array<argument<k>, expected_type<std::array<…>>, given_type<std::vector<…>>>
//   no_overload_takes_these_arguments<algorithm_named<'r', 'n', 'e', 'a'>, the arguments' types…>
// and, for chains::frame<"tool9">, the_tree_has_no_frame_named<'t', 'o', 'o', 'l', '9'>.
//
// The algorithm headers include this one before the others, so that the include chain a compiler
// prints before the first diagnosed line is short (GCC and Clang print one line a level). An
// argument given as a braced list ({}) cannot be diagnosed (nothing is deduced from it): a wrong
// call with one is the compiler's own error.
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include "ctga/algebra/fixed_string.hpp"
#include "ctga/mechanics/coscrew.hpp"

namespace ctga::chains {

template <class Tree, class T = double>
using configuration = std::array<T, Tree::nq>;  // q: the joints' numbers in body order
template <class Tree, class T = double>
using joint_vector = std::array<T, Tree::nv>;  // q̇, q̈, τ
template <class Tree, class T = double>
using body_wrenches = std::array<coscrew<T>, Tree::size>;  // external wrench on each body, body frame

// ---- what the diagnoses say --------------------------------------------------------------------

template <std::size_t K>
struct argument {};  // the K-th argument of the call, from 1
template <std::size_t N>
struct expected {};  // the length the algorithm reads
template <std::size_t N>
struct given {};
template <class X>
struct expected_type {};
template <class X>
struct given_type {};
template <char... Name>
struct algorithm_named {};

template <class Argument, class Expected, class Given>
struct configuration_has_the_wrong_length {};
template <class Argument, class Expected, class Given>
struct joint_vector_has_the_wrong_length {};
template <class Argument, class Expected, class Given>
struct state_array_has_the_wrong_length {};
template <class Argument, class Expected, class Given>
struct body_wrenches_have_the_wrong_length {};
template <class Argument, class Expected, class Given>
struct state_array_has_another_scalar {};
template <class Argument, class Expected, class Given>
struct state_array_is_not_a_std_array {};
template <class Algorithm, class... Arguments>
struct no_overload_takes_these_arguments {};

// Instantiated to report a call no overload takes; Problem is one of the above.
template <class Problem>
struct report {
    static_assert(reported<Problem>, "ctga::chains: no overload of this algorithm takes these arguments: the problem is "
                                     "named in report<...>, with the argument (counting from 1, the model first), the "
                                     "length or type expected and the one given");
};

// Instantiated to report chains::frame<"name"> on a tree without a frame of that name (tree.hpp).
template <char... Name>
struct the_tree_has_no_frame_named {
    static_assert(reported<the_tree_has_no_frame_named>,
                  "ctga::chains::frame: the tree has no frame of this name (spelt out in the_tree_has_no_frame_named<...>)");
};

// ---- the diagnosis -------------------------------------------------------------------------------

namespace argument_detail {
template <class X>
inline constexpr bool std_array = false;
template <class U, std::size_t N>
inline constexpr bool std_array<std::array<U, N>> = true;

// An argument the diagnosis may replace: numbers in a container (std::array, std::vector, …).
template <class X>
concept numbers = std_array<X> || requires { typename X::value_type; };

// A model: its tree's and scalar's types (tree.hpp's model).
template <class M>
concept a_model = requires {
    typename M::tree_type;
    typename M::scalar_type;
};

// Choice D for an argument X of a call on model M: 0 keeps X; 1, 2, 3 replace it with the model's
// configuration, joint vector or body wrenches.
template <class M, class X, std::size_t D>
using chosen = std::tuple_element_t<D, std::tuple<X, configuration<typename M::tree_type, typename M::scalar_type>,
                                                  joint_vector<typename M::tree_type, typename M::scalar_type>,
                                                  body_wrenches<typename M::tree_type, typename M::scalar_type>>>;
inline constexpr std::size_t choices = 4;

// The problem with argument K (from 1), given as Given where choice D was expected.
template <std::size_t K, class Given, class M, std::size_t D>
constexpr auto problem() {
    using Tree = typename M::tree_type;
    using Expected = chosen<M, Given, D>;
    if constexpr (!std_array<Given>) {
        return std::type_identity<state_array_is_not_a_std_array<argument<K>, expected_type<Expected>, given_type<Given>>>{};
    } else if constexpr (!std::is_same_v<typename Given::value_type, typename Expected::value_type>) {
        return std::type_identity<state_array_has_another_scalar<argument<K>, expected_type<typename Expected::value_type>,
                                                                 given_type<typename Given::value_type>>>{};
    } else {
        using e = expected<std::tuple_size_v<Expected>>;
        using g = given<std::tuple_size_v<Given>>;
        if constexpr (D == 3) return std::type_identity<body_wrenches_have_the_wrong_length<argument<K>, e, g>>{};
        else if constexpr (Tree::nq == Tree::nv) return std::type_identity<state_array_has_the_wrong_length<argument<K>, e, g>>{};
        else if constexpr (D == 1) return std::type_identity<configuration_has_the_wrong_length<argument<K>, e, g>>{};
        else return std::type_identity<joint_vector_has_the_wrong_length<argument<K>, e, g>>{};
    }
}

// The arguments A… after model M of a call that no overload takes: the fewest state arrays to
// replace by the model's configuration, joint vector or body wrenches so that one does (a repair R:
// a digit in base `choices` per replaceable argument, 0 where it is kept), and the first of them.
template <class Overloads, class M, class... A>
struct repairs {
    static constexpr std::array<bool, sizeof...(A)> replaceable{numbers<A>...};
    static constexpr std::size_t count = [] {
        std::size_t c = 1;
        for (bool r : replaceable) c *= r ? choices : 1;
        return c;
    }();
    // argument k's choice in repair r
    static constexpr std::size_t digit(std::size_t r, std::size_t k) {
        if (!replaceable[k]) return 0;
        for (std::size_t j = 0; j < k; ++j) r /= replaceable[j] ? choices : 1;
        return r % choices;
    }
    template <std::size_t R, std::size_t... K>
    static constexpr bool works(std::index_sequence<K...>) {
        return std::invocable<const Overloads&, const M&, const chosen<M, A, digit(R, K)>&...>;
    }
    // what repair R changes: the arguments it replaces by another type
    template <std::size_t R, std::size_t... K>
    static constexpr std::array<bool, sizeof...(A)> changed(std::index_sequence<K...>) {
        return {!std::is_same_v<chosen<M, A, digit(R, K)>, A>...};
    }
    template <std::size_t R>
    static constexpr std::size_t changes = [] {
        std::size_t n = 0;
        for (bool c : changed<R>(std::index_sequence_for<A...>{})) n += c;
        return n;
    }();
    // the working repair with the fewest changes (the first of those), or count when none works
    static constexpr std::size_t best = []<std::size_t... R>(std::index_sequence<R...>) {
        constexpr std::array<bool, count> work{works<R>(std::index_sequence_for<A...>{})...};
        constexpr std::array<std::size_t, count> change{changes<R>...};
        std::size_t b = count;
        for (std::size_t r = 0; r < count; ++r)
            if (work[r] && (b == count || change[r] < change[b])) b = r;
        return b;
    }(std::make_index_sequence<count>{});
    static constexpr std::size_t first = [] {
        const auto c = changed<best>(std::index_sequence_for<A...>{});
        std::size_t k = 0;
        while (!c[k]) ++k;
        return k;
    }();
};

template <class Overloads, fixed_string Name, class... Args>
constexpr auto diagnosis() {
    using none = no_overload_takes_these_arguments<spelt<algorithm_named, Name>, Args...>;
    if constexpr (sizeof...(Args) == 0) {
        return std::type_identity<none>{};
    } else {
        using M = std::tuple_element_t<0, std::tuple<Args...>>;
        if constexpr (!a_model<M>) {
            return std::type_identity<none>{};
        } else {
            return []<class... A>(std::type_identity<std::tuple<M, A...>>) {
                using R = repairs<Overloads, M, A...>;
                if constexpr (R::best == R::count) {
                    return std::type_identity<none>{};
                } else {
                    constexpr std::size_t k = R::first;
                    using Given = std::tuple_element_t<k, std::tuple<A...>>;
                    return problem<k + 2, Given, M, R::digit(R::best, k)>();
                }
            }(std::type_identity<std::tuple<Args...>>{});
        }
    }
}
}  // namespace argument_detail

// An algorithm: the overload set Overloads (a class whose operator()s are the algorithm), named
// Name in its diagnoses. Any arguments are accepted in overload resolution (the last overload
// reports them), so that generic code asks algorithm::overloads whether a call is well formed.
template <class Overloads, fixed_string Name>
struct algorithm : Overloads {
    using overloads = Overloads;
    using Overloads::operator();

    // The problem with a call on arguments of types Args… (without references and const) that no
    // overload takes: one of the problems above.
    template <class... Args>
    using problem_with = typename decltype(argument_detail::diagnosis<Overloads, Name, Args...>())::type;

    // The call no overload takes: a compile error naming its problem. (The return type is deduced,
    // so that the body, and its error, comes before anything that uses the result.)
    template <class... Args>
        requires(!std::invocable<const Overloads&, Args...>)
    constexpr auto operator()(Args&&...) const noexcept {
        (void)report<problem_with<std::remove_cvref_t<Args>...>>{};
    }
};

}  // namespace ctga::chains
