#pragma once
// The daemon's limits: every bound a client can hit, its default and the status code it yields.
// The config file can change them (keys in brackets); the README's "Limits" table mirrors this.
//
// | limit                         | default      | config key              | when exceeded |
// |-------------------------------|--------------|-------------------------|------------------------|
// | request message size          | 16 MiB       | max_message_bytes       | RESOURCE_EXHAUSTED |
// | vertices in one polygon set   | 200,000      | max_vertices            | INVALID_ARGUMENT | |
// |coordinate| of a polygon     | 1e12         | (fixed)                 | INVALID_ARGUMENT       |
// | rational string length        | 4,096 chars  | (fixed)                 | INVALID_ARGUMENT | |
// precision delta               | >= r / 2^20  | (fixed)                 | INVALID_ARGUMENT       |
// | samples in one stroke         | 100,000      | max_stroke_samples      | INVALID_ARGUMENT | |
// geometry call duration        | 120 s        | max_call_seconds        | DEADLINE_EXCEEDED      |
// | queued geometry jobs          | 64           | worker_queue_jobs       | RESOURCE_EXHAUSTED |
// (per lane: geometry RPCs on worker_threads, stroke analyses on stroke_worker_threads; see
// daemon_state.hpp for the lanes and their priorities)
// | concurrent subscribers        | 128          | max_subscribers         | RESOURCE_EXHAUSTED |
// | events queued per subscriber  | 1,024        | subscriber_queue_events | oldest dropped,
// counted|
// | raw-report subscribers        | 8            | max_raw_report_subscribers | RES._EXHAUSTED |
// | SubmitStroke group_keys kept  | 64           | max_group_keys          | LRU key forgotten |
// | group_key length              | 128 bytes    | (fixed)                 | INVALID_ARGUMENT |
// (each StreamSamples stream groups its own strokes: streams count within max_subscribers; every
// grouping keeps only the strokes its window can reach, at most 6 * (group_max_strokes - 1))
//
// Why delta >= r / 2^20: the engines approximate disks of radius r by polygons D̄_{a,b} with
// b - a about delta; their vertex count grows like 4·sqrt(r / (2·delta)), which reaches the core's
// 4,096-vertex disk limit near r / delta = 2^21. The bound keeps requests well inside it.
// A deadline the client does not set, or sets beyond max_call_seconds, is cut to max_call_seconds.
#include <cstddef>
#include <cstdint>

namespace penshape::daemon {

struct Limits {
  std::size_t max_message_bytes = 16U << 20U;
  std::size_t max_vertices = 200'000;
  double max_abs_coordinate = 1e12;
  std::size_t max_rational_chars = 4'096;
  // delta * min_precision_denominator >= r.
  std::uint32_t min_precision_denominator = 1U << 20U;
  std::size_t max_stroke_samples = 100'000;
  std::uint32_t max_call_seconds = 120;
  std::size_t worker_queue_jobs = 64;
  std::size_t worker_threads = 0;        // geometry RPC workers; 0: one per hardware thread
  std::size_t stroke_worker_threads = 0; // stroke analysis workers; 0: one per hardware thread
  std::size_t max_subscribers = 128;
  std::size_t subscriber_queue_events = 1'024;
  // Subscribe calls with include_raw_reports at once (each gets every report of its devices, up
  // to the tablets' report rate); counted within max_subscribers. 0 turns raw reports off.
  std::size_t max_raw_report_subscribers = 8;
  // SubmitStroke group_keys whose groupings are kept; a new key beyond them forgets the least
  // recently used one. Each grouping keeps at most 6 * (group_max_strokes - 1) strokes.
  std::size_t max_group_keys = 64;
  std::size_t max_group_key_bytes = 128;
};

} // namespace penshape::daemon
