#pragma once
// Where a live stroke's pen-up analysis spends its time, step by step, in thread CPU time (the
// figure that stays meaningful on a loaded machine, where wall time measures the other programs)
// beside wall time: the steps the daemon's grouping session runs for each finished stroke, each
// timed on its own on the same strokes, added in drawing order as the daemon's strand adds them.
//   ink      the ink polygon Q and its proto form (core ink_polygon + to_proto); of it at
//            pen-up: what is left when its chunks were built while the pen was down (InkBuilder,
//            as the daemon does); the two Q must be equal bit for bit (a mismatch is printed);
//            of that: Q's final union alone (Clipper), and the union of the closed chunks' union
//            with the last chunk (not used: not the same Q, penup_stages_ink.hpp; how often its
//            vertices differ, and how often its set provably differs, is printed)
//   intent   the writing/drawing decision with the 24 strokes before it as context: as before
//            (decide_intent on that page, every stroke measured again), and as the daemon now
//            decides it (LiveIntent: each stroke measured once)
//   alone    the stroke recognized alone, certified on its ink (core recognize() with Q)
//   family fits, path certificates   of it: the stroke's family fits (fit_all) and their path
//            certificates (evaluate), each timed on its own
//   ink certificate, flat / pruned   of it: the ink certificate of the stroke's shape (the
//            winner, else the best alternative) on its prepared Q, visiting every grid point
//            (the former scan) and pruning blocks (the scan recognize() runs), on the same
//            inputs; the two bounds must be equal bit for bit (a mismatch is printed)
//   grouper  core StrokeGrouper::add with Q given: unions with recent strokes, the stroke alone
//            (arrows included), tidy-up
//   session  the daemon's whole grouping session add() on one thread (all of the above)
//   strand   the same add() as the daemon's strand runs it: Q on a second worker, the shape
//            returned first when it read no Q (InkOffload::shape_first); the strand's CPU
//            time and its wall time up to the shape (Q's own CPU is the helper's)
// Used by daemon_penup_latency (and its hold twin) so that a change is judged by CPU time per
// step, printed beside the wall-time rows of the same run.
#include <time.h>

#include <chrono>
#include <cstdio>
#include <deque>
#include <string>
#include <vector>

#include "bench_support.hpp"
#include "penshape/core/group_recognize.hpp"
#include "penshape/core/ink.hpp"
#include "penshape/core/ink_builder.hpp"
#include "penshape/core/intent.hpp"
#include "penshape/core/recognize.hpp"
#include "penshape/daemon/ink_analyzer.hpp"
#include "penshape/daemon/proto_convert.hpp"
#include "penshape/daemon/stroke_analyzer.hpp"
#include "penshape/daemon/worker_pool.hpp"
#include "penup_stages_ink.hpp"
#include "penup_stages_time.hpp"
#include "recognize/certify/ink_certificate.hpp"
#include "recognize/classify/classifier.hpp"
#include "recognize/fitting/clean_shape.hpp"
#include "recognize/fitting/dot.hpp"

namespace penshape::bench {

// The tip-down path in millimetres, as the daemon's analyzer reads a stroke.
inline std::vector<StrokePoint> stage_path_mm(const Stroke& stroke) {
  const double rx = stroke.tablet.x_resolution > 0 ? stroke.tablet.x_resolution : 1.0;
  const double ry = stroke.tablet.y_resolution > 0 ? stroke.tablet.y_resolution : 1.0;
  std::vector<StrokePoint> out;
  for (const PenSample& s : stroke.samples) {
    if (s.tip) out.push_back({s.x / rx, s.y / ry, static_cast<double>(s.time_us) * 1e-6});
  }
  return out;
}

// The ink certificate of the stroke's shape (the winner, else the best alternative) timed both
// ways on the same prepared Q; a mismatch of the bounds is counted (it would be a bug).
struct InkScanTimes {
  StepTime flat, pruned;
  std::size_t mismatches = 0;
  void time(const InkPolygon& q, const Recognition& rec) {
    const bool won = rec.shape != ShapeClass::kFreeform;
    if (!won && rec.alternatives.empty()) return;
    const ShapeClass cls = won ? rec.shape : rec.alternatives.front().shape;
    const ShapeParams& params = won ? rec.params : rec.alternatives.front().params;
    if (cls == ShapeClass::kFreeform || q.region.empty()) return;
    recognize_detail::CleanShape shape;
    try {
      shape = recognize_detail::clean_shape_of(cls, params);
    } catch (const InvalidInput&) {
      return;
    }
    using recognize_detail::InkScan;
    const recognize_detail::InkRegion region = recognize_detail::prepare_ink(q, rec.epsilon);
    Certificate a, b;
    flat.time([&] { a = certify_ink(region, shape, rec.epsilon, rec.pen_radius, InkScan::kFlat); });
    pruned.time(
        [&] { b = certify_ink(region, shape, rec.epsilon, rec.pen_radius, InkScan::kPruned); });
    if (a.bound != b.bound) ++mismatches;
  }
};

// The stroke alone's two path steps, timed on their own: the family fits (fit_all, the
// refinement's objective and the corner search) and their path certificates (evaluate).
struct PathStepTimes {
  StepTime fits, certificates;
  void time(const StrokeInput& input, const RecognizerConfig& config) {
    const ToleranceChoice tol = choose_tolerance(input.samples, config);
    if (recognize_detail::is_dot(input.samples)) return; // answered before any fit
    const recognize_detail::PreparedStroke s = recognize_detail::prepare(
        input.samples, recognize_detail::thinning_tolerance(config, tol.epsilon));
    std::vector<recognize_detail::Fit> f;
    fits.time([&] { f = recognize_detail::fit_all(s, config, tol.epsilon); });
    certificates.time([&] {
      (void)recognize_detail::evaluate(s, std::move(f), tol.epsilon, tol.pen_radius, config);
    });
  }
};

// Q as the daemon's pen-up builds it: the chunks the samples complete built ahead (untimed, as
// the daemon builds them while the pen is down), then the rest and the union with the proto form
// (timed). Q must equal the one-shot one bit for bit (a mismatch is printed).
struct AheadInkTimes {
  StepTime penup;
  std::size_t mismatches = 0;
  void time(const Stroke& stroke, const InkOptions& options, const InkPolygon& one_shot) {
    const std::vector<InkSample> samples = ink_samples(stroke, options);
    InkBuilder builder(options);
    builder.add(samples);
    while (builder.build_next()) {
    }
    InkPolygon q;
    v1::PolygonSet proto, expected;
    penup.time([&] {
      q = builder.polygon(samples);
      daemon::to_proto(q.region, &proto);
    });
    daemon::to_proto(one_shot.region, &expected);
    if (proto.SerializeAsString() != expected.SerializeAsString() ||
        q.hausdorff_bound != one_shot.hausdorff_bound) {
      ++mismatches;
    }
  }
};

// Times each step on `strokes` (already back to back in time, in drawing order) and prints one
// row per step: thread CPU p50/p99/max, then wall p50/p99.
inline void print_penup_stages(bool json, const std::string& tag,
                               const std::vector<Stroke>& strokes,
                               daemon::StrokeAnalyzer& analyzer) {
  const daemon::PenSettings settings{};
  const InkOptions ink_options = daemon::ink_options_for(settings);
  RecognizerConfig config;
  config.pen_radius = settings.pen_radius_mm;
  StepTime ink, intent, live_intent, alone, grouper, session, strand;
  LiveIntent live_context;
  InkScanTimes ink_scan;
  PathStepTimes path_steps;
  AheadInkTimes ahead;
  InkUnionTimes unions;
  StrokeGrouper core_grouper(GroupingConfig{}, config);
  auto whole = analyzer.group_session(settings, GroupingConfig{});
  auto live = analyzer.group_session(settings, GroupingConfig{});
  daemon::WorkerPool helper(1, 16, daemon::WorkerPriority::kNormal);
  daemon::InkOffload offload;
  offload.run_elsewhere = [&helper](std::function<void()> job) {
    return helper.submit([job = std::move(job)](const auto& /*stop*/) { job(); });
  };
  offload.shape_first = true;
  std::deque<std::vector<StrokePoint>> context; // IntentStroke is a view: the paths stay here
  for (const Stroke& stroke : strokes) {
    StrokeInput input;
    input.samples = stage_path_mm(stroke);
    input.pen_radius = settings.pen_radius_mm;
    if (input.samples.empty()) continue;
    InkPolygon q;
    ink.time([&] {
      q = ink_polygon(ink_samples(stroke, ink_options), ink_options);
      v1::PolygonSet proto;
      daemon::to_proto(q.region, &proto);
    });
    ahead.time(stroke, ink_options, q);
    unions.time(ink_samples(stroke, ink_options), ink_options);
    intent.time([&] {
      std::vector<IntentStroke> page(context.begin(), context.end());
      page.emplace_back(input.samples);
      (void)decide_intent(page);
    });
    live_intent.time([&] { (void)live_context.add(input.samples); });
    context.emplace_back(input.samples);
    if (context.size() > 24) context.pop_front();
    input.ink = &q;
    Recognition rec;
    alone.time([&] { rec = recognize(input, config); });
    ink_scan.time(q, rec);
    path_steps.time(input, config);
    grouper.time([&] {
      (void)core_grouper.add(input);
      core_grouper.forget_unreachable();
    });
    session.time([&] { (void)whole->add(stroke, true, {}, {}); });
    daemon::GroupedStrokeAnalysis result;
    strand.time([&] { result = live->add(stroke, true, {}, offload); });
    result.wait_ink(); // after the shape, as the strand publishes StrokeFinished
  }
  const std::pair<const char*, StepTime*> steps[] = {
      {"ink polygon + proto", &ink},
      {"  of it at pen-up, chunks built ahead", &ahead.penup},
      {"    of that: Q's final union (Clipper)", &unions.final_union},
      {"    not used: closed chunks' union + last", &unions.chain_union},
      {"intent decision, page (as before)", &intent},
      {"intent decision, LiveIntent", &live_intent},
      {"stroke alone, ink certificate", &alone},
      {"  of it: family fits (path)", &path_steps.fits},
      {"  of it: path certificates of the fits", &path_steps.certificates},
      {"  of it: ink certificate, flat scan", &ink_scan.flat},
      {"  of it: ink certificate, pruned scan", &ink_scan.pruned},
      {"StrokeGrouper::add (unions+alone)", &grouper},
      {"whole session add, one thread", &session},
      {"strand to the shape, ink on 2nd worker", &strand}};
  for (const auto& [name, step] : steps) {
    const Percentiles c = percentiles(step->cpu_ms);
    const Percentiles w = percentiles(step->wall_ms);
    if (json) {
      std::printf(
          "{\"case\":\"step: %s%s\",\"n\":%zu,\"cpu_p50\":%.4f,\"cpu_p99\":%.4f,"
          "\"cpu_max\":%.4f,\"wall_p50\":%.4f,\"wall_p99\":%.4f,\"unit\":\"ms\"}\n",
          name, tag.c_str(), c.n, c.p50, c.p99, c.max, w.p50, w.p99);
    } else {
      std::printf("%-48s %6zu %10.3f %10.3f %10.3f ms  thread CPU (wall p50 %.3f, p99 %.3f)\n",
                  ("step: " + std::string(name) + tag).c_str(), c.n, c.p50, c.p99, c.max, w.p50,
                  w.p99);
    }
  }
  if (ahead.mismatches > 0) {
    std::printf("ink polygon: built ahead differs from one-shot on %zu strokes (a bug)\n",
                ahead.mismatches);
  }
  if (!json) {
    std::printf(
        "not used: closed chunks' union + last chunk: vertices differ from Q's on %zu of "
        "%zu strokes, the set provably differs on %zu\n",
        unions.other_vertices, unions.strokes, unions.other_sets);
  }
  if (ink_scan.mismatches > 0) {
    std::printf(
        "ink certificate: the pruned scan's bound differs from the flat one on %zu "
        "strokes (a bug)\n",
        ink_scan.mismatches);
  }
}

} // namespace penshape::bench
