// Runs of same-style strokes recognized on a pool of threads (see snap_pages.hpp).
#include "snap_pages.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <thread>

#include "clean_shape.hpp"
#include "drawn_direction.hpp"
#include "snap_error.hpp"

namespace penshape::snap {
namespace {

struct Run {
  std::size_t page = 0;
  std::vector<std::size_t> strokes; // indices into the page
  std::vector<StrokeSnap> snaps;    // the recognizer's answers
  std::string failure;              // the recognizer refused the run
};

bool has_distinct_points(const InkStroke& s) {
  return std::any_of(s.points.begin(), s.points.end(), [&](const StrokePoint& p) {
    return p.x != s.points.front().x || p.y != s.points.front().y;
  });
}

bool same_style(const InkStroke& a, const InkStroke& b) {
  const double ra = clean_pen_radius(a, SnapSettings{}), rb = clean_pen_radius(b, SnapSettings{});
  return a.style == b.style && std::abs(ra - rb) <= kGroupWidthTolerance * std::max(ra, rb);
}

// Whether stroke i of page p is writing to be left as drawn.
bool left_as_writing(const std::vector<std::vector<IntentDecision>>& intents, std::size_t p,
                     std::size_t i, const SnapSettings& settings) {
  return !settings.snap_writing && p < intents.size() && i < intents[p].size() &&
         intents[p][i].intent == Intent::kWriting;
}

std::vector<Run> runs_of(const std::vector<std::vector<const InkStroke*>>& pages,
                         const std::vector<std::vector<IntentDecision>>& intents,
                         const SnapSettings& settings) {
  std::vector<Run> runs;
  for (std::size_t p = 0; p < pages.size(); ++p) {
    const InkStroke* last = nullptr;
    for (std::size_t i = 0; i < pages[p].size(); ++i) {
      const InkStroke& s = *pages[p][i];
      // A dot has nothing to snap, and writing stays as written: either parts its neighbours.
      if (!has_distinct_points(s) || left_as_writing(intents, p, i, settings)) {
        last = nullptr;
        continue;
      }
      if (last == nullptr || !same_style(*last, s)) runs.push_back({p, {}, {}, {}});
      runs.back().strokes.push_back(i);
      last = &s;
    }
  }
  return runs;
}

// Recognizes every run on min(threads, runs) threads.
void recognize_runs(std::vector<Run>& runs, const std::vector<std::vector<const InkStroke*>>& pages,
                    const SnapSettings& settings, const PageRecognizer& recognize_page,
                    const Progress& progress, std::size_t threads) {
  std::size_t total = 0;
  for (const Run& r : runs) total += r.strokes.size();
  std::atomic<std::size_t> next{0}, done{0};
  std::mutex report;
  const auto work = [&] {
    for (std::size_t k = next.fetch_add(1); k < runs.size(); k = next.fetch_add(1)) {
      Run& run = runs[k];
      std::vector<InkStroke> inks;
      for (const std::size_t i : run.strokes) inks.push_back(*pages[run.page][i]);
      try {
        run.snaps = recognize_page(inks, settings);
      } catch (const SnapInputError& e) {
        run.failure = e.what();
      }
      const std::size_t now = done += run.strokes.size();
      if (progress) {
        const std::lock_guard<std::mutex> lock(report);
        progress(now, total);
      }
    }
  };
  std::vector<std::jthread> pool;
  for (std::size_t t = 1; t < std::min(threads, runs.size()); ++t) pool.emplace_back(work);
  work();
}

bool consecutive(const std::vector<std::size_t>& v) {
  for (std::size_t i = 1; i < v.size(); ++i) {
    if (v[i] != v[i - 1] + 1) return false;
  }
  return !v.empty();
}

} // namespace

std::vector<PageSnap> recognize_pages(const std::vector<std::vector<const InkStroke*>>& pages,
                                      const std::vector<std::vector<IntentDecision>>& intents,
                                      const SnapSettings& settings,
                                      const PageRecognizer& recognize_page,
                                      const Progress& progress, std::size_t threads,
                                      std::vector<std::string>& warnings) {
  std::vector<Run> runs = runs_of(pages, intents, settings);
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  recognize_runs(runs, pages, settings, recognize_page, progress, threads);
  std::vector<PageSnap> out;
  for (Run& run : runs) {
    if (!run.failure.empty()) warnings.push_back(run.failure + ": left as drawn");
    for (StrokeSnap& snap : run.snaps) {
      if (!is_snap(snap.recognition)) continue;
      std::vector<std::size_t> strokes;
      for (const std::size_t i : snap.strokes) strokes.push_back(run.strokes.at(i));
      std::sort(strokes.begin(), strokes.end());
      if (!consecutive(strokes)) continue; // not drawn one after the other: left as drawn
      const InkStroke& first = *pages[run.page][strokes.front()];
      const InkStroke& last = *pages[run.page][strokes.back()];
      const StrokePoint a = first.points.front(), b = last.points.back();
      const bool backwards = orient_like_drawn(snap.recognition, {a.x, a.y}, {b.x, b.y});
      const double pen = clean_pen_radius(first, settings);
      out.push_back({run.page, std::move(strokes), std::move(snap), pen, backwards});
    }
  }
  return out;
}

} // namespace penshape::snap
