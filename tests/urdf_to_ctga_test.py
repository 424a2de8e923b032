#!/usr/bin/env python3
"""tools/urdf_to_ctga.py on small URDFs written to temporary files: every error case exits with
status 1 and a message naming the offending element (and writes no header); good URDFs give the
expected joint types, body order, names, numbers (rotations, inertia tensors) and options.
Registered in tests/CMakeLists.txt as the CTest test urdf_to_ctga_script. Standard library only."""

import math
import os
import re
import subprocess
import sys
import tempfile
import unittest

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, "tools", "urdf_to_ctga.py")


def inertial(mass="1.0", xyz="0 0 0", rpy="0 0 0", tensor='ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"'):
    return (f'<inertial><origin xyz="{xyz}" rpy="{rpy}"/><mass value="{mass}"/>'
            f'<inertia {tensor}/></inertial>')


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


class Converter(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.addCleanup(self.tmp.cleanup)

    def run_script(self, text, *args, name="robot"):
        path = os.path.join(self.tmp.name, "robot.urdf")
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

    # ---- errors ------------------------------------------------------------------------------

    def test_unsupported_joint_types(self):
        err = self.assert_error(chain(joint_b=joint("knee", "planar", "a", "b")), 'joint "knee"', '"planar"')
        self.assertIn("is not supported (revolute, continuous, prismatic, fixed, floating)", err)
        self.assert_error(chain(joint_b=joint("knee", "spherical", "a", "b")), 'joint "knee"', '"spherical"')
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

    def test_inertials(self):
        self.assert_error(chain(link_b=link("b", "")), 'link "b"', "no <inertial>")
        self.assert_error(chain(link_b=link("b", inertial(mass="0"))), 'link "b"', "mass 0.0 is not positive")
        self.assert_error(chain(link_a=link("a", inertial(mass="-2.5"))), 'link "a"', "not positive")
        self.assert_error(chain(link_a=link("a", '<inertial><mass value="1"/></inertial>')), 'link "a"', "<inertia>")
        self.assert_error(chain(link_a=link("a", '<inertial><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/>'
                                                 '</inertial>')), 'link "a"', "<mass>")
        self.assert_error(chain(link_a=link("a", inertial(tensor='ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0"'))),
                          'link "a"', "izz")
        bad_pd = 'ixx="0.1" ixy="0.2" ixz="0" iyy="0.1" iyz="0" izz="0.1"'
        self.assert_error(chain(link_b=link("b", inertial(tensor=bad_pd))), 'link "b"', "not positive definite")
        bad_triangle = 'ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.3"'
        self.assert_error(chain(link_b=link("b", inertial(tensor=bad_triangle))), 'link "b"', "triangle inequality")
        # the root is the world: its inertial (even a massless one) is dropped, and it may have none
        header = self.convert(robot(link("base", inertial(mass="0")), joint("ja", "revolute", "base", "a"), link("a")))
        self.assertIn('The root link "base" is the fixed world', header)
        self.assertIn("(mass 0.0) is dropped", header)
        # but with --floating-base the root is a body and needs a good one
        self.assert_error(chain(), 'link "base"', "no <inertial>", args=("--floating-base",))

    def test_zero_axis(self):
        self.assert_error(chain(joint_b=joint("jb", "revolute", "a", "b", axis="0 0 0")), 'joint "jb"', "axis is zero")
        self.assert_error(chain(joint_b=joint("jb", "prismatic", "a", "b", axis="0.0 -0 0e3")), 'joint "jb"',
                          "axis is zero")

    def test_malformed_numbers(self):
        cases = [
            (joint("jb", "revolute", "a", "b", xyz="0 0"), "<origin xyz>"),
            (joint("jb", "revolute", "a", "b", xyz="0 0 0 1"), "<origin xyz>"),
            (joint("jb", "revolute", "a", "b", rpy="0 x 0"), "<origin rpy>"),
            (joint("jb", "revolute", "a", "b", rpy="nan 0 0"), "<origin rpy>"),
            (joint("jb", "revolute", "a", "b", xyz="inf 0 0"), "<origin xyz>"),
            (joint("jb", "revolute", "a", "b", axis="0 1_0 0"), "<axis xyz>"),
            (joint("jb", "revolute", "a", "b", axis="0,0,1"), "<axis xyz>"),
        ]
        for j, where in cases:
            with self.subTest(where=where, joint=j):
                self.assert_error(chain(joint_b=j), 'joint "jb"', where)
        self.assert_error(chain(link_b=link("b", inertial(mass="1kg"))), 'link "b"', "<mass value>", "'1kg'")
        self.assert_error(chain(link_b=link("b", inertial(xyz="0 0 1e999"))), 'link "b"', "<origin xyz>")
        self.assert_error(chain(link_b=link("b", inertial(tensor='ixx="a" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"'))),
                          'link "b"', "ixx")
        self.assert_error(chain(), "--gravity", args=("--gravity", "0", "0", "nan"))
        self.assert_error(chain() + "<oops", "not well-formed XML")

    def test_mimic(self):
        j = joint("jb", "revolute", "a", "b", extra='<mimic joint="ja" multiplier="1"/>')
        self.assert_error(chain(joint_b=j), 'joint "jb"', "<mimic> is not supported")

    def test_duplicates_and_names(self):
        self.assert_error(chain() .replace("</robot>", link("a") + "</robot>"), 'link "a" is defined twice')
        text = chain().replace("</robot>", joint("ja", "fixed", "b", "c") + link("c") + "</robot>")
        self.assert_error(text, 'joint "ja" is defined twice')
        rc, header, err = self.run_script(chain(), name="not-an-identifier")
        self.assertEqual(rc, 1)
        self.assertIn("--name", err)

    # ---- good URDFs ---------------------------------------------------------------------------

    def tree_lines(self, header):
        body = header[header.index("using tree = ctga::chains::tree<"):header.index(">;") + 2]
        return re.findall(r"ctga::chains::link<(-?\d+), ctga::chains::(\w+)>", body)

    def test_joint_types_and_order(self):
        text = robot(
            link("base", inertial(mass="7")),  # dropped: the world
            joint("j_rz", "revolute", "base", "a", axis="0 0 2"),          # normalised: exactly +z
            link("a"),
            joint("j_cont", "continuous", "a", "b", axis="0 -1 0"),        # -y: not +y
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
        header = self.convert(text)
        # depth first from the root, children in document order: a (b (d), c), e (f (g (h)))
        self.assertEqual(self.tree_lines(header), [
            ("-1", "revolute_z"), ("0", "revolute_about"), ("1", "revolute_about"), ("0", "prismatic_y"),
            ("-1", "fixed"), ("4", "prismatic_along"), ("5", "floating"), ("6", "revolute_x")])
        self.assertIn('body_names{\n    "a",\n    "b",\n    "d",\n    "c",\n    "e",\n    "f",\n    "g",\n    "h",\n};',
                      header)
        self.assertIn('joint_names{\n    "j_rz",\n    "j_cont",\n    "j_gen",\n    "j_py",\n    "j_fix",\n    "j_pa",\n'
                      '    "j_free",\n    "j_default",\n};', header)
        self.assertIn("ctga::vec3<T>{T(0.0), T(0.6), T(0.8)});", header)
        self.assertIn("ctga::vec3<T>{T(0.0), T(-1.0), T(0.0)});", header)
        s = 1 / math.sqrt(2)
        self.assertIn(f"ctga::vec3<T>{{T({s!r}), T({s!r}), T(0.0)}});", header)
        # only the joints whose axis is a run-time parameter pass one to make_link (for the
        # others their type fixes it, and make_link refuses an axis)
        for body in range(8):
            takes_axis = self.tree_lines(header)[body][1] in ("revolute_about", "prismatic_along")
            self.assertEqual("ctga::vec3<T>{" in self.body_block(header, body).split("make_mass_properties")[1]
                             .split("if (!x)")[0].split("ctga::mat3<T>")[1], takes_axis, body)
        self.assertIn("(mass 7.0) is dropped", header)
        self.assertIn("Ignored: joint limits", header)
        self.assertIn("m.gravity = ctga::vec3<T>{T(0.0), T(0.0), T(-9.81)};", header)
        self.assertTrue(header.startswith("// Generated by tools/urdf_to_ctga.py from robot.urdf; do not edit.\n"))
        for needed in ("#pragma once", "#include <array>", "#include <string_view>", "#include <ctga/ctga.hpp>",
                       "namespace robot {", "template <class T = double>",
                       "constexpr ctga::checked<ctga::chains::model<tree, T>> make_model() noexcept {",
                       "inline constexpr std::array<std::string_view, tree::size> body_names{",
                       "if (!x) return {{}, x.error};", "m.template link<7>() = *x;",
                       "return {m, ctga::error_code::none};"):
            self.assertIn(needed, header)

    def test_floating_base_gravity_namespace(self):
        header = self.convert(chain(base=link("base")), "--floating-base", "--gravity", "0", "-9.8", "0",
                              "--namespace", "robots::mine")
        self.assertEqual(self.tree_lines(header), [("-1", "floating"), ("0", "revolute_z"), ("1", "revolute_y")])
        self.assertIn('joint_names{\n    "floating_base",\n    "ja",\n    "jb",\n};', header)
        self.assertIn('body_names{\n    "base",\n    "a",\n    "b",\n};', header)
        self.assertIn("m.gravity = ctga::vec3<T>{T(0.0), T(-9.8), T(0.0)};", header)
        self.assertIn("namespace robots::mine {", header)
        # a URDF joint already called floating_base: the base joint's name stays unique
        text = chain(joint_a=joint("floating_base", "revolute", "base", "a"), base=link("base"))
        header = self.convert(text, "--floating-base")
        self.assertIn('joint_names{\n    "floating_base_",\n    "floating_base",\n', header)

    def test_names_are_escaped(self):
        text = chain(link_b='<link name="b &quot;quoted&quot; \\ é">' + inertial() + "</link>",
                     joint_b=joint("jb", "revolute", "a", 'b &quot;quoted&quot; \\ é'))
        header = self.convert(text)
        self.assertIn('"b \\"quoted\\" \\\\ \\303\\251",', header)

    # ---- numbers ------------------------------------------------------------------------------

    @staticmethod
    def numbers(s):
        return [float(x) for x in re.findall(r"T\(([^()]*)\)", s)]

    def body_block(self, header, index):
        start = header.index(f"{{  // body {index}:")
        return header[start:header.index("m.template link<", start)]

    def test_placement_rotation(self):
        # the emitted (u, theta) must give Rz(yaw) Ry(pitch) Rx(roll), computed here independently
        for rpy in [(0.1, -0.2, 0.3), (math.pi / 2, 0, 0), (0, 0, math.pi), (3.0, 1.2, -2.5), (0, 0, 0)]:
            with self.subTest(rpy=rpy):
                header = self.convert(chain(joint_a=joint("ja", "fixed", "base", "a", xyz="1 2 3",
                                                          rpy=" ".join(repr(a) for a in rpy))))
                block = self.body_block(header, 0)
                call = block[block.index("ctga::make_translator("):block.index("ctga::make_mass_properties")]
                t = self.numbers(call[:call.index("ctga::make_rotor(")])
                theta, ux, uy, uz = self.numbers(call[call.index("ctga::make_rotor("):])
                self.assertEqual(t, [1.0, 2.0, 3.0])
                self.assertAlmostEqual(ux * ux + uy * uy + uz * uz, 1.0, places=15)
                expected = rpy_matrix_here(*rpy)
                got = rodrigues(ux, uy, uz, theta)
                for r in range(3):
                    for c in range(3):
                        self.assertAlmostEqual(got[r][c], expected[r][c], places=14)

    def test_inertia_rotation(self):
        # a quarter turn of the inertial frame about z swaps ixx and iyy and negates ixy
        tensor = 'ixx="0.1" ixy="0.01" ixz="0.02" iyy="0.2" iyz="0.03" izz="0.25"'
        header = self.convert(chain(link_a=link("a", inertial(mass="2", xyz="0.1 0.2 0.3", rpy=f"0 0 {math.pi / 2!r}",
                                                              tensor=tensor))))
        block = self.body_block(header, 0)
        mp = self.numbers(block[block.index("ctga::make_mass_properties("):block.index("if (!x)")])[:13]
        mass, com, I = mp[0], mp[1:4], [mp[4:7], mp[7:10], mp[10:13]]
        self.assertEqual(mass, 2.0)
        self.assertEqual(com, [0.1, 0.2, 0.3])  # the com is the inertial origin, not rotated
        expected = [[0.2, -0.01, -0.03], [-0.01, 0.1, 0.02], [-0.03, 0.02, 0.25]]
        for r in range(3):
            for c in range(3):
                self.assertAlmostEqual(I[r][c], expected[r][c], places=15)
                self.assertEqual(I[r][c], I[c][r])  # exactly symmetric
        # and a general rotation, R I Rᵀ, against the matrices computed here
        rpy = (0.3, -0.4, 1.1)
        header = self.convert(chain(link_a=link("a", inertial(rpy=" ".join(map(repr, rpy)), tensor=tensor))))
        block = self.body_block(header, 0)
        mp = self.numbers(block[block.index("ctga::make_mass_properties("):block.index("if (!x)")])[:13]
        R = rpy_matrix_here(*rpy)
        I0 = [[0.1, 0.01, 0.02], [0.01, 0.2, 0.03], [0.02, 0.03, 0.25]]
        RI = [[sum(R[i][k] * I0[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
        expected = [[sum(RI[i][k] * R[j][k] for k in range(3)) for j in range(3)] for i in range(3)]
        for r in range(3):
            for c in range(3):
                self.assertAlmostEqual(mp[4 + 3 * r + c], expected[r][c], places=15)

    def test_numbers_keep_full_precision(self):
        header = self.convert(chain(joint_b=joint("jb", "revolute", "a", "b", xyz="0.1 0.30000000000000004 1e-7")))
        self.assertIn("ctga::make_translator(T(0.1), T(0.30000000000000004), T(1e-07))", header)

    def test_stdout(self):
        path = os.path.join(self.tmp.name, "r.urdf")
        with open(path, "w", encoding="utf-8") as f:
            f.write(chain())
        r = subprocess.run([sys.executable, SCRIPT, path, "--name", "r"], capture_output=True, text=True, check=False)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("namespace r {", r.stdout)


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


if __name__ == "__main__":
    unittest.main()
