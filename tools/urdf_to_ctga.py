#!/usr/bin/env python3
"""URDF -> C++: a robot's joint tree as a ctga::chains tree type and a function building its
parameters (a ctga::chains::model), in one header.

    python3 tools/urdf_to_ctga.py robot.urdf --name arm7 -o arm7.hpp
    python3 tools/urdf_to_ctga.py dog.urdf --name dog --floating-base --gravity 0 0 -9.81

The header declares, in namespace NAME (or --namespace):

    using tree = ctga::chains::tree<ctga::chains::link<parent, joint>, ...>;
    inline constexpr std::array<std::string_view, tree::size> body_names{...};   // URDF link names
    inline constexpr std::array<std::string_view, tree::size> joint_names{...};  // URDF joint names
    template <class T = double>
    constexpr ctga::checked<ctga::chains::model<tree, T>> make_model() noexcept;

How URDF maps onto ctga::chains (include/ctga/chains/tree.hpp, joints.hpp):
  * a URDF child link's frame is the joint frame moved by the joint, which is ctga's body frame;
    the joint's <origin xyz rpy> is the body's placement in its parent link's frame at q = 0
    (R = Rz(yaw) Ry(pitch) Rx(roll), emitted as a translation and an axis-angle rotation);
  * revolute and continuous -> revolute_x/_y/_z when the normalised <axis> is exactly +x, +y or
    +z, else revolute_about with the normalised axis; prismatic -> prismatic_x/_y/_z or
    prismatic_along; fixed -> fixed; floating -> floating (q: the 8 coefficients of a motor);
  * a link's <inertial>: mass, centre of mass = <origin xyz>, and the tensor about the centre of
    mass rotated into the link frame, I = R_rpy I_inertial R_rpy^T;
  * the root link (no joint's child) is the fixed world and its <inertial> is dropped; with
    --floating-base it becomes body 0 on a floating joint (identity placement) and keeps it;
  * bodies in depth-first order from the root, children in document order.
Joint limits, dynamics (damping, friction), visuals, collisions, transmissions and Gazebo
extensions are ignored. Anything that cannot be represented exactly (planar joints, <mimic>, a
graph that is not a tree, a body without mass) is an error: exit status 1 and a message naming
the element on stderr; no header is written.

Standard library only.
"""

import argparse
import math
import os
import re
import sys
import xml.etree.ElementTree as ET

PROG = "urdf_to_ctga"
SUPPORTED_TYPES = ("revolute", "continuous", "prismatic", "fixed", "floating")


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


# ---- rotations --------------------------------------------------------------------------------


def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def transpose(a):
    return [[a[j][i] for j in range(3)] for i in range(3)]


def rpy_matrix(rpy):
    """URDF's fixed-axis roll, pitch, yaw: R = Rz(yaw) Ry(pitch) Rx(roll)."""
    r, p, y = rpy
    cr, sr, cp, sp, cy, sy = math.cos(r), math.sin(r), math.cos(p), math.sin(p), math.cos(y), math.sin(y)
    rx = [[1.0, 0.0, 0.0], [0.0, cr, -sr], [0.0, sr, cr]]
    ry = [[cp, 0.0, sp], [0.0, 1.0, 0.0], [-sp, 0.0, cp]]
    rz = [[cy, -sy, 0.0], [sy, cy, 0.0], [0.0, 0.0, 1.0]]
    return matmul(rz, matmul(ry, rx))


def rpy_axis_angle(rpy):
    """(u, theta) with Rot(u, theta) = Rz(yaw) Ry(pitch) Rx(roll), theta in [0, pi], u a unit
    vector (right hand). Through the quaternion q = qz(yaw) qy(pitch) qx(roll), whose half-angle
    products are exact to rounding at every angle (no acos of a trace)."""
    if rpy == [0.0, 0.0, 0.0]:
        return [0.0, 0.0, 1.0], 0.0
    hr, hp, hy = (a / 2 for a in rpy)
    cr, sr, cp, sp, cy, sy = math.cos(hr), math.sin(hr), math.cos(hp), math.sin(hp), math.cos(hy), math.sin(hy)
    w = cr * cp * cy + sr * sp * sy
    x = sr * cp * cy - cr * sp * sy
    y = cr * sp * cy + sr * cp * sy
    z = cr * cp * sy - sr * sp * cy
    if w < 0:
        w, x, y, z = -w, -x, -y, -z
    s = math.sqrt(x * x + y * y + z * z)
    if s == 0.0:
        return [0.0, 0.0, 1.0], 0.0
    return [x / s, y / s, z / s], 2.0 * math.atan2(s, w)


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


# ---- the URDF -----------------------------------------------------------------------------------


class Inertial:
    def __init__(self, mass, com, tensor):
        self.mass = mass      # kg
        self.com = com        # centre of mass, link frame
        self.tensor = tensor  # about the centre of mass, link axes (symmetric)


class Link:
    def __init__(self, name, inertial, inertial_error):
        self.name = name
        self.inertial = inertial              # Inertial or None
        self.inertial_error = inertial_error  # why a present <inertial> is unusable, or None


class Joint:
    def __init__(self, name, kind, parent, child, xyz, rpy, axis):
        self.name = name
        self.kind = kind      # one of SUPPORTED_TYPES
        self.parent = parent  # link names
        self.child = child
        self.xyz = xyz
        self.rpy = rpy
        self.axis = axis      # unit, joint frame (revolute, continuous, prismatic), else None


def _origin(elem, where):
    o = elem.find("origin")
    if o is None:
        return [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]
    return (parse_vector(o.get("xyz"), f"{where}: <origin xyz>", (0.0, 0.0, 0.0)),
            parse_vector(o.get("rpy"), f"{where}: <origin rpy>", (0.0, 0.0, 0.0)))


def _parse_inertial(link_elem, where):
    """(Inertial or None, error or None). The numbers are parsed (a malformed one is an error at
    once); whether a missing or massless inertial matters depends on whether the link becomes a
    body, so those are returned as errors for later."""
    elems = link_elem.findall("inertial")
    if not elems:
        return None, f"{where}: no <inertial> (a link that becomes a body needs its mass)"
    if len(elems) > 1:
        raise UrdfError(f"{where}: more than one <inertial>")
    inertial = elems[0]
    xyz, rpy = _origin(inertial, f"{where} <inertial>")
    mass_elem = inertial.find("mass")
    if mass_elem is None:
        raise UrdfError(f"{where}: <inertial> has no <mass>")
    mass = parse_number(mass_elem.get("value"), f"{where}: <mass value>")
    inertia_elem = inertial.find("inertia")
    if inertia_elem is None:
        raise UrdfError(f"{where}: <inertial> has no <inertia>")
    i = {k: parse_number(inertia_elem.get(k), f"{where}: <inertia {k}>")
         for k in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")}
    tensor = [[i["ixx"], i["ixy"], i["ixz"]], [i["ixy"], i["iyy"], i["iyz"]], [i["ixz"], i["iyz"], i["izz"]]]
    error = None
    if not mass > 0:
        error = f"{where}: mass {mass!r} is not positive"
    else:
        ev = symmetric_eigenvalues(tensor)
        tol = 64 * sys.float_info.epsilon * (abs(tensor[0][0]) + abs(tensor[1][1]) + abs(tensor[2][2]))
        if not ev[0] > 0:
            error = f"{where}: the inertia tensor is not positive definite (principal moments {ev})"
        elif ev[2] > ev[0] + ev[1] + tol:
            error = (f"{where}: the inertia tensor's principal moments {ev} violate the triangle inequality "
                     "I_i <= I_j + I_k")
    if rpy != [0.0, 0.0, 0.0]:
        r = rpy_matrix(rpy)
        rotated = matmul(r, matmul(tensor, transpose(r)))
        tensor = [[rotated[min(a, b)][max(a, b)] for b in range(3)] for a in range(3)]  # exactly symmetric
    return Inertial(mass, xyz, tensor), error


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
        inertial, error = _parse_inertial(le, where)
        links.append(Link(name, inertial, error))

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
        if je.find("mimic") is not None:
            raise UrdfError(f"{where}: <mimic> is not supported (ctga's joints are independent coordinates)")
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
        axis = None
        if kind in ("revolute", "continuous", "prismatic"):
            ae = je.find("axis")
            a = parse_vector(ae.get("xyz") if ae is not None else None, f"{where}: <axis xyz>", (1.0, 0.0, 0.0))
            n = math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2])
            if n == 0.0:
                raise UrdfError(f"{where}: the axis is zero")
            axis = [c / n for c in a]
            if a.count(0.0) == 2:  # a coordinate axis: exactly, not to rounding
                axis = [c / abs(c) if c != 0.0 else 0.0 for c in a]
        joints.append(Joint(name, kind, ends["parent"], ends["child"], xyz, rpy, axis))
    return root.get("name", ""), links, joints


# ---- the tree -----------------------------------------------------------------------------------


class Body:
    def __init__(self, index, parent, link, joint_name, kind, axis, xyz, rpy, cpp_joint):
        self.index, self.parent, self.link = index, parent, link
        self.joint_name, self.kind, self.axis, self.xyz, self.rpy = joint_name, kind, axis, xyz, rpy
        self.cpp_joint = cpp_joint


def cpp_joint_of(joint):
    if joint.kind == "fixed":
        return "fixed"
    if joint.kind == "floating":
        return "floating"
    prefix = "prismatic" if joint.kind == "prismatic" else "revolute"
    for i, letter in enumerate("xyz"):
        if joint.axis == [1.0 if k == i else 0.0 for k in range(3)]:
            return f"{prefix}_{letter}"
    return "prismatic_along" if joint.kind == "prismatic" else "revolute_about"


def build_tree(links, joints, floating_base):
    """(root Link, [Body] in depth-first order)."""
    if not links:
        raise UrdfError("the URDF has no <link>")
    by_name = {l.name: l for l in links}
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

    bodies = []

    def needs_inertial(link):
        if link.inertial_error is not None:
            raise UrdfError(link.inertial_error)

    if floating_base:
        needs_inertial(root)
        used = {j.name for j in joints}
        name = "floating_base"
        while name in used:
            name += "_"
        bodies.append(Body(0, -1, root, name, "floating", None, [0.0] * 3, [0.0] * 3, "floating"))
    # depth first, children in document order (an explicit stack: no recursion limit)
    stack = [(j, 0 if floating_base else -1) for j in reversed(children[root.name])]
    while stack:
        j, parent = stack.pop()
        link = by_name[j.child]
        needs_inertial(link)
        body = Body(len(bodies), parent, link, j.name, j.kind, j.axis, j.xyz, j.rpy, cpp_joint_of(j))
        bodies.append(body)
        stack.extend((c, body.index) for c in reversed(children[link.name]))
    unreachable = [l.name for l in links if l is not root and all(b.link is not l for b in bodies)]
    if unreachable:
        raise UrdfError(f'link "{unreachable[0]}" is not connected to the root link "{root.name}" '
                        "(a loop: the URDF is not a tree)")
    if not bodies:
        raise UrdfError(f'the robot has no bodies: the root link "{root.name}" is the world and no joint moves '
                        "anything (use --floating-base to make it a free body)")
    return root, bodies


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


def num(x):
    """T(x), x with repr() precision (the shortest decimal that reads back as the same double)."""
    return f"T({float(x)!r})"


def vec(v):
    return ", ".join(num(x) for x in v)


def generate(urdf_path, robot_name, root, bodies, name, namespace, floating_base, gravity):
    source = os.path.basename(urdf_path)
    L = []
    L.append(f"// Generated by tools/urdf_to_ctga.py from {cpp_string(source)[1:-1]}; do not edit.")
    opts = f"--name {name}" + (f" --namespace {namespace}" if namespace != name else "")
    opts += " --floating-base" if floating_base else ""
    opts += "" if gravity == [0.0, 0.0, -9.81] else " --gravity " + " ".join(repr(g) for g in gravity)
    L.append(f"// Robot {cpp_string(robot_name)}, {len(bodies)} bodies; options: {opts}")
    L.append("//")
    if floating_base:
        L.append(f"// The root link {cpp_string(root.name)} is body 0 on a floating joint named "
                 f"{cpp_string(bodies[0].joint_name)} (identity")
        L.append("// placement; q: the 8 coefficients of its motor in the world, ctga::motor's order).")
    else:
        dropped = ("it has no <inertial>" if root.inertial is None
                   else f"its <inertial> (mass {root.inertial.mass!r}) is dropped")
        L.append(f"// The root link {cpp_string(root.name)} is the fixed world (parent -1); {dropped}.")
    L.append("// Body frame = the URDF child link's frame; placement = the joint's <origin> (at q = 0).")
    L.append("// Ignored: joint limits (<limit>, <safety_controller>), <dynamics> (damping, friction),")
    L.append("// <calibration>, visuals, collisions, transmissions. Floating joints read 8 motor coefficients.")
    L.append("#pragma once")
    L.append("")
    L.append("#include <array>")
    L.append("#include <string_view>")
    L.append("")
    L.append("#include <ctga/ctga.hpp>")
    L.append("")
    L.append(f"namespace {namespace} {{")
    L.append("")
    L.append("using tree = ctga::chains::tree<")
    for k, b in enumerate(bodies):
        end = ">;" if k == len(bodies) - 1 else ","
        L.append(f"    ctga::chains::link<{b.parent}, ctga::chains::{b.cpp_joint}>{end}  "
                 f"// body {b.index}: link {cpp_string(b.link.name)}, joint {cpp_string(b.joint_name)}")
    L.append("")
    L.append("// URDF link names (body i's frame) and the names of the joints joining them to their parents")
    L.append("inline constexpr std::array<std::string_view, tree::size> body_names{")
    L.extend(f"    {cpp_string(b.link.name)}," for b in bodies)
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
        inertial = b.link.inertial
        u, theta = rpy_axis_angle(b.rpy)
        axis = b.axis if b.axis is not None else [0.0, 0.0, 1.0]
        L.append(f"    {{  // body {b.index}: link {cpp_string(b.link.name)}, joint {cpp_string(b.joint_name)} "
                 f"({b.kind}{', axis ' + ' '.join(repr(a) for a in b.axis) if b.axis is not None else ''}); "
                 f"origin xyz {' '.join(repr(x) for x in b.xyz)} rpy {' '.join(repr(x) for x in b.rpy)}")
        L.append(f"        const auto x = ctga::chains::make_link<ctga::chains::{b.cpp_joint}>(")
        L.append(f"            ctga::rigid_motion(ctga::make_translator({vec(b.xyz)}),")
        L.append(f"                               ctga::make_rotor({num(theta)}, {vec(u)})),")
        L.append(f"            ctga::make_mass_properties({num(inertial.mass)}, ctga::vec3<T>{{{vec(inertial.com)}}},")
        L.append(f"                                       ctga::mat3<T>{{{{{{{vec(inertial.tensor[0])}}},")
        L.append(f"                                                      {{{vec(inertial.tensor[1])}}},")
        if b.cpp_joint in ("revolute_about", "prismatic_along"):  # the joints whose axis is a run-time parameter
            L.append(f"                                                      {{{vec(inertial.tensor[2])}}}}}}}),")
            L.append(f"            ctga::vec3<T>{{{vec(axis)}}});")
        else:
            L.append(f"                                                      {{{vec(inertial.tensor[2])}}}}}}}));")
        L.append("        if (!x) return {{}, x.error};")
        L.append(f"        m.template link<{b.index}>() = *x;")
        L.append("    }")
    L.append("    return {m, ctga::error_code::none};")
    L.append("}")
    L.append("")
    L.append(f"}}  // namespace {namespace}")
    return "\n".join(L) + "\n"


# ---- command line -------------------------------------------------------------------------------


def main(argv=None):
    ap = argparse.ArgumentParser(prog=PROG, description="Convert a URDF's joint tree into a ctga::chains header.")
    ap.add_argument("urdf", help="the URDF file")
    ap.add_argument("--name", required=True, help="the robot's C++ name (the namespace unless --namespace)")
    ap.add_argument("--namespace", help="the namespace of the declarations (a::b allowed); default: --name")
    ap.add_argument("--floating-base", action="store_true",
                    help="the root link becomes body 0 on a floating joint (else it is the fixed world)")
    ap.add_argument("--gravity", nargs=3, metavar=("GX", "GY", "GZ"), default=["0", "0", "-9.81"],
                    help="gravity in the world frame (default 0 0 -9.81)")
    ap.add_argument("-o", "--output", help="the header to write (default: standard output)")
    args = ap.parse_args(argv)
    try:
        check_namespace(args.name, "--name")
        namespace = args.namespace if args.namespace is not None else args.name
        check_namespace(namespace, "--namespace")
        gravity = [parse_number(g, "--gravity") for g in args.gravity]
        robot_name, links, joints = parse_urdf(args.urdf)
        root, bodies = build_tree(links, joints, args.floating_base)
        text = generate(args.urdf, robot_name, root, bodies, args.name, namespace, args.floating_base, gravity)
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
