// MuJoCo (2.2.2, Debian's libmujoco-dev) as a third implementation of ctga_chains_bench's RNEA,
// CRBA and ABA rows: rnea_<tree>/mujoco, crba_<tree>/mujoco, aba_<tree>/mujoco (chains_mujoco.cpp).
//
// The interface the per-tree translation units call: plain numbers only, neither ctga's nor
// MuJoCo's headers, so that it costs those units nothing to compile. A tree unit fills a
// mujoco_case with its description and states and ctga's results on them
// (make_mujoco_case, chains_mujoco_case.hpp) and hands it to add_mujoco, which builds the MuJoCo
// model from the same numbers, checks MuJoCo's results against ctga's on every state and
// registers the rows only if they agree. Without CTGA_BENCH_MUJOCO (MuJoCo not found by CMake)
// add_mujoco does nothing.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "runner.hpp"

namespace bench::chains {

// A body's joint to its parent, as MuJoCo has it.
enum class mujoco_joint {
    hinge,       // revolute about `axis`
    slide,       // prismatic along `axis`
    fixed,       // no joint: the body welded to its parent
    free,        // ctga's floating joint (MuJoCo's free joint)
    unsupported  // a joint this bridge cannot express (the case is reported and skipped)
};

// One body, in the numbers of bench::chains::body_description (chain_models.hpp).
struct mujoco_body {
    int parent;                                // −1: the world; parent < own index
    mujoco_joint joint;
    std::array<double, 3> axis;                // hinge, slide: unit, joint-frame coordinates
    std::array<double, 3> t;                   // joint frame in the parent's frame (rotation: identity)
    double mass;
    std::array<double, 3> com;                 // body frame
    std::array<std::array<double, 3>, 3> Ic;   // about the centre of mass, body frame axes
};

// A tree, its states and ctga's results on them. Per state s (all vectors of one length):
//   q[s]    per body in ctga's order: a floating joint as the rigid motion of ctga's motor, its
//           translation then its unit quaternion (w, x, y, z) (ctga::map_of; 7 numbers), a
//           hinge or slide as ctga's coordinate (1), a fixed joint nothing
//   qd[s], qdd[s], tau[s]   ctga's velocity coordinates (nv): a floating joint's are (ω, v), the
//           body's twist in body coordinates, v the velocity of the body origin
//   tau_ref[s]  ch::rnea(q, qd, qdd)      empty outer vector: rnea not registered
//   H_ref[s]    ch::crba(q), row-major nv × nv   (likewise crba)
//   qdd_ref[s]  ch::aba(q, qd, tau)               (likewise aba)
struct mujoco_case {
    std::string label;  // "arm7", "chain30", "tree", …: rows <algorithm>_<label>/mujoco
    std::vector<mujoco_body> bodies;
    std::array<double, 3> gravity;  // world coordinates
    std::size_t nq = 0, nv = 0;     // lengths of q[s] and of the velocity vectors
    std::vector<std::vector<double>> q, qd, qdd, tau;
    std::vector<std::vector<double>> tau_ref, H_ref, qdd_ref;
};

// A robot that touches, for contact_step_<label>/<engine> (chains_contact_steps.hpp): standing or
// lying on the ground (the plane z = 0) on spheres, or holding a free body between its fingers.
// Both engines step it from the same start: τ_k = kp (target_k − q_k) on every hinge and slide
// plus the joints' viscous damping (implicit in both), Coulomb friction mu, step h. Measured after
// `settle` steps, over `measure` more: without a held body, a sphere's slip (the speed along the
// ground of its material point at the bottom) and its sinking (r − its centre's height, when
// positive), the largest of each; with one, its speed (slip) and the deepest overlap of any
// contact, as each engine reports it.
struct body_shape {
    std::size_t body;
    std::array<double, 3> at;    // the centre in the body's frame
    double radius;               // a sphere, when half is zero
    std::array<double, 3> half;  // a box's half extents, along the body's axes
};
struct contact_scenario {
    std::string label;
    std::vector<mujoco_body> bodies;                // free joints on the world only
    std::array<double, 3> gravity;
    std::vector<std::array<double, 7>> free_start;  // each free joint's start: position, quaternion (w, x, y, z)
    std::vector<double> target;                     // per hinge or slide in body order: the start and the PD's target
    std::vector<body_shape> shapes;
    double h, mu, kp, damping;
    std::size_t settle, measure;
    int held = -1;                                  // the held body (grasp), or −1
};
struct contact_figures {
    double slip = 0, sinking = 0;
};

#ifdef CTGA_BENCH_MUJOCO
inline constexpr bool mujoco_enabled = true;
// Builds the MuJoCo model of c, checks it and registers its rows (chains_mujoco.cpp).
void add_mujoco(std::vector<entry>& table, const mujoco_case& c);
// The scenario in MuJoCo: its figures (stderr) and contact_step_<label>/mujoco.
void add_mujoco_contact(std::vector<entry>& table, const contact_scenario& s);
#else
inline constexpr bool mujoco_enabled = false;
inline void add_mujoco(std::vector<entry>&, const mujoco_case&) {}
inline void add_mujoco_contact(std::vector<entry>&, const contact_scenario&) {}
#endif

}  // namespace bench::chains
