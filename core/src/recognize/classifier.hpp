#pragma once
// The classifier shared by recognize() and the live recognizer: fit every family, certify the
// plausible fits, and choose the simplest certified shape.
#include <vector>

#include "fit.hpp"

namespace penshape::recognize_detail {

// A stroke is closed when its ends are within kClosureEpsilons * epsilon: only then can a closed
// shape certify (the clean shape's closing side must lie within epsilon of the ink), and only
// then are closed families tried; open strokes try the open families (segment, polyline, arc).
inline constexpr double kClosureEpsilons = 2.0; // see recognize.hpp, "Classes"
bool is_closed(const PreparedStroke& s, double epsilon);

// All family fits for a prepared stroke (families that do not apply are left out).
std::vector<Fit> fit_all(const PreparedStroke& s, const RecognizerConfig& config, double epsilon);

// Certifies the fits (skipping those whose fit error already exceeds the tolerance by far),
// checks their plausibility and chooses the winner.
Recognition classify(const PreparedStroke& s, std::vector<Fit> fits, double epsilon,
                     double pen_radius, const RecognizerConfig& config);

// Model complexity used to prefer simpler shapes (number of free parameters).
double degrees_of_freedom(const Fit& fit);

} // namespace penshape::recognize_detail
