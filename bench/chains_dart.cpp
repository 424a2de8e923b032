// DART 6.12 on a contact scenario (chains_dart.hpp): contact_step_<label>/dart times one
// World::step of the robot standing on the ground under the scenario's PD controller: DART's
// collision detection (all shape pairs of the world), the contact constraints' boxed LCP and the
// semi-implicit Euler step, the PD torques set before it (World::step clears them after).
//
// The model, from the scenario's numbers (as chains_mujoco.cpp's MJCF): one Skeleton, a body node
// per body in index order, each on its joint to its parent: a FreeJoint (a root's floating joint),
// a RevoluteJoint (PrismaticJoint) along the body's axis, a WeldJoint for a fixed one; the joint's
// frame in the parent at the body's t, rotation identity, and the child body's frame on the joint
// frame. Inertia(mass, com, I_c): I_c about the centre of mass, body axes. The shapes are
// ShapeNodes with the collision and dynamics aspects at their centres (spheres, boxes of full
// extents 2 half), friction coefficient mu (both tangent directions). The ground is a second
// Skeleton, a body welded to the world carrying a 20 × 20 × 1 m box whose top face is the plane
// z = 0: DART 6.12's own collision detector (DARTCollisionDetector, set on the world's
// constraint solver) has sphere–box but no sphere–plane; the world's default detector, FCL's,
// replaces spheres by meshes (its PrimitiveShape is MESH by default), and setting it otherwise
// needs FCL's headers and libraries here. Gravity and the step h are the scenario's. The joints'
// damping is DART's damping coefficient, integrated implicitly (h d is added to each joint's
// projected articulated inertia); no springs, limits, armature or Coulomb joint friction. The
// contacts are DART's defaults: the world's BoxedLcpConstraintSolver (Dantzig's boxed LCP,
// projected Gauss–Seidel if it fails), friction along two tangent directions each bounded by the
// coefficient times the normal impulse (the two shapes' coefficients combined by DART: both are
// mu here), restitution 0, a contact reported only at positive depth, the penetration corrected
// by the error reduction parameter (ERP, its velocity capped) with constraint force mixing: their
// values are printed on stderr.
//
// Coordinates. DART's FreeJoint positions are the joint's transform (exponential coordinates of
// its rotation, then its translation in the parent frame); its velocities are the child body's
// twist in its own frame, angular first, the linear part the velocity of the body origin: ctga's
// (ω_b, v_b). Hinges and slides: DART's coordinate is ctga's. DART's dof order is mapped to
// ctga's through each joint's dof indices.
//
// The check, before the row: the total mass against the bodies' sum; on every state of the
// reference, DART's mass matrix (Skeleton::getMassMatrix) against ctga's H and
// M q̈ + C(q, q̇) + g (getCoriolisAndGravityForces) against ctga's τ (chains_constrained.cpp's dart_reference), as
// max |x − ref| / max |ref|; above 1e-10 the row is not registered.
//
// The figures: after `settle` steps, over `measure` more, each sphere's slip (the horizontal
// speed of its material point at the bottom, centre − r ẑ) and sinking (r − its centre's height),
// the largest of each: add_mujoco_contact's definitions. On the quadruped DART's ERP pushes the
// feet out of the box until a foot's depth reaches zero; that step the detector reports no contact
// for it, the loaded leg moves freely for one step (the foot's bottom at about 0.24 m/s, 0.7 mm
// down), and the contact returns 0.7 mm deep: the slip figure is such a step.
//
// Built for the x86-64 baseline, as libdart is (bench/CMakeLists.txt: Eigen's layout and heap).
#include "chains_dart.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <benchmark/benchmark.h>
#include <dart/collision/dart/DARTCollisionDetector.hpp>
#include <dart/config.hpp>
#include <dart/constraint/BoxedLcpConstraintSolver.hpp>
#include <dart/constraint/BoxedLcpSolver.hpp>
#include <dart/constraint/ContactConstraint.hpp>
#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/BoxShape.hpp>
#include <dart/dynamics/FreeJoint.hpp>
#include <dart/dynamics/Inertia.hpp>
#include <dart/dynamics/PrismaticJoint.hpp>
#include <dart/dynamics/RevoluteJoint.hpp>
#include <dart/dynamics/ShapeNode.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/dynamics/SphereShape.hpp>
#include <dart/dynamics/WeldJoint.hpp>
#include <dart/simulation/World.hpp>

namespace bench::chains {

namespace {

namespace dd = dart::dynamics;

constexpr double tolerance = 1e-10;

template <class... A>
std::string cat(const A&... a) {
    std::ostringstream out;
    (out << ... << a);
    return out.str();
}

Eigen::Vector3d vec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

// max |x − ref| / max |ref|, as chains_mujoco.cpp's
double relative_error(const Eigen::VectorXd& x, const Eigen::VectorXd& ref) {
    double e = 0, scale = 0;
    for (Eigen::Index i = 0; i < ref.size(); ++i) {
        e = std::max(e, std::abs(x[i] - ref[i]));
        scale = std::max(scale, std::abs(ref[i]));
    }
    return std::isfinite(e) ? e / (scale > 0 ? scale : 1.0) : INFINITY;
}

struct dart_bridge {
    dart::simulation::WorldPtr world;
    dd::SkeletonPtr robot;
    std::vector<std::size_t> dofs;  // the hinges' and slides' DART dofs, in the scenario's order
    std::vector<double> target;
    std::vector<dd::ShapeNode*> shapes;
    double kp = 0;
};

// One step: the PD's torques as joint forces, then World::step (collision, the contact LCP, the
// Euler step with implicit damping; the forces cleared).
[[gnu::noinline]] void dart_contact_kernel_step(dart_bridge& x) {
    for (std::size_t j = 0; j < x.dofs.size(); ++j)
        x.robot->setForce(x.dofs[j], x.kp * (x.target[j] - x.robot->getPosition(x.dofs[j])));
    x.world->step();
}

// The robot's Skeleton (the top); dof[k]: DART's index of ctga's velocity number k.
dd::SkeletonPtr skeleton_of(const contact_scenario& s, std::vector<std::size_t>& dof) {
    dd::SkeletonPtr skel = dd::Skeleton::create(cat("ctga_", s.label));
    std::vector<dd::BodyNode*> nodes;
    dof.clear();
    for (std::size_t i = 0; i < s.bodies.size(); ++i) {
        const mujoco_body& b = s.bodies[i];
        dd::BodyNode* parent = b.parent < 0 ? nullptr : nodes[static_cast<std::size_t>(b.parent)];
        dd::BodyNode::Properties body;
        body.mName = cat("b", i);
        Eigen::Matrix3d Ic;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) Ic(r, c) = b.Ic[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)];
        body.mInertia = dd::Inertia(b.mass, vec(b.com), Ic);
        Eigen::Isometry3d at = Eigen::Isometry3d::Identity();
        at.translation() = vec(b.t);
        const auto with = [&](auto props) {
            props.mName = cat("j", i);
            props.mT_ParentBodyToJoint = at;
            return props;
        };
        dd::Joint* joint = nullptr;
        dd::BodyNode* node = nullptr;
        if (b.joint == mujoco_joint::free) {
            std::tie(joint, node) = skel->createJointAndBodyNodePair<dd::FreeJoint>(parent, with(dd::FreeJoint::Properties()), body);
        } else if (b.joint == mujoco_joint::hinge) {
            dd::RevoluteJoint::Properties p = with(dd::RevoluteJoint::Properties());
            p.mAxis = vec(b.axis);
            std::tie(joint, node) = skel->createJointAndBodyNodePair<dd::RevoluteJoint>(parent, p, body);
        } else if (b.joint == mujoco_joint::slide) {
            dd::PrismaticJoint::Properties p = with(dd::PrismaticJoint::Properties());
            p.mAxis = vec(b.axis);
            std::tie(joint, node) = skel->createJointAndBodyNodePair<dd::PrismaticJoint>(parent, p, body);
        } else {
            std::tie(joint, node) = skel->createJointAndBodyNodePair<dd::WeldJoint>(parent, with(dd::WeldJoint::Properties()), body);
        }
        for (std::size_t k = 0; k < joint->getNumDofs(); ++k) {
            dof.push_back(joint->getIndexInSkeleton(k));
            if (b.joint != mujoco_joint::free) joint->setDampingCoefficient(k, s.damping);
        }
        nodes.push_back(node);
    }
    return skel;
}

// Sets the robot's state from q, qd in mujoco_case's coordinates.
void set_state(dd::Skeleton& skel, const contact_scenario& s, const std::vector<std::size_t>& dof, const std::vector<double>& q,
               const std::vector<double>& qd) {
    Eigen::VectorXd pos = skel.getPositions(), vel = skel.getVelocities();
    std::size_t cq = 0, cv = 0;
    for (std::size_t i = 0; i < s.bodies.size(); ++i) {
        if (s.bodies[i].joint == mujoco_joint::free) {
            Eigen::Isometry3d g = Eigen::Isometry3d::Identity();
            g.linear() = Eigen::Quaterniond(q[cq + 3], q[cq + 4], q[cq + 5], q[cq + 6]).normalized().toRotationMatrix();
            g.translation() = Eigen::Vector3d(q[cq], q[cq + 1], q[cq + 2]);
            const Eigen::Vector6d p = dd::FreeJoint::convertToPositions(g);
            for (std::size_t k = 0; k < 6; ++k) {
                pos[static_cast<Eigen::Index>(dof[cv + k])] = p[static_cast<Eigen::Index>(k)];
                vel[static_cast<Eigen::Index>(dof[cv + k])] = qd.empty() ? 0.0 : qd[cv + k];
            }
            cq += 7, cv += 6;
        } else if (s.bodies[i].joint != mujoco_joint::fixed) {
            pos[static_cast<Eigen::Index>(dof[cv])] = q[cq];
            vel[static_cast<Eigen::Index>(dof[cv])] = qd.empty() ? 0.0 : qd[cv];
            ++cq, ++cv;
        }
    }
    skel.setPositions(pos);
    skel.setVelocities(vel);
}

}  // namespace

void add_dart_contact(std::vector<entry>& table, const contact_scenario& s, const mujoco_case& reference) {
    const std::string who = cat("ctga_chains_bench: dart contact_step_", s.label);
    const auto refuse = [&](const std::string& why) { std::fprintf(stderr, "%s: %s; the row is not registered\n", who.c_str(), why.c_str()); };
    if (s.held >= 0) return refuse("a held body (not built here)");
    for (std::size_t i = 0; i < s.bodies.size(); ++i) {
        const mujoco_body& b = s.bodies[i];
        if (b.joint == mujoco_joint::unsupported) return refuse(cat("body ", i, "'s joint has no DART counterpart here"));
        if (i > 0 && b.parent < 0) return refuse("more than one tree (not built here)");
    }

    auto x = std::make_shared<dart_bridge>();
    std::vector<std::size_t> dof;  // ctga's velocity number → DART's dof
    x->robot = skeleton_of(s, dof);
    x->robot->setGravity(vec(s.gravity));
    for (std::size_t f = 0; f < s.shapes.size(); ++f) {
        const body_shape& g = s.shapes[f];
        const dd::ShapePtr shape = g.half[0] > 0 ? dd::ShapePtr(std::make_shared<dd::BoxShape>(2 * vec(g.half)))
                                                 : dd::ShapePtr(std::make_shared<dd::SphereShape>(g.radius));
        dd::ShapeNode* n =
            x->robot->getBodyNode(g.body)->createShapeNodeWith<dd::CollisionAspect, dd::DynamicsAspect>(shape, cat("shape", f));
        n->setRelativeTranslation(vec(g.at));
        n->getDynamicsAspect()->setFrictionCoeff(s.mu);
        x->shapes.push_back(n);
    }

    // the check
    double total = 0;
    for (const mujoco_body& b : s.bodies) total += b.mass;
    const double e_mass = std::abs(x->robot->getMass() - total) / total;
    const Eigen::Index nv = static_cast<Eigen::Index>(x->robot->getNumDofs());
    double e_crba = 0, e_rnea = 0;
    for (std::size_t k = 0; k < reference.q.size(); ++k) {
        set_state(*x->robot, s, dof, reference.q[k], reference.qd[k]);
        const Eigen::MatrixXd& M = x->robot->getMassMatrix();
        Eigen::VectorXd H(nv * nv), H_ref(nv * nv), qdd(nv), tau_ref(nv);
        for (Eigen::Index i = 0; i < nv; ++i) {
            const Eigen::Index di = static_cast<Eigen::Index>(dof[static_cast<std::size_t>(i)]);
            for (Eigen::Index j = 0; j < nv; ++j) {
                H[i * nv + j] = M(di, static_cast<Eigen::Index>(dof[static_cast<std::size_t>(j)]));
                H_ref[i * nv + j] = reference.H_ref[k][static_cast<std::size_t>(i * nv + j)];
            }
            qdd[di] = reference.qdd[k][static_cast<std::size_t>(i)];
            tau_ref[di] = reference.tau_ref[k][static_cast<std::size_t>(i)];
        }
        e_crba = std::max(e_crba, relative_error(H, H_ref));
        e_rnea = std::max(e_rnea, relative_error(M * qdd + x->robot->getCoriolisAndGravityForces(), tau_ref));
    }
    std::fprintf(stderr,
                 "ctga_chains_bench: dart %s (DART %s): total mass %.6g kg, relative error %.1e; max relative error against ctga over %zu "
                 "states: H (crba) %.1e, M q'' + C + g (rnea) %.1e\n",
                 s.label.c_str(), DART_VERSION, x->robot->getMass(), e_mass, reference.q.size(), e_crba, e_rnea);
    if (reference.q.empty() || !(e_mass <= tolerance && e_crba <= tolerance && e_rnea <= tolerance))
        return refuse(cat("DART's model differs from ctga's (an error above ", tolerance, ") or was not checked"));

    // the world
    x->world = dart::simulation::World::create(cat("ctga_contact_", s.label));
    x->world->setGravity(vec(s.gravity));
    x->world->setTimeStep(s.h);
    x->world->getConstraintSolver()->setCollisionDetector(dart::collision::DARTCollisionDetector::create());
    const dd::SkeletonPtr ground = dd::Skeleton::create("ground");
    dd::BodyNode* floor = ground->createJointAndBodyNodePair<dd::WeldJoint>().second;
    dd::ShapeNode* slab =
        floor->createShapeNodeWith<dd::CollisionAspect, dd::DynamicsAspect>(std::make_shared<dd::BoxShape>(Eigen::Vector3d(20, 20, 1)));
    slab->setRelativeTranslation(Eigen::Vector3d(0, 0, -0.5));
    slab->getDynamicsAspect()->setFrictionCoeff(s.mu);
    x->world->addSkeleton(ground);
    x->world->addSkeleton(x->robot);

    // the start: the free joints at free_start (ctga's motor: translation, quaternion), the hinges
    // and slides at their targets, at rest
    std::vector<double> q0;
    std::size_t free = 0, actuated = 0, cv = 0;
    for (const mujoco_body& b : s.bodies) {
        if (b.joint == mujoco_joint::free) {
            q0.insert(q0.end(), s.free_start[free].begin(), s.free_start[free].end());
            ++free, cv += 6;
        } else if (b.joint != mujoco_joint::fixed) {
            x->dofs.push_back(dof[cv++]);
            x->target.push_back(s.target[actuated]);
            q0.push_back(s.target[actuated++]);
        }
    }
    set_state(*x->robot, s, dof, q0, {});
    x->kp = s.kp;

    contact_figures fig;
    for (std::size_t n = 0; n < s.settle + s.measure; ++n) {
        dart_contact_kernel_step(*x);
        if (n < s.settle) continue;
        for (std::size_t f = 0; f < x->shapes.size(); ++f) {
            // the centre's velocity (ω, v), world axes
            const Eigen::Vector3d w = x->shapes[f]->getAngularVelocity(), v = x->shapes[f]->getLinearVelocity();
            const double r = s.shapes[f].radius;
            fig.slip = std::max(fig.slip, std::hypot(v[0] - r * w[1], v[1] + r * w[0]));
            fig.sinking = std::max(fig.sinking, r - x->shapes[f]->getWorldTransform().translation()[2]);
        }
    }
    const auto* boxed = dynamic_cast<const dart::constraint::BoxedLcpConstraintSolver*>(x->world->getConstraintSolver());
    using contact = dart::constraint::ContactConstraint;
    std::fprintf(stderr,
                 "%s (DART %s, h %g s, collision detector %s, otherwise its defaults: %s, ERP %g, max ERV %g m/s, CFM %g, allowance %g m): "
                 "after %zu steps, over %zu: slip %.1e m/s, sinking %.1e m\n",
                 who.c_str(), DART_VERSION, s.h, x->world->getConstraintSolver()->getCollisionDetector()->getType().c_str(),
                 boxed ? boxed->getBoxedLcpSolver()->getType().c_str() : "?", contact::getErrorReductionParameter(),
                 contact::getMaxErrorReductionVelocity(), contact::getConstraintForceMixing(), contact::getErrorAllowance(), s.settle,
                 s.measure, fig.slip, fig.sinking);
    table.push_back({cat("contact_step_", s.label, "/dart"),
                     [x](benchmark::State& st) {
                         for (auto _ : st) dart_contact_kernel_step(*x);
                     },
                     [x](std::size_t calls) {
                         for (std::size_t i = 0; i < calls; ++i) dart_contact_kernel_step(*x);
                     }});
}

}  // namespace bench::chains
