#pragma once
// Draws the board with SDL's renderer: strokes as the pen's ink (the path swept by a disk of
// the pen radius: thick segments with round joins), snapped shapes in red on top of a faint
// copy of the raw ink.
#include <SDL.h>

#include <string>
#include <vector>

#include "board_model.hpp"

namespace penshape::board {

struct Rgb {
  Uint8 r, g, b;
};
inline constexpr Rgb kBackground{255, 255, 255};
inline constexpr Rgb kRawInk{110, 70, 170};
inline constexpr Rgb kFaintInk{228, 220, 240};
inline constexpr Rgb kShapeInk{200, 30, 30};
inline constexpr Rgb kPreviewInk{245, 190, 190}; // a thin guide under the stroke being drawn

// The center line of a shape in window pixels, as a polyline (closed shapes repeat the first
// point at the end); circles, ellipses and arcs are sampled finely.
std::vector<PointPx> shape_polyline(const v1::Shape& shape);

void draw_board(SDL_Renderer* renderer, const BoardModel& model);

// Saves the renderer's current picture as a 24-bit BMP; false (with SDL_GetError) on failure.
bool save_screenshot(SDL_Renderer* renderer, const std::string& path);

} // namespace penshape::board
