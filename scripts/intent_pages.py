#!/usr/bin/python3
"""Composes the pages the writing/drawing decision (core/src/intent/) learns and is measured on.

Reads the shared corpus at run time (nothing of it is committed):
  strokes/handwriting-unipen/pages/*.jsonl   real handwriting, millimetres, y down, t in s
  strokes/dollar1/sNN/<speed>/*.xml          $1 shapes (pixels, ms)
  strokes/gestures/<set>-<class>/*.jsonl     MMG, MMG+ and LowVision shapes (pixels, s)
and writes JSON-lines pages (the format `penshape recognize` reads) into OUT:
  items/   every handwriting item alone, as it is (a page of text, a word, a character)
  shapes/  shapes alone, scaled to 20-60 mm
  mixed/   note pages: lines of one writer group's writing with shapes of 20-60 mm between them
Every stroke carries "intent" (writing|drawing), "kind" (text|words|characters|shape), "fold"
(0-4: the UNIPEN contributor of the writing, a hash of the subject for shapes: leave-one-group-
out keeps both unseen) and "label" (the shape's expected class, "freeform" for writing).

Usage: scripts/intent_pages.py SHARED_DATA_DIR OUT [--seed N] [--mixed-per-fold N]
"""
import argparse
import json
import os
import random
import re
import zlib

CONTRIBUTORS = ["abm", "art", "atu", "syn", "tos"]  # fold = index (the UNIPEN writer groups)
KINDS = {"8": "text", "7": "words", "1a": "characters", "1b": "characters", "1c": "characters"}
# Shape classes drawn between lines, with the class the recognizer should name ("freeform":
# a drawing with no clean class). Letters and glyphs of the gesture sets are left out.
DOLLAR1 = {"arrow": "arrow", "circle": "circle", "rectangle": "rectangle", "triangle": "triangle",
           "caret": "freeform", "check": "freeform", "v": "freeform", "x": "freeform",
           "star": "freeform", "delete_mark": "freeform", "pigtail": "freeform",
           "left_sq_bracket": "freeform", "right_sq_bracket": "freeform",
           "left_curly_brace": "freeform", "right_curly_brace": "freeform"}
# LowVision's "arrow_right" is the touch gesture ">" (a chevron with no shaft, as plotted): the
# same glyph as MMG's "arrowhead", so labelled as that one is, not as an arrow.
GESTURES = {"lowvision-circle": "circle", "lowvision-square": "rectangle",
            "lowvision-arrow_right": "freeform", "lowvision-star": "freeform",
            "lowvision-spiral": "freeform", "mmg-line": "segment", "mmgplus-line": "segment",
            "mmg-arrowhead": "freeform", "mmg-five_point_star": "freeform",
            "mmg-six_point_star": "freeform", "mmg-X": "freeform", "mmg-asterisk": "freeform",
            "mmg-null": "freeform", "mmgplus-five_point_star": "freeform",
            "mmgplus-arrowhead": "freeform", "mmgplus-null": "freeform"}
SHAPE_MM = (20.0, 60.0)  # the size (larger side) shapes are drawn at


def fold_of_subject(subject):
    return zlib.crc32(subject.encode()) % 5


def read_jsonl(path):
    with open(path, encoding="utf-8") as f:
        return [json.loads(line) for line in f if line.strip()]


def read_dollar1(path):
    text = open(path, encoding="utf-8-sig").read()
    pts = [(float(x), float(y), float(t) / 1000.0)
           for x, y, t in re.findall(r'X="([-\d.]+)" Y="([-\d.]+)" T="([-\d.]+)"', text)]
    t0 = pts[0][2]
    return [[[x, y, t - t0] for x, y, t in pts]]


def writing_items(shared):
    folder = os.path.join(shared, "strokes/handwriting-unipen/pages")
    items = []
    for name in sorted(os.listdir(folder)):
        cat, contributor = name.split("-")[1:3]
        strokes = [s["points"] for s in read_jsonl(os.path.join(folder, name))]
        items.append({"name": name, "kind": KINDS[cat], "fold": CONTRIBUTORS.index(contributor),
                      "strokes": strokes})
    return items


def shape_items(shared):
    shapes = []
    root = os.path.join(shared, "strokes/dollar1")
    for subject in sorted(os.listdir(root)):
        for speed in ("slow", "medium", "fast"):
            folder = os.path.join(root, subject, speed)
            if not os.path.isdir(folder):
                continue
            for name in sorted(os.listdir(folder)):
                match = re.fullmatch(r"(.*?)\d+\.xml", name)
                cls = match.group(1) if match else None
                if cls in DOLLAR1:
                    shapes.append({"name": f"dollar1/{subject}/{speed}/{name}",
                                   "label": DOLLAR1[cls], "fold": fold_of_subject("d" + subject),
                                   "strokes": read_dollar1(os.path.join(folder, name))})
    root = os.path.join(shared, "strokes/gestures")
    for folder, label in sorted(GESTURES.items()):
        path = os.path.join(root, folder)
        if not os.path.isdir(path):
            continue
        for name in sorted(os.listdir(path)):
            subject = "__".join(name.split("__")[:3])
            strokes = [s["points"] for s in read_jsonl(os.path.join(path, name))]
            shapes.append({"name": f"gestures/{folder}/{name}", "label": label,
                           "fold": fold_of_subject(subject), "strokes": strokes})
    return shapes


def bbox(strokes):
    xs = [p[0] for s in strokes for p in s]
    ys = [p[1] for s in strokes for p in s]
    return min(xs), min(ys), max(xs), max(ys)


def placed(strokes, x, y, t, scale=1.0):
    """The strokes scaled, their box's top-left corner moved to (x, y), times shifted to t."""
    x0, y0, _, _ = bbox(strokes)
    t0 = strokes[0][0][2] if len(strokes[0][0]) > 2 else 0.0
    out = []
    for s in strokes:
        out.append([[round(x + (p[0] - x0) * scale, 4), round(y + (p[1] - y0) * scale, 4),
                     round(t + (p[2] - t0 if len(p) > 2 else 0.0), 4)] for p in s])
    return out


def end_time(strokes):
    return strokes[-1][-1][2]


def line(points, name, intent, kind, fold, label):
    return json.dumps({"points": points, "name": name, "label": label, "intent": intent,
                       "kind": kind, "fold": fold}, separators=(",", ":"))


def write_page(path, rows):
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(rows) + "\n")


def scaled_shape(rng, shape):
    x0, y0, x1, y1 = bbox(shape["strokes"])
    size = max(x1 - x0, y1 - y0, 1e-9)
    return rng.uniform(*SHAPE_MM) / size


def writing_line(rng, pool, width):
    """Items of one writer group side by side until the line is full (a text item fills it)."""
    chosen, used = [], 0.0
    while True:
        item = rng.choice(pool)
        x0, _, x1, _ = bbox(item["strokes"])
        w = x1 - x0
        if chosen and used + w > width:
            return chosen
        chosen.append(item)
        used += w + rng.uniform(2.0, 5.0)
        if item["kind"] == "text":
            return chosen


def mixed_page(rng, writing, shapes, fold, index):
    """Lines of writing (one writer group) with 20-60 mm shapes drawn between them."""
    rows, y, t = [], 20.0, 0.0
    pool = [w for w in writing if w["fold"] == fold]
    shape_pool = [s for s in shapes if s["fold"] == fold]
    for _ in range(rng.randint(5, 9)):
        x, line_h = 15.0, 0.0
        for item in writing_line(rng, pool, 180.0):
            x0, y0, x1, y1 = bbox(item["strokes"])
            strokes = placed(item["strokes"], x, y + rng.uniform(-0.5, 0.5), t)
            for k, s in enumerate(strokes):
                rows.append(line(s, f"{item['name']}-{k}", "writing", item["kind"], fold,
                                 "freeform"))
            x += x1 - x0 + rng.uniform(2.0, 5.0)
            line_h = max(line_h, y1 - y0)
            t = end_time(strokes) + rng.uniform(0.2, 0.8)
        y += line_h + rng.uniform(3.0, 6.0)
        if rng.random() < 0.6:
            x, tallest = 15.0 + rng.uniform(0.0, 60.0), 0.0
            for _ in range(rng.randint(1, 2)):
                shape = rng.choice(shape_pool)
                scale = scaled_shape(rng, shape)
                x0, y0, x1, y1 = bbox(shape["strokes"])
                strokes = placed(shape["strokes"], x, y + rng.uniform(2.0, 5.0), t, scale)
                for k, s in enumerate(strokes):
                    rows.append(line(s, f"{shape['name']}-{k}", "drawing", "shape", fold,
                                     shape["label"]))
                x += (x1 - x0) * scale + rng.uniform(8.0, 30.0)
                tallest = max(tallest, (y1 - y0) * scale)
                t = end_time(strokes) + rng.uniform(0.5, 2.0)
            y += tallest + rng.uniform(6.0, 10.0)
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("shared")
    parser.add_argument("out")
    parser.add_argument("--seed", type=int, default=20261127)
    parser.add_argument("--mixed-per-fold", type=int, default=12)
    parser.add_argument("--shapes-alone", type=int, default=400)
    args = parser.parse_args()
    rng = random.Random(args.seed)
    writing, shapes = writing_items(args.shared), shape_items(args.shared)
    for sub in ("items", "shapes", "mixed"):
        os.makedirs(os.path.join(args.out, sub), exist_ok=True)
    for item in writing:
        rows = [line(s, f"{item['name']}-{k}", "writing", item["kind"], item["fold"], "freeform")
                for k, s in enumerate(item["strokes"])]
        write_page(os.path.join(args.out, "items", item["name"]), rows)
    for i, shape in enumerate(rng.sample(shapes, min(args.shapes_alone, len(shapes)))):
        strokes = placed(shape["strokes"], 20.0, 20.0, 0.0, scaled_shape(rng, shape))
        rows = [line(s, f"{shape['name']}-{k}", "drawing", "shape", shape["fold"], shape["label"])
                for k, s in enumerate(strokes)]
        write_page(os.path.join(args.out, "shapes", f"shape-{i:04d}.jsonl"), rows)
    for fold in range(5):
        for i in range(args.mixed_per_fold):
            rows = mixed_page(rng, writing, shapes, fold, i)
            write_page(os.path.join(args.out, "mixed", f"mixed-{fold}-{i:02d}.jsonl"), rows)


if __name__ == "__main__":
    main()
