#!/usr/bin/env bash
# record.sh CLI OUTDIR: what a change of layout must keep byte-identical: every lesson's show, key,
# validate and check output (right and four kinds of wrong answers, one sheet and a class, in both
# languages), renders (as MD5s), traces, build events, compare and every --help. Timings are
# masked. Record before and after a change, then `diff -r BEFORE AFTER`.
set -u
HERE="$(dirname "$(realpath "$0")")"
B="$(realpath "$1")"; O="$2"; mkdir -p "$O"; O="$(realpath "$O")"; cd "$O"
W="$O/wrong"
python3 "$HERE/wrong_sheets.py" "$B" "$W"
for n in $(seq 1 13); do
  for l in en it; do
    $B lesson show $n --lang $l > show$n.$l.txt 2>&1; echo "rc=$?" >> show$n.$l.txt
    $B lesson key $n --lang $l > key$n.$l.json 2>&1
    $B lesson check $n --answers key$n.en.json --lang $l > checkok$n.$l.txt 2>&1; echo "rc=$?" >> checkok$n.$l.txt
    for w in $W/$n/*.json; do
      [ -f "$w" ] || continue
      b=$(basename $w .json)
      $B lesson check $n --answers $w --lang $l > check$n.$b.$l.txt 2>&1; echo "rc=$?" >> check$n.$b.$l.txt
      $B lesson check $n --answers $w --lang $l --json > checkj$n.$b.$l.json 2>&1
    done
    $B lesson check $n --answers $W/$n --lang $l > class$n.$l.md 2>&1
    $B lesson check $n --answers $W/$n --lang $l --format csv > class$n.$l.csv 2>&1
  done
  $B lesson validate $n > validate$n.txt 2>&1; echo "rc=$?" >> validate$n.txt
done
for s in default cornell whitted lecture-dda3d; do
  for a in bruteforce grid kdtree bvh; do
    $B render $s --accel $a --width 96 --height 72 -o r.$s.$a.png > r.$s.$a.txt 2>&1
  done
done
$B render default --width 64 --height 48 --spp 4 --diffuse-samples 2 --bounces 3 -o r.spp.png > r.spp.txt 2>&1
$B render cornell --width 64 --height 48 --spp 2 --diffuse-samples 4 -o r.cornell.spp.png > r.cornell.spp.txt 2>&1
for a in grid kdtree bvh; do
  $B build lecture-kdtree --accel $a --events > b.$a.txt 2>&1
  $B build default --accel $a --events > b3.$a.txt 2>&1
  $B trace default --accel $a --pixel 40,30 -o t.$a.json > t.$a.txt 2>&1
done
$B compare default --accel grid,kdtree,bvh > cmp.txt 2>&1
$B --help > help.txt 2>&1
for c in render trace build dda intersect compare lesson; do $B $c --help > help.$c.txt 2>&1; done
md5sum *.png > png.md5; rm -f *.png
# Wall-clock times differ from run to run: masked (the "N ms" of render, compare's last column).
sed -i -E 's/, [0-9]+ ms\)/, _ ms)/' r.*.txt
sed -i -E 's/ +[0-9]+\.[0-9]+$/ _/' cmp.txt
# ... and its "build ms" column (the second), after the structure's name.
sed -i -E 's/^([a-z]+( [a-z0-9x]+)?) +[0-9]+\.[0-9]+ /\1 _ /' cmp.txt
# The binary's own path (CLI11's "Usage:" line) differs from one checkout to the next.
sed -i "s|$B|raystep-cli|g" help*.txt
