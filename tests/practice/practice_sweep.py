"""What the practice topics' tests share: `practice make --json` over many seeds and levels, each
instance handed to the topic's own check (which recomputes its answers with no raystep code),
the same seed giving the same bytes, a level's instances mostly distinct, and a lesson file
written by `-o` that validates and whose own key scores full marks in both languages."""
import json
import subprocess
import tempfile

LEVELS = ("easy", "medium", "hard")


def run(cli, topic, seed, level):
    out = subprocess.run([cli, "practice", "make", topic, "--seed", str(seed), "--level", level,
                          "--json"], check=True, capture_output=True)
    return out.stdout


def sweep(cli, checks, seeds, reruns, errors):
    """checks: (topic, check(json, level, fail) -> a kind of instance, counted for the log).
    Returns the kinds counted, by (topic, level)."""
    counted = {}
    for topic, check in checks:
        for level in LEVELS:
            seen, kinds = set(), {}
            for seed in range(1, seeds + 1):
                raw = run(cli, topic, seed, level)
                where = "%s %s seed %d" % (topic, level, seed)

                def fail(msg, where=where):
                    errors.append("%s: %s" % (where, msg))

                if seed <= reruns and run(cli, topic, seed, level) != raw:
                    fail("two runs differ")
                j = json.loads(raw)
                kind = check(j, level, fail)
                kinds[kind] = kinds.get(kind, 0) + 1
                seen.add(json.dumps(j["given"], sort_keys=True))
            if len(seen) < 0.9 * seeds:
                errors.append("%s %s: only %d of %d instances distinct"
                              % (topic, level, len(seen), seeds))
            print("%s %s: %d distinct, %s" % (topic, level, len(seen), kinds))
            counted[(topic, level)] = kinds
    return counted


def lesson_files_score(cli, topics, errors, seed=7):
    """`practice make -o` for each topic, level and language: validated, and its key scores all."""
    with tempfile.TemporaryDirectory() as tmp:
        for topic in topics:
            for level in LEVELS:
                for lang in ("en", "it"):
                    path = "%s/%s-%s-%s.json" % (tmp, topic, level, lang)
                    subprocess.run([cli, "practice", "make", topic, "--seed", str(seed), "--level",
                                    level, "--lang", lang, "-o", path], check=True,
                                   capture_output=True)
                    subprocess.run([cli, "lesson", "validate", path], check=True,
                                   capture_output=True)
                    key = subprocess.run([cli, "lesson", "key", path], check=True,
                                         capture_output=True).stdout
                    with open(tmp + "/key.json", "wb") as f:
                        f.write(key)
                    grade = json.loads(subprocess.run(
                        [cli, "lesson", "check", path, "--answers", tmp + "/key.json", "--json",
                         "--lang", lang], check=True, capture_output=True).stdout)
                    if grade["score"] != grade["out_of"] or grade["out_of"] < 2:
                        errors.append("%s: its own key does not score full marks: %s"
                                      % (path, grade))
                    # The first numeric answer off by 3: no longer full marks.
                    answers = json.loads(key)["answers"]
                    for ex, value in answers.items():
                        try:
                            wrong = float(str(value).replace(",", ".")) + 3
                        except ValueError:
                            continue
                        with open(tmp + "/wrong.json", "w") as f:
                            json.dump({**json.loads(key), "answers": {**answers, ex: str(wrong)}}, f)
                        grade = json.loads(subprocess.run(
                            [cli, "lesson", "check", path, "--answers", tmp + "/wrong.json",
                             "--json", "--lang", lang], check=True, capture_output=True).stdout)
                        if grade["score"] >= grade["out_of"]:
                            errors.append("%s: a wrong %s scores full marks" % (path, ex))
                        break


def main(argv, checks, default_seeds, reruns):
    """A topic script's main: `script RAYSTEP_CLI [SEEDS]`, every check swept, the -o files
    scored; the exit code."""
    cli = argv[1]
    seeds = int(argv[2]) if len(argv) > 2 else default_seeds
    errors = []
    sweep(cli, checks, seeds, reruns, errors)
    lesson_files_score(cli, [t for t, _ in checks], errors)
    return finish(errors)


def finish(errors):
    for e in errors[:40]:
        print("FAIL", e)
    if errors:
        print("%d failures" % len(errors))
        return 1
    return 0
