"""wrong_sheets.py CLI DIR: answers files per lesson (DIR/N/*.json) from its key: all zero, swapped
cells and doubled numbers, off by one, junk, empty."""
import json, subprocess, os, re, sys
B, OUT = sys.argv[1], sys.argv[2]
for n in range(1, 14):
    key = json.loads(subprocess.check_output([B, "lesson", "key", str(n)]))
    d = f"{OUT}/{n}"; os.makedirs(d, exist_ok=True)
    def variant(f):
        return {"lesson": key["lesson"], "answers": {k: f(v) for k, v in key["answers"].items()}}
    def swap(v):
        if isinstance(v, bool): return not v
        if isinstance(v, (int, float)): return v * 2 + 1
        s = str(v)
        if s in ("hit", "miss"): return "miss" if s == "hit" else "hit 1"
        if re.fullmatch(r"[a-f]", s): return "a" if s != "a" else "b"
        if ";" in s: return "; ".join(reversed(s.split("; ")))
        if "," in s: return ",".join(reversed(s.split(",")))
        try: return str(float(s) * 2 + 1)
        except ValueError: return s + "x"
    def off(v):
        s = str(v)
        try: return str(float(s) + 1)
        except ValueError: pass
        if "," in s and ";" not in s:
            return ",".join(str(int(float(p)) + 1) for p in s.split(","))
        return s
    json.dump(variant(lambda v: "0"), open(f"{d}/zero.json", "w"))
    json.dump(variant(swap), open(f"{d}/swap.json", "w"))
    json.dump(variant(off), open(f"{d}/off.json", "w"))
    json.dump(variant(lambda v: "nonsense"), open(f"{d}/junk.json", "w"))
    json.dump({"lesson": key["lesson"], "answers": {}}, open(f"{d}/empty.json", "w"))
