#!/usr/bin/env python3
"""Mutation check of the SpoutLab test suite (run by hand, never by ctest).

A suite proves a model only if a wrong model fails it.  This script breaks
the code on purpose, one fault at a time, and records which tests notice:

  1. copies the working tree (tracked and untracked, not ignored files) into
     a scratch directory outside the repository, writing only the files whose
     content differs, so the scratch build stays incremental between runs;
  2. configures (first run only) and builds that copy;
  3. runs every test of every fault's selection on the unbroken copy: a test
     that fails there cannot be said to catch anything and is left out;
  4. for each fault: applies a text substitution to the source, rebuilds,
     runs the fault's selection of the fast tests, records the failures and
     writes the original file back (with a new time stamp, so the next build
     recompiles it);
  5. prints the table of faults, the tests that caught each and their count,
     and exits non-zero if a fault went uncaught or could not be applied.

Each fault is a regular expression that must match its file the stated
number of times, so an edit of the code under it shows up as "not applied"
instead of silently testing nothing.  The test selections are the unit and
python tests plus, for a coupling fault, the one or two column cases whose
answer it moves, and for a procsim fault that model's tests: each fault
costs a rebuild and a few minutes.  The case variants, the spouted-bed runs
and the input fuzzer are left out (minutes each, no sharper view).

  tests/mutation/mutate.py [--scratch DIR] [--only NAME ...] [--table FILE]

The first run builds the whole copy (about ten minutes on one core with
OpenFOAM); later runs rebuild only what the faults touch.  See
tests/README.md for the last table.
"""

import argparse
import difflib
import fnmatch
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from typing import Callable, List, Tuple, Union

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


# --- faults --------------------------------------------------------------

@dataclass
class Edit:
    """Substitute `pattern` (a regular expression, MULTILINE) in every file
    matching `glob` (relative to the top).  `count` is the number of matches
    the fault expects over all those files; anything else means the code has
    moved under the fault and the script must be updated."""
    glob: str
    pattern: str
    replacement: Union[str, Callable[[re.Match], str]]
    count: int = 1


@dataclass
class Fault:
    name: str
    edits: List[Edit]
    tests: List[str]          # selectors, see select_tests
    why: str = ""


def scaled_number(factor: float) -> Callable[[re.Match], str]:
    """Replacement for a match whose group 'value' is a number: the number
    times `factor`, the rest of the match unchanged."""
    def repl(m: re.Match) -> str:
        value = float(m.group("value")) * factor
        start, end = m.span("value")
        text = m.group(0)
        offset = m.start(0)
        return text[:start - offset] + f"{value:.6g}" + text[end - offset:]
    return repl


# The coupling core's fast tests: the GoogleTest units and the python
# post-processing tests (label unit, about ten seconds).  Each coupling fault
# adds the one or two column cases (half a minute each) whose answer the
# fault moves, so a fault costs a rebuild and two or three minutes of tests.
UNIT = ["label:unit"]
PACKED_BED = "re:^case\\.packedBed$"          # dP vs Ergun, mapped voidage vs the particles
SETTLING = "re:^case\\.settlingParticle$"     # terminal velocity under Gidaspow (Wen-Yu)
MIN_FLUIDISATION = "re:^case\\.minFluidisation$"  # bed lifted at u_mf: drag plus -V grad p
FOAM = "re:^foam\\."                          # the divided model on real meshes
EVERY_LAYER = "re:^case\\.packedBed$"  # every layer, floor and surface (dragVelocity flux)
COARSE = "re:^case\\.(packedBed|minFluidisation)\\.cg3$"  # parcels against their particles' laws

FAULTS = [
    Fault("beta x 1.1",
          [Edit("coupling/MomentumExchange.cpp",
                r"(out\.beta\[\s*\w+\s*\]\s*=\s*)([^;]*drag_\s*->\s*beta\s*\([^;]*\))\s*;",
                r"\g<1>1.1 * (\g<2>);")],
          UNIT + [PACKED_BED, SETTLING], "the cell's exchange coefficient 10 % high (cellBeta)"),
    Fault("sub-spheres 30 -> 1",
          [Edit("coupling/DividedVoidFraction.cpp",
                r"samples_\s*\.\s*push_back\s*\(\s*obliqueOrientation\s*\(\s*s\s*\.\s*centroid\s*\(\s*\)\s*\)\s*\)\s*;",
                "samples_.assign(1, Vec3{0.0, 0.0, 0.0});")],
          UNIT + [FOAM, PACKED_BED], "the divided model samples one piece, the centre (the centre model in disguise)"),
    Fault("pressure-gradient force off",
          [Edit("coupling/MomentumExchange.cpp",
                r"(out\.pressureForce\[\s*\w+\s*\]\s*=\s*)[^;]*gradP[^;]*;",
                r"\g<1>Vec3{};")],
          UNIT + [MIN_FLUIDISATION], "no -V grad p (nor buoyancy) on the particles (particleForces)"),
    Fault("Cd cap removed",
          [Edit("coupling/Gidaspow.cpp",
                r"^\s*if\s*\(\s*re\s*>=?\s*1000(\.0*)?\s*\)\s*return\s+0\.44\s*\*[^;]*;[^\n]*\n",
                "")],
          UNIT + [SETTLING], "Schiller-Naumann carried on above Re 1000 instead of C_d = 0.44"),
    Fault("eps exponent -2.65 -> -1.65",
          [Edit("coupling/Gidaspow.cpp",
                r"(std::pow\s*\(\s*eps\s*,\s*)-2\.65(\s*\))",
                r"\g<1>-1.65\g<2>")],
          UNIT + [SETTLING], "Wen-Yu's voidage function eps^-1.65"),
    Fault("drag from the cell-centre U",
          [Edit("src/spoutFoam/pEqn.H",
                r"spoutlab::fluxVelocity\s*\(\s*phi\s*\)"
                r"\s*/\s*max\s*\(\s*voidfraction\s*\.\s*primitiveField\s*\(\s*\)\s*,\s*SMALL\s*\)\s*;",
                "(HbyA - rAU*voidfraction*fvc::grad(p))().primitiveField();")],
          UNIT + [EVERY_LAYER],
          "with dragVelocity flux the gas leaves its solve with the cell-centred U, which the drag then takes"),
    Fault("laws at the parcel's d",
          [Edit("coupling/Particle.hpp",
                r"(double\s+diameter\s*\(\s*\)\s*const\s*\{\s*return\s+2\.0\s*\*\s*radius)"
                r"\s*/\s*coarseGraining\s*;",
                r"\g<1>;"),
           Edit("coupling/Particle.hpp",   # the drag's and the heat's d: 6 V / surface
                r"(double\s+surface\s*\(\s*\)\s*const\s*\{[^}]*radius\s*\*\s*radius)"
                r"\s*\*\s*coarseGraining\s*;",
                r"\g<1>;")],
          UNIT + [COARSE],
          "drag, heat and water of a parcel from its own diameter cg d (the reference couplings' bug)"),
    Fault("kinetics k5 x 1.05",
          [Edit("process_cases/kinetics/*mechanism*.yaml",
                r"\{\s*id:\s*k5\s*,[^}\n]*?\bk:\s*(?P<value>[0-9.]+(?:[eE][-+]?[0-9]+)?)",
                scaled_number(1.05), count=2)],
          ["re:^kinetics\\."], "PH + OH -> CC 5 % fast in the shipped mechanisms"),
    Fault("p_sat x 1.01",
          [Edit("coupling/Psychrometrics.cpp",
                r"^double\s+saturationPressure\s*\(\s*double\s+tC\s*\)\s*\n\{",
                "static double saturationPressureUnbroken(double tC);\n"
                "double saturationPressure(double tC) { return 1.01 * saturationPressureUnbroken(tC); }\n"
                "static double saturationPressureUnbroken(double tC)\n{")],
          ["re:^dryer\\.", "re:^unit\\.Psychrometrics\\."],
          "Hyland-Wexler saturation pressure 1 % high, over ice and water"),
    Fault("QUICK -> upwind",
          [Edit("src/procsim/plume/Eulerian.cpp",
                r"if\s*\(\s*s\s*==\s*Advection::Upwind\s*\)\s*return\s+cc\s*;",
                "if (s == Advection::Upwind || true) return cc;")],
          ["re:^plume\\."], "every advection scheme's face value is the upwind cell's"),
    Fault("plume ground reflection off",
          [Edit("src/procsim/plume/Gaussian.cpp",
                r"(double\s+v\s*=\s*g\s*\(\s*z\s*-\s*h\s*\))\s*\+\s*g\s*\(\s*z\s*\+\s*h\s*\)\s*;",
                r"\g<1>;")],
          ["re:^plume\\."], "no image source below the ground in the Gaussian vertical term"),
]


# --- the scratch copy ----------------------------------------------------

def run(cmd, log=None, **kw):
    """Run a command; its output goes to `log` (appended) or is returned."""
    env = {k: v for k, v in os.environ.items() if not k.startswith("SPOUTLAB_")}
    if log is None:
        return subprocess.run(cmd, env=env, check=False, text=True,
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, **kw)
    with open(log, "a") as f:
        f.write("$ " + " ".join(cmd) + "\n")
        f.flush()
        return subprocess.run(cmd, env=env, check=False, text=True, stdout=f,
                              stderr=subprocess.STDOUT, **kw)


def working_tree_files():
    out = subprocess.run(["git", "-C", TOP, "ls-files", "-z", "--cached", "--others",
                          "--exclude-standard"], check=True, stdout=subprocess.PIPE).stdout
    names = sorted({n for n in out.decode().split("\0") if n})
    return [n for n in names if os.path.lexists(os.path.join(TOP, n))]


def same_file(a, b):
    if os.path.islink(a) or os.path.islink(b):
        return os.path.islink(a) and os.path.islink(b) and os.readlink(a) == os.readlink(b)
    if not os.path.isfile(b) or os.path.getsize(a) != os.path.getsize(b):
        return False
    with open(a, "rb") as fa, open(b, "rb") as fb:
        return fa.read() == fb.read()


def sync_copy(src_dir):
    """Make src_dir hold exactly the working tree's files.  Files are written
    only where their content differs, with a fresh time stamp, so a file left
    broken by an interrupted run is rebuilt and nothing else is."""
    names = working_tree_files()
    wanted = set(names)
    written = 0
    for name in names:
        a, b = os.path.join(TOP, name), os.path.join(src_dir, name)
        if same_file(a, b):
            continue
        os.makedirs(os.path.dirname(b), exist_ok=True)
        if os.path.lexists(b):
            os.remove(b)
        if os.path.islink(a):
            os.symlink(os.readlink(a), b)
        else:
            shutil.copyfile(a, b)
            shutil.copymode(a, b)
        written += 1
    removed = 0
    for root, dirs, files in os.walk(src_dir):
        for f in files:
            rel = os.path.relpath(os.path.join(root, f), src_dir)
            if rel not in wanted:
                os.remove(os.path.join(root, f))
                removed += 1
    return written, removed


def configure_and_build(src, build, jobs, cmake_args, log):
    if not os.path.isfile(os.path.join(build, "CMakeCache.txt")):
        r = run(["cmake", "-S", src, "-B", build, "-DCMAKE_BUILD_TYPE=Release"] + cmake_args, log)
        if r.returncode != 0:
            return False
    return run(["cmake", "--build", build, "-j", str(jobs)], log).returncode == 0


# --- tests ---------------------------------------------------------------

def list_tests(build):
    r = run(["ctest", "--test-dir", build, "--show-only=json-v1"])
    if r.returncode != 0:
        sys.exit("mutate: ctest cannot list the tests of " + build + ": " + r.stdout.strip())
    tests = {}
    # ctest numbers its tests in this order from 1, the numbers -I takes
    for number, t in enumerate(json.loads(r.stdout[r.stdout.index("{"):])["tests"], 1):
        labels = []
        for p in t.get("properties", []):
            if p["name"] == "LABELS":
                labels = p["value"]
        tests[t["name"]] = (number, labels)
    return tests


def select_tests(selectors, tests):
    """Selectors: 'label:L' (tests labelled L) or 're:R' (names matching R)."""
    chosen = []
    for name, (_, labels) in tests.items():
        for s in selectors:
            kind, _, arg = s.partition(":")
            if (kind == "label" and arg in labels) or (kind == "re" and re.search(arg, name)):
                chosen.append(name)
                break
    return chosen


def run_tests(build, tests, names, jobs, log, junit):
    """Run exactly `names`; return the names that did not pass."""
    if not names:
        return []
    if os.path.exists(junit):
        os.remove(junit)
    # by number: a regular expression of a few hundred names is past what
    # ctest's regex engine compiles
    numbers = ",".join(str(tests[n][0]) for n in names)
    run(["ctest", "--test-dir", build, "-I", "0,0,0," + numbers, "-j", str(jobs),
         "--output-on-failure", "--output-junit", junit], log)
    if not os.path.isfile(junit):
        return list(names)
    passed = {c.get("name") for c in ET.parse(junit).getroot().iter("testcase")
              if c.get("status") == "run" and c.find("failure") is None}
    return [n for n in names if n not in passed]


# --- applying a fault ----------------------------------------------------

def apply_fault(fault, src):
    """Apply every edit; return {path: original text} or raise ValueError."""
    originals = {}
    for e in fault.edits:
        files = sorted(p for p in working_tree_files() if fnmatch.fnmatch(p, e.glob))
        found = 0
        for rel in files:
            path = os.path.join(src, rel)
            with open(path) as f:
                text = f.read()
            new, n = re.subn(e.pattern, e.replacement, text, flags=re.MULTILINE)
            if n:
                originals.setdefault(path, text)
                with open(path, "w") as f:
                    f.write(new)
            found += n
        if found != e.count:
            restore(originals)
            raise ValueError(f"{e.glob}: the pattern matched {found} times, "
                             f"expected {e.count}; update the fault in {os.path.relpath(__file__, TOP)}")
    return originals


def preview(fault):
    """The fault's edits as a diff against the working tree (read only)."""
    out = []
    for e in fault.edits:
        found = 0
        for rel in sorted(p for p in working_tree_files() if fnmatch.fnmatch(p, e.glob)):
            with open(os.path.join(TOP, rel)) as f:
                text = f.read()
            new, n = re.subn(e.pattern, e.replacement, text, flags=re.MULTILINE)
            found += n
            out += difflib.unified_diff(text.splitlines(), new.splitlines(), rel, rel,
                                        n=0, lineterm="")
        out.append(f"# {e.glob}: {found} matches, expected {e.count}"
                   + ("" if found == e.count else "  <-- FAULT OUT OF DATE"))
    return "\n".join(out)


def restore(originals):
    for path, text in originals.items():
        with open(path, "w") as f:
            f.write(text)


# --- report --------------------------------------------------------------

def markdown_table(results):
    lines = ["| fault | tests that caught it | caught / run | time |",
             "|---|---|---|---|"]
    for r in results:
        caught = ", ".join(f"`{n}`" for n in r["caught"]) if r["caught"] else "**none**"
        if r["status"] not in ("caught", "NOT CAUGHT"):
            caught = "**" + r["status"] + "**"
        lines.append(f"| {r['name']} | {caught} | {len(r['caught'])} / {r['ran']} | "
                     f"{r['seconds'] / 60:.1f} min |")
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--scratch", default=os.path.join(tempfile.gettempdir(), "spoutlab-mutation"),
                    help="scratch directory outside the repository (default: %(default)s)")
    ap.add_argument("--only", nargs="+", metavar="NAME",
                    help="only the faults whose name contains one of these words")
    ap.add_argument("--list", action="store_true", help="list the faults and exit")
    ap.add_argument("--show", action="store_true",
                    help="print each fault as a diff of the working tree and exit")
    ap.add_argument("--jobs", type=int, default=1, help="build jobs (default 1)")
    ap.add_argument("--test-jobs", type=int, default=1, help="ctest jobs (default 1)")
    ap.add_argument("--cmake-arg", action="append", default=[],
                    help="extra argument for the first configure, e.g. -DSPOUTLAB_WITH_OPENFOAM=OFF")
    ap.add_argument("--no-baseline", action="store_true",
                    help="skip the run on the unbroken copy (trust it passes)")
    ap.add_argument("--table", metavar="FILE", help="also write the markdown table here")
    args = ap.parse_args()

    faults = FAULTS
    if args.only:
        faults = [f for f in FAULTS if any(w.lower() in f.name.lower() for w in args.only)]
    if args.list:
        for f in faults:
            print(f"{f.name:32s} {f.why}")
        return 0
    if args.show:
        for f in faults:
            print(f"== {f.name}: {f.why}\n{preview(f)}")
        return 0

    scratch = os.path.realpath(args.scratch)
    if scratch == TOP or scratch.startswith(TOP + os.sep) or TOP.startswith(scratch + os.sep):
        sys.exit(f"mutate: --scratch {scratch}: must lie outside the repository {TOP}")
    src, build = os.path.join(scratch, "src"), os.path.join(scratch, "build")
    logs = os.path.join(scratch, "logs")
    os.makedirs(src, exist_ok=True)
    os.makedirs(logs, exist_ok=True)

    written, removed = sync_copy(src)
    print(f"mutate: scratch copy {src}: {written} files written, {removed} removed")
    t0 = time.time()
    if not configure_and_build(src, build, args.jobs, args.cmake_arg, os.path.join(logs, "build.log")):
        sys.exit(f"mutate: the unbroken copy does not build; see {logs}/build.log")
    print(f"mutate: built in {time.time() - t0:.0f} s")

    tests = list_tests(build)
    selections = {f.name: select_tests(f.tests, tests) for f in faults}
    failing = []
    if not args.no_baseline:
        union = sorted({n for names in selections.values() for n in names})
        t0 = time.time()
        failing = run_tests(build, tests, union, args.test_jobs, os.path.join(logs, "baseline.log"),
                            os.path.join(logs, "baseline.xml"))
        print(f"mutate: baseline: {len(union)} tests in {time.time() - t0:.0f} s, "
              f"{len(failing)} failing already" + (": " + ", ".join(failing) if failing else ""))

    results = []
    for i, fault in enumerate(faults, 1):
        slug = re.sub(r"[^A-Za-z0-9]+", "_", fault.name).strip("_")
        log = os.path.join(logs, slug + ".log")
        if os.path.exists(log):
            os.remove(log)
        names = [n for n in selections[fault.name] if n not in failing]
        result = {"name": fault.name, "caught": [], "ran": 0, "seconds": 0.0}
        t0 = time.time()
        print(f"mutate: [{i}/{len(faults)}] {fault.name}: ", end="", flush=True)
        try:
            originals = apply_fault(fault, src)
        except ValueError as e:
            result["status"] = "not applied"
            print("NOT APPLIED:", e)
            results.append(result)
            continue
        try:
            if not configure_and_build(src, build, args.jobs, [], log):
                result["status"] = "build failed"
            else:
                result["caught"] = run_tests(build, tests, names, args.test_jobs, log,
                                             os.path.join(logs, slug + ".xml"))
                result["ran"] = len(names)
                result["status"] = "caught" if result["caught"] else "NOT CAUGHT"
        finally:
            restore(originals)
        result["seconds"] = time.time() - t0
        print(f"{result['status']} by {len(result['caught'])} of {result['ran']} tests "
              f"({result['seconds']:.0f} s; log {log})")
        for n in result["caught"]:
            print("    " + n)
        results.append(result)

    table = markdown_table(results)
    print("\n" + table)
    if args.table:
        with open(args.table, "w") as f:
            f.write(table)
    return 0 if all(r["status"] == "caught" for r in results) else 1


if __name__ == "__main__":
    sys.exit(main())
