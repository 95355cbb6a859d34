#pragma once
// The hand and the pen, between an ideal path and the samples a tablet logs: corner rounding,
// wobble, end hooks, a speed profile that slows in bends and at the ends, sampling, tremor and
// pressure. Internal to the stroke generator; the numbers come from stroke_measurements.hpp.
#include <vector>

#include "rng.hpp"
#include "stroke_gen.hpp"

namespace penshape::gen {

struct Pt {
  double x = 0.0;
  double y = 0.0;
};

// A polygonal path with its vertices rounded: each vertex is replaced by a quadratic curve that
// starts and ends `radius` away from it along its edges (less on short edges).
std::vector<Pt> round_corners(const std::vector<Pt>& path, double radius);

// The path resampled every `step` of arc length (first and last points kept).
std::vector<Pt> resample(const std::vector<Pt>& path, double step);

// The path's RMS low-frequency sideways drift of a hand at this size (diagonal) and speed.
double wobble_rms(double diagonal, double speed);

// Adds `rms` of smooth sideways drift: a few random sine waves along the path of 1 to 4 cycles
// per circumference of a circle of this diagonal (the measured wobble is that of circles, so its
// wavelengths are a circle's; a line of the same size gets the same wavelengths, not more waves).
void add_wobble(std::vector<Pt>& path, double rms, double diagonal, Rng& rng);

// Appends a short hook (a quick turn of the pen as it lifts) of `length`.
void add_hook(std::vector<Pt>& path, double length, Rng& rng);

// The pen moving along `path` at mean `speed` (px/s) from time `t0`, logged every measured
// sample interval, with tremor and a pressure profile.
GenStroke sample_pen(const std::vector<Pt>& path, double speed, double t0, Rng& rng);

// The measured mean speed of a speed class, varied per drawing.
double pen_speed(Speed speed, Rng& rng);

} // namespace penshape::gen
