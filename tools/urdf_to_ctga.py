#!/usr/bin/env python3
"""URDF -> C++: a robot's joint tree as a ctga::chains tree type and a function building its
parameters (a ctga::chains::model), its joint limits and its collision geometry, in one header.

    python3 tools/urdf_to_ctga.py robot.urdf --name arm7 -o arm7.hpp
    python3 tools/urdf_to_ctga.py dog.urdf --name dog --floating-base --gravity 0 0 -9.81
    python3 tools/urdf_to_ctga.py romeo.urdf --name romeo --floating-base --massless lock

The header declares, in namespace NAME (or --namespace):

    using tree = ctga::chains::tree<ctga::chains::link<parent, joint>, ...,          // the bodies
                                    ctga::chains::fixed_frame<"link", body>, ...>;   // every URDF link
    inline constexpr std::array<std::string_view, tree::size> body_names{...};   // URDF link names
    inline constexpr std::array<std::string_view, tree::size> joint_names{...};  // URDF joint names
    template <class T = double>
    constexpr ctga::checked<ctga::chains::model<tree, T>> make_model() noexcept;
    template <class T = double>
    constexpr ctga::checked<ctga::chains::joint_limits<tree, T>> make_limits() noexcept;
    // and, when the robot has collision shapes (K of them; below):
    template <class T>
    using collision_shape = ctga::collision::shape<...>;  // the kinds present: sphere, box, cylinder, convex_hull
    inline constexpr std::size_t collision_count = K;
    inline constexpr std::array<std::string_view, collision_count> collision_links{...};  // each shape's link
    template <class T = double>
    constexpr ctga::checked<ctga::constrained::robot_geometry<tree, collision_shape<T>, T, collision_count>>
    make_geometry() noexcept;

How URDF maps onto ctga::chains (include/ctga/chains/tree.hpp, joints.hpp):
  * Bodies. A body is a link on a moving joint (revolute, continuous, prismatic, floating, planar;
    planar gives three bodies, below), plus the root link with --floating-base. Bodies are numbered
    depth first over the links from the root, children in document order (a merged link's children
    in its place); body_names[i] is body i's own URDF link and joint_names[i] the joint joining it
    to its parent body (parent -1: the world).
  * Frames. A URDF child link's frame is the joint frame moved by the joint, which is ctga's body
    frame; the joint's <origin xyz rpy> is the body's placement in its parent link's frame at q = 0
    (R = Rz(yaw) Ry(pitch) Rx(roll); emitted as a translation and an axis-angle rotation).
  * Fixed joints are merged (the default). A link on a fixed joint is lumped into its nearest
    moving ancestor's body; with a fixed base, links fixed (directly or through other fixed links)
    to the root are lumped into the world. The placement of such a link in its body's frame is the
    composition of the fixed joints' origins (composed exactly, through quaternions); the children
    of a merged link are placed through it. The body's mass properties are the exact sum, in the
    body frame: total mass m = sum m_k, centre of mass c = sum m_k c_k / m, and the inertia about c
    by the parallel-axis theorem, I = sum R_k I_k R_k^T + m_k (|d_k|^2 1 - d_k d_k^T), d_k = c_k - c
    (c_k, R_k: link k's centre of mass and axes in the body frame; the diagonal's |d|^2 - d_a^2 is
    summed as the other two squares, which do not cancel when d lies far along axis a). A link
    without <inertial> adds nothing; a link of mass 0 adds its tensor R_k I_k R_k^T and nothing else
    (no parallel-axis term, no share of the centre of mass: as Pinocchio does). Inertia lumped into
    the world is dropped (the header lists those links). --keep-fixed instead keeps every link on a
    fixed joint as its own body on a `fixed` joint (its own mass properties).
  * Every URDF link is a named frame: after the bodies, the tree lists
    fixed_frame<"link", body> for every link, depth first with the root first; body is the body the
    link belongs to (-1: the world) and make_model sets m.frames[k] to the link's placement in that
    body's frame (identity for a body's own link; the composed fixed origins for a merged link).
  * Joints. revolute and continuous -> revolute_x/_y/_z when the normalised <axis> is exactly +x,
    +y or +z, revolute<axis::minus_x/_y/_z> when it is exactly -x, -y or -z, else revolute_about
    with the normalised axis (passed to make_link); prismatic likewise -> prismatic_x/_y/_z,
    prismatic<axis::minus_...> or prismatic_along; fixed -> fixed (--keep-fixed only); floating ->
    floating (q: the 8 coefficients of a motor; v: the body screw); the URDF default axis is 1 0 0.
    A body whose placement does not turn (its joint's rpy 0 0 0, and those of the fixed joints merged
    on the way, composed exactly) gets its joint as aligned<Joint> (mimic<aligned<Joint>, M> for
    a mimic, aligned<with_armature<Joint>> with an armature): its map's rotation is the joint's
    own, whose zeros the algorithms skip. One turned by multiples of pi/2 (each rpy angle k pi/2 to
    the rounding of its written digits, 1e-4 or finer: "1.57079632679", "3.141592653589793"; the
    turn made exact, and composed exactly with the merged fixed joints') gets
    turned<turn{axes}, Joint>, axes the joint frame's x, y, z axes in the parent's
    (turn{axis::minus_z, axis::y, axis::x}): its rotation is the joint's own with rows moved and
    negated, skipped as an aligned joint's. Other rotations: the joint alone (a general placement).
  * planar (axis = the plane normal n) -> three bodies in a chain: prismatic along u1, prismatic
    along u2, revolute about n, (u1, u2, n) right-handed orthonormal. The first carries the joint's
    origin as its placement, the other two identity placements. The first two are massless virtual
    bodies named "<joint>_x" and "<joint>_y" (body and joint names; "_" appended while a name is
    taken by a link or joint); the third is the child link, on joint "<joint>". Velocities (x, y,
    theta). When n is a coordinate axis, u1 and u2 are too (n = +-e_k: u1 = e_(k+1), u2 = +-e_(k+2),
    indices mod 3; n = +z: prismatic_x, prismatic_y, revolute_z); else u1 is the coordinate axis
    least aligned with n, made orthogonal to n, and u2 = n x u1.
  * <mimic joint="master" multiplier="m" offset="o"/> (defaults m = 1, o = 0) -> mimic<Joint,
    MasterBody> with coupling<T>{m, o} passed to make_link: q = m q_master + o, no coordinate of
    its own; MasterBody is the master joint's body (before or after the mimic's own body in the
    depth-first order, as the tree has it). Errors (naming the joint): the master does not exist,
    is not revolute, continuous or prismatic, or is itself a mimic; a mimic on a joint that is not
    revolute, continuous or prismatic (on a fixed joint it is ignored with a warning: nothing
    moves). --mimic independent instead makes mimic joints ordinary independent joints (the <mimic>
    element is then ignored once its numbers parse). --mimic-missing independent does so only for
    a <mimic> naming a joint that does not exist (a warning names each; e.g. a hand whose <mimic>
    elements lost the prefix of their joints' names); the others stay coupled.
  * --floating-base: the root link becomes body 0 on a floating joint (identity placement) named
    after the root link (joint_names[0]; "_joint" appended if a URDF joint has that name). Without
    it the root link is the fixed world.
  * Mass properties. A link's <inertial>: mass, centre of mass = <origin xyz>, and the tensor about
    the centre of mass rotated into the link frame, I = R_rpy I_inertial R_rpy^T. A link without
    <inertial> is massless; a link of mass 0 keeps its tensor, as written (a warning says so: Bolt's
    feet, a motor's rotor). A body whose total mass is 0 is built as
    make_mass_properties(0, {0, 0, 0}, I, mass_check::as_given), I its mass-0 links' tensors (zero
    without them).
  * Moving joints with no inertia below them. As ctga::chains::massless_subtree (which make_model
    also ends with): a moving joint (mimic joints and a planar joint's virtual bodies count, and
    name their URDF joint) needs mass in its subtree (its body and every descendant), or an
    armature, or, for a joint that turns (revolute, continuous, a planar joint's rotation), a
    rotational inertia there (a mass-0 link's tensor); else the mass matrix would be singular and
    ABA would divide by zero. --massless chooses what happens to such joints:
      refuse (the default): an error naming the first (and counting the others) and the options;
      lock: each is locked at 0 (below), and a locked master takes its mimics along;
      armature=VALUE: each 1-dof joint gets the armature VALUE (kg m^2 revolute, kg prismatic); a
        mimic joint (no coordinate, so no armature) or a planar or floating joint is then an error
        naming it and the ways out (--massless lock, --lock JOINT, --mimic independent).
  * Locks: --lock JOINT[=VALUE] (repeatable) makes a moving joint fixed at VALUE (rad or m; the
    default is 0 clamped into its <limit>; a planar or floating joint locks at its origin and takes
    no VALUE; a VALUE outside <limit> warns). Its child link is then placed at its origin followed
    by the joint's motion at VALUE (a turn about or a slide along its axis) and merged like a link
    on a fixed joint (kept as a fixed body with --keep-fixed); every link stays a frame. The
    <mimic> joints of a locked master are locked at m VALUE + o; a mimic locked alone is fixed at
    m 0 + o by default and no longer follows its master (a warning). The header lists the locked
    joints, their values and why (--lock, --massless lock, following a master).
  * Armature: --armature JOINT=VALUE (repeatable; VALUE >= 0) gives a revolute, continuous or
    prismatic joint (not a mimic, not a locked joint) the rotor inertia VALUE: its joint is
    with_armature<J> (aligned<with_armature<J>>) in the tree type and make_model sets
    m.template link<i>().armature = T(VALUE) (added to the joint's diagonal entry of the mass
    matrix; VALUE 0 keeps the type, for an armature set at run time). The header lists the
    armatures. An option that names no joint, or names one twice, is an error naming it.
  * Inertia policy. Errors: malformed or non-finite numbers, negative mass, malformed XML.
    Warnings on stderr (physically questionable but common data), per URDF link whose inertia
    enters a body and per merged body (for the lumped tensor): principal moments that are not all
    positive (the tensor is not positive definite), principal moments that violate the triangle
    inequality I_i <= I_j + I_k, a mass-0 link with a nonzero tensor (kept; inertia lumped into the
    world is dropped, so not checked). The header repeats the warnings as comments. Tolerance: with
    tol = 64 eps (|Ixx| + |Iyy| + |Izz|) (eps = 2^-52, the tolerance of ctga's own check), a moment
    >= -tol and a triangle excess <= tol are rounding, not warned (e.g. -4e-22 for a thin rod's
    zero moment). Every body's mass properties are built with mass_check::as_given (the tool
    has checked finiteness and m >= 0), so such data loads. --strict turns every warning into an
    error and builds the bodies that have mass with the physical check (no as_given), so it also
    refuses a body whose lumped tensor is singular (a zero or rounding-level moment) as ctga's
    physical check would; massless bodies still use as_given (the physical check needs m > 0).
  * Limits. make_limits<T>() returns ctga::chains::joint_limits<tree, T> (chains/joint_limits.hpp),
    checked by check_limits: from unlimited<tree, T>(), each coordinate of a revolute, continuous
    or prismatic joint takes its <limit lower upper velocity effort> and <dynamics damping
    friction> numbers as written, a comment naming its joint. A missing attribute (or element) is no
    bound (+-infinity; the URDF spec's default 0 for lower and upper would pin the joint) or 0
    damping, friction; a continuous joint has no position bounds (its lower and upper are not
    read). Floating joints, the floating base and planar joints are unlimited (URDF defines no
    limits for them); mimic and locked joints have no coordinate: a comment says their limits are
    dropped. Errors naming the joint (only for revolute, continuous and prismatic joints, whose
    limits are read): lower > upper (revolute, prismatic), a negative velocity, effort, damping or
    friction, a malformed number, two <limit> or <dynamics>. (Refusing lower > upper, rather than
    dropping the bounds with a warning: the numbers are wrong, and check_limits would refuse them.)
  * Collision geometry. Every link's <collision> elements (<origin xyz rpy> optional, as a joint's)
    become make_geometry's shapes, link by link in frame order (depth first), a link's in document
    order; collision_links names each one's link. <sphere radius> -> collision::sphere<T>; <box
    size="x y z"> -> box<T> of half extents x/2, y/2, z/2; <cylinder radius length> ->
    cylinder<T> of half height length/2 (URDF's axis is its frame's z, as ctga's: no turn);
    <mesh filename scale> -> the convex hull of an STL file's vertices (binary or ASCII; filename
    relative to the URDF's directory, package://PKG/REST found as PKG/REST in the URDF's directory
    or the nearest of its parents that has it, file://PATH), scaled (a negative scale mirrors),
    as convex_hull<T, N> built by make_hull from its vertex list, N the most vertices of the hulls.
    The hull is exact (quickhull with exact orientation tests: the doubles as integers), its vertices
    the corners (points within a face or on an edge dropped, duplicates merged); a hull of more
    corners than --hull-vertices N (default 32; 4 to 8192, convex_hull's bound) is reduced to N of
    them (grown from its extreme four by the corner farthest outside, until N), with a warning
    stating the largest distance the reduced hull lies inside the true one (at a corner left out).
    Other mesh formats (.dae, .obj, ...), a missing or unreadable file, a mesh spanning no volume
    and a geometry URDF does not define (<capsule>) are warnings naming the link and the file, the
    element left out; --meshes omit leaves every mesh out (one warning counting them). Each shape
    is on its link's body at the link's placement there (a merged link's composed fixed origins,
    those of its frame) followed by the <origin>; a link in the world (a fixed base's root and the
    links merged into it) has its shapes left out with a warning (static surroundings are the
    caller's constrained::static_shape list). make_geometry<T>() makes each shape with ctga's
    checked constructor (make_sphere, make_box, make_cylinder, make_hull), attaches it
    (robot_geometry::attach: body, placement as a motor_map) and returns the first error. Errors
    naming the link: a radius, length or box size that is not positive, a zero mesh scale, a
    <geometry> without exactly one shape, a <mesh> without filename. --exclude-pair LINK_A,LINK_B
    (repeatable) and --srdf FILE (its <disable_collisions link1 link2>) add exclude(body a, body
    b) for the links' bodies, each pair of bodies once; a pair on one body (robot_geometry never
    tests a body against itself) or with a link in the world is dropped; a link the URDF does not
    have is an error. A robot without shapes gets none of this: the header is the same as without
    <collision> (only the warnings' comments added).
<safety_controller>, <calibration>, visuals, transmissions and Gazebo extensions are ignored.
Anything that cannot be represented (a joint type outside the URDF spec, a graph that is not a
tree, a massless moving subtree under --massless refuse) is an error: exit status 1 and a message
naming the element on stderr; no header is written.

Standard library only.
"""

import argparse
import heapq
import math
import os
import re
import struct
import sys
import xml.etree.ElementTree as ET

PROG = "urdf_to_ctga"
SUPPORTED_TYPES = ("revolute", "continuous", "prismatic", "fixed", "floating", "planar")
ONE_DOF = ("revolute", "continuous", "prismatic")
EPS = sys.float_info.epsilon


class UrdfError(Exception):
    """A URDF that cannot be converted; the message names the offending element."""


# ---- numbers ----------------------------------------------------------------------------------

# A decimal number as URDF writes it; float() alone would also take "nan", "inf", "1_0".
_NUMBER = re.compile(r"^[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?$")


def parse_number(text, where):
    if text is None:
        raise UrdfError(f"{where}: missing number")
    t = text.strip()
    if not _NUMBER.match(t):
        raise UrdfError(f"{where}: malformed number {text!r}")
    x = float(t)
    if not math.isfinite(x):
        raise UrdfError(f"{where}: number {text!r} is out of range")
    return x


def parse_vector(text, where, default=None):
    """Three numbers separated by white space, or `default` when the attribute is absent."""
    if text is None:
        if default is None:
            raise UrdfError(f"{where}: missing (three numbers expected)")
        return list(default)
    parts = text.split()
    if len(parts) != 3:
        raise UrdfError(f"{where}: {text!r} is not three numbers")
    return [parse_number(p, where) for p in parts]


# ---- rotations and placements -------------------------------------------------------------------


def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def transpose(a):
    return [[a[j][i] for j in range(3)] for i in range(3)]


def matvec(a, v):
    return [a[i][0] * v[0] + a[i][1] * v[1] + a[i][2] * v[2] for i in range(3)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def normalised(v):
    n = math.sqrt(dot(v, v))
    return [c / n for c in v]


def rotate_tensor(r, t):
    """R T R^T, exactly symmetric (the upper triangle mirrored)."""
    rt = matmul(r, matmul(t, transpose(r)))
    return [[rt[min(a, b)][max(a, b)] for b in range(3)] for a in range(3)]


def rpy_matrix(rpy):
    """URDF's fixed-axis roll, pitch, yaw: R = Rz(yaw) Ry(pitch) Rx(roll)."""
    r, p, y = rpy
    cr, sr, cp, sp, cy, sy = math.cos(r), math.sin(r), math.cos(p), math.sin(p), math.cos(y), math.sin(y)
    rx = [[1.0, 0.0, 0.0], [0.0, cr, -sr], [0.0, sr, cr]]
    ry = [[cp, 0.0, sp], [0.0, 1.0, 0.0], [-sp, 0.0, cp]]
    rz = [[cy, -sy, 0.0], [sy, cy, 0.0], [0.0, 0.0, 1.0]]
    return matmul(rz, matmul(ry, rx))


IDENTITY_Q = (1.0, 0.0, 0.0, 0.0)


def rpy_quaternion(rpy):
    """q = qz(yaw) qy(pitch) qx(roll) (w, x, y, z), whose half-angle products are exact to rounding
    at every angle (no acos of a trace); exactly the identity for rpy 0 0 0."""
    if list(rpy) == [0.0, 0.0, 0.0]:
        return IDENTITY_Q
    hr, hp, hy = (a / 2 for a in rpy)
    cr, sr, cp, sp, cy, sy = math.cos(hr), math.sin(hr), math.cos(hp), math.sin(hp), math.cos(hy), math.sin(hy)
    return (cr * cp * cy + sr * sp * sy, sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
            cr * cp * sy - sr * sp * cy)


def quat_mul(a, b):
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    return (aw * bw - ax * bx - ay * by - az * bz, aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx, aw * bz + ax * by - ay * bx + az * bw)


# The quaternions of the 24 rotations by multiples of pi/2 about coordinate axes (signed
# permutations): components 0, +-1/2, +-sqrt(1/2), +-1 in one of three patterns. A placement turned
# by one (to the rounding of the file's numbers) keeps these exact values, composes exactly, and
# becomes turned<turn{...}, Joint> in the tree (its rotation skipped as aligned joints' are).
QUARTER_VALUES = (0.0, 0.5, math.sqrt(0.5), 1.0)


def snap_quarter(q):
    """q as the exact quaternion of a signed permutation (sign chosen so that the first non-zero
    component is positive) when it is one to 1e-12, else None."""
    out = []
    for c in q:
        v = min(QUARTER_VALUES, key=lambda x: abs(abs(c) - x))
        if abs(abs(c) - v) > 1e-12:
            return None
        out.append(math.copysign(v, c) if v else 0.0)
    if sorted(abs(c) for c in out) not in ([0.0, 0.0, 0.0, 1.0], [0.0, 0.0, QUARTER_VALUES[2], QUARTER_VALUES[2]],
                                           [0.5, 0.5, 0.5, 0.5]):
        return None
    first = next(c for c in out if c)
    return tuple(-c if first < 0 and c else c for c in out)


def is_quarter(q):
    """Whether q is the exact quaternion of a signed permutation (snap_quarter's output)."""
    return snap_quarter(q) == tuple(q)


def quarter_turns(rpy, texts):
    """The quaternion of rpy when each angle is a multiple k pi/2 written to its digits: |angle - k pi/2|
    at most half a unit of its last written digit (and that unit 1e-4 or finer: "1.5708", not
    "1.57"), or two units of double's rounding; else None."""
    if texts is None:
        return None
    half_pi = math.pi / 2
    for a, text in zip(rpy, texts):
        k = round(a / half_pi)
        mantissa, _, exponent = text.lower().partition("e")
        decimals = len(mantissa.partition(".")[2]) - (int(exponent) if exponent else 0)
        rounding = 0.5 * 10.0 ** -decimals
        if rounding > 5e-5 and a != 0.0:
            return None
        if abs(a - k * half_pi) > max(rounding, 4 * EPS * abs(a)):
            return None
    return snap_quarter(rpy_quaternion([round(a / half_pi) * half_pi for a in rpy]))


def quat_matrix(q):
    """The rotation matrix of a unit quaternion (normalised here against accumulated rounding;
    exact for a signed permutation's)."""
    if q == IDENTITY_Q:
        return [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    if is_quarter(q):
        w, x, y, z = q
        return [[float(round(e)) for e in row] for row in
                [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                 [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                 [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]]
    n = math.sqrt(sum(c * c for c in q))
    w, x, y, z = (c / n for c in q)
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]


def quat_axis_angle(q):
    """(u, theta) with Rot(u, theta) = q's rotation, theta in [0, pi], u a unit vector (right hand)."""
    w, x, y, z = q
    if w < 0:
        w, x, y, z = -w, -x, -y, -z
    s = math.sqrt(x * x + y * y + z * z)
    if s == 0.0:
        return [0.0, 0.0, 1.0], 0.0
    return [x / s, y / s, z / s], 2.0 * math.atan2(s, w)


class Pose:
    """A placement: rotation q (unit quaternion, w x y z) then translation p, X(v) = R(q) v + p."""

    def __init__(self, q=IDENTITY_Q, p=(0.0, 0.0, 0.0)):
        self.q, self.p = tuple(q), [float(c) for c in p]

    @staticmethod
    def origin(xyz, rpy, rpy_texts=None):
        """A URDF <origin>; with the rpy attribute's words, a turn by multiples of pi/2 to their
        rounding is made exact (quarter_turns)."""
        return Pose(quarter_turns(rpy, rpy_texts) or rpy_quaternion(rpy), xyz)

    def is_identity(self):
        return self.q == IDENTITY_Q and self.p == [0.0, 0.0, 0.0]

    def then(self, child):
        """self * child: child's placement expressed through self (exact when either is the identity)."""
        if self.is_identity():
            return child
        if child.is_identity():
            return self
        if self.q == IDENTITY_Q:
            p = [a + b for a, b in zip(self.p, child.p)]
        else:
            p = [a + b for a, b in zip(self.p, matvec(quat_matrix(self.q), child.p))]
        q = child.q if self.q == IDENTITY_Q else self.q if child.q == IDENTITY_Q else quat_mul(self.q, child.q)
        if is_quarter(self.q) and is_quarter(child.q):
            q = snap_quarter(q)  # exact again
        return Pose(q, p)

    def turn(self):
        """The joint frame's axes in the parent's, ("z", "minus_x", "y") say, when the rotation is a
        signed permutation (exact), else None."""
        if not is_quarter(self.q):
            return None
        r = quat_matrix(self.q)
        return tuple(("" if r[i][j] > 0 else "minus_") + "xyz"[i] for j in range(3) for i in range(3) if r[i][j])

    def matrix(self):
        return quat_matrix(self.q)


# ---- inertia ------------------------------------------------------------------------------------


def symmetric_eigenvalues(a):
    """The eigenvalues of a symmetric 3x3 matrix, ascending (the trigonometric closed form)."""
    p1 = a[0][1] ** 2 + a[0][2] ** 2 + a[1][2] ** 2
    q = (a[0][0] + a[1][1] + a[2][2]) / 3
    if p1 == 0.0:
        return sorted([a[0][0], a[1][1], a[2][2]])
    p2 = (a[0][0] - q) ** 2 + (a[1][1] - q) ** 2 + (a[2][2] - q) ** 2 + 2 * p1
    p = math.sqrt(p2 / 6)
    b = [[(a[i][j] - (q if i == j else 0.0)) / p for j in range(3)] for i in range(3)]
    det_b = (b[0][0] * (b[1][1] * b[2][2] - b[1][2] * b[2][1]) - b[0][1] * (b[1][0] * b[2][2] - b[1][2] * b[2][0])
             + b[0][2] * (b[1][0] * b[2][1] - b[1][1] * b[2][0]))
    r = max(-1.0, min(1.0, det_b / 2))
    phi = math.acos(r) / 3
    e1 = q + 2 * p * math.cos(phi)
    e3 = q + 2 * p * math.cos(phi + 2 * math.pi / 3)
    return sorted([e1, 3 * q - e1 - e3, e3])


def tolerance(tensor):
    """Rounding in a tensor's numbers: 64 eps (|Ixx| + |Iyy| + |Izz|), the tolerance of ctga's own
    check (include/ctga/mechanics/mass_properties.hpp)."""
    return 64 * EPS * (abs(tensor[0][0]) + abs(tensor[1][1]) + abs(tensor[2][2]))


def fmt_moments(ev):
    return "[" + ", ".join(f"{x:.6g}" for x in ev) + "]"


def questionable(tensor):
    """Why a tensor is physically questionable beyond rounding (a phrase for a message), or None."""
    ev = symmetric_eigenvalues(tensor)
    tol = tolerance(tensor)
    if ev[0] < -tol:
        return f"principal moments {fmt_moments(ev)} are not all positive (the tensor is not positive definite)"
    if ev[2] > ev[0] + ev[1] + tol:
        return f"principal moments {fmt_moments(ev)} violate the triangle inequality I_i <= I_j + I_k"
    return None


def physically_refused(tensor):
    """Why ctga's physical check (make_mass_properties without as_given, m > 0) refuses a tensor,
    or None: the same tests in the same order (Sylvester's leading minors > 0, then the triangle
    inequalities through the second moment with the same tolerances)."""
    I = tensor
    tol = tolerance(I)
    m1 = I[0][0]
    m2 = I[0][0] * I[1][1] - I[0][1] * I[0][1]
    m3 = (I[0][0] * (I[1][1] * I[2][2] - I[1][2] * I[1][2]) - I[0][1] * (I[0][1] * I[2][2] - I[1][2] * I[0][2])
          + I[0][2] * (I[0][1] * I[1][2] - I[1][1] * I[0][2]))
    ev = fmt_moments(symmetric_eigenvalues(I))
    if not (m1 > 0 and m2 > 0 and m3 > 0):
        return f"principal moments {ev}: the tensor is not positive definite"
    half = (I[0][0] + I[1][1] + I[2][2]) / 2
    S = [[(half if i == j else 0.0) - I[i][j] for j in range(3)] for i in range(3)]
    t2 = tol * half
    t3 = t2 * half
    bad = any(S[i][i] < -tol for i in range(3))
    bad = bad or any(S[i][i] * S[j][j] - S[i][j] * S[i][j] < -t2 for i in range(3) for j in range(i + 1, 3))
    det_s = (S[0][0] * (S[1][1] * S[2][2] - S[1][2] * S[1][2]) - S[0][1] * (S[0][1] * S[2][2] - S[1][2] * S[0][2])
             + S[0][2] * (S[0][1] * S[1][2] - S[1][1] * S[0][2]))
    if bad or det_s < -t3:
        return f"principal moments {ev} violate the triangle inequality I_i <= I_j + I_k"
    return None


def lump(parts):
    """Mass properties of rigidly joined parts [(m, c, I about c)], all in one frame: (m, c, I about
    c). A part of mass 0 adds its tensor as it stands (no parallel-axis term: as Pinocchio does);
    a single part is returned unchanged (no rounding); the centre of mass of no mass is 0."""
    if not parts:
        return 0.0, [0.0, 0.0, 0.0], [[0.0] * 3 for _ in range(3)]
    if len(parts) == 1 and parts[0][0] > 0:
        return parts[0]
    m = sum(p[0] for p in parts)
    c = [sum(p[0] * p[1][i] for p in parts) / m for i in range(3)] if m > 0 else [0.0, 0.0, 0.0]
    I = [[0.0] * 3 for _ in range(3)]
    for mk, ck, Ik in parts:
        d = [ck[i] - c[i] for i in range(3)]
        for a in range(3):
            # the diagonal's |d|^2 - d_a^2 as the other two squares: no cancellation when d lies
            # far along axis a (as mass_properties.hpp's inertia_about_origin)
            I[a][a] += Ik[a][a] + mk * (d[(a + 1) % 3] ** 2 + d[(a + 2) % 3] ** 2)
            for b in range(a + 1, 3):
                I[a][b] += Ik[a][b] - mk * d[a] * d[b]
    return m, c, [[I[min(a, b)][max(a, b)] for b in range(3)] for a in range(3)]


# ---- the URDF -----------------------------------------------------------------------------------


class Inertial:
    def __init__(self, mass, com, tensor):
        self.mass = mass      # kg, >= 0
        self.com = com        # centre of mass, link frame
        self.tensor = tensor  # about the centre of mass, link axes (symmetric)


class Link:
    def __init__(self, name, inertial, collisions=()):
        self.name = name
        self.inertial = inertial  # Inertial or None (massless)
        self.collisions = list(collisions)  # [Collision] in document order


class Collision:
    """A link's <collision>: its geometry as written (sizes checked positive) and its <origin>."""

    def __init__(self, kind, size, origin, filename=None):
        self.kind = kind          # sphere | box | cylinder | mesh | another tag (not URDF's: left out, a warning)
        self.size = size          # sphere [radius]; box [x, y, z] (full lengths); cylinder [radius, length];
        #                           mesh: its scale [sx, sy, sz]
        self.origin = origin      # Pose in the link frame
        self.filename = filename  # a mesh's filename as written


class Mimic:
    def __init__(self, master, multiplier, offset):
        self.master, self.multiplier, self.offset = master, multiplier, offset


class Joint:
    def __init__(self, name, kind, parent, child, xyz, rpy, axis, mimic, limit=None, dynamics=None, rpy_texts=None):
        self.name = name
        self.kind = kind      # one of SUPPORTED_TYPES
        self.parent = parent  # link names
        self.child = child
        self.xyz = xyz
        self.rpy = rpy
        self.rpy_texts = rpy_texts  # the rpy attribute's three words as written (None: absent)
        self.axis = axis      # unit, joint frame (revolute, continuous, prismatic; planar: the normal), else None
        self.mimic = mimic    # Mimic or None
        self.limit = limit        # {lower, upper, velocity, effort: those given} (1-dof joints); None: no <limit>
        self.dynamics = dynamics  # {damping, friction: those given} (1-dof joints); None: no <dynamics>

    def bounds(self):
        """(lower, upper) position bounds, None where absent (a continuous joint has none)."""
        if self.kind == "continuous" or self.limit is None:
            return None, None
        return self.limit.get("lower"), self.limit.get("upper")

    def rest(self):
        """Its position 0, clamped into its <limit> (where a lock puts it by default)."""
        lo, up = self.bounds()
        return lo if lo is not None and lo > 0.0 else up if up is not None and up < 0.0 else 0.0

    def motion(self, value):
        """The joint's motion at coordinate `value` (a revolute or continuous joint turns about its
        axis, a prismatic joint slides along it; others: their origin, value 0), as a Pose."""
        if value == 0.0 or self.kind not in ONE_DOF:
            return Pose()
        if self.kind == "prismatic":
            return Pose(IDENTITY_Q, [value * c for c in self.axis])
        s = math.sin(value / 2)
        return Pose((math.cos(value / 2), s * self.axis[0], s * self.axis[1], s * self.axis[2]))


def _origin(elem, where):
    o = elem.find("origin")
    if o is None:
        return [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]
    return (parse_vector(o.get("xyz"), f"{where}: <origin xyz>", (0.0, 0.0, 0.0)),
            parse_vector(o.get("rpy"), f"{where}: <origin rpy>", (0.0, 0.0, 0.0)))


def _rpy_texts(elem):
    """The <origin rpy> attribute's three words as written (None: absent), for quarter_turns."""
    o = elem.find("origin")
    return o.get("rpy").split() if o is not None and o.get("rpy") is not None else None


def _parse_inertial(link_elem, where):
    """The link's Inertial, or None without <inertial> (massless). The numbers are checked here
    (malformed, non-finite, negative mass: errors); the physics is checked per body later."""
    elems = link_elem.findall("inertial")
    if not elems:
        return None
    if len(elems) > 1:
        raise UrdfError(f"{where}: more than one <inertial>")
    inertial = elems[0]
    xyz, rpy = _origin(inertial, f"{where} <inertial>")
    mass_elem = inertial.find("mass")
    if mass_elem is None:
        raise UrdfError(f"{where}: <inertial> has no <mass>")
    mass = parse_number(mass_elem.get("value"), f"{where}: <mass value>")
    if mass < 0:
        raise UrdfError(f"{where}: mass {mass!r} is negative")
    mass = abs(mass)  # -0.0 -> 0.0
    inertia_elem = inertial.find("inertia")
    if inertia_elem is None:
        raise UrdfError(f"{where}: <inertial> has no <inertia>")
    i = {k: parse_number(inertia_elem.get(k), f"{where}: <inertia {k}>")
         for k in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")}
    tensor = [[i["ixx"], i["ixy"], i["ixz"]], [i["ixy"], i["iyy"], i["iyz"]], [i["ixz"], i["iyz"], i["izz"]]]
    if rpy != [0.0, 0.0, 0.0]:
        tensor = rotate_tensor(rpy_matrix(rpy), tensor)
    return Inertial(mass, xyz, tensor)


# The sizes of URDF's shapes: attributes (box: three numbers), each number positive.
SHAPE_SIZES = {"sphere": ("radius",), "box": ("size",), "cylinder": ("radius", "length")}


def _parse_collisions(link_elem, where):
    """The link's <collision> elements: sizes checked positive (errors naming the link), a mesh's
    scale checked non-zero (a negative scale mirrors it); a geometry URDF does not define is kept by
    its tag (left out later, with a warning)."""
    out = []
    for ce in link_elem.findall("collision"):
        w = f"{where} <collision>"
        xyz, rpy = _origin(ce, w)
        origin = Pose.origin(xyz, rpy, _rpy_texts(ce))
        ge = ce.find("geometry")
        shapes = [] if ge is None else list(ge)
        if len(shapes) != 1:
            raise UrdfError(f"{w}: <geometry> must hold one shape (box, sphere, cylinder or mesh)")
        g = shapes[0]
        if g.tag in SHAPE_SIZES:
            size = []
            for k in SHAPE_SIZES[g.tag]:
                what = f"{w}: <{g.tag} {k}>"
                given = parse_vector(g.get(k), what) if k == "size" else [parse_number(g.get(k), what)]
                if not all(x > 0 for x in given):
                    raise UrdfError(f"{what} {words(given)}: a size is not positive")
                size += given
            out.append(Collision(g.tag, size, origin))
        elif g.tag == "mesh":
            if not g.get("filename"):
                raise UrdfError(f'{w}: <mesh> without filename="..."')
            scale = parse_vector(g.get("scale"), f"{w}: <mesh scale>", (1.0, 1.0, 1.0))
            if 0.0 in scale:
                raise UrdfError(f"{w}: <mesh scale> {words(scale)}: a zero scale flattens the mesh")
            out.append(Collision("mesh", scale, origin, g.get("filename")))
        else:
            out.append(Collision(g.tag, None, origin))
    return out


LIMIT_KEYS = ("lower", "upper", "velocity", "effort")
DYNAMICS_KEYS = ("damping", "friction")


def _parse_numbers(je, tag, keys, where):
    """The numbers of the attributes `keys` that <tag> gives (others, e.g. Gazebo's, are ignored),
    or None without <tag>."""
    elems = je.findall(tag)
    if not elems:
        return None
    if len(elems) > 1:
        raise UrdfError(f"{where}: more than one <{tag}>")
    return {k: parse_number(elems[0].get(k), f"{where}: <{tag} {k}>") for k in keys if elems[0].get(k) is not None}


def _limits_and_dynamics(je, kind, where):
    """A 1-dof joint's <limit> and <dynamics>, checked: lower <= upper (revolute, prismatic; a
    continuous joint's bounds are not read), velocity, effort, damping and friction >= 0."""
    limit = _parse_numbers(je, "limit", LIMIT_KEYS, where)
    dynamics = _parse_numbers(je, "dynamics", DYNAMICS_KEYS, where)
    if limit is not None and kind != "continuous" and "lower" in limit and "upper" in limit \
            and limit["lower"] > limit["upper"]:
        raise UrdfError(f'{where}: <limit lower="{limit["lower"]!r}" upper="{limit["upper"]!r}">: lower > upper')
    for tag, given in (("limit", limit), ("dynamics", dynamics)):
        for k, x in (given or {}).items():
            if k not in ("lower", "upper") and x < 0:
                raise UrdfError(f"{where}: <{tag} {k}> {x!r} is negative")
    return limit, dynamics


def _unit_axis(je, where):
    ae = je.find("axis")
    a = parse_vector(ae.get("xyz") if ae is not None else None, f"{where}: <axis xyz>", (1.0, 0.0, 0.0))
    n = math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2])
    if n == 0.0:
        raise UrdfError(f"{where}: the axis is zero")
    if a.count(0.0) == 2:  # a coordinate axis: exactly, not to rounding
        return [c / abs(c) if c != 0.0 else 0.0 for c in a]
    return [c / n for c in a]


def parse_urdf(path):
    """(robot name, [Link] in document order, [Joint] in document order)."""
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as e:
        raise UrdfError(f"{path}: not well-formed XML: {e}") from None
    except OSError as e:
        raise UrdfError(f"{path}: {e.strerror}") from None
    if root.tag != "robot":
        raise UrdfError(f"{path}: the root element is <{root.tag}>, not <robot>")

    links, link_names = [], set()
    for le in root.findall("link"):
        name = le.get("name")
        if not name:
            raise UrdfError("a <link> without a name")
        where = f'link "{name}"'
        if name in link_names:
            raise UrdfError(f"{where} is defined twice")
        link_names.add(name)
        links.append(Link(name, _parse_inertial(le, where), _parse_collisions(le, where)))

    joints, joint_names = [], set()
    for je in root.findall("joint"):
        name = je.get("name")
        if not name:
            raise UrdfError("a <joint> without a name")
        where = f'joint "{name}"'
        if name in joint_names:
            raise UrdfError(f"{where} is defined twice")
        joint_names.add(name)
        kind = je.get("type")
        if kind is None:
            raise UrdfError(f"{where}: no type (supported: {', '.join(SUPPORTED_TYPES)})")
        if kind not in SUPPORTED_TYPES:
            raise UrdfError(f'{where}: type "{kind}" is not supported ({", ".join(SUPPORTED_TYPES)})')
        ends = {}
        for role in ("parent", "child"):
            e = je.find(role)
            if e is None or not e.get("link"):
                raise UrdfError(f'{where}: no <{role} link="...">')
            if e.get("link") not in link_names:
                raise UrdfError(f'{where}: {role} link "{e.get("link")}" does not exist')
            ends[role] = e.get("link")
        if ends["parent"] == ends["child"]:
            raise UrdfError(f'{where}: link "{ends["child"]}" is its own parent (not a tree)')
        xyz, rpy = _origin(je, where)
        axis = _unit_axis(je, where) if kind in ONE_DOF or kind == "planar" else None
        mimic = None
        me = je.findall("mimic")
        if len(me) > 1:
            raise UrdfError(f"{where}: more than one <mimic>")
        if me:
            master = me[0].get("joint")
            if not master:
                raise UrdfError(f'{where}: <mimic> without joint="..."')
            mult = me[0].get("multiplier")
            off = me[0].get("offset")
            mimic = Mimic(master, 1.0 if mult is None else parse_number(mult, f"{where}: <mimic multiplier>"),
                          0.0 if off is None else parse_number(off, f"{where}: <mimic offset>"))
        limit, dynamics = _limits_and_dynamics(je, kind, where) if kind in ONE_DOF else (None, None)
        joints.append(Joint(name, kind, ends["parent"], ends["child"], xyz, rpy, axis, mimic, limit, dynamics,
                            _rpy_texts(je)))
    return root.get("name", ""), links, joints


# ---- the tree -----------------------------------------------------------------------------------

AXIS_TYPES = {(1.0, 0.0, 0.0): "x", (0.0, 1.0, 0.0): "y", (0.0, 0.0, 1.0): "z"}
MINUS_AXIS_TYPES = {(-1.0, 0.0, 0.0): "x", (0.0, -1.0, 0.0): "y", (0.0, 0.0, -1.0): "z"}


def one_dof_type(prefix, axis):
    """(C++ type, whether make_link takes the axis) of a revolute or prismatic joint about/along axis."""
    a = tuple(0.0 if c == 0.0 else c for c in axis)  # -0.0 -> 0.0
    if a in AXIS_TYPES:
        return f"ctga::chains::{prefix}_{AXIS_TYPES[a]}", False
    if a in MINUS_AXIS_TYPES:
        return f"ctga::chains::{prefix}<ctga::chains::axis::minus_{MINUS_AXIS_TYPES[a]}>", False
    return ("ctga::chains::prismatic_along" if prefix == "prismatic" else "ctga::chains::revolute_about"), True


def plane_axes(n):
    """(u1, u2) with (u1, u2, n) a right-handed orthonormal basis; coordinate axes when n is one
    (n = +-e_k: u1 = e_(k+1), u2 = +-e_(k+2)), else u1 from the coordinate axis least aligned with n."""
    for k in range(3):
        e = [0.0, 0.0, 0.0]
        e[k] = 1.0
        for s in (1.0, -1.0):
            if n == [s * c if c else 0.0 for c in e]:
                u1 = [0.0, 0.0, 0.0]
                u1[(k + 1) % 3] = 1.0
                u2 = [0.0, 0.0, 0.0]
                u2[(k + 2) % 3] = s
                return u1, u2
    k = min(range(3), key=lambda i: abs(n[i]))
    a = [1.0 if i == k else 0.0 for i in range(3)]
    an = dot(a, n)
    u1 = normalised([a[i] - an * n[i] for i in range(3)])
    u2 = normalised(cross(n, u1))
    return u1, u2


class Body:
    def __init__(self, index, parent, name, joint_name, urdf_joint, kind, placement, joint_type, axis=None,
                 takes_axis=False, link=None):
        self.index, self.parent = index, parent
        self.name = name                # body_names entry
        self.joint_name = joint_name    # joint_names entry
        self.urdf_joint = urdf_joint    # the URDF joint it comes from (None: the floating base)
        self.kind = kind                # a description for comments
        self.placement = placement      # Pose in the parent body's frame (or the world)
        self.joint_type = joint_type    # C++ type of its joint, fully qualified, without the wrappers below
        self.turn = placement.turn()    # its placement's turn by multiples of pi/2 (None: another rotation)
        self.axis = axis                # the run-time axis, or the axis for comments, or None
        self.takes_axis = takes_axis    # make_link takes the axis
        self.link = link                # the body's own URDF link (None: a planar joint's virtual body)
        self.coupling = None            # (multiplier, offset) of a mimic joint
        self.parts = []                 # [(Link, Pose in this body's frame)]: its own link first, then merged ones
        self.mass, self.com, self.tensor = 0.0, [0.0] * 3, [[0.0] * 3 for _ in range(3)]
        self.dofs = 0
        self.turns = False              # its joint turns it (revolute, continuous, a planar joint's rotation)
        self.armature = None            # a 1-dof joint's rotor inertia (--armature, --massless armature=)
        self.master = None              # a mimic joint's master body

    @property
    def cpp_joint(self):
        """The joint's C++ type: mimic<aligned<J>, M>, turned<turn{...}, with_armature<J>>, or some of them."""
        t = self.joint_type
        if self.armature is not None:
            t = f"ctga::chains::with_armature<{t}>"
        if self.turn == ("x", "y", "z"):
            t = f"ctga::chains::aligned<{t}>"
        elif self.turn is not None:
            axes = ", ".join(f"ctga::chains::axis::{a}" for a in self.turn)
            t = f"ctga::chains::turned<ctga::chains::turn{{{axes}}}, {t}>"
        if self.master is not None:
            t = f"ctga::chains::mimic<{t}, {self.master}>"
        return t


class Frame:
    def __init__(self, name, body, pose, via):
        self.name, self.body, self.pose = name, body, pose
        self.via = via  # the fixed (or locked) joints composed into the pose (names), outermost first


class Lock:
    """A moving joint made fixed at `value` (a planar or floating joint: at its origin, 0)."""

    def __init__(self, value, why, given=False):
        self.value = value  # None until settled (the default: 0 clamped into <limit>; a mimic: m v + o)
        self.why = why      # "--lock", "--massless lock", 'follows "master"'
        self.given = given  # the value was given on the command line


class Options:
    """The loading options (the command line's), defaults as there."""

    def __init__(self, floating_base=False, keep_fixed=False, mimic="coupled", mimic_missing="refuse", strict=False,
                 massless="refuse", locks=(), armatures=(), meshes="hull", hull_vertices=32, exclude_pairs=(),
                 srdf=None):
        self.floating_base, self.keep_fixed, self.strict = floating_base, keep_fixed, strict
        self.mimic = mimic                  # coupled | independent
        self.mimic_missing = mimic_missing  # refuse | independent
        self.massless = massless            # "refuse" | "lock" | the armature (float) of --massless armature=VALUE
        self.locks = list(locks)            # [(joint, value or None)] as given
        self.armatures = list(armatures)    # [(joint, value)] as given
        self.meshes = meshes                # hull | omit
        self.hull_vertices = hull_vertices  # a mesh's hull's capacity (reduced beyond it)
        self.exclude_pairs = list(exclude_pairs)  # [(link a, link b)] as given
        self.srdf = srdf                    # the SRDF file's path, or None


class Model:
    def __init__(self):
        self.root = None
        self.bodies = []
        self.frames = []
        self.world_links = []  # links lumped into the world (their inertia dropped), root first
        self.warnings = []
        self.locks = {}        # joint name -> Lock, in the order decided
        self.armatures = {}    # joint name -> (value, why)
        self.mimics = {}       # joint name -> Mimic: the <mimic> joints coupled to their master
        self.shapes = []       # [Shape]: the collision geometry (collision_geometry)
        self.excluded = []     # [(body a, body b, why)]: pairs never tested against each other (excluded_pairs)


NO_MASS = "no mass in its subtree"
SINGULAR = "the mass matrix would be singular and ABA would divide by zero"


def build_tree(links, joints, opts):
    """The Model: bodies and frames in depth-first order, mass properties, locks and armatures,
    warnings."""
    if not links:
        raise UrdfError("the URDF has no <link>")
    by_name = {l.name: l for l in links}
    joint_by_name = {j.name: j for j in joints}
    parent_joint = {}
    for j in joints:
        if j.child in parent_joint:
            raise UrdfError(f'link "{j.child}" is the child of two joints, "{parent_joint[j.child].name}" and '
                            f'"{j.name}" (a loop: the URDF is not a tree)')
        parent_joint[j.child] = j
    roots = [l for l in links if l.name not in parent_joint]
    if not roots:
        raise UrdfError("no root link: every link is some joint's child (a loop: the URDF is not a tree)")
    if len(roots) > 1:
        raise UrdfError(f"more than one root link ({', '.join(repr(l.name) for l in roots)}): "
                        "every link but one must be a joint's child")
    root = roots[0]
    children = {l.name: [] for l in links}
    for j in joints:
        children[j.parent].append(j)

    warnings = []
    mimics = _resolve_mimics(joints, joint_by_name, opts, warnings)
    locks = _explicit_locks(joint_by_name, opts)
    _settle_locks(locks, joint_by_name, mimics)
    armatures = _explicit_armatures(joint_by_name, mimics, locks, opts)
    while True:
        model = _assemble(links, by_name, joint_by_name, root, children, opts, locks)
        model.warnings = list(warnings)
        _couple_mimics(model, mimics)
        _mass_properties(model, opts.strict)
        for b in model.bodies:
            if b.dofs == 1 and b.link is not None and b.urdf_joint is not None and b.urdf_joint.name in armatures:
                b.armature = armatures[b.urdf_joint.name][0]
        failing = massless_joints(model)
        if not failing:
            break
        _massless_option(failing, opts, locks, armatures, mimics)
        _settle_locks(locks, joint_by_name, mimics)
    # what the locks leave questionable
    for name, lk in locks.items():
        j = joint_by_name[name]
        mimic = mimics.get(name)
        if mimic is not None and mimic.master not in locks:
            model.warnings.append(f'joint "{name}" (a <mimic> of "{mimic.master}") is locked at {lk.value!r}: it no '
                                  f'longer follows "{mimic.master}"')
        lo, up = j.bounds()
        if lk.given and mimic is None and ((lo is not None and lk.value < lo) or (up is not None and lk.value > up)):
            model.warnings.append(f'joint "{name}" is locked at {lk.value!r}, outside its <limit> [{lo!r}, {up!r}]')
    model.locks = locks
    model.armatures = {n: a for n, a in armatures.items() if n not in locks}
    model.mimics = mimics
    return model


def _resolve_mimics(joints, joint_by_name, opts, warnings):
    """{joint name: Mimic} of the <mimic> joints coupled to their master (--mimic coupled): checked,
    a <mimic> on a fixed joint dropped with a warning, one naming a missing joint refused or (with
    --mimic-missing independent) dropped with a warning."""
    if opts.mimic != "coupled":
        return {}
    out = {}
    for j in joints:
        if j.mimic is None:
            continue
        where = f'joint "{j.name}"'
        if j.kind == "fixed":  # it does not move: nothing to couple (TALOS's gripper links)
            warnings.append(f"{where}: <mimic> on a fixed joint is ignored (the joint does not move)")
            continue
        if j.kind not in ONE_DOF:
            raise UrdfError(f'{where}: <mimic> on a {j.kind} joint (only revolute, continuous and prismatic joints '
                            "can mimic another; --mimic independent ignores <mimic>)")
        if j.mimic.master not in joint_by_name:
            if opts.mimic_missing == "independent":
                warnings.append(f'{where}: <mimic joint="{j.mimic.master}">: no such joint; {where} is an independent '
                                "joint (--mimic-missing independent)")
                continue
            raise UrdfError(f'{where}: <mimic joint="{j.mimic.master}">: no such joint (--mimic-missing independent '
                            "makes such a joint an ordinary independent joint; --mimic independent does so for every "
                            "<mimic> joint)")
        out[j.name] = j.mimic
    for name, mimic in out.items():
        where = f'joint "{name}"'
        master = joint_by_name[mimic.master]
        if master.kind not in ONE_DOF:
            raise UrdfError(f'{where}: <mimic joint="{master.name}">: the master is a {master.kind} joint (it must '
                            "be revolute, continuous or prismatic)")
        if master.name in out:
            raise UrdfError(f'{where}: <mimic joint="{master.name}">: the master itself mimics '
                            f'"{master.mimic.master}" (a mimic must follow an independent joint)')
    return out


def _option_joint(option, name, joint_by_name, table):
    """The joint an option names (an error naming the option and the name if there is none, or if
    the option already named it)."""
    j = joint_by_name.get(name)
    if j is None:
        raise UrdfError(f'{option}: no joint named "{name}"')
    if name in table:
        raise UrdfError(f'{option}: joint "{name}" is named twice')
    return j


def _explicit_locks(joint_by_name, opts):
    locks = {}
    for name, value in opts.locks:
        option = f"--lock {name}" + ("" if value is None else f"={value!r}")
        j = _option_joint(option, name, joint_by_name, locks)
        if j.kind == "fixed":
            raise UrdfError(f'{option}: joint "{name}" is fixed already')
        if value is not None and j.kind not in ONE_DOF:
            raise UrdfError(f'{option}: joint "{name}" is {j.kind}: it locks at its origin, without a value '
                            f"(--lock {name})")
        locks[name] = Lock(value, "--lock", value is not None)
    return locks


def _settle_locks(locks, joint_by_name, mimics):
    """Gives each lock without a value its value, and locks the mimics of locked masters: a 1-dof
    joint at 0 clamped into its <limit>; a mimic at m v + o, v its master's locked value (0 if its
    master is free); a planar or floating joint at its origin (0)."""
    for name, lk in locks.items():
        if lk.value is None and name not in mimics:
            lk.value = joint_by_name[name].rest()
    for name, mimic in mimics.items():
        master = locks.get(mimic.master)
        follows = mimic.multiplier * (master.value if master is not None else 0.0) + mimic.offset
        if name in locks:
            if locks[name].value is None:
                locks[name].value = follows
        elif master is not None:
            locks[name] = Lock(follows, f'follows "{mimic.master}"')


def _explicit_armatures(joint_by_name, mimics, locks, opts):
    out = {}
    for name, value in opts.armatures:
        option = f"--armature {name}={value!r}"
        j = _option_joint(option, name, joint_by_name, out)
        if j.kind not in ONE_DOF:
            raise UrdfError(f'{option}: joint "{name}" is {j.kind}: armature is for revolute, continuous and prismatic '
                            "joints")
        if name in mimics:
            raise UrdfError(f'{option}: joint "{name}" mimics "{mimics[name].master}": it has no coordinate of its own '
                            f'(give the armature to "{mimics[name].master}", or use --mimic independent)')
        if name in locks:
            raise UrdfError(f'{option}: joint "{name}" is locked ({locks[name].why}): a locked joint has no armature')
        if value < 0:
            raise UrdfError(f"{option}: the armature is negative")
        out[name] = (value, "--armature")
    return out


def _assemble(links, by_name, joint_by_name, root, children, opts, locks):
    """The bodies and frames, depth first: a locked joint is a fixed one whose origin is followed
    by the joint's motion at its value."""
    model = Model()
    model.root = root
    bodies, frames = model.bodies, model.frames
    taken = set(by_name) | set(joint_by_name)  # names a virtual body or the floating base must not take

    def fresh(name, suffix):
        while name in taken:
            name += suffix
        taken.add(name)
        return name

    def new_body(parent, name, joint_name, urdf_joint, kind, placement, joint_type, **kw):
        b = Body(len(bodies), parent, name, joint_name, urdf_joint, kind, placement, joint_type, **kw)
        bodies.append(b)
        return b

    stack = []

    def visit(link, body, pose, via):
        frames.append(Frame(link.name, body, pose, via))
        if body >= 0:
            bodies[body].parts.append((link, pose))
        else:
            model.world_links.append(link)
        stack.extend((j, body, pose, via) for j in reversed(children[link.name]))

    if opts.floating_base:
        name = root.name
        while name in joint_by_name or (name != root.name and name in taken):
            name += "_joint"
        taken.add(name)
        b = new_body(-1, root.name, name, None, "floating base", Pose(), "ctga::chains::floating", link=root)
        b.dofs = 6
        visit(root, 0, Pose(), [])
    else:
        visit(root, -1, Pose(), [])
    # depth first, children in document order (an explicit stack: no recursion limit)
    while stack:
        j, parent, ppose, pvia = stack.pop()
        link = by_name[j.child]
        lock = locks.get(j.name)
        origin = Pose.origin(j.xyz, j.rpy, j.rpy_texts)
        placement = ppose.then(origin if lock is None else origin.then(j.motion(lock.value)))
        if (j.kind == "fixed" or lock is not None) and not opts.keep_fixed:
            visit(link, parent, placement, pvia + [j.name])
            continue
        if lock is not None:  # --keep-fixed
            b = new_body(parent, link.name, j.name, j, f"{j.kind}, locked at {lock.value!r}", placement,
                         "ctga::chains::fixed", link=link)
        elif j.kind == "planar":
            u1, u2 = plane_axes(j.axis)
            cpp, takes = one_dof_type("prismatic", u1)
            bx = new_body(parent, None, None, j, "planar, translation along u1", placement, cpp, axis=u1,
                          takes_axis=takes)
            bx.name = bx.joint_name = fresh(j.name + "_x", "_")
            cpp, takes = one_dof_type("prismatic", u2)
            by = new_body(bx.index, None, None, j, "planar, translation along u2", Pose(), cpp, axis=u2,
                          takes_axis=takes)
            by.name = by.joint_name = fresh(j.name + "_y", "_")
            bx.dofs = by.dofs = 1
            cpp, takes = one_dof_type("revolute", j.axis)
            b = new_body(by.index, link.name, j.name, j, "planar, rotation about the normal", Pose(), cpp,
                         axis=j.axis, takes_axis=takes, link=link)
            b.dofs, b.turns = 1, True
        elif j.kind in ONE_DOF:
            cpp, takes = one_dof_type("prismatic" if j.kind == "prismatic" else "revolute", j.axis)
            b = new_body(parent, link.name, j.name, j, j.kind, placement, cpp, axis=j.axis, takes_axis=takes,
                         link=link)
            b.dofs, b.turns = 1, j.kind != "prismatic"
        elif j.kind == "floating":
            b = new_body(parent, link.name, j.name, j, "floating", placement, "ctga::chains::floating", link=link)
            b.dofs = 6
        else:  # fixed, --keep-fixed
            b = new_body(parent, link.name, j.name, j, "fixed", placement, "ctga::chains::fixed", link=link)
        visit(link, b.index, Pose(), [])

    reached = {f.name for f in frames}
    unreachable = [l.name for l in links if l.name not in reached]
    if unreachable:
        raise UrdfError(f'link "{unreachable[0]}" is not connected to the root link "{root.name}" '
                        "(a loop: the URDF is not a tree)")
    if not bodies:
        raise UrdfError(f'the robot has no bodies: the root link "{root.name}" is the world and no joint moves '
                        "anything (use --floating-base to make it a free body)")
    return model


def _couple_mimics(model, mimics):
    bodies = model.bodies
    body_of_joint = {b.urdf_joint.name: b for b in bodies if b.urdf_joint is not None and b.link is not None}
    for b in bodies:
        j = b.urdf_joint
        if j is None or j.name not in mimics or b.link is None or b.dofs == 0:
            continue
        master = body_of_joint[mimics[j.name].master]
        b.master = master.index
        b.coupling = (j.mimic.multiplier, j.mimic.offset)
        b.dofs = 0


def _mass_properties(model, strict):
    bodies = model.bodies

    def complain(message):
        if strict:
            raise UrdfError(message + " (--strict)")
        model.warnings.append(message)

    # per URDF link whose inertia enters a body
    for b in bodies:
        for link, _ in b.parts:
            if link.inertial is None:
                continue
            t = link.inertial.tensor
            if link.inertial.mass == 0 and any(x != 0.0 for row in t for x in row):
                complain(f'link "{link.name}": mass 0 with a nonzero inertia tensor (kept, as Pinocchio does: it adds '
                         "to its body's rotational inertia, without a parallel-axis term)")
            why = questionable(t)
            if why:
                complain(f'link "{link.name}": {why}')
    # per body: the lumped mass properties, and its own checks
    for b in bodies:
        parts = []
        for link, pose in b.parts:
            i = link.inertial
            if i is None or (i.mass == 0 and not any(x != 0.0 for row in i.tensor for x in row)):
                continue
            if pose.is_identity():
                parts.append((i.mass, list(i.com), i.tensor))
            else:
                r = pose.matrix()
                c = [a + d for a, d in zip(pose.p, matvec(r, i.com))]
                parts.append((i.mass, c, rotate_tensor(r, i.tensor)))
        b.mass, b.com, b.tensor = lump(parts)
        what = f'body {b.index} "{b.name}"'
        if len(parts) > 1:
            why = questionable(b.tensor)
            if why:
                merged = ", ".join(f'"{l.name}"' for l, _ in b.parts[1:])
                complain(f"{what} (link \"{b.name}\" with the merged links {merged}): lumped {why}")
        if strict and b.mass > 0:
            why = physically_refused(b.tensor)
            if why:
                raise UrdfError(f"{what}: {why}, which ctga's physical check refuses (--strict)")


def massless_joints(model):
    """The bodies whose joint moves but meets no inertia, as ctga::chains::massless_subtree finds
    them: no mass in the body or below it, no armature, and for a joint that turns no rotational
    inertia there either (the trace of the massless tensors)."""
    bodies = model.bodies
    mass = [b.mass for b in bodies]
    turning = [b.tensor[0][0] + b.tensor[1][1] + b.tensor[2][2] for b in bodies]
    for b in reversed(bodies):
        if b.parent >= 0:
            mass[b.parent] += mass[b.index]
            turning[b.parent] += turning[b.index]
    return [b for b in bodies if (b.dofs > 0 or b.coupling is not None) and not mass[b.index] > 0
            and not (b.armature or 0.0) > 0 and not (b.turns and turning[b.index] > 0)]


def _massless_option(failing, opts, locks, armatures, mimics):
    """What --massless does with the joints that meet no inertia: refuse (an error naming the
    first and the options), lock them, or give them an armature."""
    joints = []
    for b in failing:
        if b.urdf_joint is None:  # the floating base: nothing below it has mass
            raise UrdfError(f'joint "{b.joint_name}": {NO_MASS}: {SINGULAR} (the floating base: the robot has no '
                            "mass at all)")
        if b.urdf_joint not in joints:
            joints.append(b.urdf_joint)
    first = joints[0]
    if opts.massless == "refuse":
        others = [f'"{j.name}"' for j in joints[1:]]
        also = ""
        if others:
            also = "; the same for " + ", ".join(others[:4])
            also += f" and {len(others) - 4} more" if len(others) > 4 else ""
        raise UrdfError(f'joint "{first.name}": {NO_MASS}: {SINGULAR} (no armature either, nor, for a joint that '
                        f"turns, a rotational inertia){also}. Options: "
                        "--massless lock (fix such joints at 0), --massless armature=VALUE (give them a rotor inertia), "
                        f"or per joint --lock {first.name}[=VALUE], --armature {first.name}=VALUE")
    for j in joints:
        if opts.massless == "lock":
            locks[j.name] = Lock(None, "--massless lock")
        elif j.name in mimics:
            raise UrdfError(f'joint "{j.name}": {NO_MASS}, and --massless armature cannot help: a <mimic> joint has no '
                            f"coordinate, so no armature of its own (use --massless lock, --lock {j.name}, or --mimic "
                            "independent)")
        elif j.kind not in ONE_DOF:
            raise UrdfError(f'joint "{j.name}": {NO_MASS}, and --massless armature cannot help: armature is for '
                            f"revolute, continuous and prismatic joints, this one is {j.kind} (use --massless lock or "
                            f"--lock {j.name})")
        elif j.name in armatures:  # given as 0
            raise UrdfError(f'joint "{j.name}": {NO_MASS}: {SINGULAR}, and its armature is {armatures[j.name][0]!r} '
                            "(--armature)")
        else:
            armatures[j.name] = (opts.massless, "--massless armature")


# ---- collision geometry -------------------------------------------------------------------------


def _exact(points):
    """The points' coordinates as integers, all scaled by one power of two: exact (a double is an
    integer times a power of two), so that the hull's orientation tests are exact."""
    ratios = [[c.as_integer_ratio() for c in p] for p in points]
    den = max(d for r in ratios for _, d in r)
    return [tuple(n * (den // d) for n, d in r) for r in ratios]


def _minus(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def _square(v):
    return dot(v, v)


def _extreme_four(X):
    """The starting tetrahedron's corners (as hull.hpp's): the lowest x (then y, z), the farthest
    from it, the farthest from their line, the farthest from their plane; None if the points span no
    volume."""
    i0 = min(range(len(X)), key=lambda i: X[i])
    i1 = max(range(len(X)), key=lambda i: _square(_minus(X[i], X[i0])))
    e = _minus(X[i1], X[i0])
    i2 = max(range(len(X)), key=lambda i: _square(cross(e, _minus(X[i], X[i0]))))
    n = cross(e, _minus(X[i2], X[i0]))
    i3 = max(range(len(X)), key=lambda i: abs(dot(n, _minus(X[i], X[i0]))))
    return None if dot(n, _minus(X[i3], X[i0])) == 0 else (i0, i1, i2, i3)


def convex_hull(points, budget=None):
    """The convex hull of distinct points (float triples): (corners, triangles), the corners' indices
    ascending, the triangles (i, j, k) counter-clockwise seen from outside; None if the points span
    no volume. Quickhull (Barber, Dobkin and Huhdanpaa 1996) with exact orientation tests (_exact):
    from the tetrahedron of _extreme_four, the point farthest above its triangle is added, over all
    triangles, until no point is above any; with a budget, until the hull has `budget` vertices (a
    vertex more at most per point added: it stops at `budget` exactly when the whole hull has more).
    A corner is a vertex on three or more distinct planes of triangles (a point within a flat face or
    a straight edge, kept by the triangulation, is on one or two)."""
    if len(points) < 4:
        return None
    X = _exact(points)
    start = _extreme_four(X)
    if start is None:
        return None
    faces, plane, edge, outside, uses = {}, {}, {}, {}, [0] * len(X)
    heap, alive, next_id = [], 0, 0

    def above(f, i):  # exact: the height of point i over face f's plane, times |n| (> 0: strictly above)
        n, d, _ = plane[f]
        return dot(n, X[i]) - d

    def add_face(a, b, c):
        nonlocal alive, next_id
        f, next_id = next_id, next_id + 1
        n = cross(_minus(X[b], X[a]), _minus(X[c], X[a]))
        faces[f], plane[f] = (a, b, c), (n, dot(n, X[a]), math.sqrt(_square(n)))
        for u, v in ((a, b), (b, c), (c, a)):
            edge[(u, v)] = f
            alive += uses[u] == 0
            uses[u] += 1
        return f

    def remove_face(f):
        nonlocal alive
        a, b, c = faces.pop(f)
        for u, v in ((a, b), (b, c), (c, a)):
            del edge[(u, v)]
            uses[u] -= 1
            alive -= uses[u] == 0

    def assign(candidates, new):  # each point to the new face it is farthest above (none: inside)
        for i in candidates:
            best, height = None, 0.0
            for f in new:
                h = above(f, i)
                if h > 0 and (best is None or h / plane[f][2] > height):
                    best, height = f, h / plane[f][2]
            if best is not None:
                outside.setdefault(best, []).append((height, i))
        for f in new:
            if f in outside:
                heapq.heappush(heap, (-max(outside[f])[0], f))

    i0, i1, i2, i3 = start
    new = []
    for a, b, c, o in ((i0, i1, i2, i3), (i0, i3, i1, i2), (i1, i3, i2, i0), (i2, i3, i0, i1)):
        if dot(cross(_minus(X[b], X[a]), _minus(X[c], X[a])), _minus(X[o], X[a])) > 0:  # o above: turned inwards
            b, c = c, b
        new.append(add_face(a, b, c))
    assign([i for i in range(len(X)) if i not in start], new)
    while heap and (budget is None or alive < budget):
        _, f = heapq.heappop(heap)
        if f not in faces:
            continue
        p = max(outside[f])[1]
        visible, stack = {f}, [f]
        while stack:  # the faces p is strictly above: a connected patch around f
            a, b, c = faces[stack.pop()]
            for u, v in ((a, b), (b, c), (c, a)):
                g = edge[(v, u)]
                if g not in visible and above(g, p) > 0:
                    visible.add(g)
                    stack.append(g)
        horizon = [(u, v) for g in visible for u, v in zip(faces[g], faces[g][1:] + faces[g][:1])
                   if edge[(v, u)] not in visible]
        pending = [i for g in visible for _, i in outside.pop(g, ()) if i != p]
        for g in visible:
            remove_face(g)
        assign(pending, [add_face(u, v, p) for u, v in horizon])
    planes = {}
    for f, (a, b, c) in faces.items():
        n = plane[f][0]
        g = math.gcd(*n)
        for i in (a, b, c):
            planes.setdefault(i, set()).add(tuple(x // g for x in n))
    return sorted(i for i, s in planes.items() if len(s) >= 3), list(faces.values())


def _triangle_distance(p, a, b, c):
    """The distance from p to the triangle abc (Ericson, Real-Time Collision Detection, 5.1.5)."""
    ab, ac, ap = _minus(b, a), _minus(c, a), _minus(p, a)
    d1, d2 = dot(ab, ap), dot(ac, ap)
    if d1 <= 0 and d2 <= 0:
        q = a
    else:
        bp = _minus(p, b)
        d3, d4 = dot(ab, bp), dot(ac, bp)
        cp = _minus(p, c)
        d5, d6 = dot(ab, cp), dot(ac, cp)
        vc, vb, va = d1 * d4 - d3 * d2, d5 * d2 - d1 * d6, d3 * d6 - d5 * d4
        if d3 >= 0 and d4 <= d3:
            q = b
        elif d6 >= 0 and d5 <= d6:
            q = c
        elif vc <= 0 and d1 >= 0 and d3 <= 0:
            q = [a[k] + d1 / (d1 - d3) * ab[k] for k in range(3)]
        elif vb <= 0 and d2 >= 0 and d6 <= 0:
            q = [a[k] + d2 / (d2 - d6) * ac[k] for k in range(3)]
        elif va <= 0 and d4 - d3 >= 0 and d5 - d6 >= 0:
            w = (d4 - d3) / ((d4 - d3) + (d5 - d6))
            q = [b[k] + w * (c[k] - b[k]) for k in range(3)]
        else:
            den = va + vb + vc
            q = [a[k] + vb / den * ab[k] + vc / den * ac[k] for k in range(3)]
    return math.sqrt(_square(_minus(p, q)))


def hull_of_mesh(points, capacity):
    """(vertices, corners of the whole hull, depth) of distinct points: the hull's corners, or when
    there are more than `capacity`, `capacity` of them (the hull grown from its extreme four by the
    farthest corner until it has `capacity`: convex_hull's budget), and the largest distance the
    reduced hull lies inside the true one (0 when not reduced: at a corner left out, as the distance
    to a convex set is greatest at a vertex). None if the points span no volume."""
    whole = convex_hull(points)
    if whole is None:
        return None
    corners = [points[i] for i in whole[0]]
    if len(corners) <= capacity:
        return corners, len(corners), 0.0
    kept, triangles = convex_hull(corners, capacity)
    # a point outside a convex polytope is nearest to one of the faces it is above
    faces = [(cross(_minus(b, a), _minus(c, a)), a, b, c) for a, b, c in ([corners[k] for k in t] for t in triangles)]
    depth = max(min((_triangle_distance(p, a, b, c) for n, a, b, c in faces if dot(n, _minus(p, a)) > 0), default=0.0)
                for p in (corners[i] for i in set(range(len(corners))) - set(kept)))
    return [corners[i] for i in kept], len(corners), depth


class MeshError(Exception):
    """A mesh that cannot be read (left out with a warning)."""


def read_stl(path):
    """The vertices of an STL file's triangles, binary (its size 84 + 50 per triangle) or ASCII
    ("solid ... vertex x y z ..."), in file order."""
    with open(path, "rb") as f:
        data = f.read()
    if len(data) >= 84 and len(data) == 84 + 50 * struct.unpack_from("<I", data, 80)[0]:
        points = [r[3 + 3 * k:6 + 3 * k] for r in struct.iter_unpack("<12fH", data[84:]) for k in range(3)]
    elif data.lstrip().startswith(b"solid"):
        points = []
        for v in re.findall(rb"\bvertex\s+(\S+)\s+(\S+)\s+(\S+)", data):
            try:
                points.append(tuple(float(x) for x in v))
            except ValueError:
                raise MeshError(f"malformed ASCII STL vertex {b' '.join(v).decode('ascii', 'replace')!r}") from None
    else:
        raise MeshError("not an STL file (binary: its size is not 84 + 50 bytes per triangle; ASCII: no 'solid')")
    if not all(math.isfinite(x) for p in points for x in p):
        raise MeshError("non-finite vertex coordinates")
    return points


def resolve_mesh(filename, urdf_dir):
    """The file a <mesh filename> names, or None: package://PKG/REST is PKG/REST in the URDF's
    directory or the nearest of its parents that has it; file://PATH is PATH; a relative path is
    relative to the URDF's directory."""
    if filename.startswith("package://"):
        rest, d = filename[len("package://"):], os.path.abspath(urdf_dir)
        while not os.path.isfile(os.path.join(d, rest)):
            if os.path.dirname(d) == d:
                return None
            d = os.path.dirname(d)
        return os.path.join(d, rest)
    path = os.path.join(urdf_dir, filename[len("file://"):] if filename.startswith("file://") else filename)
    return path if os.path.isfile(path) else None


class Shape:
    """A collision shape on a body: kind (sphere, box, cylinder, hull: the variant's order), its
    numbers (radius; half extents; radius and half height; the hull's vertices), what the URDF said
    (for a comment), its URDF link, body and placement in the body's frame."""

    def __init__(self, kind, numbers, source, link, body, placement):
        self.kind, self.numbers, self.source = kind, numbers, source
        self.link, self.body, self.placement = link, body, placement


SHAPE_ORDER = ("sphere", "box", "cylinder", "hull")


def _shape(c, where, urdf_dir, opts, warnings):
    """(kind, numbers, source) of a <collision>, or None (left out, with a warning)."""
    if c.kind == "sphere":
        return "sphere", c.size, f"sphere radius {c.size[0]!r}"
    if c.kind == "box":  # ctga's box takes half extents
        return "box", [x / 2 for x in c.size], f"box size {words(c.size)}"
    if c.kind == "cylinder":  # URDF's axis is its frame's z, as ctga's; ctga's takes the half height
        return "cylinder", [c.size[0], c.size[1] / 2], f"cylinder radius {c.size[0]!r} length {c.size[1]!r}"
    if c.kind != "mesh":
        warnings.append(f"{where}: <{c.kind}> is not a URDF geometry (box, sphere, cylinder, mesh): left out")
        return None
    what = f"{where}: mesh {cpp_string(c.filename)}"
    if not c.filename.lower().endswith(".stl"):
        warnings.append(f"{what}: only STL meshes are read: left out")
        return None
    path = resolve_mesh(c.filename, urdf_dir)
    if path is None:
        warnings.append(f"{what}: no such file (relative to the URDF's directory; package:// searched from there "
                        "upwards): left out")
        return None
    try:
        points = read_stl(path)
    except (OSError, MeshError) as e:
        warnings.append(f"{what}: {e.strerror if isinstance(e, OSError) else e}: left out")
        return None
    made = hull_of_mesh(list(dict.fromkeys(tuple(s * x for s, x in zip(c.size, p)) for p in points)),
                        opts.hull_vertices)
    if made is None:
        warnings.append(f"{what}: its points span no volume (fewer than four, or all on one plane): left out")
        return None
    vertices, corners, depth = made
    source = f"mesh {cpp_string(c.filename)}" + ("" if c.size == [1.0, 1.0, 1.0] else f" scale {words(c.size)}")
    if corners > len(vertices):
        warnings.append(f"{what}: its convex hull has {corners} vertices, more than --hull-vertices "
                        f"{opts.hull_vertices}: reduced to {len(vertices)} of them, whose hull lies up to "
                        f"{depth:.3g} m inside the true hull")
        source += f": the convex hull of {len(vertices)} of its {corners} hull vertices"
    else:
        source += f": its convex hull, {corners} vertices"
    return "hull", vertices, source


def collision_geometry(model, links, urdf_path, opts):
    """The robot's collision shapes (model.shapes), link by link in frame order (depth first, a
    link's in document order), each on its link's body at the link's placement there followed by
    the <collision>'s <origin>. A link in the world (fixed base) has its shapes left out, with a
    warning; so have --meshes omit's meshes (one warning) and those that cannot be read."""
    by_name = {l.name: l for l in links}
    urdf_dir = os.path.dirname(os.path.abspath(urdf_path))
    omitted = 0
    for frame in model.frames:
        collisions = by_name[frame.name].collisions
        where = f'link "{frame.name}"'
        if collisions and frame.body < 0:
            model.warnings.append(f"{where} is fixed to the world: its {len(collisions)} <collision> shape(s) left "
                                  "out (the world's shapes are constrained::static_shape, not the robot's)")
            continue
        for c in collisions:
            if c.kind == "mesh" and opts.meshes == "omit":
                omitted += 1
                continue
            made = _shape(c, where, urdf_dir, opts, model.warnings)
            if made is not None:
                model.shapes.append(Shape(*made, frame.name, frame.body, frame.pose.then(c.origin)))
    if omitted:
        model.warnings.append(f"--meshes omit: {omitted} <mesh> collision shape(s) left out")
    pairs = [(a, b, f"--exclude-pair {a},{b}") for a, b in opts.exclude_pairs]
    excluded_pairs(model, pairs + (read_srdf(opts.srdf) if opts.srdf else []))


def excluded_pairs(model, pairs):
    """model.excluded: [(body a, body b, why)] of the pairs of links [(link a, link b, why)], a pair
    on one body or with a link in the world dropped (robot_geometry tests neither), each pair of
    bodies once; a link the URDF does not have is an error naming `why`."""
    body = {f.name: f.body for f in model.frames}
    seen = set()
    for a, b, why in pairs:
        for link in (a, b):
            if link not in body:
                raise UrdfError(f'{why}: no link named "{link}"')
        key = tuple(sorted((body[a], body[b])))
        if key[0] >= 0 and key[0] != key[1] and key not in seen:
            seen.add(key)
            model.excluded.append((key[0], key[1], f'"{a}", "{b}" ({why})'))


def read_srdf(path):
    """The <disable_collisions link1 link2> pairs of an SRDF file: [(link1, link2, where)]."""
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as e:
        raise UrdfError(f"--srdf {path}: not well-formed XML: {e}") from None
    except OSError as e:
        raise UrdfError(f"--srdf {path}: {e.strerror}") from None
    out = []
    for e in root.iter("disable_collisions"):
        if not e.get("link1") or not e.get("link2"):
            raise UrdfError(f'--srdf {path}: <disable_collisions> without link1="..." and link2="..."')
        out.append((e.get("link1"), e.get("link2"), f"--srdf {os.path.basename(path)}"))
    return out


# ---- C++ ----------------------------------------------------------------------------------------

_IDENT = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")
_KEYWORDS = set("""alignas alignof and and_eq asm auto bitand bitor bool break case catch char char8_t char16_t
char32_t class compl concept const consteval constexpr constinit const_cast continue co_await co_return co_yield
decltype default delete do double dynamic_cast else enum explicit export extern false float for friend goto if
inline int long mutable namespace new noexcept not not_eq nullptr operator or or_eq private protected public
register reinterpret_cast requires return short signed sizeof static static_assert static_cast struct switch
template this thread_local throw true try typedef typeid typename union unsigned using virtual void volatile
wchar_t while xor xor_eq std ctga""".split())


def check_namespace(ns, option):
    for part in ns.split("::"):
        if not _IDENT.match(part) or part in _KEYWORDS or part.startswith("__") or re.match(r"^_[A-Z]", part):
            raise UrdfError(f"{option} {ns!r}: not a usable C++ identifier (namespace)")


def cpp_string(s):
    """A C++ string literal with the UTF-8 bytes of s (octal escapes: never longer than 3 digits)."""
    out = []
    for byte in s.encode("utf-8"):
        c = chr(byte)
        if c in '"\\':
            out.append("\\" + c)
        elif 0x20 <= byte < 0x7F:
            out.append(c)
        else:
            out.append(f"\\{byte:03o}")
    return '"' + "".join(out) + '"'


def comment_text(s):
    """s for a // comment: printable ASCII as is, a backslash doubled (never a line continuation),
    other bytes as octal escapes (never a line break)."""
    out = []
    for byte in s.encode("utf-8"):
        c = chr(byte)
        out.append("\\\\" if c == "\\" else c if 0x20 <= byte < 0x7F else f"\\{byte:03o}")
    return "".join(out)


def num(x):
    """T(x), x with repr() precision (the shortest decimal that reads back as the same double)."""
    return f"T({float(x)!r})"


def vec(v):
    return ", ".join(num(x) for x in v)


def words(v):
    return " ".join(repr(float(x)) for x in v)


def motor_lines(pose, indent):
    """The placement motor: ctga::rigid_motion(translator, rotor), as two lines."""
    u, theta = quat_axis_angle(pose.q)
    return [f"{indent}ctga::rigid_motion(ctga::make_translator({vec(pose.p)}),",
            f"{indent}                   ctga::make_rotor({num(theta)}, {vec(u)}))"]


def option_words(name, namespace, gravity, opts):
    """The command line's options as the header repeats them."""
    w = f"--name {name}" + (f" --namespace {namespace}" if namespace != name else "")
    w += " --floating-base" if opts.floating_base else ""
    w += "" if gravity == [0.0, 0.0, -9.81] else " --gravity " + " ".join(repr(g) for g in gravity)
    w += " --keep-fixed" if opts.keep_fixed else ""
    w += " --mimic independent" if opts.mimic != "coupled" else ""
    w += " --mimic-missing independent" if opts.mimic_missing != "refuse" else ""
    w += "" if opts.massless == "refuse" else " --massless " + ("lock" if opts.massless == "lock" else
                                                               f"armature={opts.massless!r}")
    w += "".join(f" --lock {n}" + ("" if v is None else f"={v!r}") for n, v in opts.locks)
    w += "".join(f" --armature {n}={v!r}" for n, v in opts.armatures)
    w += " --strict" if opts.strict else ""
    w += " --meshes omit" if opts.meshes != "hull" else ""
    w += "" if opts.hull_vertices == 32 else f" --hull-vertices {opts.hull_vertices}"
    w += "".join(f" --exclude-pair {a},{b}" for a, b in opts.exclude_pairs)
    w += f" --srdf {os.path.basename(opts.srdf)}" if opts.srdf else ""
    return comment_text(w)


def generate(urdf_path, robot_name, model, name, namespace, gravity, opts):
    root, bodies, frames = model.root, model.bodies, model.frames
    source = os.path.basename(urdf_path)
    dofs = sum(b.dofs for b in bodies)
    L = []
    L.append(f"// Generated by tools/urdf_to_ctga.py from {cpp_string(source)[1:-1]}; do not edit.")
    L.append(f"// Robot {cpp_string(robot_name)}: {len(bodies)} bodies, {len(frames)} frames, {dofs} degrees of "
             f"freedom; options: {option_words(name, namespace, gravity, opts)}")
    L.append("//")
    if opts.floating_base:
        L.append(f"// The root link {cpp_string(root.name)} is body 0 on a floating joint named "
                 f"{cpp_string(bodies[0].joint_name)} (identity")
        L.append("// placement; q: the 8 coefficients of its motor in the world, ctga::motor's order).")
    else:
        dropped = [l for l in model.world_links if l.inertial is not None]
        L.append(f"// The root link {cpp_string(root.name)} is the fixed world (parent -1).")
        if dropped:
            L.append("// Links lumped into the world, their inertia dropped: " +
                     ", ".join(f"{cpp_string(l.name)} (mass {l.inertial.mass!r})" for l in dropped) + ".")
        massless = [l for l in model.world_links if l.inertial is None]
        if massless:
            L.append("// Links in the world without <inertial>: " +
                     ", ".join(cpp_string(l.name) for l in massless) + ".")
    if opts.keep_fixed:
        L.append("// --keep-fixed: every link on a fixed (or locked) joint is its own body on a fixed joint.")
    else:
        L.append("// Links on fixed (and locked) joints are merged into their nearest moving ancestor's body (mass,")
        L.append("// centre of mass and inertia summed exactly in the body frame); every link is a frame (fixed_frame).")
    independent = [b for b in bodies if b.urdf_joint is not None and b.urdf_joint.mimic is not None
                   and b.link is not None and b.urdf_joint.name not in model.mimics and b.dofs > 0]
    if independent and opts.mimic != "coupled":
        L.append("// --mimic independent: the <mimic> joints " + ", ".join(cpp_string(b.joint_name) for b in independent)
                 + " are independent coordinates.")
    elif independent:
        L.append("// --mimic-missing independent: the <mimic> joints " +
                 ", ".join(cpp_string(b.joint_name) for b in independent) +
                 " name no joint: they are independent coordinates.")
    if model.locks:
        L.append("// Locked joints (fixed at the value: revolute rad, prismatic m; planar, floating: the origin): " +
                 ", ".join(f"{cpp_string(n)} at {lk.value!r} ({comment_text(lk.why)})" for n, lk in model.locks.items())
                 + ".")
    if model.armatures:
        L.append("// Armatures (a joint's rotor inertia: revolute kg m^2, prismatic kg): " +
                 ", ".join(f"{cpp_string(n)} {v!r} ({why})" for n, (v, why) in model.armatures.items()) + ".")
    L.append("// Body frame = the URDF child link's frame; placement = the joint's <origin> (at q = 0).")
    if opts.strict:
        L.append("// --strict: bodies with mass use ctga's physical check (no questionable inertia was found).")
    else:
        L.append("// Mass properties are built with ctga::mass_check::as_given (finite, m >= 0, checked here).")
    for w in model.warnings:
        L.append(f"// Warning: {comment_text(w)}")
    kinds = [k for k in SHAPE_ORDER if any(s.kind == k for s in model.shapes)]
    if kinds:
        L.append("// Joint limits and <dynamics>: make_limits<T>(); <collision>: make_geometry<T>() (below). Ignored:")
        L.append("// <safety_controller>, <calibration>, visuals, transmissions. Floating joints read 8 motor coefficients.")
    else:
        L.append("// Joint limits and <dynamics>: make_limits<T>() (below). Ignored: <safety_controller>, <calibration>,")
        L.append("// visuals, collisions, transmissions. Floating joints read 8 motor coefficients.")
    L.append("#pragma once")
    L.append("")
    L.append("#include <array>")
    L.append("#include <cstddef>")
    L.extend(["#include <span>"] if "hull" in kinds else [])
    L.append("#include <string_view>")
    L.append("")
    L.append("#include <ctga/ctga.hpp>")
    L.extend(f"#include <ctga/collision/{SHAPE_HEADERS[k]}>" for k in kinds)
    L.extend(["#include <ctga/collision/shape_set.hpp>", "#include <ctga/constrained/robot_geometry.hpp>"] if kinds
             else [])
    L.append("")
    L.append(f"namespace {namespace} {{")
    L.append("")
    L.append("using tree = ctga::chains::tree<")
    for b in bodies:
        L.append(f"    ctga::chains::link<{b.parent}, {b.cpp_joint}>,  "
                 f"// body {b.index}: {cpp_string(b.name)}, joint {cpp_string(b.joint_name)}")
    for k, f in enumerate(frames):
        end = ">;" if k == len(frames) - 1 else ","
        L.append(f"    ctga::chains::fixed_frame<{cpp_string(f.name)}, {f.body}>{end}  // frame {k}")
    L.append("")
    L.append("// Body i's URDF link (planar joints' virtual bodies: \"<joint>_x\", \"<joint>_y\") and the joint")
    L.append("// joining it to its parent body")
    L.append("inline constexpr std::array<std::string_view, tree::size> body_names{")
    L.extend(f"    {cpp_string(b.name)}," for b in bodies)
    L.append("};")
    L.append("inline constexpr std::array<std::string_view, tree::size> joint_names{")
    L.extend(f"    {cpp_string(b.joint_name)}," for b in bodies)
    L.append("};")
    L.append("")
    L.append("// The model's parameters; an error (ctga::error_code) if a number is rejected by ctga's checks.")
    L.append("template <class T = double>")
    L.append("constexpr ctga::checked<ctga::chains::model<tree, T>> make_model() noexcept {")
    L.append("    ctga::chains::model<tree, T> m;")
    L.append(f"    m.gravity = ctga::vec3<T>{{{vec(gravity)}}};")
    for b in bodies:
        desc = b.kind
        if b.axis is not None:
            desc += ", axis " + words(b.axis)
        if b.coupling is not None:
            desc += f", mimic: q = {b.coupling[0]!r} q[{b.urdf_joint.mimic.master}] + {b.coupling[1]!r}"
        L.append(f"    {{  // body {b.index}: {cpp_string(b.name)}, joint {cpp_string(b.joint_name)} ({desc})")
        j = b.urdf_joint
        if j is not None and b.placement is not None and not b.placement.is_identity():
            origin = f"origin xyz {words(j.xyz)} rpy {words(j.rpy)}"
            pf = next((f for f in frames if f.name == j.parent), None)
            if pf is not None and pf.via:
                origin += f", after link {cpp_string(j.parent)}'s fixed placement in body {pf.body}"
            if j.name in model.locks:
                origin += f", then the joint's motion at its locked value {model.locks[j.name].value!r}"
            L.append(f"        // placement: {origin}")
        merged = [l.name for l, _ in b.parts[1:]]
        if merged:
            L.append("        // merged: " + ", ".join(cpp_string(n) for n in merged) +
                     f"; total mass {b.mass!r}")
        L.append(f"        const auto x = ctga::chains::make_link<{b.cpp_joint}>(")
        motor = motor_lines(b.placement, "            ")
        motor[-1] += ","
        L.extend(motor)
        check = "" if opts.strict and b.mass > 0 else ", ctga::mass_check::as_given"
        L.append(f"            ctga::make_mass_properties({num(b.mass)}, ctga::vec3<T>{{{vec(b.com)}}},")
        L.append(f"                                       ctga::mat3<T>{{{{{{{vec(b.tensor[0])}}},")
        L.append(f"                                                      {{{vec(b.tensor[1])}}},")
        L.append(f"                                                      {{{vec(b.tensor[2])}}}}}}}{check})")
        extra = []
        if b.coupling is not None:
            extra.append(f"ctga::chains::coupling<T>{{{vec(b.coupling)}}}")
        if b.takes_axis:  # the joints whose axis is a run-time parameter
            extra.append(f"ctga::vec3<T>{{{vec(b.axis)}}}")
        if extra:
            L[-1] += ","
            for k, e in enumerate(extra):
                L.append(f"            {e}" + ("," if k < len(extra) - 1 else ""))
        L[-1] += ");"
        L.append("        if (!x) return {{}, x.error};")
        L.append(f"        m.template link<{b.index}>() = *x;")
        if b.armature is not None:
            L.append(f"        m.template link<{b.index}>().armature = {num(b.armature)};  "
                     f"// {model.armatures[b.urdf_joint.name][1]}")
        L.append("    }")
    # the frames' placements as a table and one loop (one copy of the motor code, whatever the count)
    L.append("    // each frame's placement in its body: translation (x, y, z), then rotation angle and unit axis")
    L.append(f"    const T frame_placements[{len(frames)}][7] = {{")
    for k, f in enumerate(frames):
        where = "the world" if f.body < 0 else f"body {f.body}"
        via = f" (through {', '.join(cpp_string(v) for v in f.via)})" if f.via else ""
        u, theta = quat_axis_angle(f.pose.q)
        L.append(f"        {{{vec(f.pose.p)}, {num(theta)}, {vec(u)}}},  // frame {k}: link {cpp_string(f.name)} in {where}{via}")
    L.append("    };")
    L.append("    for (std::size_t k = 0; k < tree::frame_count; ++k) {")
    L.append("        const T* x = frame_placements[k];")
    L.append("        const auto f = ctga::chains::make_frame<T>(")
    L.append("            ctga::rigid_motion(ctga::make_translator(x[0], x[1], x[2]), ctga::make_rotor(x[3], x[4], x[5], x[6])));")
    L.append("        if (!f) return {{}, f.error};")
    L.append("        m.frames[k] = *f;")
    L.append("    }")
    L.append("    if (const int b = ctga::chains::massless_subtree(m); b >= 0) return {{}, "
             "ctga::error_code::massless_subtree};")
    L.append("    return {m, ctga::error_code::none};")
    L.append("}")
    L.append("")
    L.extend(limits_lines(model))
    L.append("")
    if kinds:
        L.extend(geometry_lines(model, kinds))
        L.append("")
    L.append(f"}}  // namespace {namespace}")
    return "\n".join(L) + "\n"


def limits_lines(model):
    """make_limits<T>(): the URDF's <limit> and <dynamics> per velocity number (a missing bound or
    limit is none, a missing damping or friction 0), checked by ctga::chains::check_limits."""
    L = ["// The joints' <limit> (position bounds, velocity, effort) and <dynamics> (damping, friction) per",
         "// velocity number (tree::v_offset[i] is body i's first); a missing attribute: no bound (+-infinity),",
         "// damping and friction 0. Floating joints and planar joints are unlimited (URDF gives them no limits).",
         "template <class T = double>",
         "constexpr ctga::checked<ctga::chains::joint_limits<tree, T>> make_limits() noexcept {",
         "    auto l = ctga::chains::unlimited<tree, T>();"]
    k = 0
    for b in model.bodies:
        j = b.urdf_joint
        what = f"joint {cpp_string(b.joint_name)} (body {b.index}"
        if b.dofs == 0:
            if b.coupling is not None:
                L.append(f"    // {what}, a <mimic> of {cpp_string(j.mimic.master)}: no coordinate, its limits dropped)")
            continue
        span = f"v {k}" if b.dofs == 1 else f"v {k}..{k + b.dofs - 1}"
        if j is None or j.kind not in ONE_DOF:
            L.append(f"    // {span}: {what}, {b.kind}): unlimited")
        else:
            keys = LIMIT_KEYS[2:] if j.kind == "continuous" else LIMIT_KEYS  # continuous: no position bounds
            notes = []
            for tag, given, wanted in (("limit", j.limit, keys), ("dynamics", j.dynamics, DYNAMICS_KEYS)):
                if given is None:
                    notes.append(f"no <{tag}>")
                elif [a for a in wanted if a not in given]:
                    notes.append("no " + ", ".join(a for a in wanted if a not in given))
            if j.kind == "continuous" and j.limit is not None and ("lower" in j.limit or "upper" in j.limit):
                notes.append("continuous: its lower, upper ignored")
            given = {a: x for a, x in (j.limit or {}).items() if a in keys}
            given.update(j.dynamics or {})
            L.append(f"    // {span}: {what}, {j.kind})" + (": " + "; ".join(notes) if notes else ""))
            for a in LIMIT_KEYS + DYNAMICS_KEYS:
                if a in given:
                    L.append(f"    l.{a}[{k}] = {num(given[a])};")
        k += b.dofs
    for name, lk in model.locks.items():
        L.append(f"    // joint {cpp_string(name)}: locked at {lk.value!r}, no coordinate, its limits dropped")
    L.append("    return ctga::chains::check_limits(l);")
    L.append("}")
    return L


SHAPE_HEADERS = {"sphere": "sphere.hpp", "box": "box.hpp", "cylinder": "cylinder.hpp", "hull": "hull.hpp"}


def geometry_lines(model, kinds):
    """collision_shape<T> (the variant of the kinds present), collision_count, collision_links and
    make_geometry<T>(): each shape made by ctga's checked constructor and attached to its body at its
    placement (the first error returned), then the excluded pairs of bodies."""
    shapes = model.shapes
    capacity = max((len(s.numbers) for s in shapes if s.kind == "hull"), default=0)
    cpp_kind = {"sphere": "ctga::collision::sphere<T>", "box": "ctga::collision::box<T>",
                "cylinder": "ctga::collision::cylinder<T>", "hull": f"ctga::collision::convex_hull<T, {capacity}>"}
    geometry = "ctga::constrained::robot_geometry<tree, collision_shape<T>, T, collision_count>"
    L = ["// Collision geometry: the URDF's <collision> elements, link by link (depth first), each on its link's",
         "// body at the link's placement there followed by the element's <origin>. A box takes half extents, a",
         "// cylinder its radius and half height (its axis z, as URDF's); a mesh is the convex hull of its STL",
         "// file's vertices (scaled). The shape kinds present, in ctga's variant:",
         "template <class T>",
         f"using collision_shape = ctga::collision::shape<{', '.join(cpp_kind[k] for k in kinds)}>;",
         f"inline constexpr std::size_t collision_count = {len(shapes)};",
         "// The URDF link each shape comes from",
         "inline constexpr std::array<std::string_view, collision_count> collision_links{"]
    L.extend(f"    {cpp_string(s.link)}," for s in shapes)
    L += ["};",
          "",
          "// The shapes on their bodies; an error (ctga::error_code) if a size or a hull is rejected by ctga's",
          "// checks.",
          "template <class T = double>",
          f"constexpr ctga::checked<{geometry}> make_geometry() noexcept {{",
          f"    {geometry} g;",
          "    // each shape's placement in its body: translation (x, y, z), then rotation angle and unit axis",
          "    const T placements[collision_count][7] = {"]
    for k, s in enumerate(shapes):
        u, theta = quat_axis_angle(s.placement.q)
        L.append(f"        {{{vec(s.placement.p)}, {num(theta)}, {vec(u)}}},  // shape {k}: link {cpp_string(s.link)} "
                 f"in body {s.body}")
    L += ["    };",
          "    // shape k, made by its checked constructor, attached to body b at its placement",
          "    const auto place = [&](std::size_t k, int b, const auto& made) {",
          "        if (!made) return made.error;",
          "        const T* x = placements[k];",
          "        const auto at = ctga::rigid_motion(ctga::make_translator(x[0], x[1], x[2]), "
          "ctga::make_rotor(x[3], x[4], x[5], x[6]));",
          "        return g.attach(b, *made, ctga::map_of(at));",
          "    };"]
    for k, s in enumerate(shapes):
        L.append(f"    // shape {k}: link {cpp_string(s.link)}, {comment_text(s.source)}")
        if s.kind == "hull":
            L.append(f"    const std::array<ctga::vec3<T>, {len(s.numbers)}> hull_{k}{{{{")
            L.extend(f"        {{{vec(p)}}}," for p in s.numbers)
            L.append("    }};")
            made = f"ctga::collision::make_hull<{capacity}, T>(std::span<const ctga::vec3<T>>(hull_{k}))"
        else:
            made = f"ctga::collision::make_{s.kind}({vec(s.numbers)})"
        L.append(f"    if (const auto e = place({k}, {s.body}, {made}); e != ctga::error_code::none) return {{{{}}, e}};")
    if model.excluded:
        L.append("    // pairs of bodies never tested against each other (--exclude-pair, --srdf)")
        L.append(f"    const int excluded[{len(model.excluded)}][2] = {{")
        L.extend(f"        {{{a}, {b}}},  // links {comment_text(why)}" for a, b, why in model.excluded)
        L += ["    };",
              "    for (const auto& p : excluded)",
              "        if (const auto e = g.exclude(p[0], p[1]); e != ctga::error_code::none) return {{}, e};"]
    L += ["    return {g, ctga::error_code::none};", "}"]
    return L


# ---- command line -------------------------------------------------------------------------------


def _joint_value(text, option, joint_names, need_value):
    """JOINT[=VALUE] of --lock / --armature: (joint, value or None). A name that is a joint's whole
    name is taken as it stands (joint names may hold '='); else the text splits at its last '='."""
    if text in joint_names and not need_value:
        return text, None
    name, eq, value = text.rpartition("=")
    if not eq:
        if need_value:
            raise UrdfError(f"{option} {text}: expected JOINT=VALUE")
        return text, None
    return name, parse_number(value, f"{option} {text}")


def _massless_choice(text):
    if text in ("refuse", "lock"):
        return text
    if text.startswith("armature="):
        value = parse_number(text[len("armature="):], f"--massless {text}")
        if not value > 0:
            raise UrdfError(f"--massless {text}: the armature must be positive")
        return value
    raise UrdfError(f"--massless {text}: expected refuse, lock or armature=VALUE")


def _hull_capacity(text):
    if not re.match(r"^\d+$", text) or not 4 <= int(text) <= 8192:
        raise UrdfError(f"--hull-vertices {text}: expected a whole number from 4 to 8192 (ctga::collision::convex_hull's "
                        "capacity)")
    return int(text)


def _link_pair(text, link_names):
    """LINK_A,LINK_B of --exclude-pair: split at the comma that leaves two link names (names may hold
    commas); an error naming the link that is not one when there is one comma."""
    splits = [(text[:i], text[i + 1:]) for i, c in enumerate(text) if c == ","]
    for a, b in splits:
        if a in link_names and b in link_names:
            return a, b
    if len(splits) == 1:
        missing = next(n for n in splits[0] if n not in link_names)
        raise UrdfError(f'--exclude-pair {text}: no link named "{missing}"')
    raise UrdfError(f"--exclude-pair {text}: expected LINK_A,LINK_B, two links of the URDF")


def main(argv=None):
    ap = argparse.ArgumentParser(prog=PROG, description="Convert a URDF's joint tree into a ctga::chains header.")
    ap.add_argument("urdf", help="the URDF file")
    ap.add_argument("--name", required=True, help="the robot's C++ name (the namespace unless --namespace)")
    ap.add_argument("--namespace", help="the namespace of the declarations (a::b allowed); default: --name")
    ap.add_argument("--floating-base", action="store_true",
                    help="the root link becomes body 0 on a floating joint (else it is the fixed world)")
    ap.add_argument("--gravity", nargs=3, metavar=("GX", "GY", "GZ"), default=["0", "0", "-9.81"],
                    help="gravity in the world frame (default 0 0 -9.81)")
    ap.add_argument("--keep-fixed", action="store_true",
                    help="keep every link on a fixed joint as its own body on a fixed joint (default: merge it "
                         "into its moving ancestor's body and keep it as a frame)")
    ap.add_argument("--mimic", choices=("coupled", "independent"), default="coupled",
                    help="coupled (default): a <mimic> joint follows its master (ctga::chains::mimic); "
                         "independent: it is an ordinary joint with its own coordinate")
    ap.add_argument("--mimic-missing", choices=("refuse", "independent"), default="refuse",
                    help="a <mimic> naming a joint that does not exist: refuse (default: an error), or independent "
                         "(that joint becomes an ordinary joint, with a warning)")
    ap.add_argument("--massless", default="refuse", metavar="refuse|lock|armature=VALUE",
                    help="a moving joint with no inertia below it (no mass, no armature, for a revolute joint no "
                         "rotational inertia): refuse (default: an error naming it), lock (fixed at 0, clamped into "
                         "its <limit>), or armature=VALUE (a rotor inertia, kg m^2 or kg, for each such 1-dof joint)")
    ap.add_argument("--lock", action="append", default=[], metavar="JOINT[=VALUE]",
                    help="make JOINT fixed at VALUE (rad or m; default 0 clamped into its <limit>; a planar or "
                         "floating joint: at its origin); its links stay frames; repeatable")
    ap.add_argument("--armature", action="append", default=[], metavar="JOINT=VALUE",
                    help="give the 1-dof JOINT the rotor inertia VALUE (kg m^2 or kg); repeatable")
    ap.add_argument("--meshes", choices=("hull", "omit"), default="hull",
                    help="<collision> meshes: hull (default: an STL file's convex hull; other formats are left out "
                         "with a warning) or omit (every mesh left out, one warning)")
    ap.add_argument("--hull-vertices", default="32", metavar="N",
                    help="a mesh's convex hull keeps at most N vertices (4 to 8192, default 32); a hull with more is "
                         "reduced to N of its extreme points, with a warning stating how far inside the true hull the "
                         "reduced one lies")
    ap.add_argument("--exclude-pair", action="append", default=[], metavar="LINK_A,LINK_B",
                    help="the bodies of the two links are never tested against each other (make_geometry's "
                         "robot_geometry::exclude); repeatable")
    ap.add_argument("--srdf", metavar="FILE",
                    help="an SRDF file: its <disable_collisions link1 link2> pairs are excluded as by --exclude-pair")
    ap.add_argument("--strict", action="store_true",
                    help="questionable inertia (not positive definite, triangle inequality) is an error, and "
                         "bodies with mass use ctga's physical check")
    ap.add_argument("-o", "--output", help="the header to write (default: standard output)")
    args = ap.parse_args(argv)
    try:
        check_namespace(args.name, "--name")
        namespace = args.namespace if args.namespace is not None else args.name
        check_namespace(namespace, "--namespace")
        gravity = [parse_number(g, "--gravity") for g in args.gravity]
        massless = _massless_choice(args.massless)
        robot_name, links, joints = parse_urdf(args.urdf)
        names = {j.name for j in joints}
        opts = Options(args.floating_base, args.keep_fixed, args.mimic, args.mimic_missing, args.strict, massless,
                       [_joint_value(t, "--lock", names, False) for t in args.lock],
                       [_joint_value(t, "--armature", names, True) for t in args.armature],
                       args.meshes, _hull_capacity(args.hull_vertices),
                       [_link_pair(t, {l.name for l in links}) for t in args.exclude_pair], args.srdf)
        model = build_tree(links, joints, opts)
        collision_geometry(model, links, args.urdf, opts)
        for w in model.warnings:
            print(f"{PROG}: warning: {w}", file=sys.stderr)
        text = generate(args.urdf, robot_name, model, args.name, namespace, gravity, opts)
    except UrdfError as e:
        print(f"{PROG}: {e}", file=sys.stderr)
        return 1
    if args.output is None:
        sys.stdout.write(text)
        return 0
    # written whole or not at all: a failed run never leaves a header a build would take as current
    tmp = args.output + ".tmp"
    try:
        os.makedirs(os.path.dirname(os.path.abspath(args.output)), exist_ok=True)
        with open(tmp, "w", encoding="utf-8", newline="\n") as f:
            f.write(text)
        os.replace(tmp, args.output)
    except OSError as e:
        print(f"{PROG}: {args.output}: {e.strerror}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
