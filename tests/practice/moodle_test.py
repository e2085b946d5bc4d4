#!/usr/bin/env python3
"""raystep-cli export moodle read back by independent readers (docs/practice.md, "Moodle").

The Moodle XML is parsed with Python's xml.etree and the GIFT with the small GIFT parser below
(written from Moodle's GIFT documentation, not from raystep's writer); each question's right answer
is compared with `raystep-cli lesson key` of its lesson, exercise by exercise, and each embedded
figure is checked to be a PNG.

usage: moodle_test.py RAYSTEP_CLI
"""
import base64
import json
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

CLI = sys.argv[1]
failures = []


def fail(where, message):
    failures.append(f"{where}: {message}")


def run(*args):
    return subprocess.run([CLI, *args], capture_output=True, check=True, text=True).stdout


keys = {}


def key(lesson):
    if lesson not in keys:
        keys[lesson] = json.loads(run("lesson", "key", lesson))["answers"]
    return keys[lesson]


def same_number(text, want, tolerance):
    return abs(float(text) - float(want)) <= max(tolerance, 1e-6 * max(1, abs(float(want))))


def check_right(where, qtype, rights, want, options=None):
    """rights: the answers given 100%; want: the key's answer as a student types it."""
    if qtype == "numerical":
        if not any(same_number(v, want, tol) for v, tol in rights):
            fail(where, f"right answers {rights}, the key says {want}")
    elif qtype == "shortanswer":
        if want not in [r for r, _ in rights]:
            fail(where, f"the key's {want!r} is not among {rights}")
    elif qtype == "multichoice":
        if len(rights) != 1:
            fail(where, f"{len(rights)} right options")
        elif want.isalpha() and len(want) == 1 and options is not None:
            if options[ord(want) - ord("a")] != rights[0][0]:
                fail(where, f"the right option is {rights[0][0]!r}, the key says {want}")


def check_xml(path, expect_figures):
    root = ET.parse(path).getroot()  # well-formed, or this raises
    if root.tag != "quiz":
        fail(path, "the root is not <quiz>")
    count, category = 0, None
    for q in root:
        qtype = q.get("type")
        if qtype == "category":
            category = q.find("category/text").text
            continue
        count += 1
        lesson, exercise = q.find("name/text").text.split(" ")
        where = f"{path} {lesson}/{exercise}"
        if not category or not category.endswith("/" + exercise):
            fail(where, f"in category {category}")
        answers = q.findall("answer")
        rights = [(a.find("text").text, float(a.findtext("tolerance") or 0))
                  for a in answers if float(a.get("fraction")) == 100]
        options = [a.find("text").text for a in answers]
        check_right(where, qtype, rights, key(lesson)[exercise], options)
        for a in answers:
            if float(a.get("fraction")) == 0 and not (a.findtext("feedback/text") or "").strip():
                fail(where, "a wrong answer without the slip it betrays")
        files = q.findall("questiontext/file")
        text = q.findtext("questiontext/text")
        if expect_figures:
            if len(files) != 1 or "@@PLUGINFILE@@/figure.png" not in text:
                fail(where, "no embedded figure")
            elif not base64.b64decode(files[0].text).startswith(b"\x89PNG\r\n\x1a\n"):
                fail(where, "the figure is not a PNG")
    return count


def gift_split(text):
    """GIFT: questions separated by blank lines; $CATEGORY lines; // comments."""
    blocks, current = [], []
    for line in text.splitlines():
        if line.strip() == "":
            if current:
                blocks.append("\n".join(current))
                current = []
        elif not line.startswith("//"):
            current.append(line)
    if current:
        blocks.append("\n".join(current))
    return blocks


def gift_unescape(s):
    return re.sub(r"\\(.)", r"\1", s).strip()


def gift_parse(block):
    """-> (title, text, type, [(answer, fraction, tolerance, feedback)], general feedback)."""
    m = re.match(r"::((?:\\.|[^:\\])*)::(.*)$", block, re.S)
    title, rest = m.group(1), m.group(2)
    # The answer block: the first unescaped '{' to its unescaped '}'.
    depth_start = re.search(r"(?<!\\)\{", rest).start()
    end = max(i for i, c in enumerate(rest) if c == "}" and rest[i - 1] != "\\")
    text, body = rest[:depth_start], rest[depth_start + 1:end]
    general = ""
    parts = re.split(r"(?<!\\)####", body)
    body = parts[0]
    if len(parts) > 1:
        general = gift_unescape(parts[1])
    numerical = body.startswith("#")
    if numerical:
        body = body[1:]
    answers = []
    for m in re.finditer(r"(?<!\\)([=~])((?:\\.|[^=~\\])*)", body):
        kind, content = m.group(1), m.group(2)
        fraction = 100 if kind == "=" else 0
        pm = re.match(r"%(-?\d+)%", content)
        if pm:
            fraction = int(pm.group(1))
            content = content[pm.end():]
        fb_split = re.split(r"(?<!\\)#", content, maxsplit=1)
        value, feedback = fb_split[0], gift_unescape(fb_split[1]) if len(fb_split) > 1 else ""
        tolerance = 0.0
        if numerical:
            vm = re.match(r"\s*(-?[\d.eE+-]+)\s*(?<!\\):\s*([\d.eE+-]+)\s*$", value.replace("\\:", ":"))
            value, tolerance = vm.group(1), float(vm.group(2))
        answers.append((gift_unescape(value), fraction, tolerance, feedback))
    qtype = "numerical" if numerical else ("multichoice" if any(k == "~" for k in re.findall(r"(?<!\\)([=~])", body)) else "shortanswer")
    return gift_unescape(title), gift_unescape(text), qtype, answers, general


def check_gift(path):
    count = 0
    with open(path, encoding="utf-8") as f:
        blocks = gift_split(f.read())
    category = None
    for block in blocks:
        if block.startswith("$CATEGORY:"):
            category = block.split(":", 1)[1].strip()
            continue
        title, text, qtype, answers, general = gift_parse(block)
        count += 1
        lesson, exercise = title.split(" ")
        where = f"{path} {lesson}/{exercise}"
        if not category.endswith("/" + exercise):
            fail(where, f"in category {category}")
        if not general:
            fail(where, "no general feedback (the explanation)")
        rights = [(a, t) for a, fr, t, _ in answers if fr == 100]
        check_right(where, qtype, rights, key(lesson)[exercise], [a for a, *_ in answers])
    return count


with tempfile.TemporaryDirectory() as tmp:
    out = run("export", "moodle", "--topic", "dda-2d", "--variants", "20", "--seed", "7",
              "--level", "medium", "-o", f"{tmp}/dda.xml")
    n = check_xml(f"{tmp}/dda.xml", True)
    if n != 20 * 7 or f"{n} questions" not in out:
        fail("dda.xml", f"{n} questions, expected 140 ({out.strip()})")
    run("export", "moodle", "--topic", "dda-3d", "--variants", "5", "-o", f"{tmp}/dda3.xml")
    check_xml(f"{tmp}/dda3.xml", False)
    # Every topic `practice list` names, at every level: read back against the key.
    topics = [line.split()[0] for line in subprocess.run(
        [CLI, "practice", "list"], capture_output=True, text=True, check=True).stdout.splitlines()
        if line and not line[0].isspace()]
    if len(topics) < 6:
        fail("practice list", f"only {topics}")
    for topic in topics:
        for level in ("easy", "medium", "hard"):
            run("export", "moodle", "--topic", topic, "--variants", "2", "--level", level, "-o",
                f"{tmp}/{topic}-{level}.xml")
            check_xml(f"{tmp}/{topic}-{level}.xml", False)
    for lesson in ("6", "7", "11", "12"):
        check_xml(_ := f"{tmp}/l{lesson}.xml", False) if run(
            "export", "moodle", lesson, "-o", f"{tmp}/l{lesson}.xml") else None
    for lang in ("en", "it"):
        run("export", "moodle", "--topic", "dda-2d", "--variants", "10", "--lang", lang,
            "--format", "gift", "-o", f"{tmp}/dda-{lang}.gift")
        if check_gift(f"{tmp}/dda-{lang}.gift") != 70:
            fail(f"dda-{lang}.gift", "not 70 questions")
    run("export", "moodle", "6", "--format", "gift", "-o", f"{tmp}/l6.gift")
    check_gift(f"{tmp}/l6.gift")
    # The same command, the same bytes.
    run("export", "moodle", "--topic", "dda-2d", "--variants", "20", "--seed", "7", "--level",
        "medium", "-o", f"{tmp}/again.xml")
    if open(f"{tmp}/dda.xml", "rb").read() != open(f"{tmp}/again.xml", "rb").read():
        fail("dda.xml", "two runs differ")
    # Bad input: one line, exit 2, nothing written.
    for args in (["--topic", "nope"], ["6", "--topic", "dda-2d"], [], ["--topic", "dda-2d", "--variants", "0"],
                 ["--topic", "dda-2d", "--format", "pdf"]):
        p = subprocess.run([CLI, "export", "moodle", *args, "-o", f"{tmp}/bad.xml"],
                           capture_output=True, text=True)
        if p.returncode != 2 or len(p.stderr.strip().splitlines()) != 1:
            fail(f"export moodle {args}", f"exit {p.returncode}, stderr {p.stderr!r}")
    import os
    if os.path.exists(f"{tmp}/bad.xml"):
        fail("bad input", "a file was written")

for f in failures[:40]:
    print(f)
print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
