#!/usr/bin/env python3
"""tools/urdf_to_ctga.py on small URDFs written to temporary files and on the fixtures in
tests/data/: every error case exits with status 1 and a message naming the offending element (and
writes no header); questionable inertia warns (exit 0) unless --strict; good URDFs give the
expected joint types, body and frame order, names, numbers (rotations, merged inertias, frame
placements, parsed back from the header and checked against computations written here) and
options; <collision> elements give make_geometry's shapes (sizes, placements, STL meshes' hulls,
reduced hulls, excluded pairs), and a robot without them the header it had before. Registered in
tests/CMakeLists.txt as the CTest test urdf_to_ctga_script. Standard library only."""

import math
import os
import re
import struct
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, os.pardir, "tools", "urdf_to_ctga.py")
DATA = os.path.join(HERE, "data")
AS_GIVEN = "ctga::mass_check::as_given"
NO_MASS = "no mass in its subtree: the mass matrix would be singular and ABA would divide by zero"


def inertial(mass="1.0", xyz="0 0 0", rpy="0 0 0", tensor='ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"'):
    return (f'<inertial><origin xyz="{xyz}" rpy="{rpy}"/><mass value="{mass}"/>'
            f'<inertia {tensor}/></inertial>')


def tensor_attrs(ixx, iyy, izz, ixy=0.0, ixz=0.0, iyz=0.0):
    return f'ixx="{ixx!r}" ixy="{ixy!r}" ixz="{ixz!r}" iyy="{iyy!r}" iyz="{iyz!r}" izz="{izz!r}"'


def link(name, body=None):
    return f'<link name="{name}">{inertial() if body is None else body}</link>'


def joint(name, kind, parent, child, xyz="0 0 0", rpy="0 0 0", axis="0 0 1", extra=""):
    a = f'<axis xyz="{axis}"/>' if axis is not None else ""
    return (f'<joint name="{name}" type="{kind}"><parent link="{parent}"/><child link="{child}"/>'
            f'<origin xyz="{xyz}" rpy="{rpy}"/>{a}{extra}</joint>')


def robot(*elements):
    return '<?xml version="1.0"?>\n<robot name="test">\n' + "\n".join(elements) + "\n</robot>\n"


# base (world) - a - b, the simplest good robot, to break one thing at a time
def chain(joint_a=None, joint_b=None, link_a=None, link_b=None, base=None):
    return robot(base or link("base", ""),
                 joint_a or joint("ja", "revolute", "base", "a"),
                 link_a or link("a"),
                 joint_b or joint("jb", "revolute", "a", "b", xyz="0 0 0.3", axis="0 1 0"),
                 link_b or link("b"))


def fixture(name):
    with open(os.path.join(DATA, name), encoding="utf-8") as f:
        return f.read()


# ---- reading the header back ----------------------------------------------------------------------

def numbers(s):
    return [float(x) for x in re.findall(r"T\(([^()]*)\)", s)]


def strip_aligned(t):
    """t without the aligned<...> or turned<turn{...}, ...> the converter puts on a joint whose
    placement does not turn or turns by multiples of pi/2 (test_aligned checks where they go)."""
    t = re.sub(r"ctga::chains::turned<ctga::chains::turn\{[^{}]*\}, ", "ctga::chains::aligned<", t)
    return re.sub(r"ctga::chains::aligned<(.*)>$", r"\1", re.sub(r"ctga::chains::aligned<([^<>]*(?:<[^<>]*>)?)>", r"\1", t))


def link_entries(header):
    """[(parent, joint type as emitted)] of the tree's link entries."""
    body = header[header.index("using tree = ctga::chains::tree<"):header.index(">;  // frame")]
    return re.findall(r"^    ctga::chains::link<(-?\d+), (.+?)>,  // body", body, re.M)


def tree_lines(header):
    """[(parent, joint type without the ctga::chains:: prefix and without aligned<...>)] of the
    tree's link entries."""
    return [(p, strip_aligned(t).replace("ctga::chains::", "", 1)) for p, t in link_entries(header)]


def frame_lines(header):
    """[(name, body)] of the tree's fixed_frame entries."""
    return [(n, int(b)) for n, b in re.findall(r'^    ctga::chains::fixed_frame<"((?:[^"\\]|\\.)*)", (-?\d+)>', header,
                                                re.M)]


def names(header, which):
    block = header[header.index(f"{which}{{\n"):]
    block = block[:block.index("};")]
    return re.findall(r'^    "((?:[^"\\]|\\.)*)",$', block, re.M)


def body_block(header, index):
    start = header.index(f"{{  // body {index}:")
    return header[start:header.index("m.template link<", start)]


def frame_motor(header, index):
    """(translation, theta, unit axis) of frame index's row of the frame_placements table."""
    row = re.search(r"^        \{([^}]*)\},  // frame " + str(index) + ":", header, re.M)
    x = numbers(row.group(1))
    return x[0:3], x[3], x[4:7]


def motor(block):
    """(translation, theta, unit axis) of the first rigid_motion in block."""
    call = block[block.index("ctga::make_translator("):]
    rotor = call[call.index("ctga::make_rotor("):]
    t = numbers(call[:call.index("ctga::make_rotor(")])
    theta, ux, uy, uz = numbers(rotor[:rotor.index("))") + 2])
    return t, theta, [ux, uy, uz]


def mass_properties(block):
    """(mass, com, tensor, as_given) of a body block."""
    call = block[block.index("ctga::make_mass_properties("):]
    call = call[:call.index("}}}") + 3]
    mp = numbers(call)
    rest = block[block.index("ctga::make_mass_properties("):]
    return mp[0], mp[1:4], [mp[4:7], mp[7:10], mp[10:13]], rest.split("}}}")[1].startswith(", " + AS_GIVEN)


def extra_args(block):
    """The make_link arguments after the mass properties (coupling, axis), as text."""
    rest = block[block.index("ctga::make_mass_properties("):]
    rest = rest[rest.index("}}}") + 3:rest.index("if (!x)")]
    return rest[len(", " + AS_GIVEN):] if rest.startswith(", " + AS_GIVEN) else rest


def limits(header):
    """({(field, velocity number): value} of make_limits' assignments, its body as text)."""
    block = header[header.index("make_limits() noexcept {"):]
    block = block[:block.index("\n}\n") + 3]
    return {(a, int(k)): float(v) for a, k, v in re.findall(r"l\.(\w+)\[(\d+)\] = T\(([^()]*)\);", block)}, block


def spaced(v):
    return " ".join(map(repr, v))


def collision(geometry, xyz="0 0 0", rpy="0 0 0"):
    return f'<collision><origin xyz="{xyz}" rpy="{rpy}"/><geometry>{geometry}</geometry></collision>'


def stl_binary(path, triangles):
    with open(path, "wb") as f:
        f.write(b"binary STL written by urdf_to_ctga_test.py".ljust(80, b" "))
        f.write(struct.pack("<I", len(triangles)))
        for t in triangles:
            f.write(struct.pack("<12fH", 0.0, 0.0, 0.0, *(c for p in t for c in p), 0))


def stl_ascii(path, triangles):
    lines = ["solid test"]
    for t in triangles:
        lines += ["  facet normal 0 0 0", "    outer loop"] + [f"      vertex {x!r} {y!r} {z!r}" for x, y, z in t]
        lines += ["    endloop", "  endfacet"]
    with open(path, "w", encoding="ascii") as f:
        f.write("\n".join(lines + ["endsolid test"]) + "\n")


def split_cube(size):
    """The 24 triangles of the cube [0, size]^3, each face split at its centre: 14 points, 8 corners."""
    triangles = []
    for axis in range(3):
        for side in (0.0, size):
            def point(a, b):
                p = [0.0] * 3
                p[axis], p[(axis + 1) % 3], p[(axis + 2) % 3] = side, a, b
                return tuple(p)
            ring = [point(0.0, 0.0), point(size, 0.0), point(size, size), point(0.0, size)]
            triangles += [(ring[i], ring[(i + 1) % 4], point(size / 2, size / 2)) for i in range(4)]
    return triangles


def corners(size):
    return sorted([x, y, z] for x in (0.0, size) for y in (0.0, size) for z in (0.0, size))


def ball(rings=10, sectors=16):
    """Points on the unit sphere (rings of latitude and the poles), all corners of their hull."""
    points = [(0.0, 0.0, 1.0), (0.0, 0.0, -1.0)]
    for i in range(1, rings + 1):
        lat = math.pi * i / (rings + 1)
        points += [(math.sin(lat) * math.cos(lon), math.sin(lat) * math.sin(lon), math.cos(lat))
                   for lon in (2 * math.pi * j / sectors for j in range(sectors))]
    return points


def collision_kinds(header):
    """The kinds of collision_shape<T>, in order (convex_hull with its capacity)."""
    variant = re.search(r"using collision_shape = ctga::collision::shape<(.*)>;", header).group(1)
    return re.findall(r"ctga::collision::(\w+<T(?:, \d+)?)>", variant)


def shapes(header):
    """[(body, kind, numbers)] of make_geometry's shapes: the make_ call's numbers, a hull's vertices."""
    out = []
    for body, call in re.findall(r"if \(const auto e = place\(\d+, (-?\d+), (.*)\); e != ", header):
        if "make_hull" in call:
            name = re.search(r"\((hull_\d+)\)\)$", call).group(1)
            block = header[header.index(f" {name}{{{{"):]
            x = numbers(block[:block.index("}};")])
            out.append((int(body), "hull", sorted(x[i:i + 3] for i in range(0, len(x), 3))))
        else:
            out.append((int(body), re.match(r"ctga::collision::make_(\w+)\(", call).group(1), numbers(call)))
    return out


def shape_motor(header, index):
    """(translation, theta, unit axis) of shape index's row of make_geometry's placements table."""
    row = re.search(r"^        \{([^}]*)\},  // shape " + str(index) + ":", header, re.M)
    x = numbers(row.group(1))
    return x[0:3], x[3], x[4:7]


def excluded(header):
    """[(body a, body b)] of make_geometry's excluded pairs."""
    return [(int(a), int(b)) for a, b in re.findall(r"^        \{(\d+), (\d+)\},  // links", header, re.M)]


def dofs(types):
    n = 0
    for _, t in types:
        if t.startswith("mimic<") or t == "fixed":
            continue
        n += 6 if t == "floating" else 1
    return n


# ---- independent maths ----------------------------------------------------------------------------

def rpy_matrix_here(roll, pitch, yaw):
    """URDF: R = Rz(yaw) Ry(pitch) Rx(roll), written out (not the script's code)."""
    cr, sr, cp, sp, cy, sy = (math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch), math.cos(yaw),
                              math.sin(yaw))
    return [[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr]]


def rodrigues(ux, uy, uz, theta):
    """Rot(u, theta), right hand: 1 + sin(theta) [u]x + (1 - cos(theta)) [u]x^2."""
    s, c = math.sin(theta), math.cos(theta)
    k = [[0, -uz, uy], [uz, 0, -ux], [-uy, ux, 0]]
    k2 = [[sum(k[i][m] * k[m][j] for m in range(3)) for j in range(3)] for i in range(3)]
    return [[(1.0 if i == j else 0.0) + s * k[i][j] + (1 - c) * k2[i][j] for j in range(3)] for i in range(3)]


def mm(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def mv(a, v):
    return [sum(a[i][k] * v[k] for k in range(3)) for i in range(3)]


def tr(a):
    return [[a[j][i] for j in range(3)] for i in range(3)]


def eye():
    return [[1.0 if i == j else 0.0 for j in range(3)] for i in range(3)]


def about_origin(m, c, I):
    """The inertia about the frame's origin, I_c + m (|c|^2 1 - c c^T): additive over parts."""
    c2 = sum(x * x for x in c)
    return [[I[i][j] + m * ((c2 if i == j else 0.0) - c[i] * c[j]) for j in range(3)] for i in range(3)]


def cross3(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


class Converter(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.addCleanup(self.tmp.cleanup)

    def run_script(self, text, *args, name="robot", source=None):
        """The converter on `text` written to robot.urdf in the temporary directory (or on the file
        `source`): (exit status, header or None, stderr)."""
        path = source or os.path.join(self.tmp.name, "robot.urdf")
        if source is None:
            with open(path, "w", encoding="utf-8") as f:
                f.write(text)
        out = os.path.join(self.tmp.name, "out.hpp")
        if os.path.exists(out):
            os.remove(out)
        r = subprocess.run([sys.executable, SCRIPT, path, "--name", name, "-o", out, *args],
                           capture_output=True, text=True, check=False)
        header = None
        if os.path.exists(out):
            with open(out, encoding="utf-8") as f:
                header = f.read()
        return r.returncode, header, r.stderr

    def assert_error(self, text, *needles, args=()):
        rc, header, err = self.run_script(text, *args)
        self.assertEqual(rc, 1, f"expected exit status 1, got {rc}; stderr: {err}")
        self.assertIsNone(header, "a failed conversion must not write the header")
        self.assertTrue(err.startswith("urdf_to_ctga: "), err)
        for n in needles:
            self.assertIn(n, err)
        return err

    def convert(self, text, *args, name="robot"):
        rc, header, err = self.run_script(text, *args, name=name)
        self.assertEqual(rc, 0, err)
        self.assertEqual(err, "")
        return header

    def convert_warned(self, text, *args):
        """A conversion that succeeds with warnings: (header, [warning lines])."""
        rc, header, err = self.run_script(text, *args)
        self.assertEqual(rc, 0, err)
        self.assertIsNotNone(header)
        lines = err.splitlines()
        self.assertTrue(lines, "expected a warning")
        for line in lines:
            self.assertTrue(line.startswith("urdf_to_ctga: warning: "), line)
        return header, lines

    def assert_close(self, got, expected, tol=1e-14, msg=None):
        if isinstance(expected, (int, float)):
            self.assertLessEqual(abs(got - expected), tol * max(1.0, abs(expected)), msg)
            return
        self.assertEqual(len(got), len(expected), msg)
        for g, e in zip(got, expected):
            self.assert_close(g, e, tol, msg)

    def assert_rotation(self, theta, u, expected, tol=1e-14):
        self.assert_close(sum(x * x for x in u), 1.0, 1e-15)
        self.assert_close(rodrigues(*u, theta), expected, tol)

    # ---- errors ------------------------------------------------------------------------------

    def test_unsupported_joint_types(self):
        err = self.assert_error(chain(joint_b=joint("knee", "spherical", "a", "b")), 'joint "knee"', '"spherical"')
        self.assertIn("is not supported (revolute, continuous, prismatic, fixed, floating, planar)", err)
        self.assert_error(chain(joint_b=joint("knee", "ball", "a", "b")), 'joint "knee"', '"ball"')
        self.assert_error(chain(joint_b='<joint name="knee"><parent link="a"/><child link="b"/></joint>'),
                          'joint "knee"', "no type")

    def test_two_parents(self):
        text = robot(link("base", ""), joint("j1", "revolute", "base", "a"), link("a"), link("c"),
                     joint("j2", "revolute", "c", "a"), joint("j3", "fixed", "base", "c"))
        self.assert_error(text, 'link "a"', '"j1"', '"j2"', "not a tree")

    def test_missing_links(self):
        self.assert_error(chain(joint_b=joint("jb", "revolute", "nowhere", "b")), 'joint "jb"', 'parent link "nowhere"',
                          "does not exist")
        self.assert_error(chain(joint_b=joint("jb", "revolute", "a", "ghost")), 'joint "jb"', 'child link "ghost"',
                          "does not exist")
        self.assert_error(chain(joint_b='<joint name="jb" type="fixed"><child link="b"/></joint>'), 'joint "jb"',
                          "<parent")

    def test_more_than_one_root(self):
        text = robot(link("base", ""), joint("ja", "revolute", "base", "a"), link("a"), link("stray"))
        self.assert_error(text, "more than one root link", "'base'", "'stray'")

    def test_no_root_and_unreachable_loops(self):
        text = robot(link("a"), link("b"), joint("j1", "revolute", "a", "b"), joint("j2", "revolute", "b", "a"))
        self.assert_error(text, "no root link", "loop")
        text = robot(link("base", ""), joint("ja", "revolute", "base", "a"), link("a"), link("p"), link("q"),
                     joint("jp", "revolute", "q", "p"), joint("jq", "revolute", "p", "q"))
        self.assert_error(text, 'link "p"', "not connected to the root")
        self.assert_error(robot(link("a"), joint("j", "revolute", "a", "a")), 'joint "j"', "its own parent")

    def test_no_links(self):
        self.assert_error(robot(), "no <link>")
        self.assert_error(robot(link("only")), 'the root link "only"', "no bodies", "--floating-base")
        # fixed joints only: everything merges into the world
        self.assert_error(robot(link("base", ""), joint("j", "fixed", "base", "a"), link("a")), "no bodies")

    def test_inertial_errors(self):
        self.assert_error(chain(link_a=link("a", inertial(mass="-2.5"))), 'link "a"', "mass -2.5 is negative")
        self.assert_error(chain(link_a=link("a", '<inertial><mass value="1"/></inertial>')), 'link "a"', "<inertia>")
        self.assert_error(chain(link_a=link("a", '<inertial><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/>'
                                                 '</inertial>')), 'link "a"', "<mass>")
        self.assert_error(chain(link_a=link("a", inertial(tensor='ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0"'))),
                          'link "a"', "izz")
        self.assert_error(chain(link_a=link("a", inertial() + inertial())), 'link "a"', "more than one <inertial>")
        # the root is the world: its inertial (even a massless one) is dropped, and it may have none
        header = self.convert(robot(link("base", inertial(mass="0")), joint("ja", "revolute", "base", "a"), link("a")))
        self.assertIn('The root link "base" is the fixed world', header)
        self.assertIn('their inertia dropped: "base" (mass 0.0)', header)

    def test_massless_links_and_subtrees(self):
        # a massless link whose subtree has mass loads: a zero body built as given
        header = self.convert(chain(link_a=link("a", "")))
        m, c, I, as_given = mass_properties(body_block(header, 0))
        self.assertEqual((m, c, I, as_given), (0.0, [0.0] * 3, [[0.0] * 3] * 3, True))
        self.assertIn("if (const int b = ctga::chains::massless_subtree(m); b >= 0) return {{}, "
                      "ctga::error_code::massless_subtree};\n    return {m, ctga::error_code::none};", header)
        header = self.convert(chain(link_a=link("a", inertial(mass="0.0", tensor=tensor_attrs(0.0, 0.0, 0.0)))))
        self.assertEqual(mass_properties(body_block(header, 0))[0], 0.0)
        # a moving joint with no mass anywhere below it: an error naming the joint
        needle = "no mass in its subtree: the mass matrix would be singular and ABA would divide by zero"
        self.assert_error(chain(link_b=link("b", "")), 'joint "jb"', needle)
        self.assert_error(chain(link_b=link("b", inertial(mass="0", tensor=tensor_attrs(0.0, 0.0, 0.0)))),
                          'joint "jb"', needle)
        self.assert_error(chain(link_a=link("a", ""), link_b=link("b", "")), 'joint "ja"', needle)
        # mass on a fixed child counts (it is merged into the body); a massless fixed leaf is fine
        text = chain(link_b=link("b", "")).replace("</robot>", joint("jt", "fixed", "b", "t") + link("t") + "</robot>")
        self.assertEqual(len(tree_lines(self.convert(text))), 2)
        text = chain().replace("</robot>", joint("jt", "fixed", "b", "t") + link("t", "") + "</robot>")
        self.convert(text)
        # --keep-fixed: a massless fixed body is fine, the moving joint above it still needs mass
        text = chain(link_b=link("b", "")).replace("</robot>",
                                                   joint("jt", "fixed", "b", "t") + link("t", "") + "</robot>")
        self.assert_error(text, 'joint "jb"', needle, args=("--keep-fixed",))
        # the floating base: a robot with no mass at all
        self.assert_error(robot(link("base", ""), joint("j", "fixed", "base", "t"), link("t", "")), 'joint "base"',
                          needle, args=("--floating-base",))

    # ---- moving joints without inertia: --massless, --lock, --armature ----------------------------

    def test_massless_rule_mirrors_cpp(self):
        # as ctga::chains::massless_subtree: a revolute joint whose subtree has no mass but a rotational
        # inertia (a mass-0 link's tensor, kept) loads
        header, lines = self.convert_warned(chain(link_b=link("b", inertial(mass="0"))))
        self.assertEqual(len(lines), 1)
        self.assertEqual(mass_properties(body_block(header, 1))[:3],
                         (0.0, [0.0] * 3, [[0.1, 0.0, 0.0], [0.0, 0.1, 0.0], [0.0, 0.0, 0.1]]))
        # a prismatic joint needs mass or an armature: a tensor does not resist a translation
        prismatic = joint("jb", "prismatic", "a", "b")
        self.assert_error(chain(joint_b=prismatic, link_b=link("b", inertial(mass="0"))), 'joint "jb"', NO_MASS)
        # an armature resists either
        header = self.convert(chain(link_b=link("b", "")), "--armature", "jb=0.02")
        self.assertIn("        m.template link<1>() = *x;\n        m.template link<1>().armature = T(0.02);  // --armature",
                      header)
        self.assertIn('// Armatures (a joint\'s rotor inertia: revolute kg m^2, prismatic kg): "jb" 0.02 (--armature).',
                      header)
        self.assertEqual(header.count(".armature ="), 1)
        # the joint's type says it has an armature (inside aligned<>; make_link takes the same type)
        self.assertEqual(link_entries(header)[1],
                         ("0", "ctga::chains::aligned<ctga::chains::with_armature<ctga::chains::revolute_y>>"))
        self.assertIn("make_link<ctga::chains::aligned<ctga::chains::with_armature<ctga::chains::revolute_y>>>(", header)
        self.assertEqual(link_entries(header)[0], ("-1", "ctga::chains::aligned<ctga::chains::revolute_z>"))
        self.convert(chain(joint_b=prismatic, link_b=link("b", "")), "--armature", "jb=0.5")
        # an armature of 0 is none
        self.assert_error(chain(link_b=link("b", "")), 'joint "jb"', NO_MASS, args=("--armature", "jb=0"))
        self.assert_error(chain(link_b=link("b", "")), 'joint "jb"', NO_MASS, ", and its armature is 0.0 (--armature)",
                          args=("--armature", "jb=0", "--massless", "armature=0.1"))

    def test_massless_refused_names_the_joint_and_the_options(self):
        err = self.assert_error(fixture("limited_gripper.urdf"), 'joint "finger_left": ' + NO_MASS,
                                'the same for "thumb". Options: --massless lock (fix such joints at 0), --massless '
                                "armature=VALUE (give them a rotor inertia), or per joint --lock finger_left[=VALUE], "
                                "--armature finger_left=VALUE")
        self.assertEqual(len(err.splitlines()), 1)  # no warnings before a refusal
        # many: the first four named, the rest counted
        hand = [link("base", ""), joint("ja", "revolute", "base", "palm"), link("palm")]
        for k in range(7):
            hand += [joint(f"f{k}", "revolute", "palm", f"l{k}"), link(f"l{k}", "")]
        self.assert_error(robot(*hand), 'joint "f0"', 'the same for "f1", "f2", "f3", "f4" and 2 more')
        # the option's own errors
        self.assert_error(chain(), "--massless armature=0: the armature must be positive",
                          args=("--massless", "armature=0"))
        self.assert_error(chain(), "--massless armature=-1", "must be positive", args=("--massless", "armature=-1"))
        self.assert_error(chain(), "--massless fix: expected refuse, lock or armature=VALUE", args=("--massless", "fix"))
        self.assert_error(chain(), "--massless armature=x", "malformed number", args=("--massless", "armature=x"))

    def test_massless_lock(self):
        header, lines = self.fixture_header("limited_gripper.urdf", "--massless", "lock", warnings=2)
        self.assertIn('link "sensor": mass 0 with a nonzero inertia tensor (kept', lines)
        self.assertIn("options: --name robot --massless lock", header.splitlines()[1])
        self.assertIn('// Locked joints (fixed at the value: revolute rad, prismatic m; planar, floating: the origin): '
                      '"finger_left" at 0.0 (--massless lock), "thumb" at 0.2 (--massless lock), "finger_right" at 0.01 '
                      '(follows "finger_left").', header)
        # finger_right follows its locked master (and it has mass: merged into the hand's body)
        self.assertEqual(tree_lines(header), [("-1", "revolute_z"), ("0", "revolute_y"), ("1", "revolute_z"),
                                              ("2", "revolute_x")])
        self.assertEqual(names(header, "joint_names"), ["shoulder", "elbow", "wrist", "spinner"])
        self.assertEqual(frame_lines(header), [("base_link", -1), ("upper", 0), ("forearm", 1), ("hand", 2),
                                               ("sensor", 2), ("rotor", 3), ("finger_l", 2), ("finger_r", 2),
                                               ("thumb_link", 2), ("thumb_tip", 2)])
        # the frames through a locked joint: its origin, then its motion at the value; thumb: 0
        # clamped into <limit> [0.2, 1.0], about +x after the origin's pitch 0.3
        R = mm(rpy_matrix_here(0, 0.3, 0), rodrigues(1, 0, 0, 0.2))
        t, theta, u = frame_motor(header, 8)
        self.assert_close(t, [0.02, 0.0, 0.06])
        self.assert_rotation(theta, u, R)
        t, theta, u = frame_motor(header, 9)
        self.assert_close(t, [0.02 + mv(R, [0, 0, 0.03])[0], mv(R, [0, 0, 0.03])[1], 0.06 + mv(R, [0, 0, 0.03])[2]])
        self.assert_rotation(theta, u, R)
        self.assertEqual(frame_motor(header, 7)[:2], ([0.0, -0.02, 0.08], 0.0))  # -0.01 + 0.01 along -y
        self.assertIn('// frame 8: link "thumb_link" in body 2 (through "thumb")', header)
        # the hand's body: the hand, the sensor's tensor (mass 0: no parallel-axis term) and finger_r
        m, c, I, _ = mass_properties(body_block(header, 2))
        self.assert_close(m, 0.55)
        Rs = rpy_matrix_here(0, 0, 0.7)
        sensor = mm(mm(Rs, [[1e-4, 1e-5, 0.0], [1e-5, 2e-4, 0.0], [0.0, 0.0, 2.5e-4]]), tr(Rs))
        hand = about_origin(0.5, [0, 0, 0.04], [[4e-4, 0, 0], [0, 3e-4, 0], [0, 0, 2e-4]])
        finger = about_origin(0.05, [0, -0.02, 0.1], [[1e-5, 0, 0], [0, 1e-5, 0], [0, 0, 2e-6]])
        expected = [[hand[i][j] + sensor[i][j] + finger[i][j] for j in range(3)] for i in range(3)]
        self.assert_close(about_origin(m, c, I), expected, 1e-13)
        self.assert_close(c, [0.0, -0.001 / 0.55, (0.02 + 0.005) / 0.55])
        # the locked joints' limits are dropped
        self.assertIn('    // joint "thumb": locked at 0.2, no coordinate, its limits dropped\n', header)
        self.assertEqual(max(k for _, k in limits(header)[0]), 3)

    def test_massless_armature(self):
        header, _ = self.fixture_header("limited_gripper.urdf", "--massless", "armature=0.01", warnings=2)
        self.assertEqual(self.counts(header), (7, 10, 6))
        self.assertIn("        m.template link<4>() = *x;\n        m.template link<4>().armature = T(0.01);  // --massless "
                      "armature\n", header)
        self.assertEqual(header.count(".armature ="), 2)
        self.assertIn('"finger_left" 0.01 (--massless armature), "thumb" 0.01 (--massless armature).', header)
        # an explicit armature stands
        header, _ = self.fixture_header("limited_gripper.urdf", "--massless", "armature=0.01", "--armature",
                                        "thumb=0.03", warnings=2)
        self.assertIn('"thumb" 0.03 (--armature), "finger_left" 0.01 (--massless armature).', header)
        self.assertIn("m.template link<6>().armature = T(0.03);  // --armature", header)
        self.assertEqual(link_entries(header)[6], ("2", "ctga::chains::with_armature<ctga::chains::revolute_x>"))
        self.assertEqual(link_entries(header)[5][1], "ctga::chains::mimic<ctga::chains::aligned<"
                         "ctga::chains::prismatic<ctga::chains::axis::minus_y>>, 4>")
        # a massless mimic has no coordinate, so no armature: lock it, or make it independent
        text = fixture("limited_gripper.urdf").replace('<mass value="0.05"/>', '<mass value="0"/>')
        self.assert_error(text, 'joint "finger_right": no mass in its subtree, and --massless armature cannot help',
                          "a <mimic> joint has no coordinate", "--massless lock, --lock finger_right, or --mimic "
                          "independent", args=("--massless", "armature=0.01"))
        rc, header, err = self.run_script(text, "--massless", "armature=0.01", "--mimic", "independent")
        self.assertEqual(rc, 0, err)
        self.assertIn('"finger_right" 0.01 (--massless armature)', header)
        self.assertEqual(header.count(".armature ="), 3)
        # a planar joint: three coordinates, no single armature
        text = chain(link_b=link("b")).replace("</robot>", joint("slide", "planar", "b", "p") + link("p", "") +
                                               "</robot>")
        self.assert_error(text, 'joint "slide": no mass in its subtree, and --massless armature cannot help',
                          "this one is planar (use --massless lock or --lock slide)",
                          args=("--massless", "armature=0.01"))
        header = self.convert(text, "--massless", "lock")
        self.assertIn('"slide" at 0.0 (--massless lock)', header)
        self.assertEqual(frame_lines(header)[-1], ("p", 1))

    def test_lock(self):
        header = self.convert(chain(), "--lock", "jb=0.5")
        self.assertEqual(tree_lines(header), [("-1", "revolute_z")])
        self.assertEqual(frame_lines(header), [("base", -1), ("a", 0), ("b", 0)])
        self.assertIn("options: --name robot --lock jb=0.5", header.splitlines()[1])
        self.assertIn('"jb" at 0.5 (--lock)', header)
        t, theta, u = frame_motor(header, 2)
        self.assertEqual(t, [0.0, 0.0, 0.3])
        self.assert_rotation(theta, u, rodrigues(0, 1, 0, 0.5))
        # b's link merged at its locked pose: 2 kg, centre halfway, 0.1 1 each (turned: still 0.1 1)
        m, c, I, _ = mass_properties(body_block(header, 0))
        self.assertEqual((m, c), (2.0, [0.0, 0.0, 0.15]))
        self.assert_close(I, [[0.2 + 0.045, 0, 0], [0, 0.2 + 0.045, 0], [0, 0, 0.2]], 1e-15)
        # the default: 0 (a joint next to the world: its link lumped into the world)
        header = self.convert(chain(), "--lock", "ja")
        self.assertIn('"ja" at 0.0 (--lock)', header)
        self.assertIn('their inertia dropped: "a" (mass 1.0)', header)
        self.assertEqual(tree_lines(header), [("-1", "revolute_y")])
        # a prismatic joint slides; --keep-fixed keeps the locked link as a body on a fixed joint
        text = chain(joint_b=joint("jb", "prismatic", "a", "b", xyz="0 0 0.3", axis="0 1 0"))
        self.assertEqual(frame_motor(self.convert(text, "--lock", "jb=0.25"), 2)[:2], ([0.0, 0.25, 0.3], 0.0))
        header = self.convert(chain(), "--lock", "jb=0.5", "--keep-fixed")
        self.assertEqual(tree_lines(header), [("-1", "revolute_z"), ("0", "fixed")])
        t, theta, u = motor(body_block(header, 1))
        self.assertEqual(t, [0.0, 0.0, 0.3])
        self.assert_rotation(theta, u, rodrigues(0, 1, 0, 0.5))
        self.assertIn("(revolute, locked at 0.5)", body_block(header, 1))
        self.assertIn("then the joint's motion at its locked value 0.5", body_block(header, 1))
        # the default clamped into <limit>; a value outside it warns
        limited = chain(joint_b=joint("jb", "revolute", "a", "b", axis="0 1 0",
                                      extra='<limit lower="0.2" upper="1.0" effort="1" velocity="1"/>'))
        self.assertIn('"jb" at 0.2 (--lock)', self.convert(limited, "--lock", "jb"))
        self.assertIn('"jb" at -0.3 (--lock)', self.convert(limited.replace('lower="0.2" upper="1.0"',
                                                                             'lower="-1" upper="-0.3"'), "--lock", "jb"))
        _, lines = self.convert_warned(limited, "--lock", "jb=1.5")
        self.assertEqual(lines, ['urdf_to_ctga: warning: joint "jb" is locked at 1.5, outside its <limit> [0.2, 1.0]'])
        # a planar or floating joint locks at its origin, without a value
        planar = chain(joint_b=joint("jb", "planar", "a", "b", xyz="0 0 0.3"))
        self.assertEqual(frame_motor(self.convert(planar, "--lock", "jb"), 2)[:2], ([0.0, 0.0, 0.3], 0.0))
        self.assert_error(planar, "--lock jb=0.1: joint \"jb\" is planar: it locks at its origin, without a value "
                          "(--lock jb)", args=("--lock", "jb=0.1"))
        self.convert(chain(joint_b=joint("jb", "floating", "a", "b")), "--lock", "jb")
        # errors naming the option and the joint
        self.assert_error(chain(), '--lock nowhere: no joint named "nowhere"', args=("--lock", "nowhere"))
        self.assert_error(chain(), '--lock nowhere=0.5: no joint named "nowhere"', args=("--lock", "nowhere=0.5"))
        self.assert_error(chain(), '--lock jb=0.2: joint "jb" is named twice', args=("--lock", "jb", "--lock", "jb=0.2"))
        self.assert_error(chain(), "--lock jb=x", "malformed number", args=("--lock", "jb=x"))
        text = chain().replace("</robot>", joint("jt", "fixed", "b", "t") + link("t") + "</robot>")
        self.assert_error(text, '--lock jt: joint "jt" is fixed already', args=("--lock", "jt"))
        # a joint whose name holds '=' is named whole
        text = chain(joint_b=joint("j=b", "revolute", "a", "b"))
        self.assertIn('"j=b" at 0.0 (--lock)', self.convert(text, "--lock", "j=b"))
        self.assertIn('"j=b" at 0.5 (--lock)', self.convert(text, "--lock", "j=b=0.5"))

    def test_lock_and_mimic(self):
        # a locked master takes its mimics along (m v + o)
        header = self.convert(self.gripper(), "--lock", "left=0.02")
        self.assertIn('"left" at 0.02 (--lock), "right" at -0.01 (follows "left")', header)
        self.assertEqual(tree_lines(header), [("-1", "revolute_z")])
        self.assertEqual(frame_motor(header, 2)[0], [0.0, 0.01, 0.0])  # fr: -0.01 along -y
        # a mimic locked alone stops following its master (its default: m 0 + o)
        header, lines = self.convert_warned(self.gripper(), "--lock", "right")
        self.assertIn('"right" at 0.01 (--lock)', header)
        self.assertEqual(lines, ['urdf_to_ctga: warning: joint "right" (a <mimic> of "left") is locked at 0.01: it no '
                                 'longer follows "left"'])
        self.assertEqual(tree_lines(header), [("-1", "revolute_z"), ("0", "prismatic_y")])
        # with --mimic independent, locking the master locks it alone
        header = self.convert(self.gripper(), "--lock", "left", "--mimic", "independent")
        self.assertEqual(len(tree_lines(header)), 2)
        self.assertNotIn("follows", header)

    def test_armature_errors(self):
        self.assert_error(chain(), '--armature nowhere=0.1: no joint named "nowhere"', args=("--armature", "nowhere=0.1"))
        self.assert_error(chain(), "--armature jb: expected JOINT=VALUE", args=("--armature", "jb"))
        self.assert_error(chain(), "--armature jb=-0.1: the armature is negative", args=("--armature", "jb=-0.1"))
        self.assert_error(chain(), '--armature jb=0.2: joint "jb" is named twice',
                          args=("--armature", "jb=0.1", "--armature", "jb=0.2"))
        text = chain().replace("</robot>", joint("jt", "fixed", "b", "t") + link("t") + "</robot>")
        self.assert_error(text, '--armature jt=0.1: joint "jt" is fixed: armature is for revolute, continuous and '
                          "prismatic joints", args=("--armature", "jt=0.1"))
        self.assert_error(self.gripper(), '--armature right=0.1: joint "right" mimics "left": it has no coordinate of '
                          'its own (give the armature to "left", or use --mimic independent)',
                          args=("--armature", "right=0.1"))
        self.assertIn("m.template link<1>().armature = T(0.1);",
                      self.convert(self.gripper(), "--armature", "right=0.1", "--mimic", "independent"))
        self.assert_error(chain(), '--armature jb=0.1: joint "jb" is locked (--lock): a locked joint has no armature',
                          args=("--lock", "jb", "--armature", "jb=0.1"))

    def test_mimic_missing(self):
        text = self.gripper('<mimic joint="nobody"/>', extra=joint("r2", "prismatic", "hand", "f2", axis="0 0 1",
                                                                   extra='<mimic joint="left"/>') + link("f2"))
        self.assert_error(text, 'joint "right": <mimic joint="nobody">: no such joint (--mimic-missing independent makes '
                          "such a joint an ordinary independent joint; --mimic independent does so for every <mimic> "
                          "joint)")
        header, lines = self.convert_warned(text, "--mimic-missing", "independent")
        self.assertEqual(lines, ['urdf_to_ctga: warning: joint "right": <mimic joint="nobody">: no such joint; joint '
                                 '"right" is an independent joint (--mimic-missing independent)'])
        self.assertEqual(tree_lines(header), [("-1", "revolute_z"), ("0", "prismatic<ctga::chains::axis::minus_y>"),
                                              ("0", "prismatic_y"), ("0", "mimic<ctga::chains::prismatic_z, 2>")])
        self.assertIn('// --mimic-missing independent: the <mimic> joints "right" name no joint: they are independent '
                      "coordinates.", header)
        self.assertIn("--mimic-missing independent", header.splitlines()[1])
        self.assertIn("// v 1: joint \"right\" (body 1, prismatic)", header)

    # ---- mass properties: mass-0 tensors, the parallel-axis sum -----------------------------------------

    def test_mass_zero_tensor_is_kept(self):
        # merged into a body with mass: the rotated tensor adds, no parallel-axis term, the centre of
        # mass is the massive parts'
        zero = link("t", inertial(mass="0", xyz="0.3 0 0", tensor=tensor_attrs(1e-3, 2e-3, 3e-3, ixy=1e-4)))
        text = chain(link_b=link("b", inertial(mass="2", xyz="0.1 0 0"))).replace(
            "</robot>", joint("jt", "fixed", "b", "t", xyz="0.5 0 0", rpy="0.2 0 0.4") + zero + "</robot>")
        header, lines = self.convert_warned(text)
        self.assertEqual(len(lines), 1)
        m, c, I, as_given = mass_properties(body_block(header, 1))
        self.assertEqual((m, c, as_given), (2.0, [0.1, 0.0, 0.0], True))
        R = rpy_matrix_here(0.2, 0, 0.4)
        T = mm(mm(R, [[1e-3, 1e-4, 0.0], [1e-4, 2e-3, 0.0], [0.0, 0.0, 3e-3]]), tr(R))
        self.assert_close(I, [[0.1 + T[i][j] if i == j else T[i][j] for j in range(3)] for i in range(3)], 1e-15)
        # a body with no mass and a tensor: (0, 0, the tensor), as given
        header, _ = self.convert_warned(chain(link_b=link("b", inertial(mass="0", xyz="0.1 0.2 0.3",
                                                                       tensor=tensor_attrs(1e-3, 2e-3, 3e-3)))))
        self.assertEqual(mass_properties(body_block(header, 1)),
                         (0.0, [0.0] * 3, [[1e-3, 0.0, 0.0], [0.0, 2e-3, 0.0], [0.0, 0.0, 3e-3]], True))
        # the tensor is checked as any link's
        _, lines = self.convert_warned(chain(link_b=link("b", inertial(mass="0", tensor=tensor_attrs(0.1, 0.1, 0.3)))))
        self.assertIn('link "b": principal moments [0.1, 0.1, 0.3] violate the triangle inequality', lines[1])

    def test_parallel_axis_far_along_an_axis(self):
        # two 1 kg parts 1e8 m either side along x, 1e-3 m off it along y: I_xx about the centre is
        # 2 (1e-3)^2 plus the parts' own, which |d|^2 - d_x^2 = (1e16 + 1e-6) - 1e16 would lose
        far = chain(link_b=link("b", inertial(mass="1", xyz="1e8 1e-3 0", tensor=tensor_attrs(1e-6, 1e-6, 1e-6))))
        far = far.replace("</robot>", joint("jt", "fixed", "b", "t") +
                          link("t", inertial(mass="1", xyz="-1e8 -1e-3 0", tensor=tensor_attrs(1e-6, 1e-6, 1e-6))) +
                          "</robot>")
        rc, header, err = self.run_script(far)
        self.assertEqual(rc, 0, err)
        m, c, I, _ = mass_properties(body_block(header, 1))
        self.assertEqual((m, c), (2.0, [0.0, 0.0, 0.0]))
        self.assert_close(I[0][0], 4e-6, 1e-12)
        self.assert_close(I[1][1], 2e16, 1e-15)
        self.assert_close(I[0][1], -2e5, 1e-15)

    # ---- joint limits ------------------------------------------------------------------------------------

    def test_limits(self):
        header, _ = self.fixture_header("limited_gripper.urdf", "--massless", "armature=0.01", warnings=2)
        values, block = limits(header)
        self.assertEqual(values, {
            ("lower", 0): -2.5, ("upper", 0): 2.5, ("velocity", 0): 3.0, ("effort", 0): 80.0, ("damping", 0): 0.5,
            ("friction", 0): 0.2,
            ("lower", 1): -0.3, ("upper", 1): 2.0, ("velocity", 1): 4.0, ("effort", 1): 40.0, ("damping", 1): 0.1,
            ("velocity", 2): 6.0, ("effort", 2): 10.0,
            ("friction", 3): 0.01,
            ("lower", 4): 0.0, ("upper", 4): 0.04, ("velocity", 4): 0.1, ("effort", 4): 20.0,
            ("lower", 5): 0.2, ("upper", 5): 1.0, ("velocity", 5): 1.0, ("effort", 5): 5.0})
        self.assertIn("template <class T = double>\nconstexpr ctga::checked<ctga::chains::joint_limits<tree, T>> "
                      "make_limits() noexcept {\n    auto l = ctga::chains::unlimited<tree, T>();\n", header)
        self.assertTrue(block.endswith("    return ctga::chains::check_limits(l);\n}\n"))
        for comment in ('// v 0: joint "shoulder" (body 0, revolute)\n', '// v 1: joint "elbow" (body 1, revolute): no friction',
                        '// v 2: joint "wrist" (body 2, continuous): no <dynamics>',
                        '// v 3: joint "spinner" (body 3, continuous): no <limit>; no damping',
                        '// joint "finger_right" (body 5, a <mimic> of "finger_left": no coordinate, its limits dropped)'):
            self.assertIn(comment, block)
        # a continuous joint's bounds are not read (not even checked); a missing bound is none
        text = chain(joint_b=joint("jb", "continuous", "a", "b", extra='<limit lower="1" upper="-1" velocity="2"/>'))
        values, block = limits(self.convert(text))
        self.assertEqual(values, {("velocity", 1): 2.0})
        self.assertIn('// v 1: joint "jb" (body 1, continuous): no effort; no <dynamics>; continuous: its lower, upper '
                      "ignored", block)
        values, block = limits(self.convert(chain(joint_b=joint("jb", "prismatic", "a", "b",
                                                                extra='<limit lower="-0.1"/><dynamics damping="3" K="9"/>'))))
        self.assertEqual(values, {("lower", 1): -0.1, ("damping", 1): 3.0})
        self.assertIn("no upper, velocity, effort; no friction", block)
        # floating and planar joints: unlimited
        block = limits(self.convert(chain(joint_b=joint("jb", "planar", "a", "b")), "--floating-base"))[1]
        self.assertIn('// v 0..5: joint "base" (body 0, floating base): unlimited', block)
        self.assertIn('// v 7: joint "jb_x" (body 2, planar, translation along u1): unlimited', block)
        # errors naming the joint: bounds reversed, negative numbers, malformed numbers, two <limit>
        self.assert_error(chain(joint_b=joint("jb", "revolute", "a", "b", extra='<limit lower="1" upper="-1"/>')),
                          'joint "jb": <limit lower="1.0" upper="-1.0">: lower > upper')
        self.assert_error(chain(joint_b=joint("jb", "revolute", "a", "b", extra='<limit velocity="-1"/>')),
                          'joint "jb": <limit velocity> -1.0 is negative')
        self.assert_error(chain(joint_b=joint("jb", "revolute", "a", "b", extra='<dynamics friction="-0.5"/>')),
                          'joint "jb": <dynamics friction> -0.5 is negative')
        self.assert_error(chain(joint_b=joint("jb", "revolute", "a", "b", extra='<limit effort="1e"/>')),
                          'joint "jb": <limit effort>', "malformed number")
        self.assert_error(chain(joint_b=joint("jb", "revolute", "a", "b", extra="<limit/><limit/>")),
                          'joint "jb": more than one <limit>')
        # a fixed joint's limits are not read
        text = chain().replace("</robot>", joint("jt", "fixed", "b", "t", extra='<limit lower="x"/>') + link("t") +
                               "</robot>")
        self.convert(text)

    def test_zero_axis(self):
        self.assert_error(chain(joint_b=joint("jb", "revolute", "a", "b", axis="0 0 0")), 'joint "jb"', "axis is zero")
        self.assert_error(chain(joint_b=joint("jb", "prismatic", "a", "b", axis="0.0 -0 0e3")), 'joint "jb"',
                          "axis is zero")
        self.assert_error(chain(joint_b=joint("jb", "planar", "a", "b", axis="0 0 0")), 'joint "jb"', "axis is zero")

    def test_malformed_numbers(self):
        cases = [
            (joint("jb", "revolute", "a", "b", xyz="0 0"), "<origin xyz>"),
            (joint("jb", "revolute", "a", "b", xyz="0 0 0 1"), "<origin xyz>"),
            (joint("jb", "revolute", "a", "b", rpy="0 x 0"), "<origin rpy>"),
            (joint("jb", "revolute", "a", "b", rpy="nan 0 0"), "<origin rpy>"),
            (joint("jb", "revolute", "a", "b", xyz="inf 0 0"), "<origin xyz>"),
            (joint("jb", "revolute", "a", "b", axis="0 1_0 0"), "<axis xyz>"),
            (joint("jb", "revolute", "a", "b", axis="0,0,1"), "<axis xyz>"),
            (joint("jb", "revolute", "a", "b", extra='<mimic joint="ja" multiplier="two"/>'), "<mimic multiplier>"),
            (joint("jb", "revolute", "a", "b", extra='<mimic joint="ja" offset="1e999"/>'), "<mimic offset>"),
        ]
        for j, where in cases:
            with self.subTest(where=where, joint=j):
                self.assert_error(chain(joint_b=j), 'joint "jb"', where)
        self.assert_error(chain(link_b=link("b", inertial(mass="1kg"))), 'link "b"', "<mass value>", "'1kg'")
        self.assert_error(chain(link_b=link("b", inertial(mass="nan"))), 'link "b"', "<mass value>")
        self.assert_error(chain(link_b=link("b", inertial(xyz="0 0 1e999"))), 'link "b"', "<origin xyz>")
        self.assert_error(chain(link_b=link("b", inertial(tensor='ixx="a" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"'))),
                          'link "b"', "ixx")
        self.assert_error(chain(), "--gravity", args=("--gravity", "0", "0", "nan"))
        self.assert_error(chain() + "<oops", "not well-formed XML")

    def test_duplicates_and_names(self):
        self.assert_error(chain() .replace("</robot>", link("a") + "</robot>"), 'link "a" is defined twice')
        text = chain().replace("</robot>", joint("ja", "fixed", "b", "c") + link("c") + "</robot>")
        self.assert_error(text, 'joint "ja" is defined twice')
        rc, header, err = self.run_script(chain(), name="not-an-identifier")
        self.assertEqual(rc, 1)
        self.assertIn("--name", err)

    # ---- joints --------------------------------------------------------------------------------

    def test_joint_types_and_order(self):
        text = robot(
            link("base", inertial(mass="7")),  # dropped: the world
            joint("j_rz", "revolute", "base", "a", axis="0 0 2"),          # normalised: exactly +z
            link("a"),
            joint("j_cont", "continuous", "a", "b", axis="0 -1 0"),        # exactly -y
            link("b"),
            joint("j_py", "prismatic", "a", "c", axis="0 1 0"),
            link("c"),
            joint("j_gen", "revolute", "b", "d", axis="0 3 4"),            # 0 0.6 0.8
            link("d"),
            joint("j_fix", "fixed", "base", "e", axis=None),
            link("e"),
            joint("j_pa", "prismatic", "e", "f", axis="1 1 0"),
            link("f"),
            joint("j_free", "floating", "f", "g", axis=None),
            link("g"),
            joint("j_default", "revolute", "g", "h", axis=None),           # URDF's default axis: 1 0 0
            link("h"),
        )
        header = self.convert(text, "--keep-fixed")
        # depth first from the root, children in document order: a (b (d), c), e (f (g (h)))
        self.assertEqual(tree_lines(header), [
            ("-1", "revolute_z"), ("0", "revolute<ctga::chains::axis::minus_y>"), ("1", "revolute_about"),
            ("0", "prismatic_y"), ("-1", "fixed"), ("4", "prismatic_along"), ("5", "floating"), ("6", "revolute_x")])
        self.assertEqual(names(header, "body_names"), ["a", "b", "d", "c", "e", "f", "g", "h"])
        self.assertEqual(names(header, "joint_names"), ["j_rz", "j_cont", "j_gen", "j_py", "j_fix", "j_pa", "j_free",
                                                        "j_default"])
        self.assertIn("ctga::vec3<T>{T(0.0), T(0.6), T(0.8)});", header)
        s = 1 / math.sqrt(2)
        self.assertIn(f"ctga::vec3<T>{{T({s!r}), T({s!r}), T(0.0)}});", header)
        # only the joints whose axis is a run-time parameter pass one to make_link (for the
        # others their type fixes it, and make_link refuses an axis)
        for body, (_, kind) in enumerate(tree_lines(header)):
            takes_axis = kind in ("revolute_about", "prismatic_along")
            self.assertEqual("ctga::vec3<T>{" in extra_args(body_block(header, body)), takes_axis, body)
        self.assertIn('their inertia dropped: "base" (mass 7.0)', header)
        self.assertIn("Joint limits and <dynamics>: make_limits<T>() (below). Ignored: <safety_controller>", header)
        self.assertNotIn("Ignored: joint limits", header)
        self.assertIn("--keep-fixed", header.splitlines()[1])
        self.assertIn("m.gravity = ctga::vec3<T>{T(0.0), T(0.0), T(-9.81)};", header)
        self.assertTrue(header.startswith("// Generated by tools/urdf_to_ctga.py from robot.urdf; do not edit.\n"))
        for needed in ("#pragma once", "#include <array>", "#include <string_view>", "#include <ctga/ctga.hpp>",
                       "namespace robot {", "template <class T = double>",
                       "constexpr ctga::checked<ctga::chains::model<tree, T>> make_model() noexcept {",
                       "inline constexpr std::array<std::string_view, tree::size> body_names{",
                       "if (!x) return {{}, x.error};", "m.template link<7>() = *x;",
                       "return {m, ctga::error_code::none};"):
            self.assertIn(needed, header)
        # by default the fixed link e is merged into the world: no body, a frame; f hangs on the world
        header = self.convert(text)
        self.assertEqual(tree_lines(header), [
            ("-1", "revolute_z"), ("0", "revolute<ctga::chains::axis::minus_y>"), ("1", "revolute_about"),
            ("0", "prismatic_y"), ("-1", "prismatic_along"), ("4", "floating"), ("5", "revolute_x")])
        self.assertEqual(frame_lines(header), [("base", -1), ("a", 0), ("b", 1), ("d", 2), ("c", 3), ("e", -1),
                                               ("f", 4), ("g", 5), ("h", 6)])

    def test_minus_axes(self):
        for kind, prefix in (("revolute", "revolute"), ("continuous", "revolute"), ("prismatic", "prismatic")):
            for axis, letter in (("-1 0 0", "x"), ("0 -2.5 0", "y"), ("0 0 -1e-3", "z"), ("-0 0 -1", "z")):
                with self.subTest(kind=kind, axis=axis):
                    header = self.convert(chain(joint_b=joint("jb", kind, "a", "b", axis=axis)))
                    self.assertEqual(tree_lines(header)[1], ("0", f"{prefix}<ctga::chains::axis::minus_{letter}>"))
                    self.assertNotIn("ctga::vec3<T>{", extra_args(body_block(header, 1)))
        # not exactly a coordinate axis: the general joint with the normalised axis
        header = self.convert(chain(joint_b=joint("jb", "revolute", "a", "b", axis="1e-9 0 -1")))
        self.assertEqual(tree_lines(header)[1], ("0", "revolute_about"))

    def test_floating_base_gravity_namespace(self):
        header = self.convert(chain(base=link("base")), "--floating-base", "--gravity", "0", "-9.8", "0",
                              "--namespace", "robots::mine")
        self.assertEqual(tree_lines(header), [("-1", "floating"), ("0", "revolute_z"), ("1", "revolute_y")])
        self.assertEqual(names(header, "joint_names"), ["base", "ja", "jb"])
        self.assertEqual(names(header, "body_names"), ["base", "a", "b"])
        self.assertEqual(frame_lines(header), [("base", 0), ("a", 1), ("b", 2)])
        self.assertIn("m.gravity = ctga::vec3<T>{T(0.0), T(-9.8), T(0.0)};", header)
        self.assertIn("namespace robots::mine {", header)
        self.assertIn('The root link "base" is body 0 on a floating joint named "base"', header)
        # a URDF joint already called like the root link: the base joint's name stays unique
        text = chain(joint_a=joint("base", "revolute", "base", "a"), base=link("base"))
        header = self.convert(text, "--floating-base")
        self.assertEqual(names(header, "joint_names"), ["base_joint", "base", "jb"])
        text = chain(joint_a=joint("base", "revolute", "base", "a"), joint_b=joint("base_joint", "revolute", "a", "b"),
                     base=link("base"))
        self.assertEqual(names(self.convert(text, "--floating-base"), "joint_names"),
                         ["base_joint_joint", "base", "base_joint"])
        # the root link without <inertial>: a massless body 0, its subtree has mass
        header = self.convert(chain(), "--floating-base")
        self.assertEqual(mass_properties(body_block(header, 0))[0], 0.0)

    def test_names_are_escaped(self):
        text = chain(link_b='<link name="b &quot;quoted&quot; \\ é">' + inertial() + "</link>",
                     joint_b=joint("jb", "revolute", "a", 'b &quot;quoted&quot; \\ é'))
        header = self.convert(text)
        self.assertIn('"b \\"quoted\\" \\\\ \\303\\251",', header)
        self.assertIn('ctga::chains::fixed_frame<"b \\"quoted\\" \\\\ \\303\\251", 1>>;', header)

    # ---- planar joints -----------------------------------------------------------------------------

    def planar(self, axis, *args):
        """chain() with ja a planar joint "slide" (normal `axis`; None: no <axis>)."""
        j = joint("slide", "planar", "base", "a", xyz="0.5 -0.25 0.125", rpy="0.1 0.2 0.3", axis=axis)
        return self.convert(chain(joint_a=j), *args)

    def test_planar_coordinate_normals(self):
        cases = {
            "0 0 1": ("prismatic_x", "prismatic_y", "revolute_z"),
            "0 0 -1": ("prismatic_x", "prismatic<ctga::chains::axis::minus_y>",
                       "revolute<ctga::chains::axis::minus_z>"),
            "1 0 0": ("prismatic_y", "prismatic_z", "revolute_x"),
            None: ("prismatic_y", "prismatic_z", "revolute_x"),  # URDF's default axis 1 0 0
            "0 2 0": ("prismatic_z", "prismatic_x", "revolute_y"),
            "0 -1 0": ("prismatic_z", "prismatic<ctga::chains::axis::minus_x>",
                       "revolute<ctga::chains::axis::minus_y>"),
            "-1 0 0": ("prismatic_y", "prismatic<ctga::chains::axis::minus_z>",
                       "revolute<ctga::chains::axis::minus_x>"),
        }
        unit = {"x": [1.0, 0, 0], "y": [0, 1.0, 0], "z": [0, 0, 1.0]}
        for axis, types in cases.items():
            with self.subTest(axis=axis):
                header = self.planar(axis)
                lines = tree_lines(header)
                self.assertEqual(lines, [("-1", types[0]), ("0", types[1]), ("1", types[2]), ("2", "revolute_y")])
                self.assertEqual(names(header, "body_names"), ["slide_x", "slide_y", "a", "b"])
                self.assertEqual(names(header, "joint_names"), ["slide_x", "slide_y", "slide", "jb"])
                self.assertEqual(frame_lines(header), [("base", -1), ("a", 2), ("b", 3)])
                # the first body carries the joint's origin, the other two identity placements
                t, theta, u = motor(body_block(header, 0))
                self.assertEqual(t, [0.5, -0.25, 0.125])
                self.assert_rotation(theta, u, rpy_matrix_here(0.1, 0.2, 0.3))
                for b in (1, 2):
                    self.assertEqual(motor(body_block(header, b))[:2], ([0.0, 0.0, 0.0], 0.0))
                # the two translations are virtual (massless), the child link carries the mass
                self.assertEqual(mass_properties(body_block(header, 0))[0], 0.0)
                self.assertEqual(mass_properties(body_block(header, 1))[0], 0.0)
                self.assertEqual(mass_properties(body_block(header, 2))[0], 1.0)
                # (u1, u2, n) right-handed
                axes = []
                for t in types:
                    m = re.search(r"_([xyz])$", t) or re.search(r"minus_([xyz])>$", t)
                    v = list(unit[m.group(1)])
                    axes.append([-c for c in v] if "minus" in t else v)
                self.assertEqual(cross3(axes[0], axes[1]), axes[2])
                self.assertEqual(dofs(lines), 4)

    def test_planar_general_normal(self):
        header = self.planar("1 2 2")
        self.assertEqual(tree_lines(header), [("-1", "prismatic_along"), ("0", "prismatic_along"),
                                              ("1", "revolute_about"), ("2", "revolute_y")])
        u1, u2, n = (numbers(extra_args(body_block(header, b))) for b in range(3))
        self.assert_close(n, [1 / 3, 2 / 3, 2 / 3], 1e-15)
        for v in (u1, u2, n):
            self.assert_close(sum(x * x for x in v), 1.0, 1e-15)
        for a, b in ((u1, u2), (u1, n), (u2, n)):
            self.assert_close(sum(x * y for x, y in zip(a, b)), 0.0, 1e-15)
        self.assert_close(cross3(u1, u2), n, 1e-15)

    def test_planar_names_and_errors(self):
        # the virtual bodies' names avoid the URDF's names
        text = chain(joint_a=joint("p", "planar", "base", "a")).replace("</robot>", link("p_x", "") + "</robot>")
        text = text.replace("</robot>", joint("jx", "fixed", "b", "p_x") + "</robot>")
        header = self.convert(text)
        self.assertEqual(names(header, "body_names")[:3], ["p_x_", "p_y", "a"])
        # a massless planar subtree names the URDF joint
        self.assert_error(robot(link("base", ""), joint("p", "planar", "base", "a"), link("a", "")), 'joint "p"',
                          "no mass in its subtree")

    # ---- aligned joints -----------------------------------------------------------------------------

    def test_aligned(self):
        """A body whose placement does not turn gets aligned<Joint>; one turned by multiples of pi/2
        turned<turn{...}, Joint>; one whose placement turns otherwise (its own rpy, or a merged fixed
        joint's) keeps the plain joint; a mimic wraps the aligned joint."""
        header = self.convert(robot(
            link("base", ""),
            joint("a", "revolute", "base", "l1", xyz="0 0 0.3"), link("l1"),
            joint("b", "revolute", "l1", "l2", xyz="0 0.1 0", rpy="0 0 1.5707963267948966", axis="0 1 0"), link("l2"),
            joint("f", "fixed", "l2", "flange", rpy="0.5 0 0"), link("flange"),
            joint("c", "prismatic", "flange", "l3", axis="1 0 0"), link("l3"),
            joint("d", "revolute", "l3", "l4", xyz="0.2 0 0", rpy="0 0 0", axis="0 1 0",
                  extra='<mimic joint="a" multiplier="2"/>'), link("l4")))
        self.assertEqual(link_entries(header), [
            ("-1", "ctga::chains::aligned<ctga::chains::revolute_z>"),
            ("0", "ctga::chains::turned<ctga::chains::turn{ctga::chains::axis::y, ctga::chains::axis::minus_x, "
                  "ctga::chains::axis::z}, ctga::chains::revolute_y>"),
            ("1", "ctga::chains::prismatic_x"),
            ("2", "ctga::chains::mimic<ctga::chains::aligned<ctga::chains::revolute_y>, 0>")])
        # with a floating base the base's identity placement is aligned too
        header = self.convert(robot(link("base"), joint("a", "revolute", "base", "l1", rpy="0.1 0 0"), link("l1")),
                              "--floating-base")
        self.assertEqual(link_entries(header), [("-1", "ctga::chains::aligned<ctga::chains::floating>"),
                                                ("0", "ctga::chains::revolute_z")])

    def test_turned(self):
        """A turn by multiples of pi/2 is recognised to the rounding of the angle's written digits
        (1e-4 or finer), made exact (its motor's numbers 0, +-1/2, +-sqrt(1/2), +-1), and composed
        exactly with merged fixed joints' turns (two that cancel leave aligned<>)."""
        def body(rpy, extra_fixed_rpy=None):
            parts = [link("base", ""), joint("a", "revolute", "base", "l1", xyz="0 0 0.3", rpy=rpy), link("l1")]
            if extra_fixed_rpy is not None:
                parts = [link("base", ""), joint("f", "fixed", "base", "mid", rpy=extra_fixed_rpy), link("mid", ""),
                         joint("a", "revolute", "mid", "l1", xyz="0 0 0.3", rpy=rpy), link("l1")]
            return link_entries(self.convert(robot(*parts)))[0][1]
        turned = "ctga::chains::turned<ctga::chains::turn{"
        # URDF rpy: R = Rz(yaw) Ry(pitch) Rx(roll); roll pi/2 takes y to z and z to -y
        self.assertEqual(body("1.5707963267948966 0 0"), turned + "ctga::chains::axis::x, ctga::chains::axis::z, "
                         "ctga::chains::axis::minus_y}, ctga::chains::revolute_z>")
        for rpy in ("1.57079632679 0 0", "1.5708 0 0", "15707.963e-4 0 0"):  # rounded to their digits
            self.assertTrue(body(rpy).startswith(turned), rpy)
        for rpy in ("1.571 0 0", "1.5707 0 0", "0.5 0 0", "1.57079632679 0.1 0"):  # coarser, off, or another angle
            self.assertEqual(body(rpy), "ctga::chains::revolute_z", rpy)
        # Rz(-pi/2) Rx(pi): x -> -y, y -> -x, z -> -z
        self.assertEqual(body("3.14159265359 0 -1.57079632679"), turned + "ctga::chains::axis::minus_y, "
                         "ctga::chains::axis::minus_x, ctga::chains::axis::minus_z}, ctga::chains::revolute_z>")
        # a merged fixed joint's turn composed exactly: yaw +pi/2 then -pi/2 is no turn
        self.assertEqual(body("0 0 -1.5707963267948966", "0 0 1.5707963267948966"),
                         "ctga::chains::aligned<ctga::chains::revolute_z>")
        self.assertTrue(body("0 0 1.5707963267948966", "1.5707963267948966 0 0").startswith(turned))
        # the placement motor's rotation is exact: a quarter turn's numbers are sqrt(1/2) and 0
        t, theta, u = motor(body_block(self.convert(robot(link("base", ""), joint(
            "a", "revolute", "base", "l1", rpy="1.57079632679 0 0"), link("l1"))), 0))
        self.assertEqual((theta, u), (math.pi / 2, [1.0, 0.0, 0.0]))

    # ---- mimic ------------------------------------------------------------------------------------

    def gripper(self, mimic='<mimic joint="left" multiplier="-1" offset="0.01"/>', kind="prismatic", extra=""):
        return robot(link("base", ""), joint("ja", "revolute", "base", "hand"), link("hand"),
                     joint("right", kind, "hand", "fr", axis="0 -1 0", extra=mimic), link("fr"),
                     joint("left", "prismatic", "hand", "fl", axis="0 1 0"), link("fl"), extra)

    def test_mimic(self):
        header = self.convert(self.gripper())
        # the mimic comes first in depth-first order; its master body (3) may come after it
        self.assertEqual(tree_lines(header), [("-1", "revolute_z"),
                                              ("0", "mimic<ctga::chains::prismatic<ctga::chains::axis::minus_y>, 2>"),
                                              ("0", "prismatic_y")])
        self.assertIn("ctga::chains::make_link<ctga::chains::mimic<"
                      "ctga::chains::aligned<ctga::chains::prismatic<ctga::chains::axis::minus_y>>, 2>>(", header)
        self.assertEqual(extra_args(body_block(header, 1)).strip(),
                         "),\n            ctga::chains::coupling<T>{T(-1.0), T(0.01)});")
        self.assertEqual(dofs(tree_lines(header)), 2)
        # the defaults: multiplier 1, offset 0; a revolute_about mimic passes coupling, then axis
        header = self.convert(self.gripper('<mimic joint="left"/>', kind="revolute").replace('axis xyz="0 -1 0"',
                                                                                              'axis xyz="0 3 4"'))
        self.assertEqual(tree_lines(header)[1], ("0", "mimic<ctga::chains::revolute_about, 2>"))
        self.assertEqual(extra_args(body_block(header, 1)).strip(),
                         "),\n            ctga::chains::coupling<T>{T(1.0), T(0.0)},\n"
                         "            ctga::vec3<T>{T(0.0), T(0.6), T(0.8)});")
        # --mimic independent: an ordinary joint with its own coordinate, said in the header
        header = self.convert(self.gripper(), "--mimic", "independent")
        self.assertEqual(tree_lines(header)[1], ("0", "prismatic<ctga::chains::axis::minus_y>"))
        self.assertNotIn("coupling", header)
        self.assertIn('--mimic independent: the <mimic> joints "right" are independent coordinates', header)
        self.assertEqual(dofs(tree_lines(header)), 3)

    def test_mimic_errors(self):
        self.assert_error(self.gripper('<mimic joint="nobody"/>'), 'joint "right"', '<mimic joint="nobody">',
                          "no such joint")
        self.assert_error(self.gripper('<mimic/>'), 'joint "right"', "<mimic> without joint")
        # the master is not a 1-dof joint
        text = self.gripper('<mimic joint="jt"/>', extra=joint("jt", "fixed", "hand", "t") + link("t"))
        self.assert_error(text, 'joint "right"', '<mimic joint="jt">', "fixed joint")
        text = self.gripper('<mimic joint="jf"/>', extra=joint("jf", "floating", "hand", "t") + link("t"))
        self.assert_error(text, 'joint "right"', "floating joint")
        # the master is itself a mimic
        text = self.gripper().replace('<axis xyz="0 1 0"/>', '<axis xyz="0 1 0"/><mimic joint="ja"/>')
        self.assert_error(text, 'joint "right"', '<mimic joint="left">', 'the master itself mimics "ja"')
        self.assert_error(self.gripper('<mimic joint="right"/>'), 'joint "right"', "the master itself mimics")
        # a mimic on a joint without one coordinate
        for kind in ("floating", "planar"):
            with self.subTest(kind=kind):
                self.assert_error(self.gripper('<mimic joint="left"/>', kind=kind), 'joint "right"',
                                  f"<mimic> on a {kind} joint")
        # on a fixed joint it is ignored with a warning (nothing moves; TALOS's gripper links)
        rc, header, err = self.run_script(self.gripper('<mimic joint="left"/>', kind="fixed"))
        self.assertEqual(rc, 0, err)
        self.assertIn('warning: joint "right": <mimic> on a fixed joint is ignored', err)
        self.assertNotIn("coupling", header)
        # --mimic independent ignores the element (once its numbers parse)
        self.convert(self.gripper('<mimic joint="nobody"/>'), "--mimic", "independent")

    # ---- numbers ------------------------------------------------------------------------------

    def test_placement_rotation(self):
        # the emitted (u, theta) must give Rz(yaw) Ry(pitch) Rx(roll), computed here independently
        for rpy in [(0.1, -0.2, 0.3), (math.pi / 2, 0, 0), (0, 0, math.pi), (3.0, 1.2, -2.5), (0, 0, 0)]:
            with self.subTest(rpy=rpy):
                header = self.convert(chain(joint_a=joint("ja", "revolute", "base", "a", xyz="1 2 3",
                                                          rpy=" ".join(repr(a) for a in rpy))))
                t, theta, u = motor(body_block(header, 0))
                self.assertEqual(t, [1.0, 2.0, 3.0])
                self.assert_rotation(theta, u, rpy_matrix_here(*rpy))

    def test_inertia_rotation(self):
        # a quarter turn of the inertial frame about z swaps ixx and iyy and negates ixy
        tensor = 'ixx="0.1" ixy="0.01" ixz="0.02" iyy="0.2" iyz="0.03" izz="0.25"'
        header = self.convert(chain(link_a=link("a", inertial(mass="2", xyz="0.1 0.2 0.3", rpy=f"0 0 {math.pi / 2!r}",
                                                              tensor=tensor))))
        mass, com, I, as_given = mass_properties(body_block(header, 0))
        self.assertEqual(mass, 2.0)
        self.assertTrue(as_given)
        self.assertEqual(com, [0.1, 0.2, 0.3])  # the com is the inertial origin, not rotated
        expected = [[0.2, -0.01, -0.03], [-0.01, 0.1, 0.02], [-0.03, 0.02, 0.25]]
        for r in range(3):
            for c in range(3):
                self.assertAlmostEqual(I[r][c], expected[r][c], places=15)
                self.assertEqual(I[r][c], I[c][r])  # exactly symmetric
        # and a general rotation, R I Rᵀ, against the matrices computed here
        rpy = (0.3, -0.4, 1.1)
        header = self.convert(chain(link_a=link("a", inertial(rpy=" ".join(map(repr, rpy)), tensor=tensor))))
        I = mass_properties(body_block(header, 0))[2]
        R = rpy_matrix_here(*rpy)
        I0 = [[0.1, 0.01, 0.02], [0.01, 0.2, 0.03], [0.02, 0.03, 0.25]]
        self.assert_close(I, mm(mm(R, I0), tr(R)), 1e-15)

    def test_numbers_keep_full_precision(self):
        header = self.convert(chain(joint_b=joint("jb", "revolute", "a", "b", xyz="0.1 0.30000000000000004 1e-7")))
        self.assertIn("ctga::make_translator(T(0.1), T(0.30000000000000004), T(1e-07))", header)
        # a body without merged links keeps the URDF's numbers exactly
        header = self.convert(chain(link_b=link("b", inertial(mass="0.30000000000000004", xyz="0.1 0.2 0.7",
                                                              tensor=tensor_attrs(0.1, 0.2, 0.25, 0.01)))))
        self.assertEqual(mass_properties(body_block(header, 1))[:3],
                         (0.30000000000000004, [0.1, 0.2, 0.7], [[0.1, 0.01, 0.0], [0.01, 0.2, 0.0], [0.0, 0.0, 0.25]]))

    # ---- merging fixed joints and frames -----------------------------------------------------------

    # a (revolute) carries c (fixed, rotated and offset), c carries d (fixed) and the massless g;
    # d carries e on a revolute joint; inertial frames rotated
    MERGE_PARTS = {
        # link: (mass, com, rpy of the inertial frame, (ixx, iyy, izz, ixy, ixz, iyz))
        "a": (2.0, [0.1, 0.0, 0.05], (0.0, 0.0, 0.0), (0.03, 0.04, 0.05, 0.001, -0.002, 0.003)),
        "c": (1.5, [0.01, 0.02, -0.03], (0.1, 0.2, 0.3), (0.01, 0.012, 0.015, 0.0005, 0.0, -0.001)),
        "d": (0.5, [0.0, 0.0, 0.02], (0.0, 0.0, 0.0), (0.002, 0.002, 0.001, 0.0, 0.0, 0.0)),
        "e": (1.0, [0.0, 0.0, 0.1], (0.0, 0.0, 0.0), (0.01, 0.01, 0.002, 0.0, 0.0, 0.0)),
    }
    MERGE_JOINTS = {  # child: (name, kind, parent, xyz, rpy)
        "a": ("ja", "revolute", "base", (0.0, 0.0, 0.1), (0.0, 0.0, 0.0)),
        "c": ("jc", "fixed", "a", (0.2, -0.1, 0.3), (0.3, -0.2, 0.5)),
        "g": ("jg", "fixed", "a", (0.0, 0.05, 0.0), (0.0, 0.0, 1.0)),
        "d": ("jd", "fixed", "c", (0.0, 0.0, 0.1), (0.0, 0.0, math.pi / 2)),
        "e": ("je", "revolute", "d", (0.05, 0.0, 0.2), (0.4, 0.0, 0.0)),
    }

    def merge_robot(self):
        parts = [link("base", "")]
        for child, (name, kind, parent, xyz, rpy) in self.MERGE_JOINTS.items():
            parts.append(joint(name, kind, parent, child, xyz=" ".join(map(repr, xyz)), rpy=" ".join(map(repr, rpy)),
                               axis="0 1 0"))
            if child in self.MERGE_PARTS:
                m, c, irpy, (ixx, iyy, izz, ixy, ixz, iyz) = self.MERGE_PARTS[child]
                parts.append(link(child, inertial(repr(m), " ".join(map(repr, c)), " ".join(map(repr, irpy)),
                                                  tensor_attrs(ixx, iyy, izz, ixy, ixz, iyz))))
            else:
                parts.append(link(child, ""))
        return robot(*parts)

    def pose_in_a(self, link_name):
        """(R, p) of a link in a's frame, composing the fixed joints here."""
        R, p = eye(), [0.0, 0.0, 0.0]
        chain_ = []
        while link_name != "a":
            chain_.append(link_name)
            link_name = self.MERGE_JOINTS[link_name][2]
        for l in reversed(chain_):
            _, _, _, xyz, rpy = self.MERGE_JOINTS[l]
            p = [p[i] + mv(R, xyz)[i] for i in range(3)]
            R = mm(R, rpy_matrix_here(*rpy))
        return R, p

    def test_merged_inertia(self):
        header = self.convert(self.merge_robot())
        self.assertEqual(tree_lines(header), [("-1", "revolute_y"), ("0", "revolute_y")])
        self.assertEqual(names(header, "body_names"), ["a", "e"])
        mass, com, I, as_given = mass_properties(body_block(header, 0))
        self.assertTrue(as_given)
        # the parts in a's frame, computed here
        parts = []
        for l in ("a", "c", "d"):
            m, c, irpy, (ixx, iyy, izz, ixy, ixz, iyz) = self.MERGE_PARTS[l]
            R, p = self.pose_in_a(l)
            Ri = mm(R, rpy_matrix_here(*irpy))
            Il = [[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]]
            parts.append((m, [p[i] + mv(R, c)[i] for i in range(3)], mm(mm(Ri, Il), tr(Ri))))
        # invariants: total mass, first moment, inertia about a's origin (additive)
        self.assert_close(mass, sum(m for m, _, _ in parts))
        self.assert_close([mass * x for x in com], [sum(m * c[i] for m, c, _ in parts) for i in range(3)])
        Io = [[sum(about_origin(*pt)[i][j] for pt in parts) for j in range(3)] for i in range(3)]
        self.assert_close(about_origin(mass, com, I), Io)
        # and the tensor about the combined centre of mass, by the parallel-axis theorem
        expected = [[sum(Ik[i][j] + m * (sum((ck[n] - com[n]) ** 2 for n in range(3)) * (i == j) -
                                         (ck[i] - com[i]) * (ck[j] - com[j])) for m, ck, Ik in parts)
                     for j in range(3)] for i in range(3)]
        self.assert_close(I, expected)
        for r in range(3):
            for c in range(3):
                self.assertEqual(I[r][c], I[c][r])
        self.assertIn('// merged: "c", "d", "g"; total mass 4.0', body_block(header, 0))
        # e's placement goes through the merged links c and d: composed here
        R, p = self.pose_in_a("d")
        _, _, _, xyz, rpy = self.MERGE_JOINTS["e"]
        t, theta, u = motor(body_block(header, 1))
        self.assert_close(t, [p[i] + mv(R, xyz)[i] for i in range(3)])
        self.assert_rotation(theta, u, mm(R, rpy_matrix_here(*rpy)))
        self.assertEqual(mass_properties(body_block(header, 1))[:3],
                         (1.0, [0.0, 0.0, 0.1], [[0.01, 0.0, 0.0], [0.0, 0.01, 0.0], [0.0, 0.0, 0.002]]))

    def test_frames(self):
        header = self.convert(self.merge_robot())
        # one loop builds every frame's placement from the table (make_frame, checked)
        self.assertIn("ctga::chains::make_frame<T>(", header)
        self.assertIn("if (!f) return {{}, f.error};", header)
        # every link, depth first, the root first; children in document order (c before g)
        self.assertEqual(frame_lines(header), [("base", -1), ("a", 0), ("c", 0), ("d", 0), ("e", 1), ("g", 0)])
        for k, (name, body) in enumerate(frame_lines(header)):
            with self.subTest(frame=name):
                t, theta, u = frame_motor(header, k)
                if name in ("base", "a", "e"):  # a body's own link (or the world's root): identity
                    self.assertEqual((t, theta, u), ([0.0] * 3, 0.0, [0.0, 0.0, 1.0]))
                    continue
                R, p = self.pose_in_a(name)
                self.assert_close(t, p)
                self.assert_rotation(theta, u, R)
        self.assertIn('// frame 3: link "d" in body 0 (through "jc", "jd")', header)
        # every frame is set, after the links and before the massless-subtree check
        self.assertLess(header.index("m.template link<1>() = *x;"), header.index("m.frames[k] = *f;"))
        self.assertLess(header.index("m.frames[k] = *f;"), header.index("ctga::chains::massless_subtree(m)"))
        # links fixed to the world's root are frames of the world, placed in it
        text = robot(link("world", ""), joint("j0", "fixed", "world", "plate", xyz="1 0 0", rpy="0 0 0.5"),
                     link("plate", inertial(mass="3")), joint("j1", "revolute", "plate", "arm", xyz="0 2 0"),
                     link("arm"))
        header = self.convert(text)
        self.assertEqual(frame_lines(header), [("world", -1), ("plate", -1), ("arm", 0)])
        self.assertIn('their inertia dropped: "plate" (mass 3.0)', header)
        t, theta, u = frame_motor(header, 1)
        self.assertEqual(t, [1.0, 0.0, 0.0])
        self.assert_rotation(theta, u, rpy_matrix_here(0, 0, 0.5))
        t, theta, u = motor(body_block(header, 0))
        self.assert_close(t, [1 - 2 * math.sin(0.5), 2 * math.cos(0.5), 0.0])

    def test_keep_fixed(self):
        header = self.convert(self.merge_robot(), "--keep-fixed")
        self.assertEqual(tree_lines(header), [("-1", "revolute_y"), ("0", "fixed"), ("1", "fixed"), ("2", "revolute_y"),
                                              ("0", "fixed")])
        self.assertIn("ctga::chains::turned<ctga::chains::turn{ctga::chains::axis::y, ctga::chains::axis::minus_x, "
                      "ctga::chains::axis::z}, ctga::chains::fixed>", header)  # d: yawed by pi/2
        self.assertEqual(names(header, "body_names"), ["a", "c", "d", "e", "g"])
        self.assertEqual(names(header, "joint_names"), ["ja", "jc", "jd", "je", "jg"])
        self.assertEqual(frame_lines(header), [("base", -1), ("a", 0), ("c", 1), ("d", 2), ("e", 3), ("g", 4)])
        for k in range(6):
            self.assertEqual(frame_motor(header, k)[:2], ([0.0] * 3, 0.0))
        # each body keeps its own link's numbers; the massless g is a massless body
        m, c, irpy, _ = self.MERGE_PARTS["c"]
        self.assertEqual(mass_properties(body_block(header, 1))[:2], (m, c))
        self.assertEqual(mass_properties(body_block(header, 4))[0], 0.0)
        t, theta, u = motor(body_block(header, 1))
        self.assertEqual(t, [0.2, -0.1, 0.3])
        self.assert_rotation(theta, u, rpy_matrix_here(0.3, -0.2, 0.5))
        self.assertIn("--keep-fixed: every link on a fixed (or locked) joint is its own body", header)

    # ---- inertia policy ------------------------------------------------------------------------

    def test_questionable_inertia_warns(self):
        bad_triangle = tensor_attrs(0.1, 0.1, 0.3)
        header, lines = self.convert_warned(chain(link_b=link("b", inertial(tensor=bad_triangle))))
        self.assertEqual(lines, ['urdf_to_ctga: warning: link "b": principal moments [0.1, 0.1, 0.3] violate the '
                                 "triangle inequality I_i <= I_j + I_k"])
        self.assertTrue(mass_properties(body_block(header, 1))[3])
        self.assertIn('// Warning: link "b": principal moments [0.1, 0.1, 0.3] violate', header)
        bad_pd = 'ixx="0.1" ixy="0.2" ixz="0" iyy="0.1" iyz="0" izz="0.1"'  # moments -0.1, 0.1, 0.3
        _, lines = self.convert_warned(chain(link_b=link("b", inertial(tensor=bad_pd))))
        self.assertEqual(len(lines), 1)
        self.assertIn('link "b": principal moments [-0.1, 0.1, 0.3] are not all positive', lines[0])
        # a merged link is named (not only its body), and so is the lumped body when it stays bad
        text = chain().replace("</robot>", joint("jcam", "fixed", "b", "camera") +
                               link("camera", inertial(mass="0.01", tensor=tensor_attrs(1e-4, 1e-4, 5e-4))) +
                               "</robot>")
        _, lines = self.convert_warned(text)
        self.assertEqual(len(lines), 1)
        self.assertIn('link "camera": principal moments [0.0001, 0.0001, 0.0005] violate', lines[0])
        text = chain(link_b=link("b", inertial(tensor=tensor_attrs(1e-3, 1e-3, 5e-3)))).replace(
            "</robot>", joint("jcam", "fixed", "b", "camera") +
            link("camera", inertial(mass="1", tensor=tensor_attrs(1e-3, 1e-3, 5e-3))) + "</robot>")
        _, lines = self.convert_warned(text)
        self.assertEqual(len(lines), 3)
        self.assertIn('body 1 "b" (link "b" with the merged links "camera"): lumped principal moments', lines[2])
        # mass 0 with a tensor: the tensor is kept (test_mass_zero_tensor_is_kept), with a warning
        _, lines = self.convert_warned(chain().replace(
            "</robot>", joint("jt", "fixed", "b", "t") + link("t", inertial(mass="0")) + "</robot>"))
        self.assertEqual(lines, ['urdf_to_ctga: warning: link "t": mass 0 with a nonzero inertia tensor (kept, as '
                                 "Pinocchio does: it adds to its body's rotational inertia, without a parallel-axis "
                                 "term)"])
        # inertia lumped into the world is not checked (it is dropped)
        self.convert(robot(link("base", inertial(tensor=bad_triangle)), joint("ja", "revolute", "base", "a"),
                           link("a")))

    def test_rounding_level_negatives_are_not_warned(self):
        rod = tensor_attrs(0.006, 0.006, -4e-22)
        header = self.convert(chain(link_b=link("b", inertial(tensor=rod))))
        self.assertEqual(mass_properties(body_block(header, 1))[2][2][2], -4e-22)
        lamina = tensor_attrs(0.1, 0.2, 0.30000000000000004)  # I_z = I_x + I_y to rounding
        self.convert(chain(link_b=link("b", inertial(tensor=lamina))))
        # a point mass (zero tensor) is no warning either
        self.convert(chain(link_b=link("b", inertial(tensor=tensor_attrs(0.0, 0.0, 0.0)))))
        # but just beyond the tolerance 64 eps trace is
        _, lines = self.convert_warned(chain(link_b=link("b", inertial(tensor=tensor_attrs(0.006, 0.006, -1e-14)))))
        self.assertIn("are not all positive", lines[0])

    def test_strict(self):
        self.assert_error(chain(link_b=link("b", inertial(tensor=tensor_attrs(0.1, 0.1, 0.3)))), 'link "b"',
                          "triangle inequality", "(--strict)", args=("--strict",))
        self.assert_error(chain().replace("</robot>", joint("jt", "fixed", "b", "t") + link("t", inertial(mass="0")) +
                                          "</robot>"), 'link "t"', "(--strict)", args=("--strict",))
        # what ctga's physical check refuses must not reach it: a singular tensor
        self.assert_error(chain(link_b=link("b", inertial(tensor=tensor_attrs(0.006, 0.006, -4e-22)))), 'body 1 "b"',
                          "not positive definite", args=("--strict",))
        self.assert_error(chain(link_b=link("b", inertial(tensor=tensor_attrs(0.0, 0.0, 0.0)))), 'body 1 "b"',
                          args=("--strict",))
        # a clean model: the physical check for bodies with mass, as_given only for massless ones
        header = self.convert(chain(link_a=link("a", "")), "--strict")
        self.assertTrue(mass_properties(body_block(header, 0))[3])
        self.assertFalse(mass_properties(body_block(header, 1))[3])
        self.assertIn("{T(0.0), T(0.0), T(0.1)}}}));", body_block(header, 1))
        self.assertIn("--strict", header.splitlines()[1])

    # ---- collision geometry ------------------------------------------------------------------

    def write(self, name, text):
        path = os.path.join(self.tmp.name, name)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
        return path

    def test_collision_shapes(self):
        text = chain(link_a=link("a", inertial() + collision('<box size="0.4 0.2 0.1"/>', xyz="0.1 0 0.2",
                                                             rpy="0.3 -0.2 0.5")),
                     link_b=link("b", inertial() + collision('<cylinder radius="0.03" length="0.2"/>') +
                                 collision('<sphere radius="0.05"/>', xyz="0 0 0.4")))
        header = self.convert(text)
        # the variant of the kinds present, in ctga's order; the shapes link by link, each link's in document order
        self.assertEqual(collision_kinds(header), ["sphere<T", "box<T", "cylinder<T"])
        self.assertIn("inline constexpr std::size_t collision_count = 3;", header)
        self.assertEqual(names(header, "collision_links"), ["a", "b", "b"])
        self.assertIn("constexpr ctga::checked<ctga::constrained::robot_geometry<tree, collision_shape<T>, T, "
                      "collision_count>> make_geometry() noexcept {", header)
        # a box's half extents, a cylinder's radius and half height (z its axis in both), a sphere's radius
        self.assertEqual(shapes(header), [(0, "box", [0.2, 0.1, 0.05]), (1, "cylinder", [0.03, 0.1]),
                                          (1, "sphere", [0.05])])
        t, theta, u = shape_motor(header, 0)
        self.assertEqual(t, [0.1, 0.0, 0.2])
        self.assert_rotation(theta, u, rpy_matrix_here(0.3, -0.2, 0.5))
        self.assertEqual(shape_motor(header, 1), ([0.0] * 3, 0.0, [0.0, 0.0, 1.0]))
        self.assertEqual(shape_motor(header, 2), ([0.0, 0.0, 0.4], 0.0, [0.0, 0.0, 1.0]))
        # the headers of the kinds present, and no more
        for h in ("sphere.hpp", "box.hpp", "cylinder.hpp", "shape_set.hpp"):
            self.assertIn(f"#include <ctga/collision/{h}>", header)
        self.assertIn("#include <ctga/constrained/robot_geometry.hpp>", header)
        self.assertNotIn("hull.hpp", header)
        self.assertNotIn("#include <span>", header)
        self.assertIn("<collision>: make_geometry<T>()", header)
        # without <collision>: none of it
        header = self.convert(chain())
        for absent in ("make_geometry", "collision_shape", "robot_geometry.hpp", "#include <ctga/collision/"):
            self.assertNotIn(absent, header)
        self.assertIn("visuals, collisions, transmissions.", header)

    def test_collision_on_merged_links_and_the_world(self):
        jc_xyz, jc_rpy, c_xyz, c_rpy = [0.1, 0.2, 0.3], [0.2, 0.1, -0.4], [0.05, 0.0, -0.02], [0.0, 0.3, 0.0]
        text = chain(base=link("base", collision('<sphere radius="0.1"/>'))).replace(
            "</robot>", joint("jc", "fixed", "b", "c", xyz=spaced(jc_xyz), rpy=spaced(jc_rpy)) +
            link("c", collision('<box size="0.1 0.1 0.1"/>', xyz=spaced(c_xyz), rpy=spaced(c_rpy))) + "</robot>")
        header, lines = self.convert_warned(text)
        self.assertEqual(lines, ['urdf_to_ctga: warning: link "base" is fixed to the world: its 1 <collision> shape(s) '
                                 "left out (the world's shapes are constrained::static_shape, not the robot's)"])
        # c is merged into b's body: its box there, at jc's origin followed by the box's
        self.assertEqual(shapes(header), [(1, "box", [0.05, 0.05, 0.05])])
        self.assertEqual(names(header, "collision_links"), ["c"])
        R = rpy_matrix_here(*jc_rpy)
        t, theta, u = shape_motor(header, 0)
        self.assert_close(t, [jc_xyz[i] + mv(R, c_xyz)[i] for i in range(3)])
        self.assert_rotation(theta, u, mm(R, rpy_matrix_here(*c_rpy)))
        # with a floating base the root is body 0, its sphere on it
        header = self.convert(text, "--floating-base")
        self.assertEqual([(b, k) for b, k, _ in shapes(header)], [(0, "sphere"), (2, "box")])

    def test_collision_stl_meshes(self):
        stl_binary(os.path.join(self.tmp.name, "cube.stl"), split_cube(0.125))
        os.makedirs(os.path.join(self.tmp.name, "pkg", "meshes"))
        stl_ascii(os.path.join(self.tmp.name, "pkg", "meshes", "cube.STL"), split_cube(0.125))
        text = chain(link_a=link("a", inertial() + collision('<mesh filename="cube.stl"/>')),
                     link_b=link("b", inertial() + collision('<mesh filename="package://pkg/meshes/cube.STL" '
                                                             'scale="2 2 -2"/>', xyz="0 0 0.5") +
                                 collision(f'<mesh filename="file://{self.tmp.name}/cube.stl"/>')))
        header = self.convert(text)
        # each face's centre is no corner: the hull's 8 vertices; a mirroring scale is a mirrored hull
        self.assertEqual(shapes(header), [(0, "hull", corners(0.125)),
                                          (1, "hull", sorted([x, y, -z] for x, y, z in corners(0.25))),
                                          (1, "hull", corners(0.125))])
        self.assertEqual(collision_kinds(header), ["convex_hull<T, 8"])
        self.assertIn("ctga::collision::make_hull<8, T>(std::span<const ctga::vec3<T>>(hull_0))", header)
        self.assertIn('// shape 1: link "b", mesh "package://pkg/meshes/cube.STL" scale 2.0 2.0 -2.0: its convex hull, '
                      "8 vertices", header)
        self.assertEqual(shape_motor(header, 1)[0], [0.0, 0.0, 0.5])
        for h in ("#include <span>", "#include <ctga/collision/hull.hpp>"):
            self.assertIn(h, header)

    def test_collision_mesh_reduced(self):
        points = ball()
        stl_ascii(os.path.join(self.tmp.name, "ball.stl"),
                  [(points[i], points[(i + 1) % len(points)], points[(i + 2) % len(points)])
                   for i in range(0, len(points), 3)])
        text = chain(link_a=link("a", inertial() + collision('<mesh filename="ball.stl"/>')))
        header, lines = self.convert_warned(text, "--hull-vertices", "12")
        self.assertEqual(len(lines), 1)
        found = re.fullmatch(r'urdf_to_ctga: warning: link "a": mesh "ball.stl": its convex hull has 162 vertices, '
                             r"more than --hull-vertices 12: reduced to 12 of them, whose hull lies up to (\S+) m "
                             r"inside the true hull", lines[0])
        self.assertIsNotNone(found, lines[0])
        depth = float(found.group(1))
        [(body, kind, kept)] = shapes(header)
        self.assertEqual((body, kind, len(kept)), (0, "hull", 12))
        self.assertIn("convex_hull<T, 12>", header)
        self.assertIn("--hull-vertices 12", header.splitlines()[1])
        # the vertices kept are the mesh's (extreme points), and the depth lies between a lower bound (each
        # point's height above the reduced hull's support plane along it) and an upper one (to its nearest kept vertex)
        self.assertTrue(all(any(math.dist(k, p) == 0 for p in points) for k in kept))
        lower = max(math.hypot(*p) - max(sum(a * b for a, b in zip(k, p)) for k in kept) for p in points)
        upper = max(min(math.dist(p, k) for k in kept) for p in points)
        self.assertGreater(lower, 0.05)
        self.assertTrue(lower * (1 - 5e-3) <= depth <= upper * (1 + 5e-3), (lower, depth, upper))
        # within the default capacity (32 < 162): 32 vertices; a capacity above the hull's: all of them, no warning
        header, _ = self.convert_warned(text)
        self.assertEqual(len(shapes(header)[0][2]), 32)
        header = self.convert(text, "--hull-vertices", "200")
        self.assertEqual(shapes(header)[0][2], sorted(list(p) for p in points))
        for bad in ("3", "8193", "x"):
            self.assert_error(text, f"--hull-vertices {bad}", "4 to 8192", args=("--hull-vertices", bad))

    def test_collision_meshes_left_out(self):
        stl_binary(os.path.join(self.tmp.name, "cube.stl"), split_cube(0.125))
        stl_binary(os.path.join(self.tmp.name, "flat.stl"), [((0, 0, 0), (1, 0, 0), (0, 1, 0)),
                                                             ((1, 0, 0), (1, 1, 0), (0, 1, 0))])
        self.write("junk.stl", "neither binary nor ASCII STL")
        left_out = (collision('<mesh filename="arm.dae"/>') + collision('<mesh filename="missing.stl"/>') +
                    collision('<mesh filename="junk.stl"/>') + collision('<mesh filename="flat.stl"/>') +
                    collision('<capsule radius="0.1" length="0.2"/>'))
        header, lines = self.convert_warned(chain(link_a=link("a", inertial() + left_out)))
        self.assertEqual([l[len("urdf_to_ctga: warning: "):] for l in lines], [
            'link "a": mesh "arm.dae": only STL meshes are read: left out',
            'link "a": mesh "missing.stl": no such file (relative to the URDF\'s directory; package:// searched from '
            "there upwards): left out",
            'link "a": mesh "junk.stl": not an STL file (binary: its size is not 84 + 50 bytes per triangle; ASCII: '
            "no 'solid'): left out",
            'link "a": mesh "flat.stl": its points span no volume (fewer than four, or all on one plane): left out',
            'link "a": <capsule> is not a URDF geometry (box, sphere, cylinder, mesh): left out'])
        # no shape left: the header of the robot without <collision>, but for the warnings' comments
        self.assertEqual([l for l in header.splitlines() if not l.startswith("// Warning: ")],
                         self.convert(chain()).splitlines())
        # --meshes omit: every mesh left out, one warning; the other shapes stay
        text = chain(link_a=link("a", inertial() + collision('<mesh filename="cube.stl"/>') + left_out +
                                 collision('<box size="1 1 1"/>')))
        header, lines = self.convert_warned(text, "--meshes", "omit")
        self.assertEqual(lines, ["urdf_to_ctga: warning: link \"a\": <capsule> is not a URDF geometry (box, sphere, "
                                 "cylinder, mesh): left out",
                                 "urdf_to_ctga: warning: --meshes omit: 5 <mesh> collision shape(s) left out"])
        self.assertEqual(shapes(header), [(0, "box", [0.5, 0.5, 0.5])])
        self.assertIn("--meshes omit", header.splitlines()[1])

    def test_collision_sizes_refused(self):
        for geometry, needle in (('<box size="0.1 0 0.1"/>', '<box size> 0.1 0.0 0.1: a size is not positive'),
                                 ('<sphere radius="-0.1"/>', "<sphere radius> -0.1: a size is not positive"),
                                 ('<cylinder radius="0.1" length="0"/>',
                                  "<cylinder length> 0.0: a size is not positive"),
                                 ('<mesh filename="cube.stl" scale="1 0 1"/>', "a zero scale flattens the mesh"),
                                 ('<mesh/>', '<mesh> without filename="..."'),
                                 ('<box size="1 1"/>', "is not three numbers"),
                                 ("", "<geometry> must hold one shape"),
                                 ('<box size="1 1 1"/><sphere radius="1"/>', "<geometry> must hold one shape")):
            with self.subTest(geometry=geometry):
                self.assert_error(chain(link_b=link("b", inertial() + collision(geometry))), 'link "b" <collision>: ',
                                  needle)

    def test_exclude_pair_and_srdf(self):
        sphere = collision('<sphere radius="0.05"/>')
        text = robot(link("base", sphere), joint("ja", "revolute", "base", "a"), link("a", inertial() + sphere),
                     joint("jb", "revolute", "a", "b"), link("b", inertial() + sphere),
                     joint("jc", "fixed", "b", "c"), link("c", sphere),
                     joint("jd", "revolute", "a", "d"), link("d", inertial() + sphere))
        srdf = self.write("robot.srdf", '<robot name="test"><disable_collisions link1="d" link2="b" reason="Never"/>'
                                        '<disable_collisions link1="c" link2="a" reason="Adjacent"/>'
                                        '<disable_collisions link1="base" link2="a" reason="Adjacent"/></robot>')
        header, _ = self.convert_warned(text, "--exclude-pair", "a,c", "--exclude-pair", "b,c", "--srdf", srdf)
        # bodies a 0, b 1 (c merged into it), d 2: (a, c) is (0, 1), (b, c) one body, (d, b) (1, 2), (c, a) (0, 1)
        # again; the world's base is in no pair of bodies
        self.assertEqual(excluded(header), [(0, 1), (1, 2)])
        self.assertIn('{0, 1},  // links "a", "c" (--exclude-pair a,c)', header)
        self.assertIn('{1, 2},  // links "d", "b" (--srdf robot.srdf)', header)
        self.assertIn("if (const auto e = g.exclude(p[0], p[1]); e != ctga::error_code::none) return {{}, e};", header)
        self.assertIn("--exclude-pair a,c --exclude-pair b,c --srdf robot.srdf", header.splitlines()[1])
        # names the URDF does not have, malformed input
        self.assert_error(text, '--exclude-pair a,zz: no link named "zz"', args=("--exclude-pair", "a,zz"))
        self.assert_error(text, "--exclude-pair a: expected LINK_A,LINK_B", args=("--exclude-pair", "a"))
        self.write("bad.srdf", '<robot><disable_collisions link1="a" link2="e"/></robot>')
        self.assert_error(text, '--srdf bad.srdf: no link named "e"', args=("--srdf", os.path.join(self.tmp.name,
                                                                                                    "bad.srdf")))
        self.write("broken.srdf", "<robot><disable_collisions link1=")
        self.assert_error(text, "broken.srdf: not well-formed XML", args=("--srdf", os.path.join(self.tmp.name,
                                                                                                 "broken.srdf")))

    # ---- fixtures --------------------------------------------------------------------------------

    def fixture_header(self, name, *args, warnings=0):
        rc, header, err = self.run_script(None, *args, source=os.path.join(DATA, name))
        self.assertEqual(rc, 0, err)
        self.assertEqual(len(err.splitlines()), warnings, err)
        return header, err

    def counts(self, header):
        types = tree_lines(header)
        return len(types), len(frame_lines(header)), dofs(types)

    def test_fixture_ur5e(self):
        header, _ = self.fixture_header("ur5e.urdf")
        self.assertEqual(self.counts(header), (6, 11, 6))
        self.assertEqual(tree_lines(header), [(str(i - 1), "revolute_z") for i in range(6)])
        self.assertEqual(frame_lines(header), [("base_link", -1), ("base_link_inertia", -1), ("shoulder_link", 0),
                                               ("upper_arm_link", 1), ("forearm_link", 2), ("wrist_1_link", 3),
                                               ("wrist_2_link", 4), ("wrist_3_link", 5), ("flange", 5), ("tool0", 5),
                                               ("base", -1)])
        self.assertIn('their inertia dropped: "base_link_inertia" (mass 4.0)', header)
        # the shoulder sits 0.1625 m above base_link_inertia, which is yawed by pi in the world
        t, theta, u = motor(body_block(header, 0))
        self.assert_close(t, [0.0, 0.0, 0.1625])
        self.assert_rotation(theta, u, rpy_matrix_here(0, 0, math.pi))
        # flange: the rotation of its rpy; tool0 (flange then tool0): wrist_3's own axes again
        t, theta, u = frame_motor(header, 8)
        self.assert_rotation(theta, u, rpy_matrix_here(0, -math.pi / 2, -math.pi / 2))
        t, theta, u = frame_motor(header, 9)
        self.assertEqual(t, [0.0] * 3)
        self.assert_rotation(theta, u, eye(), 1e-15)
        masses = [mass_properties(body_block(header, b))[0] for b in range(6)]
        self.assertEqual(masses, [3.761, 8.058, 2.846, 1.37, 1.3, 0.365])

    def test_fixture_mobile_gripper(self):
        header, err = self.fixture_header("mobile_gripper.urdf", warnings=1)
        self.assertIn('warning: link "camera_link": principal moments [0.0001, 0.0001, 0.0005] violate', err)
        self.assertEqual(self.counts(header), (9, 11, 8))
        self.assertEqual(tree_lines(header), [
            ("-1", "prismatic_x"), ("0", "prismatic_y"), ("1", "revolute_z"), ("2", "revolute_z"),
            ("3", "revolute<ctga::chains::axis::minus_y>"), ("4", "prismatic<ctga::chains::axis::minus_z>"),
            ("5", "revolute_about"), ("6", "prismatic_y"), ("6", "mimic<ctga::chains::prismatic_y, 7>")])
        self.assertEqual(names(header, "body_names"), ["base_planar_x", "base_planar_y", "base_link", "turret",
                                                       "upper_arm", "forearm_link", "hand", "finger_left",
                                                       "finger_right"])
        self.assertEqual(names(header, "joint_names")[:3], ["base_planar_x", "base_planar_y", "base_planar"])
        self.assertEqual(frame_lines(header), [("odom", -1), ("base_link", 2), ("imu_link", 2), ("camera_link", 2),
                                               ("turret", 3), ("upper_arm", 4), ("forearm_link", 5), ("hand", 6),
                                               ("finger_left", 7), ("finger_right", 8), ("tcp", 6)])
        self.assertIn("ctga::chains::coupling<T>{T(-1.0), T(0.01)}", body_block(header, 8))
        # the base body lumps the camera: 25 + 0.2 kg
        self.assert_close(mass_properties(body_block(header, 2))[0], 25.2)
        # the imu frame: yawed by pi/2
        t, theta, u = frame_motor(header, 2)
        self.assertEqual(t, [0.1, 0.0, 0.21])
        self.assert_rotation(theta, u, rpy_matrix_here(0, 0, math.pi / 2))
        # --strict: the camera is an error; --mimic independent: one more coordinate
        rc, _, err = self.run_script(fixture("mobile_gripper.urdf"), "--strict")
        self.assertEqual(rc, 1)
        self.assertIn('link "camera_link"', err)
        header, _ = self.fixture_header("mobile_gripper.urdf", "--mimic", "independent", warnings=1)
        self.assertEqual(self.counts(header), (9, 11, 9))

    def test_fixture_legged(self):
        header, _ = self.fixture_header("legged.urdf", "--floating-base")
        self.assertEqual(self.counts(header), (13, 26, 18))
        self.assertEqual(names(header, "joint_names")[:4], ["base", "LF_HAA", "LF_HFE", "LF_KFE"])
        self.assertEqual(tree_lines(header)[9], ("8", "revolute<ctga::chains::axis::minus_y>"))
        self.assertEqual(frame_lines(header)[:11], [
            ("base", 0), ("base_inertia", 0), ("imu_link", 0), ("face", 0), ("depth_camera", 0),
            ("depth_camera_optical", 0), ("LF_HIP", 1), ("LF_THIGH", 2), ("LF_SHANK", 3), ("LF_shank_fixed", 3),
            ("LF_FOOT", 3)])
        # body 0 (no inertial of its own) lumps the trunk, the face and the camera
        self.assert_close(mass_properties(body_block(header, 0))[0], 16.8 + 0.7 + 0.12)
        self.assert_close(mass_properties(body_block(header, 3))[0], 0.33 + 0.14)
        self.assertIn('// merged: "base_inertia", "imu_link", "face", "depth_camera", "depth_camera_optical"',
                      body_block(header, 0))
        # the foot: through the shank_fixed link (yawed by pi/2 on the left legs)
        t, theta, u = frame_motor(header, 10)
        self.assert_close(t, [0.1 + 0.08795, -0.02 + 0.01305, -0.33797])
        self.assert_rotation(theta, u, rpy_matrix_here(0, 0, math.pi / 2))

    def test_fixtures_from_before(self):
        header, _ = self.fixture_header("arm7.urdf")
        self.assertEqual(self.counts(header), (7, 9, 7))
        self.assertEqual(frame_lines(header)[-1], ("tool", 6))
        header, _ = self.fixture_header("quadruped.urdf", "--floating-base")
        self.assertEqual(self.counts(header), (13, 17, 18))
        self.assertEqual(names(header, "joint_names")[0], "trunk")
        header, _ = self.fixture_header("quadruped.urdf", "--floating-base", "--keep-fixed")
        self.assertEqual(self.counts(header), (17, 17, 18))

    def test_fixture_quadruped_collisions(self):
        header, _ = self.fixture_header("quadruped.urdf", "--floating-base")
        hip_cover = sorted([x, y, z] for x in (-0.03125, 0.03125) for y in (0.0, 0.046875)
                           for z in (-0.015625, 0.015625))
        self.assertEqual(collision_kinds(header), ["sphere<T", "box<T", "convex_hull<T, 8"])
        self.assertEqual(names(header, "collision_links"),
                         ["trunk", "FL_hip", "FL_foot", "FR_foot", "RL_foot", "RR_foot"])
        # the trunk's box on body 0, meshes/hip_cover.stl's hull on FL_hip's body, the feet on their calves'
        self.assertEqual(shapes(header), [(0, "box", [0.25, 0.1, 0.05]), (1, "hull", hip_cover)] +
                         [(b, "sphere", [0.02]) for b in (3, 6, 9, 12)])
        for k in range(6):
            self.assertEqual(shape_motor(header, k), ([0.0, 0.0, -0.2 if k >= 2 else 0.0], 0.0, [0.0, 0.0, 1.0]))

    def test_stdout(self):
        path = os.path.join(self.tmp.name, "r.urdf")
        with open(path, "w", encoding="utf-8") as f:
            f.write(chain())
        r = subprocess.run([sys.executable, SCRIPT, path, "--name", "r"], capture_output=True, text=True, check=False)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("namespace r {", r.stdout)


if __name__ == "__main__":
    unittest.main()
