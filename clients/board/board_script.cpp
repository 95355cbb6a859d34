#include "board_script.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

namespace penshape::board {

std::vector<ScriptCommand> read_script(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ScriptError("cannot read the script " + path);
  std::vector<ScriptCommand> out;
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    std::string op;
    if (!(words >> op)) continue;
    const std::string where = path + ":" + std::to_string(number) + ": ";
    ScriptCommand c;
    if (op == "down" || op == "move" || op == "up") {
      c.op = op == "down"   ? ScriptCommand::Op::kDown
             : op == "move" ? ScriptCommand::Op::kMove
                            : ScriptCommand::Op::kUp;
      if (!(words >> c.x >> c.y) || c.x < 0 || c.y < 0 || c.x > 100000 || c.y > 100000) {
        throw ScriptError(where + op + " needs two pixel coordinates >= 0");
      }
    } else if (op == "key") {
      c.op = ScriptCommand::Op::kKey;
      if (!(words >> c.text)) throw ScriptError(where + "key needs a key name");
    } else if (op == "wait-answers" || op == "wait-held") {
      c.op = op == "wait-held" ? ScriptCommand::Op::kWaitHeld : ScriptCommand::Op::kWaitAnswers;
      if (words >> c.seconds) {
        if (!std::isfinite(c.seconds) || c.seconds <= 0 || c.seconds > 3600) {
          throw ScriptError(where + op + " needs seconds in (0, 3600]");
        }
      }
    } else if (op == "hold") {
      c.op = ScriptCommand::Op::kHold;
      double ms = 0;
      if (!(words >> ms) || !std::isfinite(ms) || ms <= 0 || ms > 60000) {
        throw ScriptError(where + "hold needs milliseconds in (0, 60000]");
      }
      c.seconds = ms / 1000;
    } else if (op == "screenshot") {
      c.op = ScriptCommand::Op::kScreenshot;
      if (!(words >> c.text)) throw ScriptError(where + "screenshot needs a file name");
    } else if (op == "quit") {
      c.op = ScriptCommand::Op::kQuit;
    } else {
      throw ScriptError(where + "unknown command '" + op + "'");
    }
    std::string extra;
    if (words >> extra) throw ScriptError(where + "unexpected '" + extra + "'");
    out.push_back(c);
  }
  return out;
}

} // namespace penshape::board
