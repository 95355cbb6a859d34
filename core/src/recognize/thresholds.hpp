#pragma once
// Every threshold of the recognizer, each with the one-line reason it has this value. The rules
// that read them are in the stage folders (README.md); tolerances in epsilons are relative to the
// shape's tolerance, sizes relative to the drawing's size. Most follow from geometry; the few
// picked on real strokes (kPolygonFraction, kDiamondSkew, kMinCornerTurnShare, kMaxBacktrack) say
// on which strokes, and what the values around them gave.
#include <cstddef>
#include <numbers>

namespace penshape::recognize_detail {

inline constexpr double kDegree = std::numbers::pi / 180.0;

// --- fitting/ ------------------------------------------------------------------------------

// Coordinates beyond this are refused: far past any tablet or page, and squares stay finite.
inline constexpr double kMaxAbsCoordinate = 1e9;
// Resampled points the fitters use: enough for 8 corners with 6 points a side, cheap to refit.
inline constexpr std::size_t kFitPoints = 48;
// Certified thinning works on windows of this many points, so its worst case is linear.
inline constexpr std::size_t kThinWindow = 128;
// A closed polygon class has kMinPolygonCorners..kMaxPolygonCorners corners (3 and 4 have their
// own classes; beyond 8 a hand-drawn outline is a curve).
inline constexpr std::size_t kMinPolygonCorners = 5;
inline constexpr std::size_t kMaxPolygonCorners = 8;
// A curved arrow shaft is certified as this many chords: each strays from the arc by < 0.2%.
inline constexpr std::size_t kShaftChords = 12;
// A bent arrow shaft has at most this many bends (more is a scribble, not a shaft).
inline constexpr std::size_t kMaxShaftBends = 2;

// The minimax refinement keeps a trial only when it gains more than this share of the stroke's
// size: far below any tolerance (epsilon is about a tenth of the size), far above the rounding of
// distances on a drawing up to 10^6 sizes from the origin, so that ties between trials (a step
// that leaves the farthest point where it is) do not depend on the drawing's origin. Measured
// (recognize_bench --invariance, 2655 real strokes): answers changed by a move of 10^6 0.3 ->
// 0.1%, by a scale of 0.01 / 1000 0.3 / 0.4 -> 0.2 / 0.1%; --classes: no class lower; the size x
// pen cells (--accuracy-only) move by one stroke either way (+-0.2 points).
inline constexpr double kLeastRefineGain = 1e-8;

// --- certify/ ------------------------------------------------------------------------------

// A path certificate samples a clean shape with at most this many points (bounded time).
inline constexpr double kMaxSamples = 50'000.0;
// The ink certificate's grid spacing is epsilon / kInkGridDivisions, coarsened to at most
// kMaxInkGridPoints points (ink box grown by the tolerance band on every side): bounded time.
inline constexpr double kInkGridDivisions = 10.0;
inline constexpr double kMaxInkGridPoints = 250'000.0;
// The ink certificate samples curves (box, ellipse chords) with at most about this many points.
inline constexpr double kMaxCurveSamples = 20'000.0;

// --- classify/ -----------------------------------------------------------------------------

// A stroke is closed when its end comes back within this many epsilons of its start: only then
// are closed families tried (recognize.hpp, "Classes").
inline constexpr double kClosureEpsilons = 2.0;
// A candidate's rank: its bound plus kRmsWeight times its RMS distance (in epsilons), plus a
// price per free parameter, so a simpler shape wins unless a richer one fits clearly better.
inline constexpr double kPricePerParameter = 0.15;
inline constexpr double kRmsWeight = 2.0;
// A shape is drawn once: the stroke may be at most this much longer than the clean shape
// (overshoot, a closing overlap and wobble stay well below). Snaps and live prospects alike.
inline constexpr double kMaxTracing = 1.6;
// ... and may turn at most half a turn more than the clean shape (end hooks, a closing overlap).
inline constexpr double kMaxExtraTurning = std::numbers::pi;
// A polygon of 5..8 corners turns at most this much at a corner (interior angle >= 30 deg): a
// sharper corner is a line drawn down and back (the stems of P, D, b drawn in one stroke).
inline constexpr double kMaxPolygonTurn = 5.0 * std::numbers::pi / 6.0;
// A polygon of 5..8 corners must certify within this fraction of epsilon: 99% of real one-stroke
// triangles and rectangles do (leaving one writer out: 0.68..0.85); looser is a scribble.
inline constexpr double kPolygonFraction = 0.85;
// A rhombus is a diamond when its angles are this far from 90 deg: beyond the tidy-up's right-angle
// slack, with room for a box drawn skewed (10 / 15 / 20 deg keep 99.6 / 100 / 100% of real
// one-stroke rectangles and 98.6 / 98.6 / 97.1% of diamonds made from them).
inline constexpr double kDiamondSkew = 1.5 * (10.0 * kDegree); // 1.5 x kRightAngleSlack
// A closed stroke turns at a polygon's corners as a drawn corner does when, between chords a
// quarter of the shorter side beside the corner either way, it turns by at least this share of the
// polygon's turn there: a circle through the corners turns 0.24..0.25, a corner drawn sharp about
// 1. A polygon of 5..8 such corners that fits nearly as tightly (kSharpPolygonSlack) is no circle
// or ellipse, even within their tolerance. recognize_bench --rule-folds: every fold picks 0.5
// (with the polygon fitting at least as tightly, every fold picked 0.3, the lowest tried, on a
// score the made polygons dominate); 0.5 keeps a margin over a circle's 0.25: no real class
// changes at 0.3..0.5, but at 0.4 2 of 45 generated circles become polygons. (Read on the mean over
// the corners instead, jittery generated circles pass it:
// RecognizeSynthetic.NoisyShapesSnapToTheirClass.)
inline constexpr double kCornerWindow = 0.25;
// Corners are also sought where a closed stroke turns most, when each of its k sharpest turns is
// at least this share of a regular k-gon's turn (a fit costs time; round strokes skip it).
inline constexpr double kLeastSeedTurnShare = 0.5;
inline constexpr double kMinSharpCornerShare = 0.5;
// A sharp polygon's corner stands at least this many epsilons off its neighbours' chord (a
// polyline's corner's margin; a blunt polygon's corners: one epsilon) ...
inline constexpr double kSharpCornerOffChord = 0.5;
// ... or at least this many where the stroke turns at it by kMinFlatCornerTurn of the regular
// polygon's turn: a lump of the hand flattens one corner of an octagon (its corners stand out
// 0.9 epsilon at the default tolerance) but not the turn it made there. Set at half the margin,
// not tuned (0.15 / 0.25 / 0.33 at kMinFlatCornerTurn 0.5: $1 made octagons 72.2 / 72.2 /
// 67.2%, no real class changes).
inline constexpr double kTurnedCornerOffChord = 0.25;
// recognize_bench --rule-folds: 99 of 102 folds pick 0.6 (held out 91.4% / 0.4%, rule off 88.9% /
// 0.4%): made octagons $1 45.6 -> 70.6%, gestures 64.6 -> 86.4%, heptagons 70.6 -> 72.2% /
// 85.7 -> 91.2%; made pentagons and hexagons lose a little (84.4 -> 82.8%, 79.4 -> 77.2%: a
// circle's kink read as one more corner); no real class changes at any value from 0.3 to 1.
inline constexpr double kMinFlatCornerTurn = 0.6;
// A circle or ellipse gives way to a sharp polygon that fits up to this factor more loosely
// (fit_measure: bound + 2 rms). A drawn octagon's corners stand out 8% of its radius, within the
// hand's wobble, so the circle may fit it more tightly than the octagon does: made octagons' sharp
// fits are within 1.2 times their circle's for 70% of them, within 1.0 for 51%. A jittery circle
// may turn sharply at a polygon's corners by chance, and that polygon fits it looser: at 1.3 the
// circle of RecognizeSynthetic.TighterToleranceRejectsTheSameStroke (sigma 3 on a radius of 100)
// becomes a polygon, at 1.5 those of NoisyShapesSnapToTheirClass too. No real one-stroke circle
// changes class at 1.2 ($1 180, gestures 147).
inline constexpr double kSharpPolygonSlack = 1.2;
// A triangle's, quadrilateral's, polygon's or regular polygon's fitted corners must be turned at:
// the stroke turns, in the same window, by at least this share of each measured corner's turn.
// Real one-stroke triangles turn 0.62 or more at every corner ($1, 160); at the least corner of
// their triangle fits, generated hearts turn 0.35 and more (median 0.43, one of 30 at 0.5 or
// above), loops on sticks 0.25..0.29; a regular pentagon whose band holds a made octagon passes
// the octagon's corners as a curve (made polygons of 5..8 named with their corner count, $1:
// 41 -> 58% when regular polygons were held to the rule). recognize_bench --rule-folds (made
// polygons scored on their corner count): 102 of 102 folds pick 0.5 (held out 88.9% / 0.4%,
// 88.6% / 0.7% with the rule off); no value from 0.2 to 0.5 changes a real shape; non-shapes
// snapped 0.7 -> 0.6% (P, half notes, a treble clef; LowVision star outlines 92.4 -> 97.8% left
// as ink in --classes).
inline constexpr double kMinFittedCornerShare = 0.5;
// A rectangle's, square's or diamond's corners may be drawn round one by one (low-vision squares
// are), but on the whole the stroke turns at them: the mean share over its measured corners is at
// least this. A circle through the corners makes 0.25 (the window); real one-stroke circles that a
// square's band holds make 0.27..0.36 on the mean (none more than 0.48 at any corner), real
// rectangles and squares ($1, LowVision) 0.54 or more: the middle of that gap. recognize_bench
// --rule-folds: 102 of 102 folds pick 0.45 (held out 90.2% / 0.4%, rule off 90.0% / 0.6%, with
// made polygons counted by class; by corner count 88.9% / 0.4% against 88.9% / 0.6%).
inline constexpr double kMinModelCornerShare = 0.45;
// A shape of k = 3..7 corners gives way to a polygon snap of more corners when the stroke turns
// sharply at k + 1 places, each by at least this share of a regular (k + 1)-gon's turn (and twice
// the stroke's median turn; one place in the plane counts once: a closed stroke running on past
// its start turns at that corner twice). recognize_bench --rule-folds (made polygons scored on
// their corner count): 102 of 102 folds pick 0.3, the best of 0..1 (held out 88.9% / 0.4%; 0.2
// and 0.4 88.7%, 0.5 88.5%, rule off 85.1%): made heptagons $1 48 -> 71%, gestures 68 -> 86%,
// hexagons 71 -> 79% / 87 -> 96%; made pentagons lose a little (87 -> 84%: a circle's kink read
// as a sixth corner); no real class changes.
inline constexpr double kMinMissedCornerTurn = 0.3;
// An arc stands out from its chord by at least this many epsilons (as a polyline's corner must):
// flatter, the segment says the same within tolerance (a quick line drawn with a slight bow).
inline constexpr double kArcMinSagitta = 0.5;
// Fits whose estimate exceeds this many epsilons are not certified (their certificate could not
// pass: the estimate is measured on points of the stroke).
inline constexpr double kCertifyIfBelow = 1.25;

// --- arrow/ --------------------------------------------------------------------------------

// Arrows are fitted and judged within this share of epsilon (ArrowRules::tolerance_share):
// 12.5 / 13.5, the fraction of the size their rules were measured at before the default
// tolerance rose to the one derived on single strokes (recognize.hpp; no arrow is counted there).
// At the full epsilon a looser band lets a brace's middle or a half note's head pass for one
// (group_recognize_bench --arrow-share 1: four $1 curly braces read as arrows through the
// grouper, single non-shapes snapped 0.8 -> 1.1%; non-shape drawings of other people snapped
// together 1.3 -> 1.8%, MMG arrows in 2 strokes 95.9 -> 93.8%).
inline constexpr double kArrowToleranceShare = 0.925;
// The scales of that share at which arrows are sought, in turn until one snaps
// (group_classifier.cpp score_each_arrow): epsilon follows the whole drawing, a head may be much
// smaller.
inline constexpr double kArrowHeadScales[] = {1.0, 0.5};

// A head's barbs open between these angles to the shaft: flatter is a line, wider a T or a hook.
inline constexpr double kMinHeadAngle = 10.0 * kDegree;
inline constexpr double kMaxHeadAngle = 80.0 * kDegree;
// A barb is at most this fraction of the shaft (a longer one makes a V or a chevron).
inline constexpr double kMaxBarbFraction = 0.8;
// Arrows are straight pieces: they fit as tightly as polylines, a little looser for the small head.
inline constexpr double kStraightFraction = 0.6;
// An arrow's stroke may be at most this much longer than the clean arrow (as kMaxTracing).
inline constexpr double kMaxTracingArrow = 1.6;
// The drawing is resampled to about this many points for the arrow fit (cost vs. coverage).
inline constexpr std::size_t kCloudPoints = 64;
// The second shaft start is polished when the first ends above this many epsilons: well below
// the straight fraction, since the certificate adds its sampling and thinning margins.
inline constexpr double kSecondStartAbove = 0.4;
// A head sought against the shaft's end: the direction back along the shaft is taken to the
// shaft's first point this share of its length from the tip (at least epsilon, at most half).
inline constexpr double kShaftEndReach = 0.15;
// ... only for a shaft whose end leaves its chord by at least this (a curve, a bend).
inline constexpr double kMinShaftEndTurn = 15.0 * kDegree;
// A stroke may have an arrow's tip where it turns back by more than this (a head's V, a shaft
// leaving along a barb).
inline constexpr double kTipTurn = 100.0 * kDegree;
// ... and is sought only in a drawing that ends or turns back in at most this many places (an
// arrow's tail, tip and barbs' ends, a double arrow's too).
inline constexpr std::size_t kMaxArrowPlaces = 8;
// A curved shaft bows by at most this fraction of its chord (more is an arc, not a shaft).
inline constexpr double kMaxBulge = 0.25;
// Free parameters (as degrees_of_freedom() counts them) of straight, curved and double arrows,
// and what each bend of a bent shaft adds.
inline constexpr double kStraightParameters = 8;
inline constexpr double kCurvedParameters = 9;
inline constexpr double kDoubleParameters = 12;
inline constexpr double kBendParameters = 2;
// A bent shaft's seed is polished only within kSeedWithin epsilons, and again only below
// kRepolishBelow (= kCertifyIfBelow: fits above it are not certified).
inline constexpr double kSeedWithin = 2.0;
inline constexpr double kRepolishBelow = 1.25;
// A bend stands out from its neighbours' chord by this many epsilons (as a polyline's corner).
inline constexpr double kMinBendOffset = 0.5;
// The shaft turns at most this much at a bend: beyond a right angle (with a hand's slack) it
// doubles back, a hook or a letter rather than a shaft that leads to its tip.
inline constexpr double kMaxBendTurn = 100.0 * kDegree;
// A bent shaft's last piece is within this angle of the head's axis (the barbs' bisector).
inline constexpr double kMaxBentHeadSkew = 25.0 * kDegree;
// Points per stroke checked when the head is drawn apart from the shaft (jitter averages out).
inline constexpr std::size_t kPieceSamples = 16;

// --- tidy/ ---------------------------------------------------------------------------------

// An ellipse is offered as a circle when its minor / major semi-axis is at least this.
inline constexpr double kRoundEllipse = 0.8;
// Corners within this of 90 deg are offered as right angles (a hand's slack); a rhombus this
// close to square is a square, not a diamond.
inline constexpr double kRightAngleSlack = 10.0 * kDegree;
// Sides within this relative difference are offered as equal.
inline constexpr double kEqualSides = 0.15;
// Sides within this of the axes are offered as axis-parallel.
inline constexpr double kAxisSlack = 10.0 * kDegree;
// Sides within this of each other are offered as parallel (tighter: two sides, not one axis).
inline constexpr double kParallelSlack = 6.0 * kDegree;
// An angle already within this (radians) of its target needs no tidying.
inline constexpr double kAlreadyExact = 1e-9;

// --- group/ --------------------------------------------------------------------------------

// A group has at most this many strokes (a drawn shape has few sides; bounds the unions tried).
inline constexpr std::size_t kMaxGroupStrokes = 8;
// A round shape's piece that is no arc alone (a polyline, freeform: a hand's third of a circle
// wobbles into corners, hooks where it starts) is one when an arc of it fits the piece, standing
// out from its chord (kArcMinSagitta) and centred within this share of the shape's radius of the
// shape's centre: inside the shape, as a circle's pieces bend. group_recognize_bench, $1 circles
// cut anywhere into 2-4 strokes, 0.5 / 0.75 / 1 / 1.5: 31.5 / 74.4 / 84.3 / 86.5% one circle
// (9.8% with no piece bowed), MMG D's drawn as a round shape 5 / 5 / 7 / 6 of 149 (8 before:
// their bowls, read as polylines, had kept some apart); measured before pieces smaller than
// epsilon were let be (87.0% at 1). Set at the shape's own radius, not tuned.
inline constexpr double kMaxBowedCentreOff = 1.0;
// A round shape's straight piece over which the shape is as straight (GroupRules::
// flat_round_pieces) goes on into the pieces it meets turned by at most this (radians; each way
// over epsilon of its path): a circle's pieces go on as the curve does, a D's stem meets its bowl
// at corners. Half a right angle, not tuned.
inline constexpr double kMaxSmoothJoinTurn = std::numbers::pi / 4;
// A circle's or ellipse's piece that stands out from its chord, on the side the shape's own path
// over it does, by at least this share of that path's sagitta is a stretch of it
// (GroupRules::bent_round_pieces). Half, not tuned.
inline constexpr double kMinBendShare = 0.5;
// A stroke that runs on along another within this many epsilons (of the largest stroke alone)
// past their crossing overlaps it, as a closing stroke overlaps the first
// (GroupRules::overlaps_are_no_crossings). Half, not tuned.
inline constexpr double kOverlapAlongside = 0.5;
// Recent groups a new stroke is tried with: at most 2^6 - 1 unions.
inline constexpr std::size_t kMaxRecentGroups = 6;
// Touch tests run on paths thinned within this fraction of their size (added to the join
// distance, so thinning never separates touching strokes).
inline constexpr double kTouchThinning = 0.005;
// Stroke orders are searched exhaustively up to this many strokes, greedily beyond (6! = 720).
inline constexpr std::size_t kExhaustiveUpTo = 6;
// Several strokes close a shape only when it is wider than this many epsilons: narrower, all its
// inside is within epsilon of its outline, so any strokes side by side would certify as it.
inline constexpr double kMinClosedWidth = 2.0;

// A corner of a straight-sided group inside one stroke is a corner of that stroke: within epsilon
// of arc length either side, the stroke turns by at least this share of the shape's turn (a D's or
// P's bowl turns far less; MMG D's 0.30/0.35/0.40/0.45 -> 11/5/3/1% snapped, held-out MMG+ D's
// 35/13/7/5%, 2-stroke squares kept 96/96/96/86%).
inline constexpr double kMinCornerTurnShare = 0.4;
// Crossings are looked for on strokes thinned within this fraction of their epsilon (a crossing
// that thinning moves stays within the join distance, which is much larger).
inline constexpr double kCrossingThinning = 0.05;
// An arrow's strokes cross in their middles beyond this share of each stroke from its ends: a
// shaft overshooting its head's tip is no such crossing; arms across a stick figure's body are.
inline constexpr double kMiddleOfArrowPiece = 0.25;

// --- live/ ---------------------------------------------------------------------------------

// The drawing grew by half: epsilon grew with it, so the candidates are refitted.
inline constexpr double kGrowthForRefit = 1.5;
// An open stroke is tried as a closed shape still being drawn when its length is at least
// kProspectLength sizes and its end-to-start gap at most kProspectGap sizes.
inline constexpr double kProspectLength = 1.5;
inline constexpr double kProspectGap = 0.75;

// --- classify/: evidence beyond the band (issue 23 item 2) ------------------------------------

// A shape is traced once: the stroke may run back along the shape's path over at most this share
// of it (jitter and a closing hook stay below; a stem drawn down and up in a box's band does not).
// Chosen per held-out writer (recognize_bench --rule-folds): 100 of 102 folds pick 0.1 (2: 0.05);
// held out 98.2% shapes / 0.7% non-shapes snapped against 98.4% / 1.4% without the rule.
inline constexpr double kMaxBacktrack = 0.1;

// --- arrow/ and group/, several strokes (a23) ----------------------------------------------

// A head drawn in its own stroke may have barbs up to this many shafts: people draw a large head
// on a short shaft (the MMG "arrowhead" template's barbs are 1.07 shafts; drawn ones reach 2).
inline constexpr double kMaxSeparateHeadBarb = 2.0;
// A shaft drawn in its own stroke runs along at least this share of the tail-to-tip distance
// (people stop short of the tip; a stroke across the shaft, the bar of an A, spans nothing).
inline constexpr double kMinShaftSpan = 0.5;

// --- group/, several strokes (b23) ------------------------------------------------------------

// A stroke continues an arrow's tip when it leaves the tip within this angle of the shaft's
// direction: nearer the shaft's line than across it (a box or circle met at the tip runs across).
// Swept on the gestures (group_recognize_bench --loso): 45, 60 and 75 deg snap 29 of 3,104
// non-shape drawings, 30 deg 31, no arrow changes; every held-out writer's fold picks 45.
inline constexpr double kMaxContinuationAngle = 45.0 * kDegree;

// --- arrow/, a shaft that stops short of its tip (a23, #23) ----------------------------------

// A shaft drawn in its own stroke may stop short of the tip by at most this many mean barbs (a
// longer gap is a dash beside a chevron). group_recognize_bench --loso: 0.7/1/1.3/1.6 get 421/
// 425/432/432 of 450 gesture shapes, 30/30/31/32 of 3104 non-shapes; every held-out fold picks 1.3.
inline constexpr double kMaxGapBarb = 1.3;
// ... and is aimed at the tip: the gap leaves the shaft's end within this angle of the shaft's
// direction (the MMG misses: within 6 deg but one 16.8; a stroke beside the head is not aimed).
inline constexpr double kMaxGapAim = 12.0 * kDegree;
// Free parameters a shaft's end adds to an arrow's rank (a point: two coordinates).
inline constexpr double kGapParameters = 2;
// Two strokes up to this many epsilons farther apart than touching are tried as an arrow (a
// shaft that stops short: its gap is up to a barb; 1, 2 and 3 gain the same, LOSO picks 2).
inline constexpr double kApartJoin = 2.0;

} // namespace penshape::recognize_detail
