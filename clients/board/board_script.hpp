#pragma once
// `penshape-board --script FILE`: input for tests and demos, one command per line, run in order
// through the same event path as a real mouse or pen ('#' starts a comment):
//   down X Y | move X Y | up X Y    pointer at window pixel (X, Y): press, drag, release
//   key NAME                        a key press, by SDL key name ("u", "=", "-", "[", "]", "c")
//   wait-answers [SECONDS]          until the daemon has answered every stroke (default 20 s;
//                                   past it the board exits with code 1)
//   hold MS                         the pen stays down where it is for MS milliseconds (the board
//                                   repeats its position meanwhile, as a tablet does)
//   wait-held [SECONDS]             until the stroke being drawn shows a hold snap (default 20 s;
//                                   past it the board exits with code 1)
//   screenshot FILE                 the window's picture as a 24-bit BMP
//   quit
#include <stdexcept>
#include <string>
#include <vector>

namespace penshape::board {

struct ScriptCommand {
  enum class Op { kDown, kMove, kUp, kKey, kWaitAnswers, kHold, kWaitHeld, kScreenshot, kQuit };
  Op op = Op::kQuit;
  int x = 0;
  int y = 0;
  double seconds = 20;
  std::string text; // key name or file
};

struct ScriptError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Throws ScriptError naming the file, line and problem.
std::vector<ScriptCommand> read_script(const std::string& path);

} // namespace penshape::board
