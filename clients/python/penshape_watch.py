#!/usr/bin/python3
"""Prints the shapes penshaped recognizes, as they are drawn: a minimal Python client.

Run it with Debian's Python (it has python3-grpcio) and the stubs the build generates from
proto/penshape/v1/*.proto:

    PYTHONPATH=build/release/clients/python/gen /usr/bin/python3 clients/python/penshape_watch.py

Options: --socket PATH or --address ADDR (default: unix:$XDG_RUNTIME_DIR/penshape.sock),
--count N (stop after N shapes), --json (one JSON object per shape). With hold to snap
(penshaped's snap_trigger hold or both) it also prints each hold snap ("held, pen down"), the
updates as the shape follows the pen ("follows the pen") and the final shape ("released").
Exit codes: 0 ok (also on Ctrl-C), 2 bad usage, 1 daemon not running or failed.
"""
import argparse
import json
import os
import signal
import sys

try:
    import grpc
    from penshape.v1 import live_pb2, live_pb2_grpc, shape_pb2
except ImportError as error:  # explain the two usual causes instead of a traceback
    sys.stderr.write(
        "penshape_watch: %s\n  use /usr/bin/python3 (Debian's python3-grpcio) and put the "
        "generated stubs on PYTHONPATH (build/<preset>/clients/python/gen)\n" % error)
    sys.exit(1)


def default_address():
    runtime = os.environ.get("XDG_RUNTIME_DIR") or "/tmp"
    return "unix:" + os.path.join(runtime, "penshape.sock")


def shape_kind(shape):
    name = shape_pb2.ShapeKind.Name(shape.kind)
    return name[len("SHAPE_KIND_"):].lower()


def shape_record(device_id, stroke_id, shape):
    """The shape as plain data: kind, confidence, geometry in mm, certified Hausdorff bound."""
    record = {"device_id": device_id, "stroke_id": stroke_id, "kind": shape_kind(shape),
              "confidence": shape.confidence}
    params = shape.WhichOneof("params")
    if params == "vertices":
        record["vertices"] = [[p.x, p.y] for p in shape.vertices.vertices]
    elif params == "circle":
        record["center"] = [shape.circle.center.x, shape.circle.center.y]
        record["radius"] = shape.circle.radius
    elif params == "ellipse":
        e = shape.ellipse
        record.update(center=[e.center.x, e.center.y], semi_major=e.semi_major,
                      semi_minor=e.semi_minor, rotation_rad=e.rotation_rad)
    elif params == "arc":
        a = shape.arc
        record.update(center=[a.center.x, a.center.y], radius=a.radius,
                      start_rad=a.start_rad, sweep_rad=a.sweep_rad)
    if shape.HasField("certificate"):
        record["hausdorff_bound_mm"] = shape.certificate.hausdorff_bound.approx
        record["tolerance_mm"] = shape.certificate.tolerance.approx
    if shape.intent != shape_pb2.INTENT_UNSPECIFIED:  # writing is left as drawn
        record["intent"] = shape_pb2.Intent.Name(shape.intent)[len("INTENT_"):].lower()
        record["writing_score"] = shape.writing_score
    return record


def add_grouping(record, recognized):
    """What a grouped answer replaces: an app removes the ink of the replaced strokes and the
    superseded shapes (an upgrade, e.g. three sides and then the rectangle), then draws this one.
    """
    record["shape_id"] = recognized.shape_id
    record["replaced_stroke_ids"] = list(recognized.replaced_stroke_ids)
    record["supersedes_shape_ids"] = list(recognized.supersedes_shape_ids)
    record["tidy"] = list(recognized.tidy)


TRIGGERS = {live_pb2.SHAPE_TRIGGER_HOLD: "hold", live_pb2.SHAPE_TRIGGER_FOLLOW: "follow",
            live_pb2.SHAPE_TRIGGER_RELEASE: "release"}


def add_hold(record, recognized):
    """Hold to snap: "hold" while the pen is still down, "follow" as the shape follows the pen
    after the hold, "release" for the final shape at pen-up ("pen_up": a snap without a hold)."""
    record["trigger"] = TRIGGERS.get(recognized.trigger, "pen_up")
    if recognized.HasField("hold"):
        record["hold_point"] = [recognized.hold.hold_point.x, recognized.hold.hold_point.y]
        record["pen_point"] = [recognized.hold.pen_point.x, recognized.hold.pen_point.y]
        record["adjusted"] = recognized.hold.adjusted


def describe(record):
    text = "stroke %d on %s: %s" % (record["stroke_id"], record["device_id"], record["kind"])
    trigger = record.get("trigger", "pen_up")
    if trigger == "hold":
        text = "held, pen down: " + text
    elif trigger == "follow":
        text = "follows the pen: " + text
    elif trigger == "release":
        text = ("released, adjusted: " if record.get("adjusted") else "released: ") + text
    if record.get("intent") == "writing":
        text += " (writing, left as drawn unless snap_writing)"
    if "vertices" in record:
        text += " " + " ".join("(%.2f, %.2f)" % tuple(v) for v in record["vertices"])
    if "radius" in record:
        text += " r=%.2f mm at (%.2f, %.2f)" % (record["radius"], *record["center"])
    if "hausdorff_bound_mm" in record:
        text += ", within %.3g mm of the ink (tolerance %.3g mm)" % (
            record["hausdorff_bound_mm"], record["tolerance_mm"])
    if len(record.get("replaced_stroke_ids", [])) > 1:
        text += "; replaces strokes " + " ".join(map(str, record["replaced_stroke_ids"]))
    if record.get("supersedes_shape_ids"):
        text += "; supersedes shapes " + " ".join(map(str, record["supersedes_shape_ids"]))
    return text


def main():
    parser = argparse.ArgumentParser(description="Print the shapes penshaped recognizes.")
    where = parser.add_mutually_exclusive_group()
    where.add_argument("--socket", help="the daemon's unix socket")
    where.add_argument("--address", help="gRPC address: unix:PATH, unix-abstract:NAME, HOST:PORT")
    parser.add_argument("--count", type=int, default=0, help="stop after this many shapes")
    parser.add_argument("--json", action="store_true", help="one JSON object per shape")
    args = parser.parse_args()  # exits with 2 on bad usage
    if args.count < 0:
        parser.error("--count must be >= 0")
    address = ("unix:" + args.socket) if args.socket else (args.address or default_address())

    channel = grpc.insecure_channel(address)
    try:
        grpc.channel_ready_future(channel).result(timeout=3)
    except grpc.FutureTimeoutError:
        sys.stderr.write("penshape_watch: penshaped is not running at %s\n" % address)
        return 1
    stub = live_pb2_grpc.LiveStub(channel)
    call = stub.Subscribe(live_pb2.SubscribeRequest())
    signal.signal(signal.SIGINT, lambda *_: call.cancel())
    signal.signal(signal.SIGTERM, lambda *_: call.cancel())
    call.initial_metadata()  # the daemon sends its headers once we are subscribed
    sys.stderr.write("penshape_watch: subscribed to %s\n" % address)
    sys.stderr.flush()
    shapes = 0
    try:
        for event in call:
            kind = event.WhichOneof("kind")
            if kind == "stroke_finished" and event.stroke_finished.not_analysed:
                print("stroke %d on %s: not analysed (%s)" % (
                    event.stroke_finished.stroke.id, event.device_id,
                    event.stroke_finished.not_analysed), flush=True)
            elif kind == "shape":
                record = shape_record(event.device_id, event.shape.stroke_id, event.shape.shape)
                add_grouping(record, event.shape)
                add_hold(record, event.shape)
                print(json.dumps(record) if args.json else describe(record), flush=True)
                shapes += 1
                if args.count and shapes >= args.count:
                    call.cancel()
                    break
            elif kind == "dropped":
                sys.stderr.write("penshape_watch: lost %d events\n" % event.dropped.count)
    except grpc.RpcError as error:
        if error.code() == grpc.StatusCode.CANCELLED:
            return 0
        sys.stderr.write("penshape_watch: %s: %s\n" % (error.code().name, error.details()))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
