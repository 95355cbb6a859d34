#include "penshape/daemon/recognizing_analyzer.hpp"

#include <atomic>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>

#include "penshape/core/ink.hpp"
#include "penshape/core/intent.hpp"
#include "penshape/core/intent_grouper.hpp"
#include "penshape/core/live_recognizer.hpp"
#include "penshape/daemon/build_once.hpp"
#include "penshape/daemon/ink_analyzer.hpp"
#include "penshape/daemon/proto_convert.hpp"
#include "penshape/proto/shape_kind.hpp"

#include "ink_ahead.hpp"

namespace penshape::daemon {
namespace {

void set_point(PointD p, v1::Point* out) {
  out->set_x(p.x);
  out->set_y(p.y);
}

// A sample in millimetres (a resolution of 0, unknown, takes device units as millimetres).
StrokePoint point_mm(const PenSample& s, const TabletInfo& tablet) {
  const double rx = tablet.x_resolution > 0 ? tablet.x_resolution : 1.0;
  const double ry = tablet.y_resolution > 0 ? tablet.y_resolution : 1.0;
  return {s.x / rx, s.y / ry, static_cast<double>(s.time_us) * 1e-6};
}

// The pen path in millimetres: only samples with the tip down draw.
std::vector<StrokePoint> path_mm(const Stroke& stroke) {
  std::vector<StrokePoint> out;
  out.reserve(stroke.samples.size());
  for (const PenSample& s : stroke.samples) {
    if (s.tip) out.push_back(point_mm(s, stroke.tablet));
  }
  return out;
}

RecognizerConfig config_for(const PenSettings& settings) {
  RecognizerConfig config;
  config.pen_radius = settings.pen_radius_mm;
  return config;
}

// The proto form of a recognition's certified alternatives (runner-ups), best first.
void add_alternatives(const Recognition& r, std::vector<v1::Shape>* out) {
  for (const Candidate& c : r.alternatives) {
    if (!c.certificate.certified || !c.rejected.empty()) continue;
    out->push_back(to_proto_shape(
        c.shape, c.params, c.clean, c.certificate,
        c.certificate.epsilon > 0 ? 1 - c.certificate.bound / (2 * c.certificate.epsilon) : 0));
  }
}

// The decision on the answer (a writing stroke snapped only with snap_writing).
void set_intent(const IntentDecision& d, v1::Shape* shape) {
  shape->set_intent(d.intent == Intent::kWriting ? v1::INTENT_WRITING : v1::INTENT_DRAWING);
  shape->set_writing_score(d.writing_score);
}

// A group's intent: writing only when each of its strokes is (a grouped answer is drawing
// unless snap_writing grouped writing); its score the strokes' mean P(writing).
IntentDecision answer_intent(const std::vector<IntentDecision>& intents,
                             const std::vector<std::size_t>& strokes) {
  IntentDecision out{Intent::kWriting, 0.0};
  for (const std::size_t i : strokes) {
    if (intents.at(i).intent != Intent::kWriting) out.intent = Intent::kDrawing;
    out.writing_score += intents.at(i).writing_score / static_cast<double>(strokes.size());
  }
  return out;
}

// One tablet's live grouping: core's StrokeGrouper on the strokes' paths in mm; a lone stroke is
// certified on its ink polygon (as analyze() does), a group on the union of its strokes' paths.
class GroupSession final : public StrokeGroupSession {
  // A stroke's ink polygon Q, then its proto form (on the worker that builds Q, or where the
  // answer needs it): the recognizer waits for Q alone, to certify on it.
  struct StrokeInk {
    // `ahead`: the chunks of Q built while the stroke was drawn (null: none).
    StrokeInk(std::vector<InkSample> samples, const InkOptions& options,
              std::shared_ptr<InkAhead> ahead)
        : polygon([samples = std::move(samples), options, ahead = std::move(ahead)] {
            return ahead ? ahead->polygon(samples, options) : ink_polygon(samples, options);
          }),
          proto([this] {
            v1::PolygonSet out;
            to_proto(polygon.get().region, &out);
            return out;
          }) {}
    StrokeInk(const StrokeInk&) = delete;
    StrokeInk& operator=(const StrokeInk&) = delete;
    // The helper's side: Q unless somebody has started it, then its proto form (waiting for Q
    // when another thread builds it).
    void build_if_not_started() {
      polygon.build_if_not_started();
      proto.build_if_not_started();
    }
    BuildOnce<InkPolygon> polygon;
    BuildOnce<v1::PolygonSet> proto;    // reads polygon: declared after it
    std::atomic<bool> abandoned{false}; // the call that asked for Q was cancelled
  };

 public:
  // `finished` is told each finished stroke's id (the analyzer drops its preview state).
  // `ahead` gives a stroke's Q built while it was drawn (or null).
  GroupSession(const PenSettings& settings, const GroupingConfig& grouping,
               std::function<void(std::uint64_t)> finished,
               std::function<std::shared_ptr<InkAhead>(std::uint64_t)> ahead)
      : settings_(settings),
        grouper_(grouping, config_for(settings)),
        finished_(std::move(finished)),
        ahead_(std::move(ahead)) {}

  using StrokeGroupSession::add;
  GroupedStrokeAnalysis add(const Stroke& stroke, bool with_ink, const CancelHook& cancel,
                            const InkOffload& offload) override {
    return add_stroke(stroke, with_ink, false, cancel, offload);
  }
  GroupedStrokeAnalysis add_held(const Stroke& stroke, const CancelHook& cancel,
                                 const InkOffload& offload) override {
    return add_stroke(stroke, true, true, cancel, offload);
  }

  [[nodiscard]] std::unique_ptr<StrokeGroupSession> clone() const override {
    return std::make_unique<GroupSession>(*this);
  }
  [[nodiscard]] std::size_t stroke_count() const override { return grouper_.stroke_count(); }
  [[nodiscard]] std::size_t oldest_retained_stroke() const override {
    return grouper_.oldest_retained_stroke();
  }
  [[nodiscard]] std::size_t retained_stroke_count() const override {
    return grouper_.retained_stroke_count();
  }

 private:
  // The new stroke's intent, decided with the recent strokes before it as its context (which it
  // then joins). A held stroke is drawing: the hold asks for a snap.
  IntentDecision decide(const std::vector<StrokePoint>& path, bool held) {
    if (!held) return intent_.add(path);
    intent_.remember(path);
    return {};
  }

  // Q's proto form into the answer, or (InkOffload::shape_first, Q not built yet: the answer read
  // no Q) handed over as ink_later, so that the shape need not wait for it. A shape that read Q
  // carries its proto form: StrokeFinished goes out before the shape, as subscribers expect.
  static void hand_over_ink(const std::shared_ptr<StrokeInk>& ink, const InkOffload& offload,
                            GroupedStrokeAnalysis& out) {
    if (!ink) return;
    if (offload.shape_first && !ink->polygon.built()) {
      out.ink_later = [ink] { return std::move(ink->proto.get()); };
    } else {
      out.analysis.ink_polygon = std::move(ink->proto.get());
    }
  }

  GroupedStrokeAnalysis add_stroke(const Stroke& stroke, bool with_ink, bool held,
                                   const CancelHook& cancel, const InkOffload& offload) {
    GroupedStrokeAnalysis out;
    std::shared_ptr<InkAhead> ahead = with_ink && ahead_ ? ahead_(stroke.id) : nullptr;
    if (with_ink && finished_) finished_(stroke.id);
    StrokeInput input;
    input.samples = path_mm(stroke);
    input.pen_radius = settings_.pen_radius_mm;
    if (cancel && cancel()) throw Cancelled();
    const bool no_path = input.samples.empty(); // no tip-down sample: nothing to recognize
    // Q is built on another worker while the stroke is judged and fitted, or here once the
    // recognizer (or the answer) needs it.
    std::shared_ptr<StrokeInk> ink;
    if (with_ink) {
      // The job owns what it reads: a helper may start it after this session is gone.
      const InkOptions options = ink_options_for(settings_);
      ink = std::make_shared<StrokeInk>(ink_samples(stroke, options), options, std::move(ahead));
      if (offload.run_elsewhere) {
        (void)offload.run_elsewhere([ink] {
          if (!ink->abandoned) ink->build_if_not_started();
        });
      }
      // Q is needed once the unions and the stroke's fits are done: a cancelled call (a hold's
      // work ahead that a pen-up overtook) stops there rather than wait for Q and certify.
      input.ink_when_needed = [&ink, &cancel] {
        if (cancel && cancel()) {
          ink->abandoned = true; // a helper that has not started it leaves Q unbuilt
          throw Cancelled();
        }
        return &ink->polygon.get();
      };
    }
    const IntentDecision intent = no_path ? IntentDecision{} : decide(input.samples, held);
    const bool writing = intent.intent == Intent::kWriting && !settings_.snap_writing;
    if (no_path || writing) { // alone, as drawn (a dot is a shape)
      hand_over_ink(ink, offload, out);
      out.analysis.shape.set_kind(v1::SHAPE_KIND_NONE);
      if (!no_path) set_intent(intent, &out.analysis.shape);
      return out;
    }
    const GroupUpdate u = grouper_.add(input);
    hand_over_ink(ink, offload, out);
    grouper_.forget_unreachable(); // memory follows the grouping window, however long the session
    const Recognition& r = u.shape.recognition;
    out.analysis.shape = to_proto_shape(r.shape, r.params, r.clean, r.certificate, r.confidence);
    set_intent(intent, &out.analysis.shape);
    add_alternatives(r, &out.analysis.alternatives);
    out.grouped = true;
    out.answer = u.shape.id;
    out.strokes = u.shape.strokes;
    out.superseded = u.superseded;
    out.tidy = u.shape.tidy;
    return out;
  }

  PenSettings settings_;
  StrokeGrouper grouper_;
  std::function<void(std::uint64_t)> finished_;
  std::function<std::shared_ptr<InkAhead>(std::uint64_t)> ahead_;
  // The last 24 strokes' measures (core's default context), each measured once.
  LiveIntent intent_;
};

class RecognizingAnalyzer final : public StrokeAnalyzer,
                                  public std::enable_shared_from_this<RecognizingAnalyzer> {
 public:
  StrokeAnalysis analyze(const Stroke& stroke, const PenSettings& settings,
                         const CancelHook& cancel) override {
    // The ink polygon Q (what the ink analyzer reports), kept to certify the shape on the ink.
    StrokeAnalysis analysis;
    const InkPolygon ink = analyze_ink(stroke, settings, cancel, &analysis);
    forget(stroke.id);

    StrokeInput input;
    input.samples = path_mm(stroke);
    if (input.samples.empty()) { // no tip-down sample (a dot is recognized as SHAPE_KIND_DOT)
      analysis.shape.set_kind(v1::SHAPE_KIND_NONE);
      return analysis;
    }
    // The clean shape is drawn with the settings' pen radius; the snap is decided by the
    // ink-level certificate against Q (the path screening picks the candidates cheaply).
    input.ink = &ink;
    input.pen_radius = settings.pen_radius_mm;
    const Recognition r = recognize(input, config_for(settings));
    if (cancel && cancel()) throw Cancelled();
    analysis.shape = to_proto_shape(r.shape, r.params, r.clean, r.certificate, r.confidence);
    add_alternatives(r, &analysis.alternatives);
    return analysis;
  }

  std::unique_ptr<StrokeGroupSession> group_session(const PenSettings& settings,
                                                    const GroupingConfig& grouping) override {
    return std::make_unique<GroupSession>(
        settings, grouping,
        [self = weak_from_this()](std::uint64_t id) {
          if (auto analyzer = self.lock()) analyzer->forget(id);
        },
        [self = weak_from_this()](std::uint64_t id) {
          auto analyzer = self.lock();
          return analyzer ? analyzer->ink_ahead_.find(id) : nullptr;
        });
  }

  void work_ahead(const Stroke& partial, const PenSettings& settings,
                  const CancelHook& cancel) override {
    ink_ahead_.open(partial.id, ink_options_for(settings))->feed(partial, cancel);
  }

  std::vector<v1::RecognizedGroup> recognize_group(const std::vector<Stroke>& strokes,
                                                   const PenSettings& settings,
                                                   const GroupingConfig& grouping) override {
    std::vector<StrokeInput> inputs;
    for (std::size_t i = 0; i < strokes.size(); ++i) {
      StrokeInput in;
      in.samples = path_mm(strokes[i]);
      if (in.samples.empty()) {
        throw InvalidInput("strokes[" + std::to_string(i) + "]: the stroke has no tip-down sample");
      }
      in.pen_radius = settings.pen_radius_mm;
      inputs.push_back(std::move(in));
    }
    // The strokes are the page: each stroke's intent has the strokes around it as context.
    std::vector<IntentStroke> page;
    page.reserve(inputs.size());
    for (const StrokeInput& in : inputs) page.emplace_back(in.samples);
    const std::vector<IntentDecision> intents = decide_intent(page);
    IntentGrouper grouper(grouping, config_for(settings), settings.snap_writing);
    for (std::size_t i = 0; i < inputs.size(); ++i) (void)grouper.add(inputs[i], intents[i].intent);
    std::vector<v1::RecognizedGroup> out;
    for (const GroupedShape& g : grouper.shapes()) {
      v1::RecognizedGroup group;
      const Recognition& r = g.recognition;
      *group.mutable_shape() =
          to_proto_shape(r.shape, r.params, r.clean, r.certificate, r.confidence);
      set_intent(answer_intent(intents, g.strokes), group.mutable_shape());
      for (const std::size_t i : g.strokes) group.add_strokes(static_cast<std::uint32_t>(i));
      for (const std::string& t : g.tidy) group.add_tidy(t);
      for (const Candidate& c : r.alternatives) {
        if (!c.certificate.certified || !c.rejected.empty()) continue;
        *group.add_alternatives() = to_proto_shape(
            c.shape, c.params, c.clean, c.certificate,
            c.certificate.epsilon > 0 ? 1 - c.certificate.bound / (2 * c.certificate.epsilon) : 0);
      }
      out.push_back(std::move(group));
    }
    return out;
  }

  std::vector<v1::Shape> preview(const Stroke& partial, const PenSettings& settings,
                                 const CancelHook& cancel) override {
    std::shared_ptr<State> st = live_state(partial.id, settings);
    // Only this stroke's state is locked while feeding, so a finishing stroke's analysis (and
    // other devices' previews) never wait for a preview.
    std::lock_guard lock(st->mutex);
    // Only the samples this recognizer has not seen are converted and fed.
    for (; st->fed < partial.samples.size(); ++st->fed) {
      if (cancel && cancel()) throw Cancelled(); // the stroke ended: its shape supersedes this
      const PenSample& s = partial.samples[st->fed];
      if (s.tip) st->live.add(point_mm(s, partial.tablet));
    }
    if (cancel && cancel()) throw Cancelled(); // the stroke ended while its samples were fed
    std::vector<v1::Shape> out;
    const LivePreview& p = st->live.preview();
    if (p.shape != ShapeClass::kFreeform) {
      // A preview is a candidate, not yet certified: no certificate, confidence 0.
      v1::Shape shape = to_proto_shape(p.shape, p.params, p.clean, Certificate{}, 0.0);
      shape.clear_certificate();
      out.push_back(std::move(shape));
    }
    return out;
  }

 private:
  struct State {
    explicit State(const RecognizerConfig& config) : live(config) {}
    std::mutex mutex; // held while feeding samples
    LiveRecognizer live;
    std::size_t fed = 0; // samples of the stroke seen (tip up or down)
  };
  std::shared_ptr<State> live_state(std::uint64_t stroke_id, const PenSettings& settings) {
    std::lock_guard lock(mutex_);
    auto it = live_.find(stroke_id);
    if (it == live_.end()) {
      // One live recognizer per stroke in progress; strokes seldom overlap, keep few.
      if (live_.size() > 64) live_.clear();
      it = live_.emplace(stroke_id, std::make_shared<State>(config_for(settings))).first;
    }
    return it->second;
  }
  void forget(std::uint64_t stroke_id) {
    ink_ahead_.forget(stroke_id); // a pen-up's analysis already holds what it needs
    std::lock_guard lock(mutex_); // a preview still running keeps its own reference
    live_.erase(stroke_id);
  }
  std::mutex mutex_; // guards live_ only
  std::map<std::uint64_t, std::shared_ptr<State>> live_;
  InkAheadTable ink_ahead_; // live strokes' Q in progress
};

} // namespace

v1::Shape to_proto_shape(ShapeClass shape, const ShapeParams& params,
                         const std::vector<PointD>& clean, const Certificate& certificate,
                         double confidence) {
  v1::Shape out;
  out.set_kind(proto::to_proto(shape));
  if (shape == ShapeClass::kFreeform) return out;
  switch (shape) {
    case ShapeClass::kCircle: {
      auto* c = out.mutable_circle();
      set_point(params.center, c->mutable_center());
      c->set_radius(params.radius_x);
      break;
    }
    case ShapeClass::kEllipse: {
      auto* e = out.mutable_ellipse();
      set_point(params.center, e->mutable_center());
      e->set_semi_major(std::max(params.radius_x, params.radius_y));
      e->set_semi_minor(std::min(params.radius_x, params.radius_y));
      e->set_rotation_rad(params.rotation);
      break;
    }
    case ShapeClass::kArc: {
      auto* a = out.mutable_arc();
      set_point(params.center, a->mutable_center());
      a->set_radius(params.radius_x);
      a->set_start_rad(params.start_angle);
      a->set_sweep_rad(params.sweep_angle);
      break;
    }
    case ShapeClass::kArrow:
    case ShapeClass::kDoubleArrow: {
      auto* a = out.mutable_arrow();
      const std::vector<PointD>& v = params.vertices;
      set_point(v.at(0), a->mutable_tail());
      set_point(v.at(1), a->mutable_tip());
      for (std::size_t i = 2; i < 4; ++i) set_point(v.at(i), a->add_barbs());
      for (std::size_t i = 4; i < v.size(); ++i) set_point(v[i], a->add_tail_barbs());
      a->set_head_angle_rad(params.head_angle);
      a->set_shaft_bulge(params.shaft_bulge);
      for (const PointD& b : params.shaft_bends) set_point(b, a->add_shaft_bends());
      if (params.shaft_end) set_point(*params.shaft_end, a->mutable_shaft_end());
      break;
    }
    default: {
      auto* v = out.mutable_vertices();
      for (const PointD& p : params.vertices) set_point(p, v->add_vertices());
      break;
    }
  }
  // The clean path as straight pieces (circles come densely sampled from the recognizer); an
  // arrow whose shaft stops short of its tip is two pieces, the gap between them no segment.
  for (const std::vector<PointD>& piece : clean_pieces(shape, params, clean)) {
    for (std::size_t i = 0; i + 1 < piece.size(); ++i) {
      auto* seg = out.mutable_clean_path()->add_pieces()->mutable_segment();
      set_point(piece[i], seg->mutable_start());
      set_point(piece[i + 1], seg->mutable_end());
    }
  }
  out.set_confidence(confidence);
  auto* cert = out.mutable_certificate();
  to_proto(exact(certificate.pen_radius), cert->mutable_pen_radius());
  to_proto(exact(certificate.epsilon), cert->mutable_tolerance());
  to_proto(exact(certificate.bound), cert->mutable_hausdorff_bound());
  cert->set_method(certificate.method == "ink" ? "ink-hausdorff-sampling"
                                               : "path-hausdorff-sampling");
  return out;
}

std::shared_ptr<StrokeAnalyzer> make_recognizing_analyzer() {
  return std::make_shared<RecognizingAnalyzer>();
}

} // namespace penshape::daemon
