#!/usr/bin/env bash
# Shows that recording off costs nothing: compiles algorithms/raystep/accel/grid.cpp as it is and from a copy of
# the sources with every recording hook (`if constexpr (Rec::kEnabled) ...`) deleted, and compares
# the machine code of the NullRecorder walks. Prints IDENTICAL or the difference
# (docs/performance.md, "Recording").
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
cp -r "$ROOT/algorithms" "$TMP/algorithms"
/usr/bin/python3 - "$TMP/algorithms/raystep/accel/grid.cpp" "$TMP/algorithms/raystep/accel/mailbox.h" <<'PY'
import sys
HOOK = "if constexpr (Rec::kEnabled)"
def strip(s):
    """Deletes each hook statement: a braced block, or one statement up to its ';'."""
    while True:
        a = s.find(HOOK)
        if a < 0:
            return s
        i = a + len(HOOK)
        while s[i].isspace():
            i += 1
        depth = 0
        if s[i] == "{":
            while True:
                depth += {"{": 1, "}": -1}.get(s[i], 0)
                i += 1
                if depth == 0:
                    break
        else:
            while not (s[i] == ";" and depth == 0):
                depth += {"(": 1, ")": -1, "{": 1, "}": -1}.get(s[i], 0)
                i += 1
            i += 1
        s = s[:a] + s[i:]
for path in sys.argv[1:]:
    text = open(path).read()
    assert HOOK in text, path + ": no hook found: update this script"
    open(path, "w").write(strip(text))
PY
FLAGS=(-std=c++20 -O3 -DNDEBUG)
g++ "${FLAGS[@]}" -I"$ROOT/algorithms" -c "$ROOT/algorithms/raystep/accel/grid.cpp" -o "$TMP/with.o"
g++ "${FLAGS[@]}" -I"$TMP/algorithms" -c "$TMP/algorithms/raystep/accel/grid.cpp" -o "$TMP/without.o"
for f in with without; do
  objdump -d --no-show-raw-insn -C "$TMP/$f.o" |
    awk '/^[0-9a-f]+ <.*walk<(true|false), raystep::NullRecorder>/{p=1; print; next} p&&/^$/{p=0} p' |
    sed -E 's/^ *[0-9a-f]+:\s*//; s/[0-9a-f]+ <[^>]*>/<addr>/g; s/# [0-9a-f]+ <[^>]*>//' > "$TMP/$f.s"
done
lines=$(wc -l < "$TMP/with.s")
[ "$lines" -gt 100 ] || { echo "no NullRecorder walk found in the object code" >&2; exit 1; }
if grep -q "kEnabled" "$TMP/algorithms/raystep/accel/grid.cpp" "$TMP/algorithms/raystep/accel/mailbox.h"; then
  echo "a hook was left in the stripped copy" >&2; exit 1
fi
if diff -q "$TMP/with.s" "$TMP/without.s" >/dev/null; then
  echo "IDENTICAL: $lines lines of NullRecorder walk code, with and without the hooks"
else
  diff "$TMP/with.s" "$TMP/without.s" | head -40 || true  # head may close the pipe early
  exit 1
fi
