#!/usr/bin/env python3
"""Draws docs/images/graph-scaling.svg from tools/graph-figures.sh's rows.csv:
primitive evaluations per pixel and frame time against the primitive count,
pruned against --no-prune, on log-log axes. No dependencies.

  tools/graph-plot.py out/graph-figures/rows.csv docs/images/graph-scaling.svg
"""
import csv
import math
import os
import sys

W, H, PAD = 360, 260, 54


def panel(x0, title, ylabel, series, xs_all):
    ys_all = [y for _, pts in series for _, y in pts if y > 0]
    lx = (math.floor(math.log10(min(xs_all))), math.ceil(math.log10(max(xs_all))))
    ly = (math.floor(math.log10(min(ys_all))), math.ceil(math.log10(max(ys_all))))
    def px(x):
        return x0 + PAD + (math.log10(x) - lx[0]) / (lx[1] - lx[0]) * (W - PAD - 34)
    def py(y):
        return H - PAD + 14 - (math.log10(y) - ly[0]) / (ly[1] - ly[0]) * (H - PAD - 20)
    out = [f'<text x="{x0 + W / 2}" y="16" text-anchor="middle" font-weight="bold">{title}</text>']
    for e in range(lx[0], lx[1] + 1):
        out.append(f'<line x1="{px(10**e):.1f}" y1="{py(10**ly[0]):.1f}" x2="{px(10**e):.1f}" y2="{py(10**ly[1]):.1f}" stroke="#ddd"/>')
        out.append(f'<text x="{px(10**e):.1f}" y="{H - PAD + 30}" text-anchor="middle">{10**e:,}</text>')
    for e in range(ly[0], ly[1] + 1):
        out.append(f'<line x1="{px(10**lx[0]):.1f}" y1="{py(10**e):.1f}" x2="{px(10**lx[1]):.1f}" y2="{py(10**e):.1f}" stroke="#ddd"/>')
        out.append(f'<text x="{px(10**lx[0]) - 4:.1f}" y="{py(10**e) + 4:.1f}" text-anchor="end">1e{e}</text>')
    out.append(f'<text x="{x0 + W / 2}" y="{H - 6}" text-anchor="middle">primitives</text>')
    out.append(f'<text x="{x0 + 12}" y="{H / 2}" transform="rotate(-90 {x0 + 12} {H / 2})" text-anchor="middle">{ylabel}</text>')
    for (name, pts), colour in zip(series, ["#1f77b4", "#d62728"]):
        if not pts:
            continue
        path = " ".join(f"{'M' if i == 0 else 'L'}{px(x):.1f},{py(y):.1f}" for i, (x, y) in enumerate(pts))
        out.append(f'<path d="{path}" fill="none" stroke="{colour}" stroke-width="2"/>')
        for x, y in pts:
            out.append(f'<circle cx="{px(x):.1f}" cy="{py(y):.1f}" r="3" fill="{colour}"/>')
    return out


def main():
    rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["primitives"].isdigit()]
    def pts(mode, key):
        return sorted((int(r["primitives"]), float(r[key])) for r in rows if r["mode"] == mode and float(r[key]) > 0)
    xs = [int(r["primitives"]) for r in rows]
    svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{2 * W}" height="{H + 24}" font-family="sans-serif" font-size="11">',
           '<rect width="100%" height="100%" fill="white"/>']
    svg += panel(0, "primitive evaluations per pixel", "evaluations",
                 [("pruned", pts("pruned", "primitive_evals_mean")), ("--no-prune", pts("whole", "primitive_evals_mean"))], xs)
    svg += panel(W, "frame time (64x36, llvmpipe)", "ms",
                 [("pruned", pts("pruned", "frame_ms")), ("--no-prune", pts("whole", "frame_ms"))], xs)
    svg.append(f'<text x="{W - 150}" y="{H + 18}" fill="#1f77b4">— pruned</text>')
    svg.append(f'<text x="{W + 10}" y="{H + 18}" fill="#d62728">— --no-prune</text>')
    svg.append("</svg>")
    tmp = sys.argv[2] + ".tmp"
    with open(tmp, "w") as f:
        f.write("\n".join(svg) + "\n")
    os.replace(tmp, sys.argv[2])


if __name__ == "__main__":
    main()
