#pragma once
// Arrow and double-arrow proposals for one or several strokes (group_recognize.hpp, "Arrows").
#include <cmath>
#include <string>
#include <vector>

#include "recognize/certify/union_certificate.hpp"
#include "recognize/fitting/fit.hpp"
#include "recognize/thresholds.hpp"

namespace penshape::recognize_detail {

// About 64 points spread along every piece in proportion to its length (no jumps between
// pieces): what the fits and the RMS of a union are measured on.
std::vector<PointD> cloud_of(const UnionStroke& u);

// Candidates (arrow in either direction, double arrow) fitted to the union of the strokes, best
// fit first; empty when no head stands out. Estimates only: the certificate decides. Kinds whose
// least possible rank (kPricePerParameter x free parameters, classifier.hpp) is not below
// `rank_to_beat` are not fitted: they could never win over the snap that set it. kStraightShafts
// fits straight shafts only: no curved or bent one, and no head sought at a shaft's own end
// (ArrowRules::heads_at_shaft_end).
enum class ArrowSearch { kAll, kStraightShafts };
std::vector<Fit> fit_arrows(const UnionStroke& u, double epsilon, double rank_to_beat = INFINITY,
                            ArrowSearch search = ArrowSearch::kAll);

// Whether a single arrow fitted to several strokes has its head drawn apart from its shaft: every
// stroke lies within epsilon of the shaft or of the head, some only of the shaft and some only of
// the head (the shaft, then the head, or the head first). The strokes then tell the shaft from
// the head, which a tight fit must tell otherwise.
bool head_drawn_apart(const Fit& f, const UnionStroke& u, double epsilon);

// The arrow rules added with measured held-out figures, each switchable so that
// group_recognize_bench and the tests can show what one rule does (as GroupRules). All on by
// default; the library never changes them (set them before recognizing, from one thread).
struct ArrowRules {
  // Two strokes are also fitted as a head stroke and a shaft stroke (fit_arrows).
  bool seed_from_strokes = true;
  // A head is also sought against the shaft's end, not only the chord tail -> tip (a curved or
  // bent shaft reaches its tip along a direction far from the chord).
  bool heads_at_shaft_end = true;
  // A head drawn apart may have barbs up to this many shafts (arrow_implausibility).
  double max_apart_barb = kMaxSeparateHeadBarb;
  // A shaft drawn in its own stroke spans at least this share of the shaft (head_drawn_apart).
  double min_shaft_span = kMinShaftSpan;
  // A shaft stroke may stop short of the tip (fit_from_strokes: a fit with ShapeParams::
  // shaft_end), when its head is drawn apart, the gap is at most max_gap_barb mean barbs and it
  // leaves the shaft's end within max_gap_aim of the shaft's direction (arrow_implausibility).
  bool gapped_shafts = true;
  // Arrows are sought again at the finer scales of kArrowHeadScales when none snaps at epsilon
  // (group_classifier.cpp, score_each_arrow): a long shaft's small head.
  bool finer_head_scales = true;
  // Arrows are fitted and judged within this share of epsilon (kArrowToleranceShare).
  double tolerance_share = kArrowToleranceShare;
  double max_gap_barb = kMaxGapBarb;
  double max_gap_aim = kMaxGapAim;
};
ArrowRules& arrow_rules();

// Why a certified arrow is not a plausible snap (empty when it is); `drawn_length` is the summed
// length of the strokes. An arrow must fit within 0.6 epsilon (it is straight pieces) with
// barbs up to 0.8 shafts; with its head drawn apart, within epsilon (the certificate) with
// barbs up to ArrowRules::max_apart_barb shafts.
std::string arrow_implausibility(const Fit& f, const Certificate& c, double drawn_length,
                                 bool head_apart = false);

} // namespace penshape::recognize_detail
