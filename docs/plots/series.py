#!/usr/bin/env python3
"""Plots issue 36's verification series (docs/performance.md) as an SVG.

Reads the `series-csv,...` lines that tests/bench/series_benchmarks prints
(the benchmark's whole output may be given: other lines are skipped) and
writes two panels side by side, time and peak memory against the series'
size, GG Studio and SPIN's pan, both on logarithmic axes; solid as both run by
default (write-only memories hidden), dashed with both keeping them. Python 3, standard
library only.

    ./build/tests/bench/series_benchmarks > series.txt
    python3 docs/plots/series.py series.txt docs/plots/series.svg
"""

import csv
import math
import sys

WIDTH, HEIGHT = 900, 400
PANEL_W, PANEL_H = 360, 260
MARGIN_LEFT, MARGIN_TOP = 70, 50
COLORS = {"GG Studio": "#1f77b4", "SPIN (pan)": "#d62728",
          "GG Studio, memories kept": "#1f77b4", "SPIN (pan), memories kept": "#d62728"}
DASHED = {"GG Studio, memories kept", "SPIN (pan), memories kept"}


def read_rows(path):
    rows = []
    with open(path, encoding="utf-8") as text:
        lines = [line[len("series-csv,"):] for line in text if line.startswith("series-csv,")]
    for row in csv.DictReader(lines):
        if row["grafcets"] == "0":
            continue  # the stress model: not a point of the series
        rows.append(row)
    return rows


def log_ticks(low, high):
    ticks = []
    decade = 10 ** math.floor(math.log10(low))
    while decade <= high * 10:
        for factor in (1, 2, 5):
            value = decade * factor
            if low <= value <= high:
                ticks.append(value)
        decade *= 10
    return ticks


def label(value):
    if value >= 1:
        return f"{value:g}"
    return f"{value:.2g}"


def panel(out, x0, y0, title, unit, labels, series):
    values = [v for points in series.values() for v in points if v and v > 0]
    low = 10 ** math.floor(math.log10(min(values)))
    high = 10 ** math.ceil(math.log10(max(values)))

    def y_of(value):
        return y0 + PANEL_H - (math.log10(value) - math.log10(low)) / (math.log10(high) - math.log10(low)) * PANEL_H

    def x_of(i):
        return x0 + (i + 0.5) * PANEL_W / len(labels)

    out.append(f'<text x="{x0 + PANEL_W / 2}" y="{y0 - 18}" text-anchor="middle" font-weight="bold">{title}</text>')
    out.append(f'<rect x="{x0}" y="{y0}" width="{PANEL_W}" height="{PANEL_H}" fill="none" stroke="#444"/>')
    for tick in log_ticks(low, high):
        y = y_of(tick)
        out.append(f'<line x1="{x0}" y1="{y:.1f}" x2="{x0 + PANEL_W}" y2="{y:.1f}" stroke="#ddd"/>')
        out.append(f'<text x="{x0 - 6}" y="{y + 4:.1f}" text-anchor="end" font-size="11">{label(tick)}</text>')
    out.append(f'<text x="{x0 - 52}" y="{y0 + PANEL_H / 2}" text-anchor="middle" font-size="12" '
               f'transform="rotate(-90 {x0 - 52} {y0 + PANEL_H / 2})">{unit}</text>')
    for i, name in enumerate(labels):
        out.append(f'<text x="{x_of(i):.1f}" y="{y0 + PANEL_H + 16}" text-anchor="middle" font-size="10">{name}</text>')
    for name, points in series.items():
        coords = [(x_of(i), y_of(v)) for i, v in enumerate(points) if v and v > 0]
        if not coords:
            continue
        path = " ".join(f"{x:.1f},{y:.1f}" for x, y in coords)
        dash = ' stroke-dasharray="6,4"' if name in DASHED else ""
        out.append(f'<polyline points="{path}" fill="none" stroke="{COLORS[name]}" stroke-width="2"{dash}/>')
        for x, y in coords:
            out.append(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="3.5" fill="{COLORS[name]}"/>')


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: series.py BENCHMARK_OUTPUT OUTPUT.svg")
    rows = read_rows(sys.argv[1])
    if not rows:
        sys.exit(f"{sys.argv[1]}: no series-csv lines")
    hidden = [r for r in rows if r.get("memories", "hidden") == "hidden"]
    kept = {r["label"]: r for r in rows if r.get("memories") == "kept"}
    labels = [f'{r["grafcets"]}×{r["bools"]}' for r in hidden]

    def number(row, key):
        return float(row[key]) if row and row.get(key) else None

    def kept_of(key, scale=1.0):
        return [number(kept.get(r["label"]), key) / scale if number(kept.get(r["label"]), key) else None
                for r in hidden]

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{HEIGHT}" '
           f'font-family="sans-serif" font-size="12">',
           f'<rect width="{WIDTH}" height="{HEIGHT}" fill="white"/>']
    panel(out, MARGIN_LEFT, MARGIN_TOP, "Time (best of three)", "ms", labels,
          {"GG Studio": [number(r, "gg_ms") for r in hidden], "SPIN (pan)": [number(r, "pan_ms") for r in hidden],
           "GG Studio, memories kept": kept_of("gg_ms"), "SPIN (pan), memories kept": kept_of("pan_ms")})
    panel(out, MARGIN_LEFT + PANEL_W + 100, MARGIN_TOP, "Peak memory", "MB", labels,
          {"GG Studio": [number(r, "gg_peak_bytes") / 1e6 for r in hidden],
           "SPIN (pan)": [number(r, "pan_total_mb") for r in hidden],
           "GG Studio, memories kept": kept_of("gg_peak_bytes", 1e6),
           "SPIN (pan), memories kept": kept_of("pan_total_mb")})
    legend_y = HEIGHT - 22
    for i, name in enumerate(COLORS):
        x = MARGIN_LEFT + (i % 2) * 230
        y = legend_y - 18 * (1 - i // 2)
        dash = ' stroke-dasharray="6,4"' if name in DASHED else ""
        out.append(f'<line x1="{x}" y1="{y}" x2="{x + 24}" y2="{y}" stroke="{COLORS[name]}" stroke-width="2"{dash}/>')
        out.append(f'<text x="{x + 30}" y="{y + 4}">{name}</text>')
    out.append(f'<text x="{MARGIN_LEFT + 480}" y="{legend_y - 14}" font-size="11">size: nested GRAFCETs × stored BOOLs</text>')
    out.append(f'<text x="{MARGIN_LEFT + 480}" y="{legend_y + 4}" font-size="11">(factory::verificationSeriesModel)</text>')
    out.append("</svg>")
    with open(sys.argv[2], "w", encoding="utf-8") as svg:
        svg.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
