#!/usr/bin/python3
"""Measures real pen strokes so that the stroke generator (stroke_gen.cpp) draws like people do.

Reads the $1 gesture logs (../shared/data/strokes/dollar1, never copied into the repository) and
writes stroke_measurements.hpp: the numbers the generator reads. Rerun it when the corpus changes:

    cd tests/support/gen && ./measure_strokes.py ../../../../shared/data/strokes/dollar1 \
        > stroke_measurements.hpp

Measured (all lengths in the logs' pixels, times in seconds):
  - sampling interval, stroke size (bounding-box diagonal) and mean pen speed per speed class;
  - wobble against size and speed: circles fitted by least squares, the RMS radial residual
    regressed on radius and mean speed (residual = a + b * radius + c * speed);
  - tremor: RMS distance of a point from the midpoint of its neighbours, minus the part the
    fitted circle's curvature explains;
  - closure gap of closed shapes (end-to-start distance / diagonal) and corner rounding of
    rectangles (distance from a bounding-box corner to the stroke / diagonal);
  - end hooks: the share of strokes whose last 8% of length turns more than 60 degrees from the
    direction before it, and that part's length / diagonal.
Debian's python3 with python3-numpy (scripts/setup.sh installs both).
"""
import glob
import math
import os
import re
import sys

import numpy as np

POINT = re.compile(r'<Point X="(-?[0-9.]+)" Y="(-?[0-9.]+)" T="(-?[0-9.]+)"')


def read(path):
    with open(path, encoding="utf-8-sig") as f:
        pts = [(float(x), float(y), float(t) / 1000.0) for x, y, t in POINT.findall(f.read())]
    return np.array(pts)


def length(p):
    return float(np.sum(np.hypot(np.diff(p[:, 0]), np.diff(p[:, 1]))))


def diagonal(p):
    return float(np.hypot(np.ptp(p[:, 0]), np.ptp(p[:, 1])))


def fit_circle(p):
    """Kasa's algebraic fit: centre and radius."""
    a = np.column_stack([2 * p[:, 0], 2 * p[:, 1], np.ones(len(p))])
    b = p[:, 0] ** 2 + p[:, 1] ** 2
    cx, cy, c = np.linalg.lstsq(a, b, rcond=None)[0]
    return cx, cy, math.sqrt(max(c + cx * cx + cy * cy, 1e-12))


def tremor(p, r):
    mid = 0.5 * (p[:-2, :2] + p[2:, :2])
    dev = np.hypot(*(p[1:-1, :2] - mid).T)
    step = np.mean(np.hypot(np.diff(p[:, 0]), np.diff(p[:, 1])))
    sagitta = step * step / (2 * r)  # what a perfect circle's curvature gives
    return max(float(np.sqrt(np.mean(dev ** 2))) - sagitta, 0.0)


def hook(p):
    """(has a hook, hook length / diagonal) at the stroke's end."""
    seg = np.hypot(np.diff(p[:, 0]), np.diff(p[:, 1]))
    cum = np.concatenate([[0], np.cumsum(seg)])
    total = cum[-1]
    if total <= 0:
        return False, 0.0
    k = int(np.searchsorted(cum, 0.92 * total))
    j = int(np.searchsorted(cum, 0.80 * total))
    if k >= len(p) - 1 or j >= k:
        return False, 0.0
    before = p[k, :2] - p[j, :2]
    after = p[-1, :2] - p[k, :2]
    n1, n2 = np.linalg.norm(before), np.linalg.norm(after)
    if n1 == 0 or n2 == 0:
        return False, 0.0
    turn = math.degrees(math.acos(max(-1.0, min(1.0, float(before @ after) / (n1 * n2)))))
    return turn > 60, float(n2) / max(diagonal(p), 1e-9)


def main(root):
    files = sorted(glob.glob(os.path.join(root, "s0[2-9]", "*", "*.xml")))
    if not files:
        sys.exit("no $1 gestures under " + root)
    dts, speeds, diags = [], {}, []
    wob_rows, wob_y, tremors, gaps, corners, hooks, hook_len = [], [], [], [], [], [], []
    for f in files:
        p = read(f)
        if len(p) < 8:
            continue
        kind = re.sub(r"[0-9]+\.xml$", "", os.path.basename(f))
        speed_class = os.path.basename(os.path.dirname(f))
        dur = p[-1, 2] - p[0, 2]
        dts.extend(np.diff(p[:, 2])[np.diff(p[:, 2]) > 0])
        if dur > 0:
            speeds.setdefault(speed_class, []).append(length(p) / dur)
        d = diagonal(p)
        diags.append(d)
        has_hook, hl = hook(p)
        hooks.append(has_hook)
        if has_hook:
            hook_len.append(hl)
        if kind in ("circle", "rectangle", "triangle"):
            gaps.append(np.hypot(*(p[-1, :2] - p[0, :2])) / d)
        if kind == "circle" and dur > 0:
            cx, cy, r = fit_circle(p)
            res = np.hypot(p[:, 0] - cx, p[:, 1] - cy) - r
            wob_rows.append([1.0, r, length(p) / dur])
            wob_y.append(float(np.sqrt(np.mean(res ** 2))))
            tremors.append(tremor(p, r))
        if kind == "rectangle":
            lo, hi = p[:, :2].min(0), p[:, :2].max(0)
            for c in ([lo[0], lo[1]], [lo[0], hi[1]], [hi[0], lo[1]], [hi[0], hi[1]]):
                corners.append(float(np.min(np.hypot(*(p[:, :2] - c).T))) / d)
    coef = np.linalg.lstsq(np.array(wob_rows), np.array(wob_y), rcond=None)[0]
    print_header(root, len(files), dts, speeds, diags, coef, tremors, gaps, corners, hooks,
                 hook_len)


def print_header(root, n, dts, speeds, diags, coef, tremors, gaps, corners, hooks, hook_len):
    out = [
        "#pragma once",
        "// Generated by tests/support/gen/measure_strokes.py from the $1 gesture logs",
        "// (../shared/data/strokes/dollar1, subjects s02-s06, %d files): measurements of real pen" % n,
        "// strokes that the stroke generator reads. Do not edit; rerun the script.",
        "namespace penshape::gen::measured {",
        "",
        "// Lengths in the logs' pixels, times in seconds.",
        "inline constexpr double kSampleInterval = %.5f; // median time between samples" % np.median(dts),
        "inline constexpr double kDiagonalMean = %.2f;     // stroke bounding-box diagonal" % np.mean(diags),
        "inline constexpr double kDiagonalSd = %.2f;" % np.std(diags),
    ]
    for name in ("slow", "medium", "fast"):
        v = speeds.get(name, [0.0])
        out.append("inline constexpr double kSpeed%s = %.1f; // mean pen speed, px/s" %
                   (name.capitalize(), np.mean(v)))
    out += [
        "// Circle wobble: RMS radial residual = kWobble0 + kWobblePerRadius * r + kWobblePerSpeed * v",
        "inline constexpr double kWobble0 = %.4f;" % coef[0],
        "inline constexpr double kWobblePerRadius = %.5f;" % coef[1],
        "inline constexpr double kWobblePerSpeed = %.6f;" % coef[2],
        "inline constexpr double kTremor = %.4f; // RMS point jitter beyond the curve, px" % np.mean(tremors),
        "// Closed shapes: end-to-start gap / diagonal (mean, sd); rectangle corner rounding / diagonal.",
        "inline constexpr double kClosureGapMean = %.4f;" % np.mean(gaps),
        "inline constexpr double kClosureGapSd = %.4f;" % np.std(gaps),
        "inline constexpr double kCornerRounding = %.4f;" % np.median(corners),
        "// End hooks: share of strokes with one, and its length / diagonal.",
        "inline constexpr double kHookShare = %.4f;" % np.mean(hooks),
        "inline constexpr double kHookLength = %.4f;" % (np.mean(hook_len) if hook_len else 0.0),
        "",
        "} // namespace penshape::gen::measured",
    ]
    print("\n".join(out))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "../../../../shared/data/strokes/dollar1")
