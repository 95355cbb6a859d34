#!/usr/bin/python3
"""Learns the writing/drawing model's weights (core/src/intent/intent_weights.hpp).

The model is a small neural network (one hidden layer of 8 tanh units, a logistic output) over
the per-stroke measures core computes
(penshape::intent_features; read here through `intent_bench --features PAGES`, so the features
have one definition, in C++). Pages come from scripts/intent_pages.py (real UNIPEN handwriting
and real shapes from the shared corpus, composed at run time; nothing of it is committed).
Lone handwriting items, lone shapes, and the writing and the shapes of mixed pages weigh the same
in total, with an L2 penalty; the seed is fixed, so the weights are reproducible.

Leave-one-writer-group-out: for each of the 5 UNIPEN contributors (abm, art, atu, syn, tos),
weights learned on the other four score its pages (its shapes are those of subjects hashed to
the same fold, unseen too). Printed per group, beside the figures of the all-data weights.

Usage:
  scripts/intent_learn.py [--pages DIR | --shared DIR] [--bench BIN]
                          [--write-header FILE] [--logo-scores FILE] [--hold-out N]
  --pages DIR          pages made by intent_pages.py (else composed into a temporary folder
                       from --shared, default ../shared/data)
  --bench BIN          intent_bench (default build/release/bench/intent_bench)
  --write-header FILE  write the all-data weights there (core/src/intent/intent_weights.hpp)
  --logo-scores FILE   write every stroke's leave-one-group-out P(writing): page, index, score
  --hold-out N         learn without group N and print its figures only
"""
import argparse
import os
import subprocess
import sys
import tempfile

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GROUPS = ["abm", "art", "atu", "syn", "tos"]
L2 = 1e-4
HIDDEN = 8
ITERATIONS = 3000
RATE = 0.01
SEED = 20261127
TIMING = ["timed", "speed", "pause"]  # left at their mean for an untimed stroke (core does)


def read_features(bench, pages):
    out = subprocess.run([bench, "--features", pages], check=True, capture_output=True,
                         text=True).stdout.splitlines()
    header = out[0].split("\t")
    rows = [line.split("\t") for line in out[1:]]
    names = header[5:]
    meta = [(r[0], int(r[1]), int(r[2]), int(r[3]), r[4]) for r in rows]
    x = np.array([[float(v) for v in r[5:]] for r in rows])
    return names, meta, x


def set_weights(y, sets):
    """Four parts weigh the same: lone handwriting items, lone shapes, and the writing and the
    shapes of mixed pages (so that rare cases, e.g. a lone character, are not drowned)."""
    w = np.zeros(len(y))
    for part in [(sets == "items") & (y == 1), (sets == "shapes") & (y == 0),
                 (sets == "mixed") & (y == 1), (sets == "mixed") & (y == 0)]:
        w[part] = 0.25 / max(1, part.sum())
    return w


def fit(x, y, sets):
    """One hidden layer of HIDDEN tanh units and a logistic output, on standardized features,
    by full-batch Adam on the weighted log-loss with an L2 penalty (fixed seed)."""
    mean, scale = x.mean(axis=0), x.std(axis=0)
    scale[scale < 1e-9] = 1.0
    z, sw = (x - mean) / scale, set_weights(y, sets)
    rng = np.random.default_rng(SEED)
    params = [rng.normal(0, 0.3, (z.shape[1], HIDDEN)), np.zeros(HIDDEN),
              rng.normal(0, 0.3, HIDDEN), np.zeros(1)]
    params[0][x.std(axis=0) < 1e-9] = 0.0  # a constant feature (e.g. "timed") weighs nothing
    m1 = [np.zeros_like(p) for p in params]
    m2 = [np.zeros_like(p) for p in params]
    for it in range(1, ITERATIONS + 1):
        h = np.tanh(z @ params[0] + params[1])
        d = sw * (1 / (1 + np.exp(-(h @ params[2] + params[3][0]))) - y)
        dh = np.outer(d, params[2]) * (1 - h * h)
        grads = [z.T @ dh + L2 * params[0], dh.sum(axis=0), h.T @ d + L2 * params[2],
                 np.array([d.sum()])]
        for k, g in enumerate(grads):
            m1[k] = 0.9 * m1[k] + 0.1 * g
            m2[k] = 0.999 * m2[k] + 0.001 * g * g
            params[k] -= RATE * (m1[k] / (1 - 0.9**it)) / (np.sqrt(m2[k] / (1 - 0.999**it)) + 1e-8)
    return mean, scale, params


def score(model, x):
    mean, scale, (w1, b1, w2, b2) = model
    h = np.tanh(((x - mean) / scale) @ w1 + b1)
    return 1 / (1 + np.exp(-(h @ w2 + b2[0])))


def figures(label, y, p, kinds):
    """Writing strokes decided drawing, and shape strokes decided writing."""
    wr, dr = y == 1, y == 0
    miss_w = 100 * np.mean(p[wr] < 0.5) if wr.any() else float("nan")
    miss_d = 100 * np.mean(p[dr] >= 0.5) if dr.any() else float("nan")
    per_kind = "  ".join(f"{k} {100 * np.mean(p[wr & (kinds == k)] < 0.5):.1f}%"
                         for k in ("text", "words", "characters") if (wr & (kinds == k)).any())
    print(f"  {label:<22} writing->drawing {miss_w:5.2f}% of {wr.sum():5d}  "
          f"shape->writing {miss_d:5.2f}% of {dr.sum():5d}   ({per_kind})")


def write_header(path, names, model):
    mean, scale, (w1, b1, w2, b2) = model

    def arr(v):
        return "{" + ", ".join(f"{x:.9g}" for x in v) + "}"
    rows = ",\n    ".join(arr(w1[:, j]) for j in range(HIDDEN))
    with open(path, "w", encoding="utf-8") as f:
        f.write("#pragma once\n"
                "// Generated by scripts/intent_learn.py --write-header: the writing/drawing\n"
                "// model's weights (standardized intent_features(), one hidden layer of tanh\n"
                "// units, a logistic output), learned on pages composed by\n"
                "// scripts/intent_pages.py from the shared corpus. Do not edit by hand.\n"
                "// Features: " + ", ".join(names) + ".\n"
                "#include <array>\n#include <cstddef>\n\n#include \"penshape/core/intent.hpp\"\n\n"
                "namespace penshape::intent::weights {\n"
                f"inline constexpr std::size_t kHidden = {HIDDEN};\n"
                "using Row = std::array<double, kIntentFeatureCount>;\n"
                f"inline constexpr Row kMean{arr(mean)};\n"
                f"inline constexpr Row kScale{arr(scale)};\n"
                f"inline constexpr std::array<Row, kHidden> kHiddenWeight{{{{\n    {rows}}}}};\n"
                f"inline constexpr std::array<double, kHidden> kHiddenBias{arr(b1)};\n"
                f"inline constexpr std::array<double, kHidden> kOutputWeight{arr(w2)};\n"
                f"inline constexpr double kOutputBias = {b2[0]:.9g};\n"
                "} // namespace penshape::intent::weights\n")
    subprocess.run(["clang-format", "-i", path], check=False)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--pages")
    ap.add_argument("--shared", default=os.path.join(ROOT, "..", "shared", "data"))
    ap.add_argument("--bench", default=os.path.join(ROOT, "build/release/bench/intent_bench"))
    ap.add_argument("--write-header")
    ap.add_argument("--logo-scores")
    ap.add_argument("--hold-out", type=int)
    args = ap.parse_args()
    tmp = None
    if not args.pages:
        tmp = tempfile.TemporaryDirectory()
        args.pages = tmp.name
        subprocess.run([sys.executable, os.path.join(ROOT, "scripts/intent_pages.py"),
                        args.shared, args.pages], check=True)
    names, meta, x = read_features(args.bench, args.pages)
    y = np.array([m[2] for m in meta], dtype=float)
    folds = np.array([m[3] for m in meta])
    kinds = np.array([m[4] for m in meta])
    sets = np.array([m[0].split("/")[0] for m in meta])
    mixed = sets == "mixed"
    held = [args.hold_out] if args.hold_out is not None else range(len(GROUPS))
    logo, untimed = np.full(len(y), np.nan), np.full(len(y), np.nan)
    timing = [names.index(n) for n in TIMING]
    print("leave-one-writer-group-out (weights learned on the other 4 groups):")
    for g in held:
        model = fit(x[folds != g], y[folds != g], sets[folds != g])
        sel = folds == g
        logo[sel] = score(model, x[sel])
        # As core scores a stroke without times: its timing features at their mean.
        xu = x[sel].copy()
        xu[:, timing] = model[0][timing]
        untimed[sel] = score(model, xu)
        figures(f"{GROUPS[g]}, all pages", y[sel], logo[sel], kinds[sel])
        figures(f"{GROUPS[g]}, mixed pages", y[sel & mixed], logo[sel & mixed], kinds[sel & mixed])
    sel = ~np.isnan(logo)
    figures("held-out, all groups", y[sel], logo[sel], kinds[sel])
    figures("held-out, times removed", y[sel], untimed[sel], kinds[sel])
    if args.hold_out is None:
        model = fit(x, y, sets)
        print("all data (the committed weights, scored on the data they learned from):")
        figures("all pages", y, score(model, x), kinds)
        figures("mixed pages", y[mixed], score(model, x[mixed]), kinds[mixed])
        if args.write_header:
            write_header(args.write_header, names, model)
    if args.logo_scores:
        with open(args.logo_scores, "w", encoding="utf-8") as f:
            for (page, index, *_), p in zip(meta, logo):
                if not np.isnan(p):
                    f.write(f"{page}\t{index}\t{p:.6f}\n")


if __name__ == "__main__":
    main()
