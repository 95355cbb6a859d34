#include "board_script.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

namespace penshape::board {

namespace {

ScriptCommand pointer_command(const std::string& op, std::istringstream& words,
                              const std::string& where) {
  ScriptCommand c;
  c.op = op == "down"   ? ScriptCommand::Op::kDown
         : op == "move" ? ScriptCommand::Op::kMove
                        : ScriptCommand::Op::kUp;
  if (!(words >> c.x >> c.y) || c.x < 0 || c.y < 0 || c.x > 100000 || c.y > 100000) {
    throw ScriptError(where + op + " needs two pixel coordinates >= 0");
  }
  return c;
}

ScriptCommand wait_command(const std::string& op, std::istringstream& words,
                           const std::string& where) {
  ScriptCommand c;
  c.op = op == "wait-held" ? ScriptCommand::Op::kWaitHeld : ScriptCommand::Op::kWaitAnswers;
  if (words >> c.seconds) { // optional: the default wait otherwise
    if (!std::isfinite(c.seconds) || c.seconds <= 0 || c.seconds > 3600) {
      throw ScriptError(where + op + " needs seconds in (0, 3600]");
    }
  }
  return c;
}

ScriptCommand hold_command(std::istringstream& words, const std::string& where) {
  ScriptCommand c;
  c.op = ScriptCommand::Op::kHold;
  double ms = 0;
  if (!(words >> ms) || !std::isfinite(ms) || ms <= 0 || ms > 60000) {
    throw ScriptError(where + "hold needs milliseconds in (0, 60000]");
  }
  c.seconds = ms / 1000;
  return c;
}

// A command whose one argument is a word (a key name, a file name).
ScriptCommand word_command(ScriptCommand::Op op, const std::string& needs,
                           std::istringstream& words, const std::string& where) {
  ScriptCommand c;
  c.op = op;
  if (!(words >> c.text)) throw ScriptError(where + needs);
  return c;
}

ScriptCommand parse_command(const std::string& op, std::istringstream& words,
                            const std::string& where) {
  if (op == "down" || op == "move" || op == "up") return pointer_command(op, words, where);
  if (op == "wait-answers" || op == "wait-held") return wait_command(op, words, where);
  if (op == "hold") return hold_command(words, where);
  if (op == "key")
    return word_command(ScriptCommand::Op::kKey, "key needs a key name", words, where);
  if (op == "screenshot") {
    return word_command(ScriptCommand::Op::kScreenshot, "screenshot needs a file name", words,
                        where);
  }
  if (op == "quit") {
    ScriptCommand c;
    c.op = ScriptCommand::Op::kQuit;
    return c;
  }
  throw ScriptError(where + "unknown command '" + op + "'");
}

} // namespace

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
    out.push_back(parse_command(op, words, where));
    std::string extra;
    if (words >> extra) throw ScriptError(where + "unexpected '" + extra.append(1, '\''));
  }
  return out;
}

} // namespace penshape::board
