// `penshape recognize` options.
#include "recognize_options.hpp"

#include "args.hpp"

namespace penshape::cli {

const char* const kRecognizeHelp =
    "usage: penshape recognize [--pen-radius R] [--tolerance E] [--ink [--pressure]] [--json]\n"
    "                          [--labels] [--no-group] [--snap-writing] [--svg-dir DIR] "
    "FILE|DIR...\n"
    "\n"
    "Names the shape each stroke, or each group of strokes, was meant to be (segment,\n"
    "polyline, triangle, quadrilateral, rectangle, square, diamond, regular_polygon, polygon,\n"
    "circle, ellipse, arc, arrow, double_arrow) and snaps only when the clean shape's ink is "
    "certified\n"
    "within Hausdorff distance E of the ink of the strokes; otherwise `freeform`. The snapped\n"
    "shape is then tidied (axis, right angles, equal sides, circle, parallel, connection) where\n"
    "the tidier shape is still certified.\n"
    "\n"
    "Input: $1 gesture logs (.xml: <Gesture Name=...><Point X= Y= T=/>...</Gesture>), one\n"
    "stroke each, and JSON lines (.jsonl/.ndjson, one stroke per line, in drawing order:\n"
    "{\"points\":[[x,y,t],...],\"name\":\"...\",\"label\":\"...\"}, t in seconds and optional,\n"
    "increasing along a stroke; a fourth number is the pen pressure in [0, 1], for every point\n"
    "or none). The strokes of one JSON-lines file are grouped: a stroke is recognized together\n"
    "with recent strokes it touches (at most 4 strokes, pauses of at most 2 s) when their union\n"
    "certifies as one shape (a rectangle drawn side by side, an arrow's shaft and head; a\n"
    "shaft stroke may stop short of its head's tip: the arrow is then two pieces).\n"
    "Directories are searched recursively.\n"
    "\n"
    "Writing is not a shape: every stroke is first decided writing or drawing, the file's\n"
    "strokes being the page (size against the page's writing height, neighbours on a text line,\n"
    "turning, speed; coordinates taken as millimetres). Writing strokes are never snapped nor\n"
    "grouped: each is a `freeform` answer with intent \"writing\".\n"
    "\n"
    "  --pen-radius R  pen radius in the file's unit (default: 2.5% of each drawing's size)\n"
    "  --tolerance E   Hausdorff tolerance (default: it follows the drawing, not the pen:\n"
    "                  min(0.125 S + R, 0.135 S), S the diagonal of the stroke's or group's\n"
    "                  bounding box; fractions derived from real strokes: recognize.hpp)\n"
    "  --ink           certify single strokes on the inks: build each stroke's ink polygon with\n"
    "                  the pen radius and certify the snap against it (certificate_method\n"
    "                  \"ink\"; default: \"path\", the pen paths, exact for one pen radius);\n"
    "                  groups and tidied shapes are certified on the union of the paths\n"
    "  --pressure      with --ink: the ink's radius follows each point's pressure p,\n"
    "                  R (0.25 + 0.75 p); the clean shape is drawn with the stroke's median\n"
    "                  radius. Needs pressure in the file (JSON lines; $1 XML has none)\n"
    "  --no-group      recognize every stroke alone\n"
    "  --snap-writing  recognize writing strokes too (the filter off: a page of drawings whose\n"
    "                  small strokes are shapes, e.g. a diagram of tiny boxes)\n"
    "  --json          one object per answer: file, line (its first stroke), lines (1-based\n"
    "                  line numbers of every stroke it covers), name, class, intent "
    "(writing|drawing),\n"
    "                  writing_score (mean P(writing) of its strokes), confidence, params,\n"
    "                  tidy, alternatives (class, certified, bound, rms, corners: its vertex\n"
    "                  count, rejected: why it is no snap), certified, certificate,\n"
    "                  certificate_method, seconds\n"
    "                  (and label with --labels); with --labels a final {\"summary\": ...}.\n"
    "                  An arrow's params: vertices (tail, tip, barb ends), head_angle,\n"
    "                  shaft_bulge, shaft_bends, and shaft_end when its shaft stops short of\n"
    "                  the tip (the shape is then the shaft tail .. shaft_end and the head)\n"
    "  --labels        expected class from the gesture name (triangle03 -> triangle, circle ->\n"
    "                  circle, rectangle -> rectangle, arrow -> arrow, others -> freeform) or the\n"
    "                  JSON \"label\" of a group's first stroke; prints a confusion table.\n"
    "                  Accepted as correct: the label itself, and circle/ellipse,\n"
    "                  rectangle/square/quadrilateral, diamond/square.\n"
    "  --svg-dir DIR   one picture per answer: the samples, their ink and the snapped shape\n"
    "                  with its tolerance band (DIR/<file stem>-<line>.svg)\n"
    "\n"
    "Exit codes: 0 ok, 2 bad input (message names file and line), 1 internal failure.";

RecognizeOptions parse_recognize_options(std::span<const std::string_view> args) {
  const ParsedArgs parsed(args, {.flags = {"--json", "--labels", "--ink", "--pressure",
                                           "--no-group", "--snap-writing", "--help"},
                                 .options = {"--pen-radius", "--tolerance", "--svg-dir"}});
  RecognizeOptions o;
  o.help = parsed.flag("--help");
  if (o.help) return o;
  if (const auto r = parsed.number("--pen-radius")) {
    if (!(*r > 0)) throw UsageError("--pen-radius must be positive");
    o.recognizer.pen_radius = *r;
  }
  if (const auto e = parsed.number("--tolerance")) {
    if (!(*e > 0)) throw UsageError("--tolerance must be positive");
    o.recognizer.tolerance = *e;
  }
  o.inputs = parsed.positionals();
  if (o.inputs.empty()) throw UsageError("no FILE or DIR given");
  o.on_ink = parsed.flag("--ink");
  o.pressure = parsed.flag("--pressure");
  if (o.pressure && !o.on_ink) throw UsageError("--pressure needs --ink");
  o.json = parsed.flag("--json");
  o.labels = parsed.flag("--labels");
  o.grouping.enabled = !parsed.flag("--no-group");
  o.snap_writing = parsed.flag("--snap-writing");
  o.svg_dir = parsed.value("--svg-dir");
  return o;
}

} // namespace penshape::cli
