#!/usr/bin/env python3
"""Mutation fuzzing of procsim's inputs: procsim never crashes on bad input.

Each mutation changes one shipped input of process_cases/ (a number made
non-finite, huge, negative, zero or text; a key duplicated or deleted; a list
item duplicated; a name made unusable as a file name; a CSV cell made bad or
given trailing text; a CSV row duplicated or deleted) or, for one in five, the
command line (a bad option value, an option given twice, an unknown option, a
second input, a bad sweep or sensitivity option) and runs procsim on it
in a scratch copy whose output directory already holds marker files in place
of the results.  Every run must either

  * succeed (the mutation was harmless): exit 0, results written, no
    temporaries left, no non-finite number in a CSV result that the clean
    run has only finite numbers in, or
  * fail cleanly: non-zero exit, no crash signal, exactly one line on stderr
    starting with "procsim: ", every marker file untouched, no temporaries.

usage: fuzz_inputs.py PROCSIM CASES_DIR WORK_DIR [--count N] [--seed S]
Only the standard library is used; the seed fixes the mutations.
"""
import argparse
import os
import random
import re
import shutil
import subprocess
import sys
import time

# command lines kept short so the whole run stays within a few minutes
TARGETS = [
    # model dir, files that may be mutated, arguments ({d} = case dir, {o} = output dir)
    ("kinetics", ["base_0.3mA_30mgL_30ppm.yaml", "phenol_acetaldehyde_mechanism.yaml"],
     ["kinetics", "run", "{d}/base_0.3mA_30mgL_30ppm.yaml", "-o", "{o}", "-q", "--no-plots"]),
    ("kinetics", ["dynamic_oh_0.3mA_30mgL_30ppm.yaml", "phenol_acetaldehyde_dynamic_oh_mechanism.yaml"],
     ["kinetics", "run", "{d}/dynamic_oh_0.3mA_30mgL_30ppm.yaml", "-o", "{o}", "-q", "--no-plots"]),
    ("kinetics", ["fig4_current.yaml"],
     ["kinetics", "run", "{d}/fig4_current.yaml", "-o", "{o}", "-q", "--no-plots"]),
    ("kinetics", ["base_0.3mA_30mgL_30ppm.yaml"],
     ["kinetics", "sensitivity", "{d}/base_0.3mA_30mgL_30ppm.yaml", "-o", "{o}"]),
    ("kinetics", ["fit_example/fit.yaml", "fit_example/synthetic_0.1mA.csv", "fit_example/synthetic_0.3mA.csv"],
     ["kinetics", "fit", "{d}/fit_example/fit.yaml", "-o", "{o}"]),
    ("kinetics", ["corona_gas_side.yaml"],
     ["kinetics", "corona", "{d}/corona_gas_side.yaml", "-o", "{o}"]),
    ("dryer", ["table1_batches.yaml"],
     ["dryer", "metrics", "{d}/table1_batches.yaml", "--out", "{o}"]),
    ("dryer", ["table1_batches.csv"],
     ["dryer", "metrics", "{d}/table1_batches.csv", "--out", "{o}"]),
    ("dryer", ["plant.yaml"],
     ["dryer", "simulate", "{d}/plant.yaml", "--batch", "1", "--out", "{o}"]),
    ("dryer", ["spouted.yaml", "spouted_circulation_synthetic.json"],
     ["dryer", "spouted", "{d}/spouted.yaml", "--samples", "20", "--out", "{o}"]),
    ("plume", ["eulerian.yaml", "met_week.csv", "terrain.asc", "measured_24h.csv"],
     ["plume", "eulerian", "{d}/eulerian.yaml", "-o", "{o}", "--hours", "1"]),
    ("plume", ["gaussian.yaml", "met_gaussian.csv"],
     ["plume", "gaussian", "{d}/gaussian.yaml", "-o", "{o}"]),
    ("plume", ["montecarlo.yaml"],
     ["plume", "montecarlo", "{d}/montecarlo.yaml", "-o", "{o}", "--years", "1", "--threads", "1"]),
]

BAD_NUMBERS = [".inf", "-.inf", ".nan", "inf", "nan", "1e308", "-1e308", "1e400", "-1", "0", "1e30",
               "1e-30", "abc", "12.5abc", "2147483648", "-2147483649", "99999999999999999999", "''"]
BAD_CELLS = ["inf", "-inf", "nan", "1e308", "-1e308", "1e400", "-1", "0", "1e30", "abc", "12.5abc", ""]
BAD_NAMES = ["a/b", "..", "x\\\\y", "''"]
NUMBER = re.compile(r"(?<![\w.+-])-?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?(?![\w.])")
KEY_LINE = re.compile(r"^(\s*)(- )?([A-Za-z_][\w.]*):(.*)$")
FLOW_PAIR = re.compile(r"([A-Za-z_]\w*): *([^,{}\[\]]+|\[[^\]]*\])")
TIMEOUT_S = 60
# result columns where "nan" is the documented "not available": a reference
# value not given, a standard error that cannot be determined, a half time not
# reached, a data point not measured
TEXT_COLUMNS = {"batch", "id", "name", "label", "key", "parameter", "output", "dataset", "quantity", "receptor"}
NOT_AVAILABLE = re.compile(r"^(paper_.*|.*_dev_percent|std_error|rel_std_error|ci95_.*|TOC_half_time_h|"
                           r"PH|AD|AA|HQ|TOC|.*_mg_per_L)$")


def code_part(line):
    """The line without its comment."""
    i = line.find(" #")
    if line.lstrip().startswith("#"):
        return ""
    return line if i < 0 else line[:i]


def mutate_yaml(text, rng):
    lines = text.split("\n")
    kinds = ["number"] * 5 + ["dup_key", "dup_flow_key", "del_key", "del_flow_key", "dup_item", "name"]
    for _ in range(20):
        kind = rng.choice(kinds)
        if kind == "number":
            spots = [(i, m) for i, l in enumerate(lines) for m in NUMBER.finditer(code_part(l))]
            if not spots:
                continue
            i, m = rng.choice(spots)
            lines[i] = lines[i][:m.start()] + rng.choice(BAD_NUMBERS) + lines[i][m.end():]
            return "\n".join(lines), "number %s -> %s" % (m.group(0), lines[i].strip()[:60])
        if kind in ("dup_key", "del_key"):
            spots = [i for i, l in enumerate(lines) if KEY_LINE.match(code_part(l))]
            if not spots:
                continue
            i = rng.choice(spots)
            m = KEY_LINE.match(lines[i])
            if kind == "del_key":
                del lines[i]
                return "\n".join(lines), "deleted line '%s'" % m.group(3)
            value = m.group(4)
            if NUMBER.search(code_part(value)) and rng.random() < 0.5:
                value = NUMBER.sub("7", value, count=1)
            indent = m.group(1) + ("  " if m.group(2) else "")
            lines.insert(i + 1, indent + m.group(3) + ":" + value)
            return "\n".join(lines), "duplicated key '%s'" % m.group(3)
        if kind in ("dup_flow_key", "del_flow_key", "name"):
            spots = [(i, m) for i, l in enumerate(lines) for m in FLOW_PAIR.finditer(code_part(l))
                     if "{" in code_part(l)]
            if kind == "name":
                spots = [(i, m) for i, l in enumerate(lines) for m in
                         re.finditer(r"(name|id): *([^,{}\s]+)", code_part(l))]
            if not spots:
                continue
            i, m = rng.choice(spots)
            if kind == "name":
                new = m.group(1) + ": " + rng.choice(BAD_NAMES)
                lines[i] = lines[i][:m.start()] + new + lines[i][m.end():]
                return "\n".join(lines), "name -> %s" % new
            if kind == "del_flow_key":
                lines[i] = lines[i][:m.start()] + lines[i][m.end():]
                lines[i] = re.sub(r",\s*,", ",", lines[i]).replace("{,", "{").replace(", }", " }")
                return "\n".join(lines), "deleted flow key '%s'" % m.group(1)
            lines[i] = lines[i][:m.end()] + ", " + m.group(0) + lines[i][m.end():]
            return "\n".join(lines), "duplicated flow key '%s'" % m.group(1)
        if kind == "dup_item":
            spots = [i for i, l in enumerate(lines) if re.match(r"^\s*- ", code_part(l))]
            if not spots:
                continue
            i = rng.choice(spots)
            lines.insert(i + 1, lines[i])
            return "\n".join(lines), "duplicated list item '%s'" % lines[i].strip()[:40]
    return text + "\nunexpected_key: 1\n", "added an unknown key"


def mutate_table(text, rng, sep):
    """CSV (sep ',') or ESRI grid rows (sep ' ')."""
    lines = text.split("\n")
    data = [i for i, l in enumerate(lines)
            if l.strip() and not l.startswith("#") and NUMBER.match(l.strip().split(sep)[0] or "x")]
    header = next((i for i, l in enumerate(lines) if l.strip() and not l.startswith("#")), 0)
    kind = rng.choice(["cell"] * 4 + ["trailing", "dup_row", "del_row", "short_row", "header"])
    if kind in ("cell", "trailing"):
        i = rng.choice(data)
        cells = lines[i].split(sep)
        j = rng.randrange(len(cells))
        old = cells[j]
        cells[j] = (cells[j] + rng.choice(["abc", "x", " 1"])) if kind == "trailing" else rng.choice(BAD_CELLS)
        lines[i] = sep.join(cells)
        return "\n".join(lines), "line %d cell %d: %s -> '%s'" % (i + 1, j + 1, old, cells[j])
    if kind == "dup_row":
        i = rng.choice(data)
        lines.insert(i + 1, lines[i])
        return "\n".join(lines), "duplicated line %d" % (i + 1)
    if kind == "del_row":
        i = rng.choice(data)
        del lines[i]
        return "\n".join(lines), "deleted line %d" % (i + 1)
    if kind == "short_row":
        i = rng.choice(data)
        lines[i] = sep.join(lines[i].split(sep)[:-1])
        return "\n".join(lines), "dropped the last cell of line %d" % (i + 1)
    if sep == ",":
        cells = lines[header].split(",")
        if len(cells) > 1:
            j = rng.randrange(1, len(cells))
            cells[j] = cells[0]
            lines[header] = ",".join(cells)
            return "\n".join(lines), "header column %d renamed to '%s'" % (j + 1, cells[0])
    # ESRI header: a value made bad
    i = rng.randrange(0, min(6, len(lines)))
    parts = lines[i].split()
    if len(parts) == 2:
        lines[i] = parts[0] + " " + rng.choice(BAD_CELLS + ["100000000"])
    return "\n".join(lines), "header line %d -> '%s'" % (i + 1, lines[i])


BAD_OPTIONS = ["0", "-1", "inf", "nan", "1e308", "abc", "1.5", "2147483648", "99999999999", ""]
EXTRA_OPTIONS = {
    "run": [["--sweep", "I=0.1,nan"], ["--sweep", "I=0.2,0.2"], ["--sweep", "I=0.1,0.3,1e308"],
            ["--sweep", "k.k1=-1"], ["--set", "I=inf"], ["--set", "time.duration_h=1e308"],
            ["--solver", "euler"], ["--sweep", "I=0.1", "--sweep", "V=9", "--sweep", "I=0.3"]],
    "sensitivity": [["--time-h", v] for v in ("0", "-1", "100", "inf", "5abc")]
                   + [["--change-percent", v] for v in ("0", "-10", "100", "nan")],
}


def mutate_args(args, rng):
    """A bad command line: an option value, a repeated option, an extra word."""
    args = list(args)
    valued = [i for i, a in enumerate(args[:-1])
              if a.startswith("-") and a not in ("-o", "--out") and not args[i + 1].startswith("-")]
    kind = rng.choice(["value", "twice", "unknown", "extra", "model"])
    if kind == "value" and valued:
        i = rng.choice(valued)
        args[i + 1] = rng.choice(BAD_OPTIONS)
        return args, "option %s %s" % (args[i], args[i + 1])
    if kind == "twice":
        i = rng.choice([i for i, a in enumerate(args) if a.startswith("-")])
        pair = args[i:i + 2] if i + 1 < len(args) and not args[i + 1].startswith("-") else args[i:i + 1]
        return args + pair, "option %s given twice" % args[i]
    if kind == "unknown":
        return args + ["--bogus"], "unknown option"
    if kind == "model" and args[1] in EXTRA_OPTIONS:
        extra = rng.choice(EXTRA_OPTIONS[args[1]])
        return args + extra, "options %s" % " ".join(extra)
    return args + ["{d}/extra.yaml"], "a second input file"


def mutate(path, rng):
    with open(path) as f:
        text = f.read()
    if path.endswith(".yaml"):
        new, what = mutate_yaml(text, rng)
    else:
        new, what = mutate_table(text, rng, "," if path.endswith(".csv") else " ")
    with open(path, "w") as f:
        f.write(new)
    return what


def snapshot(out):
    files = {}
    for root, _, names in os.walk(out):
        for n in names:
            p = os.path.join(root, n)
            with open(p, "rb") as f:
                files[os.path.relpath(p, out)] = f.read()
    return files


def non_finite_columns(data):
    """(file, column) pairs of a CSV result holding nan or inf."""
    bad = set()
    text = data.decode("utf-8", "replace").split("\n")
    header = None
    for line in text:
        if not line or line.startswith("#"):
            continue
        cells = line.split(",")
        if header is None:
            header = cells
            continue
        for j, c in enumerate(cells):
            value = c.strip().lower().lstrip("+-")
            name = header[j] if j < len(header) else str(j)
            if name in TEXT_COLUMNS:
                continue
            if value in ("inf", "infinity") or (value == "nan" and not NOT_AVAILABLE.match(name)):
                bad.add(name)
    return bad


def run(procsim, args, case_dir, out):
    cmd = [procsim] + [a.format(d=case_dir, o=out) for a in args]
    try:
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=TIMEOUT_S)
        return p.returncode, p.stderr.decode("utf-8", "replace")
    except subprocess.TimeoutExpired:
        return None, ""


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("procsim")
    ap.add_argument("cases")
    ap.add_argument("work")
    ap.add_argument("--count", type=int, default=300)
    ap.add_argument("--seed", type=int, default=13)
    a = ap.parse_args()
    rng = random.Random(a.seed)
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)

    # clean runs: which files each target writes, and which columns are non-finite by design
    baseline = []
    for t, (model, _, args) in enumerate(TARGETS):
        out = os.path.join(a.work, "clean%d" % t)
        status, err = run(a.procsim, args, os.path.join(a.cases, model), out)
        if status != 0:
            print("clean run of target %d (%s) failed: %s" % (t, " ".join(args[:2]), err.strip()))
            return 1
        results = snapshot(out)
        allowed = {f: non_finite_columns(d) for f, d in results.items() if f.endswith(".csv")}
        baseline.append((results, allowed))

    counts = {"clean error": 0, "harmless": 0, "crash": 0, "bad failure": 0, "bad success": 0, "hang": 0}
    start = time.time()
    for n in range(a.count):
        t = rng.randrange(len(TARGETS))
        model, mutable, args = TARGETS[t]
        scratch = os.path.join(a.work, "m%d" % n)
        case_dir = os.path.join(scratch, model)
        shutil.copytree(os.path.join(a.cases, model), case_dir)
        if rng.random() < 0.2:
            args, what = mutate_args(args, rng)
            what = "command line: " + what
        else:
            target_file = rng.choice(mutable)
            what = target_file + ": " + mutate(os.path.join(case_dir, target_file), rng)
        out = os.path.join(scratch, "out")
        for rel in baseline[t][0]:
            os.makedirs(os.path.dirname(os.path.join(out, rel)), exist_ok=True)
            with open(os.path.join(out, rel), "w") as f:
                f.write("marker %d\n" % n)
        before = snapshot(out)
        status, err = run(a.procsim, args, case_dir, out)
        after = snapshot(out)
        temporaries = [f for f in after if f.endswith(".tmp")]
        problem = None
        if status is None:
            kind, problem = "hang", "no answer within %d s" % TIMEOUT_S
        elif status < 0:
            kind, problem = "crash", "signal %d" % -status
        elif status == 0:
            kind = "harmless"
            bad = []
            for f, d in after.items():
                if f.endswith(".csv"):
                    extra = non_finite_columns(d) - baseline[t][1].get(f, set())
                    if extra:
                        bad.append("%s: non-finite %s" % (f, sorted(extra)[:3]))
            if temporaries:
                bad.append("temporaries left: %s" % temporaries[:3])
            if all(after.get(f) == d for f, d in before.items()):
                bad.append("no result written")
            if bad:
                kind, problem = "bad success", "; ".join(bad)
        else:
            kind = "clean error"
            lines = err.splitlines()
            bad = []
            if len(lines) != 1 or not lines[0].startswith("procsim: "):
                bad.append("stderr has %d lines: %r" % (len(lines), err[:300]))
            changed = [f for f, d in before.items() if after.get(f) != d]
            if changed:
                bad.append("earlier results changed: %s" % changed[:3])
            if temporaries:
                bad.append("temporaries left: %s" % temporaries[:3])
            if bad:
                kind, problem = "bad failure", "; ".join(bad)
        counts[kind] += 1
        if problem:
            print("FAIL %d [%s] %s: %s :: %s" % (n, " ".join(args[:2]), what, problem,
                                                 err.strip()[:200]))
            sys.stdout.flush()
        else:
            shutil.rmtree(scratch)
    elapsed = time.time() - start
    print("fuzz: %d inputs tried in %.0f s (seed %d): %d clean errors, %d harmless successes, "
          "%d crashes, %d hangs, %d unclean errors, %d insane successes"
          % (a.count, elapsed, a.seed, counts["clean error"], counts["harmless"], counts["crash"],
             counts["hang"], counts["bad failure"], counts["bad success"]))
    failed = counts["crash"] + counts["hang"] + counts["bad failure"] + counts["bad success"]
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
