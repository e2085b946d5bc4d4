#!/usr/bin/env python3
"""raystep-cli homework make and grade for a roster of three, read back with Python's csv and
json modules (docs/practice.md, "Homework").

usage: homework_test.py RAYSTEP_CLI
"""
import csv
import filecmp
import json
import os
import subprocess
import sys
import tempfile

CLI = sys.argv[1]
failures = []


def fail(message):
    failures.append(message)


def cli(*args, ok=True):
    p = subprocess.run([CLI, *args], capture_output=True, text=True)
    if ok and p.returncode != 0:
        raise SystemExit(f"{args}: exit {p.returncode}: {p.stderr}")
    return p


with tempfile.TemporaryDirectory() as tmp:
    roster = f"{tmp}/roster.csv"
    # A BOM, CRLF, and a name with a comma inside quotes.
    with open(roster, "w", encoding="utf-8-sig", newline="") as f:
        f.write('Username,Name\r\nann,"Rossi, Anna"\r\nbob,Bob\r\ncarla,Carla\r\n')
    for out in ("hw", "again"):
        cli("homework", "make", "--roster", roster, "--topics", "dda-2d,ray-sphere", "--seed", "9",
            "--level", "medium", "-o", f"{tmp}/{out}")
    hw = f"{tmp}/hw"
    for student in ("ann", "bob", "carla"):
        for name in ("sheet.md", "sheet.html", "answers-dda-2d.json", "answers-ray-sphere.json",
                     "figure-dda-2d.png"):
            path = f"{hw}/{student}/{name}"
            if not os.path.isfile(path):
                fail(f"missing {path}")
            elif not filecmp.cmp(path, f"{tmp}/again/{student}/{name}", shallow=False):
                fail(f"{path}: the same command gave other bytes")
    if "Rossi, Anna" not in open(f"{hw}/ann/sheet.md", encoding="utf-8").read():
        fail("ann's sheet does not name her")
    # A choice is answered by a letter in key.csv: the sheet lists its options, a) and b).
    for name in ("sheet.md", "sheet.html"):
        sheet = open(f"{hw}/ann/{name}", encoding="utf-8").read()
        if name == "sheet.md" and not ("  a) " in sheet and "  b) " in sheet):
            fail(f"ann's {name} lists no options for the choice exercise")
        if name == "sheet.html" and '<ol type="a">' not in sheet:
            fail(f"ann's {name} lists no options for the choice exercise")
    cli("homework", "make", "--roster", roster, "--topics", "ray-sphere", "--seed", "9",
        "--lang", "it", "-o", f"{tmp}/it")
    sheet_it = open(f"{tmp}/it/ann/sheet.md", encoding="utf-8").read()
    for word in ("Risposta:", "Id della lezione:"):
        if word not in sheet_it:
            fail(f"the Italian sheet lacks {word!r}")
    if "Answer:" in sheet_it or "Lesson id:" in sheet_it:
        fail("the Italian sheet has English labels")
    meta = json.load(open(f"{hw}/homework.json"))
    lessons = {s["id"]: s["lessons"] for s in meta["students"]}
    if len({l["dda-2d"] for l in lessons.values()}) != 3:
        fail(f"two students share an instance: {lessons}")
    # The key, read with csv: fill ann's answers from it, bob's with a wrong walk, none for carla.
    key = {}
    with open(f"{hw}/key.csv", newline="", encoding="utf-8") as f:
        for row in csv.DictReader(f):
            key.setdefault((row["student"], row["topic"]), {})[row["exercise"]] = row["answer"]
    if not key:
        fail("key.csv has no rows")
    subs = f"{tmp}/subs"
    for student in ("ann", "bob"):
        os.makedirs(f"{subs}/{student}")
        for topic in ("dda-2d", "ray-sphere"):
            answers = dict(key[(student, topic)])
            if student == "bob" and topic == "dda-2d":
                answers["walk"] = "0,0; 9,9"
            sheet = {"lesson": lessons[student][topic], "student": student, "answers": answers}
            json.dump(sheet, open(f"{subs}/{student}/answers-{topic}.json", "w"))
    cli("homework", "grade", hw, "--answers", subs)
    with open(f"{hw}/grades.csv", newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    grades = {r["id"]: r for r in rows}
    if set(grades) != {"ann", "bob", "carla"}:
        fail(f"grades.csv ids {sorted(grades)}")
    else:
        if grades["ann"]["grade"] != "100.00":
            fail(f"ann: {grades['ann']}")
        if not 0 < float(grades["bob"]["grade"]) < 100 or "walk" not in grades["bob"]["feedback"]:
            fail(f"bob: {grades['bob']}")
        if grades["carla"]["grade"] != "0.00" or "no submission" not in grades["carla"]["feedback"]:
            fail(f"carla: {grades['carla']}")
    if not os.path.isfile(f"{hw}/class.md"):
        fail("no class.md")
    # Bad input: one line, exit 2.
    bad = f"{tmp}/bad.csv"
    for text in ("Name\nann\n", "Username\nann\nann\n", "Username\n../x\n"):
        with open(bad, "w") as f:
            f.write(text)
        p = cli("homework", "make", "--roster", bad, "--topics", "dda-2d", "--seed", "1", "-o",
                f"{tmp}/badout", ok=False)
        if p.returncode != 2 or len(p.stderr.strip().splitlines()) != 1:
            fail(f"roster {text!r}: exit {p.returncode}, {p.stderr!r}")
    p = cli("homework", "make", "--roster", roster, "--topics", "nope", "--seed", "1", "-o",
            f"{tmp}/badout", ok=False)
    if p.returncode != 2 or len(p.stderr.strip().splitlines()) != 1:
        fail(f"unknown topic: exit {p.returncode}, {p.stderr!r}")

for f in failures:
    print(f)
print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
