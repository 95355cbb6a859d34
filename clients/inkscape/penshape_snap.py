#!/usr/bin/env python3
"""Inkscape extension: snap the selected strokes (or the current layer's) to clean shapes.

Inkscape runs this script with the drawing and the selection (--id=...); it saves the drawing,
runs `penshape snap` on it (the CLI uses penshaped when it runs, else the recognizer in-process)
and hands the snapped drawing back to Inkscape.
"""
import os
import shutil
import subprocess
import tempfile

import inkex


def find_cli():
    """The penshape command: $PENSHAPE_CLI, else PATH, else ~/.local/bin."""
    candidates = [os.environ.get("PENSHAPE_CLI"), shutil.which("penshape"),
                  os.path.expanduser("~/.local/bin/penshape")]
    for path in candidates:
        if path and os.path.isfile(path) and os.access(path, os.X_OK):
            return path
    return None


def daemon_socket():
    runtime = os.environ.get("XDG_RUNTIME_DIR") or "/tmp"
    return os.path.join(runtime, "penshape.sock")


class PenshapeSnap(inkex.EffectExtension):
    """Extensions > penshape > Snap shapes."""

    def add_arguments(self, pars):
        pars.add_argument("--tab", default="options")
        pars.add_argument("--pen_radius", type=float, default=0.0)
        pars.add_argument("--tolerance", type=float, default=0.0)
        pars.add_argument("--grouping", type=inkex.Boolean, default=True)
        pars.add_argument("--snap_writing", type=inkex.Boolean, default=False)

    def scope_args(self):
        ids = [i for i in self.svg.selection.ids if i]
        if ids:
            return ["--ids", ",".join(ids)]
        layer = self.svg.get_current_layer()
        if layer is not self.svg and layer.get("id"):
            return ["--layer", layer.get("id")]
        return []

    def effect(self):
        cli = find_cli()
        if cli is None:
            running = os.path.exists(daemon_socket())
            raise inkex.AbortExtension(
                "Snap shapes needs the penshape command, which was not found "
                "($PENSHAPE_CLI, PATH, ~/.local/bin). "
                + ("penshaped is running at %s, but the extension talks to it through the CLI. "
                   % daemon_socket() if running else
                   "penshaped is not running either (no %s). " % daemon_socket())
                + "Install penshape (cmake --install, or the Debian package) and try again.")
        args = []
        if self.options.pen_radius > 0:
            args += ["--pen-radius", repr(self.options.pen_radius)]
        if self.options.tolerance > 0:
            args += ["--tolerance", repr(self.options.tolerance)]
        if not self.options.grouping:
            args.append("--no-group")
        if self.options.snap_writing:
            args.append("--snap-writing")
        with tempfile.TemporaryDirectory(prefix="penshape-snap-") as tmp:
            src, dst = os.path.join(tmp, "in.svg"), os.path.join(tmp, "out.svg")
            self.document.write(src)
            run = subprocess.run([cli, "snap"] + args + self.scope_args() + [src, dst],
                                 capture_output=True, text=True, check=False)
            if run.returncode != 0:
                raise inkex.AbortExtension("penshape snap failed (exit %d): %s" % (
                    run.returncode, run.stderr.strip().replace(src + ": ", "")))
            self.document = inkex.load_svg(dst)
            self.svg = self.document.getroot()
        # stderr: warnings (elements left as drawn), maybe a progress bar, the summary last.
        lines = run.stderr.strip().splitlines()
        warnings = [line.split("warning: ", 1)[1] for line in lines if "warning: " in line]
        if warnings:
            inkex.errormsg("penshape: left as drawn:\n" + "\n".join(warnings))
        if not run.stdout.strip():
            inkex.errormsg("penshape: no stroke was certified as a shape ("
                           + (lines[-1].split(": ", 1)[-1] if lines else "") + ")")


if __name__ == "__main__":
    PenshapeSnap().run()
