// The kinematic trees of the chain benchmarks as types (their numbers: chain_models.hpp). Apart,
// so that the compile-time units (bench/compile/tree_dynamics.cpp) include the trees alone.
#pragma once

#include <cstddef>
#include <type_traits>
#include <utility>

#include <ctga/chains/tree.hpp>

namespace bench::chains {

namespace ch = ctga::chains;

// Every joint frame of these trees is its parent's moved by a translation (chain_models.hpp: the
// placements are translations), so every joint is aligned (ctga/chains/joints.hpp).
using revolute_x = ch::aligned<ch::revolute_x>;
using revolute_y = ch::aligned<ch::revolute_y>;
using revolute_z = ch::aligned<ch::revolute_z>;
using floating = ch::aligned<ch::floating>;

// The arm with its joints wrapped in W: aligned (arm7_tree), or as given (arm7_general_tree: the
// same arm with its placements' rotations read at run time, as the spatial code reads them).
template <class J>
using general = J;
template <template <class> class W>
using arm7_of = ch::tree<ch::link<-1, W<ch::revolute_z>>, ch::link<0, W<ch::revolute_y>>, ch::link<1, W<ch::revolute_z>>,
                         ch::link<2, W<ch::revolute_y>>, ch::link<3, W<ch::revolute_z>>, ch::link<4, W<ch::revolute_y>>,
                         ch::link<5, W<ch::revolute_z>>, ch::fixed_frame<"tool", 6>>;
using arm7_tree = arm7_of<ch::aligned>;
using arm7_general_tree = arm7_of<general>;
// chain<N>: joint i about z, y, x, z, …
template <std::size_t I>
using cycling_joint = std::conditional_t<I % 3 == 0, revolute_z, std::conditional_t<I % 3 == 1, revolute_y, revolute_x>>;
template <class Seq>
struct serial_tree;
template <std::size_t... I>
struct serial_tree<std::index_sequence<I...>> {
    using type = ch::tree<ch::link<static_cast<int>(I) - 1, cycling_joint<I>>...>;
};
template <std::size_t N>
using chain_tree = typename serial_tree<std::make_index_sequence<N>>::type;
using chain30_tree = chain_tree<30>;

// A trunk on a floating joint and four legs, each hip (x), thigh (y), knee (y).
using legged_tree =
    ch::tree<ch::link<-1, floating>,                                                                   //
             ch::link<0, revolute_x>, ch::link<1, revolute_y>, ch::link<2, revolute_y>,      // front left
             ch::link<0, revolute_x>, ch::link<4, revolute_y>, ch::link<5, revolute_y>,      // front right
             ch::link<0, revolute_x>, ch::link<7, revolute_y>, ch::link<8, revolute_y>,      // hind left
             ch::link<0, revolute_x>, ch::link<10, revolute_y>, ch::link<11, revolute_y>,   // hind right
             ch::fixed_frame<"foot", 3>>;                                                           // front left foot
// A humanoid: a pelvis on a floating joint; two legs of six joints (hip z, x, y, knee y, ankle y,
// x); a torso (z, y) carrying a head (z, y) and two arms of seven joints (shoulder y, x, z, elbow
// y, wrist z, y, x), each hand a thumb (z, y) and a finger (y, y). 39 bodies, 44 dofs.
using humanoid_tree =
    ch::tree<ch::link<-1, floating>,                                                                       //  0 pelvis
             ch::link<0, revolute_z>, ch::link<1, revolute_x>, ch::link<2, revolute_y>,          //  1 left leg
             ch::link<3, revolute_y>, ch::link<4, revolute_y>, ch::link<5, revolute_x>,          //
             ch::link<0, revolute_z>, ch::link<7, revolute_x>, ch::link<8, revolute_y>,          //  7 right leg
             ch::link<9, revolute_y>, ch::link<10, revolute_y>, ch::link<11, revolute_x>,        //
             ch::link<0, revolute_z>, ch::link<13, revolute_y>,                                      // 13 torso
             ch::link<14, revolute_z>, ch::link<15, revolute_y>,                                     // 15 head
             ch::link<14, revolute_y>, ch::link<17, revolute_x>, ch::link<18, revolute_z>,       // 17 left arm
             ch::link<19, revolute_y>, ch::link<20, revolute_z>, ch::link<21, revolute_y>,       //
             ch::link<22, revolute_x>,                                                                   //
             ch::link<23, revolute_z>, ch::link<24, revolute_y>,                                     // 24 thumb
             ch::link<23, revolute_y>, ch::link<26, revolute_y>,                                     // 26 finger
             ch::link<14, revolute_y>, ch::link<28, revolute_x>, ch::link<29, revolute_z>,       // 28 right arm
             ch::link<30, revolute_y>, ch::link<31, revolute_z>, ch::link<32, revolute_y>,       //
             ch::link<33, revolute_x>,                                                                   //
             ch::link<34, revolute_z>, ch::link<35, revolute_y>,                                     // 35 thumb
             ch::link<34, revolute_y>, ch::link<37, revolute_y>,                                     // 37 finger
             ch::fixed_frame<"hand", 23>>;                                                                   // left hand
}  // namespace bench::chains
