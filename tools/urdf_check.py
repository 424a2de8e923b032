#!/usr/bin/env python3
"""Every URDF in a folder through ctga: converted (tools/urdf_to_ctga.py), a checker compiled
(tools/urdf_check.cpp, -O2) and run, one table row per robot: bodies, frames, degrees of freedom,
compile time and peak memory of the checker, and the self-consistency of the dynamics (ABA's
backward error RNEA(ABA(τ)) = τ, H q̈ + C = τ, H symmetric positive definite, dE/dt = q̇ᵀτ), with
ABA's forward error (round_trip: ABA of RNEA's τ back to q̈) and its error against the same model
in long double (aba_ld) for information: both grow with H's condition number, in any algorithm
(tools/urdf_check.cpp says how each is measured), or exactly why it was refused (the converter's
or the compiler's first error).

    python3 tools/urdf_check.py FOLDER [--floating-base] [--also-floating] [--options TABLE]
                                [--exclude PATTERN ...] [--cxx g++] [-- OPTIONS...]

OPTIONS after `--` go to urdf_to_ctga.py for every robot. --options TABLE gives options per robot:
each line of the file TABLE is a file-name pattern (fnmatch, e.g. romeo__*.urdf) and the options
for the robots it matches (shell words; '#' starts a comment); a robot takes the options of every
line that matches it, in order, after those of `--`. tools/urdf_options_erd.txt is the table for
example-robot-data's collection (the options a user would pick per robot). --exclude skips the
robots a pattern matches (repeatable; e.g. a file that is not a robot). --also-floating adds a
second row for each robot converted with --floating-base. Prints a Markdown table; exit status 1
if any robot was refused or failed a check (tolerances: 1e-12 for the residual and the symmetry,
1e-10 for the others; the joint limits must pass check_limits).

Standard library only; needs the compiler and /usr/bin/time.
"""

import argparse
import fnmatch
import glob
import os
import re
import shlex
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def first_error(text):
    for line in text.splitlines():
        if "error" in line:
            return line.strip()[:200]
    return text.strip().splitlines()[0][:200] if text.strip() else "unknown"


def check(urdf, options, cxx, tmp):
    name = re.sub(r"[^A-Za-z0-9_]", "_", os.path.splitext(os.path.basename(urdf))[0])
    header = os.path.join(tmp, name + ".hpp")
    r = subprocess.run([sys.executable, os.path.join(HERE, "urdf_to_ctga.py"), urdf, "--name", "robot_" + name,
                        "-o", header, *options], capture_output=True, text=True, check=False)
    warnings = sum(1 for line in r.stderr.splitlines() if "warning:" in line)
    if r.returncode != 0:
        return {"result": "refused: " + r.stderr.strip().splitlines()[-1]}
    exe = os.path.join(tmp, name)
    c = subprocess.run(["/usr/bin/time", "-v", cxx, "-std=c++20", "-O2", "-I" + os.path.join(ROOT, "include"),
                        f'-DCTGA_ROBOT_HEADER="{header}"', f"-DCTGA_ROBOT=robot_{name}",
                        os.path.join(HERE, "urdf_check.cpp"), "-o", exe], capture_output=True, text=True, check=False)
    wall = re.search(r"Elapsed \(wall clock\) time.*: (?:(\d+):)?(\d+):([\d.]+)", c.stderr)
    seconds = (int(wall.group(1) or 0) * 3600 + int(wall.group(2)) * 60 + float(wall.group(3))) if wall else float("nan")
    peak = re.search(r"Maximum resident set size \(kbytes\): (\d+)", c.stderr)
    row = {"compile": f"{seconds:.1f} s", "memory": f"{int(peak.group(1)) / 1024:.0f} MB" if peak else "?", "warnings": warnings}
    if c.returncode != 0:
        row["result"] = "does not compile: " + first_error(c.stderr)
        return row
    run = subprocess.run([exe], capture_output=True, text=True, check=False)
    values = dict(kv.split("=", 1) for kv in run.stdout.split())
    row.update(values)
    row["result"] = "ok" if run.returncode == 0 else ("error: " + values.get("error", "") if "error" in values else "FAILED")
    return row


def read_table(path):
    """[(pattern, [options])] of an options table (see the module's docstring)."""
    rows = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            words = shlex.split(line, comments=True)
            if words:
                rows.append((words[0], words[1:]))
    return rows


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    passthrough = []
    if "--" in argv:
        i = argv.index("--")
        argv, passthrough = argv[:i], argv[i + 1:]
    ap = argparse.ArgumentParser(prog="urdf_check", description=__doc__.split("\n\n")[0])
    ap.add_argument("folder")
    ap.add_argument("--floating-base", action="store_true", help="convert every robot with --floating-base")
    ap.add_argument("--also-floating", action="store_true", help="and each also with --floating-base")
    ap.add_argument("--options", metavar="TABLE", help="a file of per-robot options: PATTERN OPTIONS... per line")
    ap.add_argument("--exclude", action="append", default=[], metavar="PATTERN",
                    help="skip the robots whose file name matches PATTERN (fnmatch); repeatable")
    ap.add_argument("--cxx", default=os.environ.get("CXX", "g++"))
    args = ap.parse_args(argv)
    try:
        table = read_table(args.options) if args.options else []
    except (OSError, ValueError) as e:
        print(f"urdf_check: {args.options}: {e}", file=sys.stderr)
        return 1
    files = [f for f in sorted(glob.glob(os.path.join(args.folder, "*.urdf")))
             if not any(fnmatch.fnmatch(os.path.basename(f), p) for p in args.exclude)]
    if not files:
        print(f"urdf_check: no *.urdf in {args.folder}", file=sys.stderr)
        return 1
    runs = []
    for f in files:
        base = passthrough + [o for pattern, opts in table if fnmatch.fnmatch(os.path.basename(f), pattern) for o in opts]
        base += ["--floating-base"] if args.floating_base and "--floating-base" not in base else []
        runs.append((f, base))
        if args.also_floating and "--floating-base" not in base:
            runs.append((f, base + ["--floating-base"]))
    cols = ["robot", "options", "result", "bodies", "frames", "nq", "nv", "mimic", "warnings", "compile", "memory",
            "limits", "round_trip", "residual", "split", "spd", "power", "aba_ld"]
    print("| " + " | ".join(cols) + " |")
    print("|" + " --- |" * len(cols))
    bad = 0
    with tempfile.TemporaryDirectory() as tmp:
        for f, options in runs:
            row = check(f, options, args.cxx, tmp)
            row["robot"] = os.path.basename(f)
            row["options"] = " ".join(options) or "(default)"
            bad += row["result"] != "ok"
            print("| " + " | ".join(str(row.get(c, "")) for c in cols) + " |", flush=True)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
