// MuJoCo 2.2.2 as ctga_chains_bench's third implementation (chains_mujoco.hpp): a tree's MJCF
// written from the numbers of its description, loaded from memory (a virtual file system), checked
// against ctga on every state, then timed as rnea_<tree>/mujoco, crba_<tree>/mujoco,
// aba_<tree>/mujoco.
//
// What is timed (each call: one of the 64 states, cycling, its MuJoCo coordinates prepared
// beforehand; one non-inlined function per algorithm, mujoco_chain_kernel_*):
//
//   rnea  copy qpos, qvel, qacc into mjData (mju_copy);
//         mj_kinematics   body poses (xpos, xquat, xmat), inertial frames (xipos, ximat), joint
//                         anchors and axes (xanchor, xaxis): ctga's joint maps, plus world poses
//                         of every body and its inertial frame;
//         mj_comPos       subtree centres of mass (subtree_com), every body's inertia in the world
//                         frame about its tree's centre of mass (cinert), the motion subspaces in
//                         that frame (cdof);
//         mj_comVel       body velocities (cvel) and the dofs' time derivatives (cdof_dot);
//         mj_rne(m, d, 1, qfrc_inverse)   the recursive Newton–Euler passes: M q̈ + C(q, q̇) + g.
//   crba  copy qpos; mj_kinematics; mj_comPos (as above);
//         mj_crb          composite inertias (crb) and the mass matrix in MuJoCo's sparse,
//                         tree-shaped storage of the lower triangle (qM; dof_Madr, dof_parentid),
//                         armature added (0 here). Not mj_fullM: the dense nv × nv copy of qM, the
//                         form ctga returns, is not timed.
//   aba   copy qpos, qvel; mj_kinematics; mj_comPos; mj_crb (as above);
//         mj_factorM      sparse L'DL factorisation of qM (qLD, qLDiagInv, qLDiagSqrtInv);
//         mj_comVel       (as above);
//         mj_rne(m, d, 0, qfrc_bias)   C(q, q̇) + g;
//         mju_sub         τ − bias;
//         mj_solveM       q̈ = M⁻¹ (τ − bias) by the factor.
//       MuJoCo has no articulated-body algorithm: its forward dynamics is this CRBA + LDL' route
//       (what mj_forward does after its collision, constraint, actuator and passive stages).
//
// Not timed: the conversion between ctga's coordinates and MuJoCo's (a coordinate choice, done
// once per state beforehand for the inputs and in the check for the outputs).
//
// The model, from the same numbers: bodies nested as the tree's parents say (depth first, the
// children of a body in index order; MuJoCo's body, qpos and dof order is then that nesting, mapped
// back by name); body pos = the joint frame's translation t, rotation identity; a revolute (prismatic)
// joint a hinge (slide) through the body origin along its axis; a fixed joint no joint; a
// floating joint a free joint (MuJoCo: only on a child of the world). The inertia in principal
// axes: <inertial pos=com mass quat diaginertia> from the eigen-decomposition of I_c (Eigen),
// the eigenvector matrix made a proper rotation (det +1), because MuJoCo 2.2.2 diagonalises a
// fullinertia itself with a loose tolerance. No geoms; no damping, armature, friction loss,
// stiffness or limits; the compiler's mass and inertia bounds off; contact, constraints,
// passive forces, actuation, sensors disabled (none of them is reached by the timed calls).
//
// Coordinates. Hinge and slide joints: MuJoCo's qpos, qvel, qacc and qfrc are ctga's (both
// turn the body by +q about the joint frame's axis, right-handed; both slide by +q along it).
// The floating joint: ctga's configuration is a motor g relative to the joint frame (position
// t_g and rotation R: the body origin is at t + t_g in the world, the joint frame being a
// child of the world turned by nothing); MuJoCo's free joint qpos is (body origin in the world,
// unit quaternion w x y z), so qpos = (t + t_g, quaternion of g's rotor). Velocities: ctga's
// ν = (ω_b, v_b), the body's twist in body coordinates (v_b = Rᵀ ṗ, the body origin's velocity);
// MuJoCo's free qvel = (ṗ in world coordinates, ω_b in body coordinates). So qvel = T ν with
//   T = [[0, R], [1, 0]]     (rows: MuJoCo's ṗ, ω_b; columns: ctga's ω_b, v_b)
// T is orthogonal (Tᵀ T = 1), so T⁻¹ = Tᵀ. MuJoCo's qacc is the time derivative of qvel:
//   d/dt(R v_b) = R (v̇_b + ω_b × v_b)  ⇒  qacc = T ν̇ + c,  c = (R (ω_b × v_b), 0),
// ctga's q̈ being ν̇ (the body-coordinate twist's derivative, the spatial acceleration in body
// coordinates). Forces by power, τᵀ ν = qfrcᵀ qvel: τ = Tᵀ qfrc (τ_ω = MuJoCo's torque about the
// body axes, τ_v = Rᵀ f_world), qfrc = T τ; the mass matrix H = Tᵀ M T; and the forward dynamics'
// q̈ = Tᵀ (qacc − c). The other joints' blocks of T are 1 (MuJoCo's dof order mapped to ctga's).
//
// The check: for every state, MuJoCo's τ (rnea), H (crba) and q̈ (aba), converted to ctga's
// coordinates, against ctga's: error = max_i |x_i − ref_i| / max_i |ref_i| over the vector (the
// matrix), the largest over the states; above 1e-10 the case's rows are not registered (a
// message on stderr), and each case prints its errors on stderr.
#include "chains_mujoco.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>
#include <benchmark/benchmark.h>
#include <mujoco/mujoco.h>

#include "mujoco_xml.hpp"

namespace bench::chains {

namespace {

constexpr double tolerance = 1e-10;

// The arguments printed one after the other (GCC 12 warns, -Wrestrict, on "literal" + std::string&&).
template <class... A>
std::string cat(const A&... a) {
    std::ostringstream out;
    (out << ... << a);
    return out.str();
}

// ---- the MJCF ------------------------------------------------------------------------------

// The principal axes of I_c: diagonal and the quaternion (w, x, y, z) of the rotation whose
// columns are the axes, det +1.
void principal_axes(const std::array<std::array<double, 3>, 3>& Ic, double diag[3], double quat[4]) {
    Eigen::Matrix3d I;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) I(i, j) = Ic[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(I);
    Eigen::Matrix3d V = es.eigenvectors();
    if (V.determinant() < 0) V.col(2) = -V.col(2);
    double R[9];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) R[3 * i + j] = V(i, j);
    for (int k = 0; k < 3; ++k) diag[k] = es.eigenvalues()(k);
    mju_mat2Quat(quat, R);
}

// A body and its subtree; with a scenario (contact_step rows), its joints' damping and its shapes.
void write_body(std::ostringstream& x, const std::vector<mujoco_body>& bodies, const std::vector<std::vector<std::size_t>>& children,
                std::size_t i, int depth, const contact_scenario* s) {
    const mujoco_body& b = bodies[i];
    const std::string pad(static_cast<std::size_t>(2 * depth), ' ');
    double diag[3], quat[4];
    principal_axes(b.Ic, diag, quat);
    x << pad << "<body name=\"b" << i << "\" pos=\"" << b.t[0] << ' ' << b.t[1] << ' ' << b.t[2] << "\">\n";
    x << pad << "  <inertial pos=\"" << b.com[0] << ' ' << b.com[1] << ' ' << b.com[2] << "\" mass=\"" << b.mass << "\" quat=\""
      << quat[0] << ' ' << quat[1] << ' ' << quat[2] << ' ' << quat[3] << "\" diaginertia=\"" << diag[0] << ' ' << diag[1] << ' '
      << diag[2] << "\"/>\n";
    const std::string passive = cat("damping=\"", s && (b.joint == mujoco_joint::hinge || b.joint == mujoco_joint::slide) ? s->damping : 0.0, "\" armature=\"0\" stiffness=\"0\" frictionloss=\"0\"");
    if (b.joint == mujoco_joint::free) {
        x << pad << "  <joint name=\"j" << i << "\" type=\"free\" " << passive << "/>\n";
    } else if (b.joint == mujoco_joint::hinge || b.joint == mujoco_joint::slide) {
        x << pad << "  <joint name=\"j" << i << "\" type=\"" << (b.joint == mujoco_joint::hinge ? "hinge" : "slide") << "\" axis=\""
          << b.axis[0] << ' ' << b.axis[1] << ' ' << b.axis[2] << "\" pos=\"0 0 0\" ref=\"0\" limited=\"false\" " << passive << "/>\n";
    }
    if (s)
        for (std::size_t f = 0; f < s->shapes.size(); ++f) {
            const body_shape& g = s->shapes[f];
            if (g.body != i) continue;
            x << pad << "  <geom name=\"shape" << f << "\" pos=\"" << g.at[0] << ' ' << g.at[1] << ' ' << g.at[2] << "\" friction=\"" << s->mu
              << " 0.005 0.0001\" ";
            if (g.half[0] > 0) x << "type=\"box\" size=\"" << g.half[0] << ' ' << g.half[1] << ' ' << g.half[2] << "\"/>\n";
            else x << "type=\"sphere\" size=\"" << g.radius << "\"/>\n";
        }
    for (std::size_t k : children[i]) write_body(x, bodies, children, k, depth + 1, s);
    x << pad << "</body>\n";
}

// The model of a case (no contact, no passive forces: the chains rows), or of a contact scenario
// (MuJoCo's defaults but for the step and the Euler integrator: its joint damping implicit).
std::string mjcf(const std::string& label, const std::vector<mujoco_body>& bodies, const std::array<double, 3>& gravity,
                 const contact_scenario* s = nullptr) {
    std::vector<std::vector<std::size_t>> children(bodies.size());
    std::vector<std::size_t> roots;
    for (std::size_t i = 0; i < bodies.size(); ++i) (bodies[i].parent < 0 ? roots : children[static_cast<std::size_t>(bodies[i].parent)]).push_back(i);
    std::ostringstream x;
    x.precision(17);
    x << "<mujoco model=\"ctga_" << label << "\">\n"
      << "  <compiler angle=\"radian\" inertiafromgeom=\"false\" boundmass=\"0\" boundinertia=\"0\" balanceinertia=\"false\""
         " fusestatic=\"false\" settotalmass=\"-1\"/>\n"
      << "  <option gravity=\"" << gravity[0] << ' ' << gravity[1] << ' ' << gravity[2] << "\" timestep=\"" << (s ? s->h : 0.001)
      << "\" integrator=\"Euler\" wind=\"0 0 0\" density=\"0\" viscosity=\"0\">\n";
    if (!s)
        x << "    <flag constraint=\"disable\" equality=\"disable\" frictionloss=\"disable\" limit=\"disable\" contact=\"disable\""
             " passive=\"disable\" actuation=\"disable\" sensor=\"disable\" gravity=\"enable\"/>\n";
    x << "  </option>\n"
      << "  <worldbody>\n";
    if (s) x << "    <geom name=\"ground\" type=\"plane\" size=\"0 0 1\" friction=\"" << s->mu << " 0.005 0.0001\"/>\n";
    for (std::size_t r : roots) write_body(x, bodies, children, r, 2, s);
    x << "  </worldbody>\n</mujoco>\n";
    return x.str();
}

// The MJCF to a file in $CTGA_BENCH_MUJOCO_XML, for a reader.
void keep_xml(const std::string& label, const std::string& xml) {
    if (const char* dir = std::getenv("CTGA_BENCH_MUJOCO_XML")) {
        if (std::FILE* out = std::fopen(cat(dir, "/", label, ".xml").c_str(), "w")) {
            std::fputs(xml.c_str(), out);
            std::fclose(out);
        }
    }
}

// ---- coordinates ---------------------------------------------------------------------------

// Where body i's numbers are: in the case's q and ctga's velocity vectors, and in MuJoCo's.
struct place {
    mujoco_joint joint;
    std::size_t cq, cv;      // case q, ctga ν
    std::size_t qadr, dadr;  // MuJoCo qpos, dof
    std::array<double, 3> t;
};

// One case in MuJoCo: the model, its data, the states in MuJoCo's coordinates.
struct bridge {
    mjModel* m = nullptr;
    mjData* d = nullptr;
    std::size_t nq = 0, nv = 0, states = 0;
    std::vector<place> places;
    std::vector<double> qpos, qvel, qacc, qfrc;  // state k at k nq (qpos) or k nv
    bridge() = default;
    bridge(const bridge&) = delete;
    bridge& operator=(const bridge&) = delete;
    ~bridge() {
        if (d) mj_deleteData(d);
        if (m) mj_deleteModel(m);
    }
};

// T (row-major nv × nv, MuJoCo's rows, ctga's columns) and c of state s (see the top).
void velocity_map(const bridge& x, const mujoco_case& cs, std::size_t s, std::vector<double>& T, std::vector<double>& c) {
    const std::size_t nv = x.nv;
    T.assign(nv * nv, 0.0);
    c.assign(nv, 0.0);
    const std::vector<double>& q = cs.q[s];
    const std::vector<double>& qd = cs.qd[s];
    for (const place& p : x.places) {
        if (p.joint == mujoco_joint::hinge || p.joint == mujoco_joint::slide) {
            T[p.dadr * nv + p.cv] = 1;
        } else if (p.joint == mujoco_joint::free) {
            double R[9];
            mju_quat2Mat(R, &q[p.cq + 3]);
            for (std::size_t i = 0; i < 3; ++i) {
                for (std::size_t j = 0; j < 3; ++j) T[(p.dadr + i) * nv + p.cv + 3 + j] = R[3 * i + j];
                T[(p.dadr + 3 + i) * nv + p.cv + i] = 1;
            }
            const double* w = &qd[p.cv];
            const double* v = &qd[p.cv + 3];
            const double wxv[3] = {w[1] * v[2] - w[2] * v[1], w[2] * v[0] - w[0] * v[2], w[0] * v[1] - w[1] * v[0]};
            for (std::size_t i = 0; i < 3; ++i) c[p.dadr + i] = R[3 * i] * wxv[0] + R[3 * i + 1] * wxv[1] + R[3 * i + 2] * wxv[2];
        }
    }
}

// y = T x (MuJoCo from ctga), y = Tᵀ x (ctga from MuJoCo)
std::vector<double> apply(const std::vector<double>& T, const std::vector<double>& x, std::size_t n, bool transposed) {
    std::vector<double> y(n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) y[transposed ? j : i] += T[i * n + j] * x[transposed ? i : j];
    return y;
}

// ---- the timed kernels -----------------------------------------------------------------------

// The calls of each algorithm (the top), on state k. The check calls these directly and the
// timed rows through the non-inlined mujoco_chain_kernel_* below: callgrind's count of one call
// (tools/bench.sh: --toggle-collect='*chain_kernel*') then holds the timed calls alone, never the
// check's, which runs at every start.
inline const mjtNum* rnea_calls(bridge& x, std::size_t k) {
    const mjModel* m = x.m;
    mjData* d = x.d;
    mju_copy(d->qpos, &x.qpos[k * x.nq], m->nq);
    mju_copy(d->qvel, &x.qvel[k * x.nv], m->nv);
    mju_copy(d->qacc, &x.qacc[k * x.nv], m->nv);
    mj_kinematics(m, d);
    mj_comPos(m, d);
    mj_comVel(m, d);
    mj_rne(m, d, 1, d->qfrc_inverse);
    return d->qfrc_inverse;
}

inline const mjtNum* crba_calls(bridge& x, std::size_t k) {
    const mjModel* m = x.m;
    mjData* d = x.d;
    mju_copy(d->qpos, &x.qpos[k * x.nq], m->nq);
    mj_kinematics(m, d);
    mj_comPos(m, d);
    mj_crb(m, d);
    return d->qM;
}

inline const mjtNum* aba_calls(bridge& x, std::size_t k) {
    const mjModel* m = x.m;
    mjData* d = x.d;
    mju_copy(d->qpos, &x.qpos[k * x.nq], m->nq);
    mju_copy(d->qvel, &x.qvel[k * x.nv], m->nv);
    mj_kinematics(m, d);
    mj_comPos(m, d);
    mj_crb(m, d);
    mj_factorM(m, d);
    mj_comVel(m, d);
    mj_rne(m, d, 0, d->qfrc_bias);
    mju_sub(d->qfrc_smooth, &x.qfrc[k * x.nv], d->qfrc_bias, m->nv);
    mj_solveM(m, d, d->qacc, d->qfrc_smooth, 1);
    return d->qacc;
}

[[gnu::noinline]] const mjtNum* mujoco_chain_kernel_rnea(bridge& x, std::size_t k) { return rnea_calls(x, k); }
[[gnu::noinline]] const mjtNum* mujoco_chain_kernel_crba(bridge& x, std::size_t k) { return crba_calls(x, k); }
[[gnu::noinline]] const mjtNum* mujoco_chain_kernel_aba(bridge& x, std::size_t k) { return aba_calls(x, k); }

using kernel = const mjtNum* (*)(bridge&, std::size_t);

void add(std::vector<entry>& table, const std::string& name, const std::shared_ptr<bridge>& p, kernel f) {
    table.push_back({name,
                     [p, f](benchmark::State& st) {
                         const std::size_t n = p->states;
                         std::size_t k = 0;
                         for (auto _ : st) {
                             const mjtNum* r = f(*p, k);
                             benchmark::DoNotOptimize(r);
                             if (++k == n) k = 0;
                         }
                     },
                     [p, f](std::size_t calls) {
                         const std::size_t n = p->states;
                         for (std::size_t i = 0; i < calls; ++i) {
                             const mjtNum* r = f(*p, i % n);
                             benchmark::DoNotOptimize(r);
                         }
                     }});
}

double relative_error(const std::vector<double>& x, const std::vector<double>& ref) {
    double e = 0, scale = 0;
    for (std::size_t i = 0; i < ref.size(); ++i) {
        e = std::max(e, std::abs(x[i] - ref[i]));
        scale = std::max(scale, std::abs(ref[i]));
    }
    return std::isfinite(e) ? e / (scale > 0 ? scale : 1.0) : INFINITY;
}

}  // namespace

void add_mujoco(std::vector<entry>& table, const mujoco_case& c) {
    const std::string who = cat("ctga_chains_bench: mujoco ", c.label);
    const auto refuse = [&](const std::string& why) { std::fprintf(stderr, "%s: %s; its MuJoCo rows are not registered\n", who.c_str(), why.c_str()); };
    if (c.bodies.empty() || c.q.empty()) return;  // (a case without MuJoCo)
    for (std::size_t i = 0; i < c.bodies.size(); ++i) {
        const mujoco_body& b = c.bodies[i];
        if (b.joint == mujoco_joint::unsupported) return refuse(cat("body ", i, "'s joint has no MuJoCo counterpart here"));
        if (b.joint == mujoco_joint::free && b.parent >= 0)
            return refuse(cat("body ", i, " floats on another body (MuJoCo's free joints hang from the world)"));
    }

    // the model
    const std::string xml = mjcf(c.label, c.bodies, c.gravity);
    keep_xml(c.label, xml);
    auto x = std::make_shared<bridge>();
    std::string error;
    x->m = bench::load_mjcf(xml, cat("ctga_", c.label, ".xml"), error);
    if (!x->m) return refuse(cat("mj_loadXML: ", error));
    x->d = mj_makeData(x->m);
    x->nq = static_cast<std::size_t>(x->m->nq);
    x->nv = static_cast<std::size_t>(x->m->nv);
    if (x->nq != c.nq || x->nv != c.nv)
        return refuse(cat("MuJoCo's model has nq ", x->nq, ", nv ", x->nv, "; ctga's ", c.nq, ", ", c.nv));
    std::size_t cq = 0, cv = 0;
    for (std::size_t i = 0; i < c.bodies.size(); ++i) {
        const mujoco_body& b = c.bodies[i];
        const int id = mj_name2id(x->m, mjOBJ_BODY, cat("b", i).c_str());
        const int jnt = id < 0 ? -1 : x->m->body_jntadr[id];
        place p{b.joint, cq, cv, 0, 0, b.t};
        if (b.joint != mujoco_joint::fixed) {
            if (jnt < 0) return refuse(cat("body b", i, " or its joint is missing from MuJoCo's model"));
            p.qadr = static_cast<std::size_t>(x->m->jnt_qposadr[jnt]);
            p.dadr = static_cast<std::size_t>(x->m->jnt_dofadr[jnt]);
        }
        const std::size_t nq = b.joint == mujoco_joint::free ? 7 : b.joint == mujoco_joint::fixed ? 0 : 1;
        const std::size_t nv = b.joint == mujoco_joint::free ? 6 : b.joint == mujoco_joint::fixed ? 0 : 1;
        cq += nq;
        cv += nv;
        x->places.push_back(p);
    }

    // the states in MuJoCo's coordinates
    const std::size_t S = c.q.size(), nq = x->nq, nv = x->nv;
    x->states = S;
    x->qpos.assign(S * nq, 0.0);
    x->qvel.assign(S * nv, 0.0);
    x->qacc.assign(S * nv, 0.0);
    x->qfrc.assign(S * nv, 0.0);
    std::vector<double> T, bias;
    for (std::size_t s = 0; s < S; ++s) {
        for (const place& p : x->places) {
            if (p.joint == mujoco_joint::free) {
                for (std::size_t k = 0; k < 3; ++k) x->qpos[s * nq + p.qadr + k] = p.t[k] + c.q[s][p.cq + k];
                for (std::size_t k = 3; k < 7; ++k) x->qpos[s * nq + p.qadr + k] = c.q[s][p.cq + k];
            } else if (p.joint != mujoco_joint::fixed) {
                x->qpos[s * nq + p.qadr] = c.q[s][p.cq];
            }
        }
        velocity_map(*x, c, s, T, bias);
        const std::vector<double> qvel = apply(T, c.qd[s], nv, false), qacc = apply(T, c.qdd[s], nv, false),
                                  qfrc = apply(T, c.tau[s], nv, false);
        for (std::size_t k = 0; k < nv; ++k) {
            x->qvel[s * nv + k] = qvel[k];
            x->qacc[s * nv + k] = qacc[k] + bias[k];
            x->qfrc[s * nv + k] = qfrc[k];
        }
    }

    // the check, by the timed calls
    double e_rnea = 0, e_crba = 0, e_aba = 0;
    std::vector<double> M(nv * nv), H(nv * nv), out(nv);
    for (std::size_t s = 0; s < S; ++s) {
        velocity_map(*x, c, s, T, bias);
        if (!c.tau_ref.empty()) {
            const mjtNum* r = rnea_calls(*x, s);
            e_rnea = std::max(e_rnea, relative_error(apply(T, std::vector<double>(r, r + nv), nv, true), c.tau_ref[s]));
        }
        if (!c.H_ref.empty()) {
            mj_fullM(x->m, M.data(), crba_calls(*x, s));
            for (std::size_t i = 0; i < nv; ++i)  // H = Tᵀ M T
                for (std::size_t j = 0; j < nv; ++j) {
                    double h = 0;
                    for (std::size_t a = 0; a < nv; ++a) {
                        const double Tai = T[a * nv + i];
                        if (Tai == 0) continue;
                        for (std::size_t b = 0; b < nv; ++b) h += Tai * M[a * nv + b] * T[b * nv + j];
                    }
                    H[i * nv + j] = h;
                }
            e_crba = std::max(e_crba, relative_error(H, c.H_ref[s]));
        }
        if (!c.qdd_ref.empty()) {
            const mjtNum* r = aba_calls(*x, s);
            for (std::size_t k = 0; k < nv; ++k) out[k] = r[k] - bias[k];
            e_aba = std::max(e_aba, relative_error(apply(T, out, nv, true), c.qdd_ref[s]));
        }
    }
    const auto shown = [](bool present, double e) {
        char b[32];
        std::snprintf(b, sizeof b, "%.1e", e);
        return present ? std::string(b) : std::string("-");
    };
    std::fprintf(stderr, "%s (MuJoCo %s): max relative error against ctga over %zu states: rnea %s, crba %s, aba %s\n", who.c_str(),
                 mj_versionString(), S, shown(!c.tau_ref.empty(), e_rnea).c_str(), shown(!c.H_ref.empty(), e_crba).c_str(),
                 shown(!c.qdd_ref.empty(), e_aba).c_str());
    if (!(e_rnea <= tolerance && e_crba <= tolerance && e_aba <= tolerance)) {
        return refuse(cat("MuJoCo's model differs from ctga's (an error above ", tolerance, ")"));
    }

    // the rows
    if (!c.tau_ref.empty()) add(table, cat("rnea_", c.label, "/mujoco"), x, mujoco_chain_kernel_rnea);
    if (!c.H_ref.empty()) add(table, cat("crba_", c.label, "/mujoco"), x, mujoco_chain_kernel_crba);
    if (!c.qdd_ref.empty()) add(table, cat("aba_", c.label, "/mujoco"), x, mujoco_chain_kernel_aba);
}

// ---- a robot that touches (contact_step_<label>/mujoco) -----------------------------------------

namespace {
struct contact_bridge {
    mjModel* m = nullptr;
    mjData* d = nullptr;
    std::vector<int> qadr, dadr;  // the hinges' and slides', in the scenario's order
    std::vector<double> target;
    std::vector<int> shapes;      // geom ids
    double kp = 0;
    contact_bridge() = default;
    contact_bridge(const contact_bridge&) = delete;
    contact_bridge& operator=(const contact_bridge&) = delete;
    ~contact_bridge() {
        if (d) mj_deleteData(d);
        if (m) mj_deleteModel(m);
    }
};
// One step: the PD's torques as applied forces, then mj_step (collision, the constraint solve,
// Euler with implicit damping).
[[gnu::noinline]] void mujoco_contact_kernel_step(contact_bridge& x) {
    for (std::size_t j = 0; j < x.qadr.size(); ++j)
        x.d->qfrc_applied[x.dadr[j]] = x.kp * (x.target[j] - x.d->qpos[x.qadr[j]]);
    mj_step(x.m, x.d);
}
}  // namespace

void add_mujoco_contact(std::vector<entry>& table, const contact_scenario& s) {
    const std::string who = cat("ctga_chains_bench: mujoco contact_step_", s.label);
    const std::string xml = mjcf(s.label, s.bodies, s.gravity, &s);
    keep_xml(cat("contact_", s.label), xml);
    auto x = std::make_shared<contact_bridge>();
    std::string error;
    x->m = bench::load_mjcf(xml, cat("ctga_contact_", s.label, ".xml"), error);
    if (!x->m) {
        std::fprintf(stderr, "%s: mj_loadXML: %s; the row is not registered\n", who.c_str(), error.c_str());
        return;
    }
    x->d = mj_makeData(x->m);
    x->kp = s.kp;
    std::size_t actuated = 0, free = 0;
    for (std::size_t i = 0; i < s.bodies.size(); ++i) {
        const int jnt = x->m->body_jntadr[mj_name2id(x->m, mjOBJ_BODY, cat("b", i).c_str())];
        if (s.bodies[i].joint == mujoco_joint::free) {
            const int a = x->m->jnt_qposadr[jnt];
            for (std::size_t k = 0; k < 7; ++k) x->d->qpos[a + static_cast<int>(k)] = s.free_start[free][k];
            ++free;
        } else if (s.bodies[i].joint == mujoco_joint::hinge || s.bodies[i].joint == mujoco_joint::slide) {
            x->qadr.push_back(x->m->jnt_qposadr[jnt]);
            x->dadr.push_back(x->m->jnt_dofadr[jnt]);
            x->target.push_back(s.target[actuated]);
            x->d->qpos[x->qadr.back()] = s.target[actuated++];
        }
    }
    for (std::size_t f = 0; f < s.shapes.size(); ++f) x->shapes.push_back(mj_name2id(x->m, mjOBJ_GEOM, cat("shape", f).c_str()));
    const int held = s.held >= 0 ? mj_name2id(x->m, mjOBJ_BODY, cat("b", s.held).c_str()) : -1;
    contact_figures fig;
    for (std::size_t n = 0; n < s.settle + s.measure; ++n) {
        mujoco_contact_kernel_step(*x);
        if (n < s.settle) continue;
        mj_forward(x->m, x->d);  // (the new state's positions, velocities and contacts)
        if (held >= 0) {
            mjtNum v[6];
            mj_objectVelocity(x->m, x->d, mjOBJ_BODY, held, v, 0);
            fig.slip = std::max(fig.slip, std::sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5]));
            for (int c = 0; c < x->d->ncon; ++c) fig.sinking = std::max(fig.sinking, -x->d->contact[c].dist);
            continue;
        }
        for (std::size_t f = 0; f < x->shapes.size(); ++f) {
            mjtNum v[6];
            mj_objectVelocity(x->m, x->d, mjOBJ_GEOM, x->shapes[f], v, 0);  // (ω, v) at the centre, world axes
            const double r = s.shapes[f].radius;
            fig.slip = std::max(fig.slip, std::hypot(v[3] - r * v[1], v[4] + r * v[0]));
            fig.sinking = std::max(fig.sinking, r - x->d->geom_xpos[3 * x->shapes[f] + 2]);
        }
    }
    std::fprintf(stderr, "%s (MuJoCo %s, h %g s, its defaults): after %zu steps, over %zu: %s %.1e m/s, %s %.1e m\n", who.c_str(),
                 mj_versionString(), s.h, s.settle, s.measure, held >= 0 ? "the held body's speed" : "slip", fig.slip,
                 held >= 0 ? "deepest overlap" : "sinking", fig.sinking);
    table.push_back({cat("contact_step_", s.label, "/mujoco"),
                     [x](benchmark::State& st) {
                         for (auto _ : st) mujoco_contact_kernel_step(*x);
                     },
                     [x](std::size_t calls) {
                         for (std::size_t i = 0; i < calls; ++i) mujoco_contact_kernel_step(*x);
                     }});
}

}  // namespace bench::chains
