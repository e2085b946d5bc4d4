#!/usr/bin/env python3
"""The starter kits of examples/assignments/ end to end: each kit copied to a temporary folder and
run as shipped (the skeleton must run and fail cleanly), with its full solution (every ray must
pass `raystep-cli assess`), and with each named mistake of docs/assignment-format.md the solution
can make (the run must fail, and the first failed ray must name the mistake). The verdicts are
read with Python's json module, and where a verdict points (the ray, the index of the first
divergence, its record) is recomputed here from the two traces, solution against mistake.

usage: assignments_test.py RAYSTEP_CLI
"""
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

CLI = os.path.abspath(sys.argv[1])
HERE = os.path.dirname(os.path.abspath(__file__))
KITS = os.path.join(HERE, "..", "..", "examples", "assignments")
CXX = os.environ.get("CXX") or shutil.which("g++") or "c++"
failures = []
missing_keys = set()
# DDA mistake -> the failed rays after the first that name another mistake, or none.
named_otherwise = {}

DDA_MISTAKES = ("start-cell-skipped", "negative-direction-boundary", "parallel-axis-division",
                "negative-zero", "tie-one-axis", "no-entry-clip", "no-exit-check")
# The same relative tolerance as the assessor's on a tMax or a hit's t.
TOLERANCE = 1e-9


def fail(message):
    failures.append(message)
    print("FAIL:", message, flush=True)


def run(args, cwd, stdout=None, check=True):
    """Runs args in cwd; stdout to the file named, if any. Exits the test on a failure to start."""
    if stdout:
        with open(os.path.join(cwd, stdout), "w") as out:
            p = subprocess.run(args, cwd=cwd, stdout=out, stderr=subprocess.PIPE, text=True)
    else:
        p = subprocess.run(args, cwd=cwd, capture_output=True, text=True)
    if check and p.returncode != 0:
        raise SystemExit(f"{' '.join(args)} (in {cwd}): exit {p.returncode}\n{p.stderr}")
    return p


def compile_cpp(source, binary, cwd):
    # The kits' own command, and no warning even with -Wall -Wextra.
    p = run([CXX, "-std=c++17", "-O2", "-Wall", "-Wextra", source, "-o", binary], cwd)
    if p.stderr.strip():
        fail(f"{source}: the compiler warns:\n{p.stderr}")


def copy_kit(name, tmp):
    dest = os.path.join(tmp, name)
    shutil.copytree(os.path.join(KITS, name), dest)
    return dest


def check_given_code(kit_file, solution_file):
    """The solution's given code (helpers, reader, log) is the kit's, byte for byte."""
    def given(path):
        text = open(path, encoding="utf-8").read()
        comment = "#" if path.endswith(".py") else "//"
        start = text.find(f"{comment} ---- Given")
        end = text.find(f"{comment} ---- end of the given code ----")
        if start < 0 or end < 0:
            fail(f"{path}: no given code between the markers")
        return text[start:end]
    if given(kit_file) != given(solution_file):
        fail(f"{solution_file}: its given code differs from {kit_file}'s")


# ---- The traces, read independently of raystep ----


def read_trace(path):
    """The rays of a student's trace: each with its line, its walk (cell or node records, with
    their line, tMax and the tests logged after them) and its end (hit or miss)."""
    rays = []
    with open(path) as f:
        for line_no, line in enumerate(f, 1):
            if not line.strip():
                continue
            record = json.loads(line)
            if "ray" in record:
                rays.append({"line": line_no, "ray": record["ray"], "walk": [], "before": [],
                             "end": None})
            elif "cell" in record or "node" in record:
                kind = "cell" if "cell" in record else "node"
                rays[-1]["walk"].append({"kind": kind, "value": record[kind], "line": line_no,
                                         "tMax": record.get("tMax"), "tests": []})
            elif "test" in record:
                walk = rays[-1]["walk"]
                (walk[-1]["tests"] if walk else rays[-1]["before"]).append(record["test"])
            elif "hit" in record or "miss" in record:
                rays[-1]["end"] = record
    return rays


def same_time(a, b):
    if a is None or b is None:
        return a is None and b is None
    return abs(a - b) <= TOLERANCE * max(1.0, abs(a), abs(b))


def same_end(a, b):
    if a is None or b is None or "miss" in a or "miss" in b:
        return a == b
    return a["hit"]["prim"] == b["hit"]["prim"] and same_time(a["hit"]["t"], b["hit"]["t"])


def divergence(right, wrong):
    """Where the wrong ray's records first differ from the right one's: (index, record), with
    docs/assignment-format.md's index (walk records; a test or the end counts for the walk record
    it follows; for `end`, how many walk records the wrong ray logged) and record kind (`end`
    where the wrong ray stops early; where it goes on past the end, the kind of its extra
    record); None when they agree."""
    a, b = right["walk"], wrong["walk"]
    for i in range(min(len(a), len(b))):
        if a[i]["value"] != b[i]["value"]:
            return i, a[i]["kind"]
        if b[i]["tMax"] is not None and a[i]["tMax"] is not None and not all(
                same_time(x, y) for x, y in zip(a[i]["tMax"], b[i]["tMax"])):
            return i, "tMax"
        if sorted(a[i]["tests"]) != sorted(b[i]["tests"]):
            return i, "test"
    if len(b) > len(a):
        return len(a), b[len(a)]["kind"]  # goes on past the end: its extra record (expected null)
    if len(b) < len(a):
        return len(b), "end"  # stops early
    if not same_end(right["end"], wrong["end"]):
        return len(a) - 1, "hit" if wrong["end"] and "hit" in wrong["end"] else "miss"
    return None


def strip_tmax(src, dest):
    """The same trace with cells only: what a student who does not log tMax writes."""
    with open(src) as f, open(dest, "w") as out:
        for line in f:
            record = json.loads(line)
            record.pop("tMax", None)
            out.write(json.dumps(record) + "\n")


# ---- The verdict ----


def assess(target, trace, cwd, what):
    """raystep-cli assess ... --json on the trace; the verdict, checked against the trace and the
    exit code (0 when every ray passes, else 1)."""
    p = run([CLI, "assess", *target, "--trace", trace, "--json"], cwd, check=False)
    if p.returncode not in (0, 1):
        fail(f"{what}: assess exit {p.returncode}: {p.stderr.strip()}")
        return None
    try:
        verdict = json.loads(p.stdout)
    except json.JSONDecodeError as e:
        fail(f"{what}: assess --json is not JSON: {e}")
        return None
    rays = read_trace(os.path.join(cwd, trace))
    for key in ("score", "rays_passed", "rays_total", "passed", "rays"):
        if key not in verdict:
            fail(f"{what}: the verdict has no {key}")
            return None
    passed = sum(1 for r in verdict["rays"] if r.get("passed"))
    if verdict["rays_total"] != len(rays) or len(verdict["rays"]) != len(rays):
        fail(f"{what}: {verdict['rays_total']} rays in the verdict, {len(rays)} in the trace")
    if verdict["rays_passed"] != passed or verdict["passed"] != (passed == len(rays)):
        fail(f"{what}: rays_passed/passed disagree with the rays' own")
    if rays and not math.isclose(verdict["score"], passed / len(rays), rel_tol=1e-12):
        fail(f"{what}: score {verdict['score']}, {passed}/{len(rays)} passed")
    if p.returncode != (0 if verdict["passed"] else 1):
        fail(f"{what}: exit {p.returncode} with passed = {verdict['passed']}")
    missing = sorted({key for r in verdict["rays"] for key in
                      ("ray", "line", "passed", "walk_records", "first_divergence", "mistake")
                      if key not in r})
    for key in missing:
        if key not in missing_keys:  # once: every verdict would repeat it
            missing_keys.add(key)
            fail(f"{what}: rays without {key!r} (docs/assignment-format.md, The verdict)")
    for r, ray in zip(verdict["rays"], rays):
        if r.get("line") != ray["line"]:
            fail(f"{what}: ray {r.get('ray')} at line {r.get('line')}, its record is at "
                 f"{ray['line']}")
        if r.get("walk_records", len(ray["walk"])) != len(ray["walk"]):
            fail(f"{what}: ray {r['ray']}: walk_records = {r['walk_records']}, it logs "
                 f"{len(ray['walk'])}")
        if r.get("passed") != (r.get("first_divergence") is None):
            fail(f"{what}: ray {r.get('ray')}: passed and first_divergence disagree")
    return verdict


def expect_pass(verdict, what):
    if verdict and not verdict["passed"]:
        bad = [r for r in verdict["rays"] if not r["passed"]]
        fail(f"{what}: {len(bad)} rays failed, the first: {json.dumps(bad[0])}")


def expect_mistake(verdict, right_trace, wrong_trace, mistake, what):
    """The run fails; the first failed ray is the first that differs from the solution's, at the
    index and record recomputed here, and names `mistake` (None: any name or none)."""
    if not verdict:
        return
    right, wrong = read_trace(right_trace), read_trace(wrong_trace)
    failed = [r for r in verdict["rays"] if not r["passed"]]
    if not failed:
        fail(f"{what}: every ray passed")
        return
    differs = [k for k in range(len(right)) if divergence(right[k], wrong[k])]
    first = failed[0]
    if [r["ray"] for r in failed] != differs:
        fail(f"{what}: rays {[r['ray'] for r in failed]} failed; {differs} differ from the "
             f"solution's")
    if first["ray"] not in range(len(wrong)):
        return
    index, record = divergence(right[first["ray"]], wrong[first["ray"]]) or (None, None)
    d = first.get("first_divergence") or {}
    if d.get("index") != index:
        fail(f"{what}: ray {first['ray']}: first_divergence.index {d.get('index')}, the traces "
             f"first differ at {index}")
    if d.get("record") != record:
        fail(f"{what}: ray {first['ray']}: first_divergence.record {d.get('record')!r}, the "
             f"traces first differ in a {record!r} record")
    name = (first.get("mistake") or {}).get("name")
    if mistake and name != mistake:
        fail(f"{what}: ray {first['ray']} names the mistake {name!r}, not {mistake!r}")
    if mistake:
        others = [(r["ray"], (r.get("mistake") or {}).get("name")) for r in failed[1:]
                  if (r.get("mistake") or {}).get("name") != mistake]
        if others:
            named_otherwise[what] = others
    # Where it points: the student's record at that line is the one `got` holds.
    walk = wrong[first["ray"]]["walk"]
    if record in ("cell", "tMax", "node") and index is not None and index < len(walk):
        if d.get("line") != walk[index]["line"]:
            fail(f"{what}: first_divergence.line {d.get('line')}, the record is at line "
                 f"{walk[index]['line']}")


# ---- The DDA kits ----


def check_against_dda(trace, grid, what):
    """The solution's cells and tMax are raystep's exact walk (raystep-cli dda --json), ray by
    ray: independent of the assessor."""
    for k, ray in enumerate(read_trace(trace)):
        def flag(name, v):
            return f"--{name}=" + ",".join(repr(float(x)) for x in v)
        p = run([CLI, "dda", "--grid", grid[0], "--min", grid[1], "--max", grid[2],
                 flag("origin", ray["ray"]["origin"]), flag("dir", ray["ray"]["dir"]), "--json"],
                os.path.dirname(trace))
        steps = json.loads(p.stdout)["steps"]
        cells = [c["value"] for c in ray["walk"]]
        if cells != [s["cell"] for s in steps]:
            fail(f"{what}: ray {k}: cells {cells}, raystep-cli dda walks "
                 f"{[s['cell'] for s in steps]}")
            continue
        for c, s in zip(ray["walk"], steps):
            if not all(same_time(x, y) for x, y in zip(c["tMax"], s["tMax"])):
                fail(f"{what}: ray {k}: tMax {c['tMax']} in {c['value']}, raystep-cli dda has "
                     f"{s['tMax']}")


def dda_kit(name, grid, skeleton_run, solution_run, tmp):
    target = ["dda", "--grid", grid[0], "--min", grid[1], "--max", grid[2]]
    kit = copy_kit(name, tmp)

    # As shipped: runs, logs the rays, says what is missing (exit 1, so that `kit > walk.jsonl &&
    # raystep-cli assess ...` fails too), and its rays alone must not pass the assessment.
    p = skeleton_run(kit, [], "walk.jsonl")
    if p.returncode != 1 or "TODO" not in p.stderr:
        fail(f"{name} skeleton: exit {p.returncode}, stderr {p.stderr.strip()!r}")
    verdict = assess(target, "walk.jsonl", kit, f"{name} skeleton")
    if verdict and verdict["passed"]:
        fail(f"{name} skeleton: passes the assessment without a walk")

    right = os.path.join(kit, "right.jsonl")
    solution_run(kit, [], "right.jsonl")
    check_against_dda(right, grid, f"{name} solution")
    expect_pass(assess(target, "right.jsonl", kit, f"{name} solution"), f"{name} solution")
    strip_tmax(right, os.path.join(kit, "right-cells.jsonl"))
    expect_pass(assess(target, "right-cells.jsonl", kit, f"{name} solution, cells only"),
                f"{name} solution, cells only")

    for mistake in DDA_MISTAKES:
        wrong = f"{mistake}.jsonl"
        solution_run(kit, ["--mistake", mistake], wrong)
        strip_tmax(os.path.join(kit, wrong), os.path.join(kit, f"{mistake}-cells.jsonl"))
        for trace, reference, how in ((wrong, "right.jsonl", "with tMax"),
                                      (f"{mistake}-cells.jsonl", "right-cells.jsonl",
                                       "cells only")):
            what = f"{name} --mistake {mistake} ({how})"
            verdict = assess(target, trace, kit, what)
            expect_mistake(verdict, os.path.join(kit, reference), os.path.join(kit, trace),
                           mistake, what)

    # A class of three: the solution, a mistake, the untouched skeleton; and a malformed trace.
    grade_class(kit, target, {"ann": "right.jsonl", "bob": "tie-one-axis.jsonl",
                              "carla": "walk.jsonl"}, f"{name} --class")


def grade_class(kit, target, traces, what):
    """--class DIR -o OUT over the kit's traces, one student each, and a malformed one: grades.csv
    (id,grade,feedback) read back with Python's csv module, grade = the share of rays passed."""
    import csv
    folder = os.path.join(kit, "class")
    os.makedirs(folder)
    expected = {}
    for student, trace in traces.items():
        shutil.copy(os.path.join(kit, trace), os.path.join(folder, f"{student}.jsonl"))
        rays = read_trace(os.path.join(kit, trace))
        verdict = assess(target, trace, kit, f"{what}, {student}")
        if verdict:
            expected[student] = 100.0 * verdict["rays_passed"] / len(rays)
    with open(os.path.join(folder, "broken.jsonl"), "w") as f:
        f.write('{"ray": {"origin": [0, 0], "dir": [1, Infinity]}}\n')
    expected["broken"] = 0.0
    p = run([CLI, "assess", *target, "--class", "class", "-o", "results"], kit, check=False)
    if p.returncode != 0:
        fail(f"{what}: --class exit {p.returncode}: {p.stderr.strip()}")
        return
    with open(os.path.join(kit, "results", "grades.csv"), newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    if rows[:1] != [["id", "grade", "feedback"]]:
        fail(f"{what}: grades.csv starts {rows[:1]}")
    grades = {row[0]: row for row in rows[1:]}
    for student, grade in expected.items():
        row = grades.get(student)
        if not row or len(row) != 3 or f"{grade:.2f}" != row[1]:
            fail(f"{what}: grades.csv has {row} for {student}, expected grade {grade:.2f}")
    if "Infinity" not in grades.get("broken", ["", "", ""])[2]:
        fail(f"{what}: the malformed trace's feedback does not say why: {grades.get('broken')}")
    if not os.path.isfile(os.path.join(kit, "results", "class.md")):
        fail(f"{what}: no class.md")


def dda_2d(tmp):
    def skeleton(kit, args, out):
        return run([sys.executable, "dda2d.py", *args], kit, stdout=out, check=False)

    def solution(kit, args, out):
        return run([sys.executable, "dda2d_solution.py", *args], kit, stdout=out)

    kit_file = os.path.join(KITS, "dda-2d", "dda2d.py")
    solution_file = os.path.join(HERE, "dda2d_solution.py")
    check_given_code(kit_file, solution_file)
    # The solution sits in the kit's copy, next to its rays.json, as a student's file would.
    dda_kit("dda-2d", ("8,6", "0,0", "8,6"), skeleton,
            lambda kit, args, out: (shutil.copy(solution_file, kit), solution(kit, args, out))[1],
            tmp)


def dda_3d(tmp):
    kit_file = os.path.join(KITS, "dda-3d", "dda3d.cpp")
    solution_file = os.path.join(HERE, "dda3d_solution.cpp")
    check_given_code(kit_file, solution_file)
    built = {}

    def binary(kit, source, name):
        if name not in built:
            compile_cpp(source, name, kit)
            built[name] = os.path.join(kit, name)
        return built[name]

    def skeleton(kit, args, out):
        return run([binary(kit, "dda3d.cpp", "dda3d"), *args], kit, stdout=out, check=False)

    def solution(kit, args, out):
        return run([binary(kit, solution_file, "dda3d_solution"), *args], kit, stdout=out)

    dda_kit("dda-3d", ("6,4,4", "-3,-2,0", "3,2,2"), skeleton, solution, tmp)


# ---- The kd-tree kit ----


def kdtree(tmp):
    kit_file = os.path.join(KITS, "kdtree", "kdtree.cpp")
    solution_file = os.path.join(HERE, "kdtree_solution.cpp")
    check_given_code(kit_file, solution_file)
    kit = copy_kit("kdtree", tmp)
    target = ["lecture-kdtree", "--accel", "kdtree"]
    # The tree as the kit's instructions make it, so that it always matches raystep's.
    run([CLI, "assess", *target, "--structure"], kit, stdout="tree.jsonl")
    compile_cpp("kdtree.cpp", "kdtree", kit)
    compile_cpp(solution_file, "kdtree_solution", kit)

    p = run(["./kdtree", "tree.jsonl", "rays.json"], kit, stdout="run.jsonl", check=False)
    if p.returncode != 1 or "TODO" not in p.stderr:
        fail(f"kdtree skeleton: exit {p.returncode}, stderr {p.stderr.strip()!r}")
    verdict = assess(target, "run.jsonl", kit, "kdtree skeleton")
    if verdict and verdict["passed"]:
        fail("kdtree skeleton: passes the assessment without a traversal")

    run(["./kdtree_solution", "tree.jsonl", "rays.json"], kit, stdout="right.jsonl")
    expect_pass(assess(target, "right.jsonl", kit, "kdtree solution"), "kdtree solution")
    # far-child-first is not in the table: raystep may name nothing, the ray must fail.
    for mistake, name in (("first-hit-in-tree", "first-hit-in-tree"), ("far-child-first", None)):
        wrong = f"{mistake}.jsonl"
        run(["./kdtree_solution", "tree.jsonl", "rays.json", "--mistake", mistake], kit,
            stdout=wrong)
        what = f"kdtree --mistake {mistake}"
        expect_mistake(assess(target, wrong, kit, what), os.path.join(kit, "right.jsonl"),
                       os.path.join(kit, wrong), name, what)

    # The solution reads any of raystep's kd-trees of the scene: the midpoint's and the median's
    # leaves hold several primitives (their tests compared as a set).
    for split in ("midpoint", "median"):
        other = [*target, "--split", split]
        run([CLI, "assess", *other, "--structure"], kit, stdout=f"tree-{split}.jsonl")
        run(["./kdtree_solution", f"tree-{split}.jsonl", "rays.json"], kit,
            stdout=f"right-{split}.jsonl")
        expect_pass(assess(other, f"right-{split}.jsonl", kit, f"kdtree solution, {split}"),
                    f"kdtree solution, {split}")

    # The kit's reader takes exactly the --structure forms: anything else is refused, naming
    # the line, not misread.
    lines = open(os.path.join(kit, "tree.jsonl")).read().splitlines()
    node = next(i for i, line in enumerate(lines) if '"children"' in line)
    prim = next(i for i, line in enumerate(lines) if '"prim"' in line)
    broken = {
        "an unknown key": (node, lines[node][:-1] + ', "depth": 3}'),
        "a 3D primitive": (prim, '{"prim": 0, "sphere": {"center": [0, 0, 0], "radius": 1}}'),
        "not JSON": (node, lines[node][:-2]),
        "a node twice": (prim, lines[node]),
    }
    for why, (at, text) in broken.items():
        bad = list(lines)
        bad[at] = text
        with open(os.path.join(kit, "bad.jsonl"), "w") as f:
            f.write("\n".join(bad) + "\n")
        p = run(["./kdtree_solution", "bad.jsonl", "rays.json"], kit, check=False)
        if p.returncode != 2 or f"bad.jsonl:{at + 1}" not in p.stderr:
            fail(f"kdtree reader, {why}: exit {p.returncode}, {p.stderr.strip()!r}")


with tempfile.TemporaryDirectory() as tmp:
    for kit in (dda_2d, dda_3d, kdtree):
        kit(tmp)

# Each of these rays makes the one mistake too: the assessor should name it on every ray.
for what, rays in named_otherwise.items():
    fail(f"{what}: later failed rays name another mistake or none: {rays}")

if failures:
    print(f"{len(failures)} failures")
    sys.exit(1)
print("assignments: every kit checked")
