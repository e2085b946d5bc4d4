#!/usr/bin/env bash
# Shows that recording off costs nothing: compiles algorithms/grid.cpp as it is and a copy with its
# recording hooks deleted, and compares the machine code of the NullRecorder walks. Prints
# IDENTICAL or the difference (docs/performance.md, "Recording").
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
/usr/bin/python3 - "$ROOT/algorithms/grid.cpp" "$TMP/grid_nohooks.cpp" <<'PY'
import sys
s = open(sys.argv[1]).read()
def cut(s, start, end):
    a = s.index(start); b = s.index(end, a)
    return s[:a] + s[b:]
s = cut(s, "    if constexpr (Rec::kEnabled) {\n        if (dda.valid()) {",
        "    for (bool more = dda.valid(); more; more = dda.next()) {")
s = cut(s, "        if constexpr (Rec::kEnabled) {\n            DdaCell e",
        "        for (std::uint32_t p : cell(dda.cell())) {")
s = s.replace("                if constexpr (Rec::kEnabled) rec(MailboxSkip{rayId, p});\n", "")
s = s.replace("            if constexpr (Rec::kEnabled)\n"
              "                rec(PrimitiveTest{rayId, p, isHit, isHit ? hit.t : kInfinity});\n", "")
assert "Rec::kEnabled" not in s, "a hook was left: update this script"
open(sys.argv[2], "w").write(s)
PY
FLAGS=(-std=c++20 -O3 -DNDEBUG -I"$ROOT/algorithms")
g++ "${FLAGS[@]}" -c "$ROOT/algorithms/grid.cpp" -o "$TMP/with.o"
g++ "${FLAGS[@]}" -c "$TMP/grid_nohooks.cpp" -o "$TMP/without.o"
for f in with without; do
  objdump -d --no-show-raw-insn -C "$TMP/$f.o" |
    awk '/^[0-9a-f]+ <.*walk<(true|false), raystep::NullRecorder>/{p=1; print; next} p&&/^$/{p=0} p' |
    sed -E 's/^ *[0-9a-f]+:\s*//; s/[0-9a-f]+ <[^>]*>/<addr>/g; s/# [0-9a-f]+ <[^>]*>//' > "$TMP/$f.s"
done
lines=$(wc -l < "$TMP/with.s")
[ "$lines" -gt 100 ] || { echo "no NullRecorder walk found in the object code" >&2; exit 1; }
if diff -q "$TMP/with.s" "$TMP/without.s" >/dev/null; then
  echo "IDENTICAL: $lines lines of NullRecorder walk code, with and without the hooks"
else
  diff "$TMP/with.s" "$TMP/without.s" | head -40
  exit 1
fi
