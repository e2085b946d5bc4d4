#!/usr/bin/python3
"""Draws the figures of docs/accuracy.md from the measurements.

Inputs (made by scripts/measure_accuracy.sh):
  docs/data/accuracy.json        raystep_accuracy --out
  docs/data/kernels_bench.json   raystep_bench_kernels --benchmark_out (Google Benchmark JSON)
Outputs: docs/images/accuracy-*.png
"""
import json
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent
DATA = ROOT / "docs" / "data"
OUT = ROOT / "docs" / "images"
STYLE = {  # one colour per method, solid for double, dashed for float
    "plane": "#d62728", "moller-trumbore": "#ff7f0e", "watertight": "#2ca02c",
    "textbook": "#d62728", "stable": "#2ca02c", "epsilon": "#d62728", "robust": "#2ca02c",
}


def line(precision):
    return "-" if precision == "double" else "--"


def save(fig, name):
    fig.tight_layout()
    fig.savefig(OUT / name, dpi=110)
    plt.close(fig)
    print("wrote", OUT / name)


def kernel_speeds():
    """M tests/s per (method, precision) with rays reused 16 times, from Google Benchmark."""
    bench = json.loads((DATA / "kernels_bench.json").read_text())
    speeds = {}
    names = {0: "plane", 1: "moller-trumbore", 2: "watertight"}
    sphere_names = {0: "textbook", 1: "stable"}
    for b in bench["benchmarks"]:
        parts = b["name"].split("/")
        kind, precision = parts[0].split("<")
        precision = precision.rstrip(">")
        args = dict(p.split(":") for p in parts[1:] if ":" in p)
        method = int(args["method"])
        if kind == "BM_Triangle":
            key = "triangle" if args.get("rays_reused") == "16" else "triangle-own"
            speeds[(key, names[method], precision)] = b["items_per_second"] / 1e6
        else:
            speeds[("sphere", sphere_names[method], precision)] = b["items_per_second"] / 1e6
    return speeds


def main():
    acc = json.loads((DATA / "accuracy.json").read_text())
    speeds = kernel_speeds()

    # Speed against crack rate: the trade in one picture.
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for c in acc["cracks"]:
        speed = speeds[("triangle", c["method"], c["precision"])]
        rate = max(c["crack_rate"], 1e-7)  # zero drawn at the floor, labelled
        ax.scatter(speed, rate, color=STYLE[c["method"]], marker="o" if c["precision"] == "double" else "s", s=60)
        label = f'{c["method"]} {c["precision"]}' + (" (0 cracks)" if c["crack_rate"] == 0 else "")
        ax.annotate(label, (speed, rate), textcoords="offset points", xytext=(6, 4), fontsize=8)
    ax.set_yscale("log")
    ax.set_ylim(5e-8, 1)
    ax.set_xlabel("million ray-triangle tests per second (one core, rays reused 16 times)")
    ax.set_ylabel("crack rate through shared edges and vertices")
    ax.set_title("Ray-triangle: speed against watertightness")
    ax.grid(True, which="both", alpha=0.3)
    save(fig, "accuracy-triangle-trade.png")

    # Sphere t error against distance.
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for method in ("textbook", "stable"):
        for precision in ("float", "double"):
            rows = [r for r in acc["sphere_t_error"] if r["method"] == method and r["precision"] == precision]
            xs = [r["distance"] for r in rows]
            ys = [max(r["max_rel_error"], 1e-17) for r in rows]
            ax.plot(xs, ys, line(precision), color=STYLE[method], marker="o", label=f"{method} {precision}")
            for r in rows:
                if r["wrong_misses"]:
                    ax.annotate(f'{100 * r["wrong_misses"] / r["rays"]:.0f}% miss', (r["distance"], max(r["max_rel_error"], 1e-17)),
                                textcoords="offset points", xytext=(-10, 6), fontsize=7, color=STYLE[method])
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("distance to a unit sphere")
    ax.set_ylabel("largest relative error of t")
    ax.set_title("Ray-sphere: textbook quadratic against the stable form")
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    save(fig, "accuracy-sphere-t-error.png")

    # Acne and leaks against scene scale.
    fig, axes = plt.subplots(1, 2, figsize=(9.6, 3.8), sharex=True)
    for key, ax, title in (("acne_share", axes[0], "shadow acne (lit points shadowed)"),
                           ("leak_share", axes[1], "light leaks (shadowed points lit)")):
        for offset in ("epsilon", "robust"):
            for precision in ("float", "double"):
                rows = [r for r in acc["acne"] if r["ray_offset"] == offset and r["precision"] == precision]
                ax.plot([r["scale"] for r in rows], [100 * r[key] for r in rows], line(precision),
                        color=STYLE[offset], marker="o", label=f"{offset} {precision}")
        ax.set_xscale("log")
        ax.set_xlabel("scene scale")
        ax.set_ylabel("% of points")
        ax.set_title(title, fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=8)
    save(fig, "accuracy-acne.png")

    # Triangle t error per method, precision and scale.
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for method in ("plane", "moller-trumbore", "watertight"):
        for precision in ("float", "double"):
            rows = [r for r in acc["triangle_t_error"] if r["method"] == method and r["precision"] == precision]
            ax.plot([r["scale"] for r in rows], [r["p99_rel_error"] for r in rows], line(precision),
                    color=STYLE[method], marker="o", label=f"{method} {precision}")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("scale of the triangles (and of their distance from the origin)")
    ax.set_ylabel("99th percentile of relative t error")
    ax.set_title("Ray-triangle: error of t against exact arithmetic")
    ax.legend(fontsize=8, ncol=2)
    ax.grid(True, which="both", alpha=0.3)
    save(fig, "accuracy-triangle-t-error.png")
    print_tables(acc, speeds)
    return 0


def print_tables(acc, speeds):
    """Markdown tables for docs/accuracy.md, printed so the page can be refreshed by hand."""
    print("\n| triangle method | precision | M tests/s (own ray) | M tests/s (ray reused 16x) | crack rate | t error p99 (scale 1) |")
    print("| --- | --- | --- | --- | --- | --- |")
    t1 = {(r["method"], r["precision"]): r for r in acc["triangle_t_error"] if r["scale"] == 1.0}
    for c in acc["cracks"]:
        own = speeds.get(("triangle-own", c["method"], c["precision"]), float("nan"))
        reused = speeds[("triangle", c["method"], c["precision"])]
        print(f'| {c["method"]} | {c["precision"]} | {own:.1f} | {reused:.1f} | '
              f'{c["edge_misses"] + c["vertex_misses"]} / {c["edge_rays"] + c["vertex_rays"]} = {c["crack_rate"]:.2e} | '
              f'{t1[(c["method"], c["precision"])]["p99_rel_error"]:.1e} |')
    print("\n| sphere method | precision | M tests/s | distance where t error first exceeds 1e-6 | misses of a sphere that is hit |")
    print("| --- | --- | --- | --- | --- |")
    for method in ("textbook", "stable"):
        for precision in ("float", "double"):
            rows = [r for r in acc["sphere_t_error"] if r["method"] == method and r["precision"] == precision]
            bad = [r["distance"] for r in rows if r["max_rel_error"] > 1e-6]
            misses = [f'{r["wrong_misses"]} at {r["distance"]:.0e}' for r in rows if r["wrong_misses"]]
            print(f'| {method} | {precision} | {speeds[("sphere", method, precision)]:.1f} | '
                  f'{f"{bad[0]:.0e}" if bad else "never (up to 1e8)"} | {", ".join(misses) if misses else "none"} |')
    print("\n| scale | float epsilon acne / leaks | float robust | double epsilon | double robust |")
    print("| --- | --- | --- | --- | --- |")
    for scale in sorted({r["scale"] for r in acc["acne"]}):
        cells = []
        for precision in ("float", "double"):
            for offset in ("epsilon", "robust"):
                r = next(r for r in acc["acne"] if r["scale"] == scale and r["precision"] == precision and r["ray_offset"] == offset)
                cells.append(f'{100 * r["acne_share"]:.2f}% / {100 * r["leak_share"]:.2f}%')
        print(f"| {scale:.0e} | " + " | ".join(cells) + " |")
    print("\n| render A | render B | pixels that differ | differ by more than 16/255 |")
    print("| --- | --- | --- | --- |")
    for c in acc["stadium"]:
        print(f'| {c["a"]} | {c["b"]} | {c["differ"]} of {c["pixels"]} | {c["differ_by_more_than_16"]} |')


if __name__ == "__main__":
    sys.exit(main())
