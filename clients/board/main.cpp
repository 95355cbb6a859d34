// penshape-board: a window to draw in with a mouse or pen; every stroke goes to penshaped
// (Live.StreamSamples) and snaps to the shape the daemon certifies. Keys: + / - pen radius,
// ] / [ tolerance, u (or Ctrl+Z) undo back to the raw stroke, c clear, s screenshot, q quit.
#include <SDL.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <deque>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "args.hpp"
#include "board_model.hpp"
#include "board_script.hpp"
#include "board_view.hpp"
#include "daemon_channel.hpp"
#include "daemon_link.hpp"
#include "live_event_text.hpp"

namespace {

using namespace penshape;
using namespace penshape::board;

constexpr const char* kUsage =
    "usage: penshape-board [--radius MM] [--tolerance FRACTION] [--size WxH]\n"
    "                      [--script FILE] [--socket PATH | --address ADDR]\n\n"
    "A drawing board: draw with the mouse or a pen; each stroke is sent to penshaped and\n"
    "snaps to the shape it certifies (drawn in red).\n\n"
    "keys: + / -  pen radius (x1.25)      ] / [  tolerance (x1.25)\n"
    "      u or Ctrl+Z  undo: the last snapped stroke goes back to its raw form, then away\n"
    "      c  clear      s  screenshot (penshape-board.bmp)      q / Esc  quit\n\n"
    "options:\n"
    "  --radius MM          pen radius in mm (default 1; 4 window pixels are 1 mm)\n"
    "  --tolerance FRACTION tolerance as a fraction of the radius (default 0.5) of the ink's\n"
    "                       outline; shapes snap with the recognizer's own rule, which follows\n"
    "                       the drawing: min(0.125 S + r, 0.135 S), S the shape's size\n"
    "  --size WxH           window size in pixels (default 800x600)\n"
    "  --script FILE        run the commands in FILE (see clients/board/board_script.hpp)\n"
    "  --socket PATH        the daemon's unix socket (default: $XDG_RUNTIME_DIR/penshape.sock)\n"
    "  --address ADDR       a gRPC address instead: unix:PATH, unix-abstract:NAME, HOST:PORT\n\n"
    "Exit codes: 0 ok, 2 bad usage or script, 1 daemon not running, no display, or failed.\n";

// Limits of the settings the daemon accepts (daemon/include/penshape/daemon/pen_settings.hpp).
constexpr double kMinRadius = 0.05, kMaxRadius = 50, kMinTolerance = 0.01, kMaxTolerance = 4;

struct Options {
  double radius = 1.0;
  double tolerance = 0.5;
  int width = 800;
  int height = 600;
  std::optional<std::string> script;
  std::string address;
};

Options parse_options(int argc, char** argv) {
  const std::vector<std::string_view> args(argv + 1, argv + argc);
  const cli::ParsedArgs parsed(
      args, cli::live_arg_spec(
                {.flags = {}, .options = {"--radius", "--tolerance", "--size", "--script"}}));
  if (parsed.flag("--help")) {
    std::fputs(kUsage, stdout);
    std::exit(0);
  }
  if (!parsed.positionals().empty()) {
    throw cli::UsageError("unexpected argument '" + parsed.positionals().front() + "'");
  }
  Options o;
  o.address = cli::daemon_address(parsed);
  if (auto r = parsed.number("--radius")) {
    if (*r < kMinRadius || *r > kMaxRadius) throw cli::UsageError("--radius must be in [0.05, 50]");
    o.radius = *r;
  }
  if (auto t = parsed.number("--tolerance")) {
    if (*t < kMinTolerance || *t > kMaxTolerance) {
      throw cli::UsageError("--tolerance must be in [0.01, 4]");
    }
    o.tolerance = *t;
  }
  if (auto size = parsed.value("--size")) {
    int w = 0, h = 0;
    char x = 0;
    if (std::sscanf(size->c_str(), "%d%c%d", &w, &x, &h) != 3 || x != 'x' || w < 100 || h < 100 ||
        w > 8192 || h > 8192) {
      throw cli::UsageError("--size must be WxH with 100..8192 pixels each");
    }
    o.width = w;
    o.height = h;
  }
  o.script = parsed.value("--script");
  return o;
}

void say(const std::string& line) {
  std::printf("board: %s\n", line.c_str());
  std::fflush(stdout);
}

// Events from the daemon's thread, handed to the UI thread.
class Inbox {
 public:
  explicit Inbox(Uint32 wake_event) : wake_(wake_event) {}
  void push(v1::LiveEvent e) {
    {
      std::lock_guard lock(m_);
      events_.push_back(std::move(e));
    }
    wake();
  }
  void error(std::string message) {
    {
      std::lock_guard lock(m_);
      errors_.push_back(std::move(message));
    }
    wake();
  }
  void drain(std::vector<v1::LiveEvent>& events, std::vector<std::string>& errors) {
    std::lock_guard lock(m_);
    events.assign(events_.begin(), events_.end());
    events_.clear();
    errors.assign(errors_.begin(), errors_.end());
    errors_.clear();
  }

 private:
  void wake() const {
    SDL_Event e{};
    e.type = wake_;
    SDL_PushEvent(&e);
  }
  Uint32 wake_;
  std::mutex m_;
  std::deque<v1::LiveEvent> events_;
  std::deque<std::string> errors_;
};

std::string describe_shape(const v1::Shape& shape) {
  std::string out = cli::shape_kind_name(shape.kind());
  const auto line = shape_polyline(shape);
  if (shape.params_case() == v1::Shape::kVertices) {
    out += ", vertices px";
    char buf[64];
    for (const auto& p : shape.vertices().vertices()) {
      std::snprintf(buf, sizeof buf, " (%.2f,%.2f)", p.x() * kPixelsPerMm, p.y() * kPixelsPerMm);
      out += buf;
    }
  }
  (void)line;
  return out;
}

class Board {
 public:
  Board(const Options& o, SDL_Window* window, SDL_Renderer* renderer,
        std::shared_ptr<grpc::Channel> channel, Uint32 wake_event)
      : options_(o),
        window_(window),
        renderer_(renderer),
        inbox_(wake_event),
        link_(
            std::move(channel), o.width, o.height,
            [this](const v1::LiveEvent& e) { inbox_.push(e); },
            [this](const std::string& m) { inbox_.error(m); }) {
    link_.start(radius_, tolerance_);
    update_title();
  }

  void handle(const SDL_Event& e) {
    switch (e.type) {
      case SDL_QUIT:
        running_ = false;
        break;
      case SDL_MOUSEBUTTONDOWN:
        if (e.button.button == SDL_BUTTON_LEFT) pointer(e.button.x, e.button.y, true, false);
        break;
      case SDL_MOUSEMOTION:
        if (model_.drawing() && (e.motion.state & SDL_BUTTON_LMASK) != 0) {
          pointer(e.motion.x, e.motion.y, true, true);
        }
        break;
      case SDL_MOUSEBUTTONUP:
        if (e.button.button == SDL_BUTTON_LEFT && model_.drawing()) {
          pointer(e.button.x, e.button.y, false, true);
        }
        break;
      case SDL_KEYDOWN:
        key(e.key.keysym.sym, (e.key.keysym.mod & KMOD_CTRL) != 0);
        break;
      case SDL_WINDOWEVENT:
        dirty_ = true;
        break;
      default:
        break;
    }
  }

  void on_stroke_finished(const v1::StrokeFinished& f) {
    if (f.not_analysed().empty()) {
      model_.server_finished(f.stroke().id());
      return;
    }
    const int i = model_.server_not_analysed(f.stroke().id(), f.not_analysed());
    if (i >= 0) say("stroke " + std::to_string(i + 1) + " not analysed: " + f.not_analysed());
    dirty_ = true;
  }

  void on_shape(const v1::ShapeRecognized& s) {
    if (s.trigger() == v1::SHAPE_TRIGGER_HOLD || s.trigger() == v1::SHAPE_TRIGGER_FOLLOW) {
      const int i = model_.server_held(s.stroke_id(), s.shape());
      if (i >= 0 && s.trigger() == v1::SHAPE_TRIGGER_HOLD) {
        say("stroke " + std::to_string(i + 1) + " held: " + describe_shape(s.shape()));
      }
      dirty_ = dirty_ || i >= 0;
      return;
    }
    const int i = model_.server_shape(s.stroke_id(), s.shape());
    if (i >= 0) {
      last_ = cli::shape_kind_name(s.shape().kind());
      say("stroke " + std::to_string(i + 1) + " is a " + describe_shape(s.shape()));
    }
    dirty_ = true;
    update_title();
  }

  void on_event(const v1::LiveEvent& e) {
    if (e.has_stroke_started()) {
      model_.server_stroke_started(e.stroke_started().stroke_id());
    } else if (e.has_stroke_finished()) {
      on_stroke_finished(e.stroke_finished());
    } else if (e.has_preview()) {
      const auto& p = e.preview();
      if (model_.server_preview(p.stroke_id(),
                                p.candidates_size() > 0 ? &p.candidates(0) : nullptr) >= 0) {
        dirty_ = true;
      }
    } else if (e.has_shape()) {
      on_shape(e.shape());
    }
  }

  void poll_daemon() {
    std::vector<v1::LiveEvent> events;
    std::vector<std::string> errors;
    inbox_.drain(events, errors);
    for (const auto& e : events) on_event(e);
    for (const auto& m : errors) {
      disconnected_ = m;
      say("disconnected: " + m);
      update_title();
    }
  }

  void render_if_needed() {
    if (!dirty_) return;
    draw_board(renderer_, model_);
    SDL_RenderPresent(renderer_);
    dirty_ = false;
  }

  bool screenshot(const std::string& path) {
    draw_board(renderer_, model_);
    const bool ok = save_screenshot(renderer_, path);
    SDL_RenderPresent(renderer_);
    say(ok ? "screenshot " + path : "screenshot " + path + " failed: " + SDL_GetError());
    return ok;
  }

  // Waits for every answer the daemon will give: restarting the stream ends the previous call
  // only after the daemon has sent all its events. Strokes that then have no shape get none.
  void sync() {
    if (model_.drawing()) return;
    link_.start(radius_, tolerance_);
    poll_daemon();
    std::vector<bool> before;
    for (const auto& s : model_.strokes()) before.push_back(s.answered);
    if (model_.settle_finished() == 0) return;
    const auto& strokes = model_.strokes();
    for (std::size_t i = 0; i < strokes.size(); ++i) {
      if (!before[i] && strokes[i].answered) {
        say("stroke " + std::to_string(i + 1) + ": " + strokes[i].note);
      }
    }
  }

  // While the pen is down and still, its position is sent again every kKeepAlive, as a tablet
  // keeps reporting: the daemon's hold to snap decides on the samples it gets.
  static constexpr std::chrono::milliseconds kKeepAlive{10};
  void keep_alive() {
    if (!model_.drawing() || model_.strokes().empty()) return;
    if (std::chrono::steady_clock::now() - last_sent_ < kKeepAlive) return;
    const PointPx p = model_.strokes().back().points.back();
    send(p, true);
  }

  [[nodiscard]] bool running() const { return running_; }
  void stop() { running_ = false; }
  [[nodiscard]] const BoardModel& model() const { return model_; }

 private:
  void pointer(int x, int y, bool tip, bool continuing) {
    const PointPx p{static_cast<float>(x), static_cast<float>(y)};
    if (tip && !continuing) {
      model_.begin_stroke(p, static_cast<float>(radius_ * kPixelsPerMm));
    } else if (tip) {
      model_.extend_stroke(p);
    } else {
      model_.end_stroke(p);
    }
    send(p, tip);
    dirty_ = true;
  }

  void send(PointPx p, bool tip) {
    // Sample times from a steady clock: they must never go back.
    const auto now = std::chrono::steady_clock::now();
    last_sent_ = now;
    time_us_ = std::max(
        time_us_ + 1,
        std::chrono::duration_cast<std::chrono::microseconds>(now.time_since_epoch()).count());
    if (!link_.send(p.x, p.y, tip, time_us_) && disconnected_.empty()) {
      disconnected_ = "the daemon's stream is closed";
      update_title();
    }
  }

  void key(SDL_Keycode k, bool ctrl) {
    if (k == SDLK_q || k == SDLK_ESCAPE) running_ = false;
    if (k == SDLK_u || (ctrl && k == SDLK_z)) say("undo: " + model_.undo());
    if (k == SDLK_c) model_.clear();
    if (k == SDLK_s) screenshot("penshape-board.bmp");
    double radius = radius_, tolerance = tolerance_;
    if (k == SDLK_EQUALS || k == SDLK_PLUS || k == SDLK_KP_PLUS) radius *= 1.25;
    if (k == SDLK_MINUS || k == SDLK_KP_MINUS) radius /= 1.25;
    if (k == SDLK_RIGHTBRACKET) tolerance *= 1.25;
    if (k == SDLK_LEFTBRACKET) tolerance /= 1.25;
    radius = std::clamp(radius, kMinRadius, kMaxRadius);
    tolerance = std::clamp(tolerance, kMinTolerance, kMaxTolerance);
    if ((radius != radius_ || tolerance != tolerance_) && !model_.drawing()) {
      radius_ = radius;
      tolerance_ = tolerance;
      link_.start(radius_, tolerance_); // the settings travel with the stream's start
      char buf[96];
      std::snprintf(buf, sizeof buf, "settings: radius %.3f mm, tolerance %.3f", radius_,
                    tolerance_);
      say(buf);
    }
    dirty_ = true;
    update_title();
  }

  void update_title() {
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "penshape board | pen r = %.2f mm (+/-) | tolerance %.2f r ([/]) | u undo | %s",
                  radius_, tolerance_,
                  disconnected_.empty() ? ("last: " + last_).c_str()
                                        : ("DISCONNECTED: " + disconnected_).c_str());
    SDL_SetWindowTitle(window_, buf);
  }

  Options options_;
  SDL_Window* window_;
  SDL_Renderer* renderer_;
  Inbox inbox_;
  DaemonLink link_;
  BoardModel model_;
  double radius_ = options_.radius;
  double tolerance_ = options_.tolerance;
  std::int64_t time_us_ = 0;
  std::chrono::steady_clock::time_point last_sent_;
  bool running_ = true;
  bool dirty_ = true;
  std::string last_ = "-";
  std::string disconnected_;
};

// Pushes the left-button event a script command stands for: pressed, released, or dragged.
void push_mouse_event(const ScriptCommand& c) {
  SDL_Event e{};
  if (c.op == ScriptCommand::Op::kMove) {
    e.type = SDL_MOUSEMOTION;
    e.motion.state = SDL_BUTTON_LMASK;
    e.motion.x = c.x;
    e.motion.y = c.y;
  } else {
    const bool down = c.op == ScriptCommand::Op::kDown;
    e.type = down ? SDL_MOUSEBUTTONDOWN : SDL_MOUSEBUTTONUP;
    e.button.button = SDL_BUTTON_LEFT;
    e.button.state = down ? SDL_PRESSED : SDL_RELEASED;
    e.button.x = c.x;
    e.button.y = c.y;
  }
  SDL_PushEvent(&e);
}

// Runs the script one command per loop turn, so the events each command pushes are handled
// (and drawn) before the next one.
class ScriptRunner {
 public:
  explicit ScriptRunner(std::vector<ScriptCommand> commands) : commands_(std::move(commands)) {}

  // Returns false when the script failed (the board then exits with 1).
  bool step(Board& board) {
    if (next_ >= commands_.size()) return true;
    const ScriptCommand& c = commands_[next_];
    SDL_Event e{};
    switch (c.op) {
      case ScriptCommand::Op::kDown:
      case ScriptCommand::Op::kUp:
      case ScriptCommand::Op::kMove:
        push_mouse_event(c);
        break;
      case ScriptCommand::Op::kKey:
        e.type = SDL_KEYDOWN;
        e.key.state = SDL_PRESSED;
        e.key.keysym.sym = SDL_GetKeyFromName(c.text.c_str());
        if (e.key.keysym.sym == SDLK_UNKNOWN) {
          say("script: unknown key '" + c.text + "'");
          return false;
        }
        SDL_PushEvent(&e);
        break;
      case ScriptCommand::Op::kWaitAnswers: {
        if (!waiting_) {
          waiting_ = true;
          deadline_ = std::chrono::steady_clock::now() +
                      std::chrono::milliseconds(static_cast<long>(c.seconds * 1000));
        }
        // Once the daemon has finished every stroke, drain the stream: a shape that has not
        // come by then will not come.
        if (!board.model().all_answered() && board.model().all_finished_or_answered()) {
          board.sync();
        }
        if (board.model().all_answered() && !board.model().drawing()) {
          waiting_ = false;
          break;
        }
        if (std::chrono::steady_clock::now() > deadline_) {
          say("script: the daemon did not answer every stroke in time");
          return false;
        }
        return true; // try again next turn
      }
      case ScriptCommand::Op::kHold:
      case ScriptCommand::Op::kWaitHeld:
        if (!waited(board, c)) return c.op == ScriptCommand::Op::kHold || !timed_out();
        break;
      case ScriptCommand::Op::kScreenshot:
        if (!board.screenshot(c.text)) return false;
        break;
      case ScriptCommand::Op::kQuit:
        board.stop();
        break;
    }
    ++next_;
    return true;
  }

 private:
  // hold: its time has passed; wait-held: the stroke being drawn shows a hold snap. Starts the
  // command's clock on its first turn and stops it when done.
  bool waited(const Board& board, const ScriptCommand& c) {
    if (!waiting_) {
      waiting_ = true;
      deadline_ = std::chrono::steady_clock::now() +
                  std::chrono::milliseconds(static_cast<long>(c.seconds * 1000));
    }
    const auto& strokes = board.model().strokes();
    const bool done = c.op == ScriptCommand::Op::kHold
                          ? std::chrono::steady_clock::now() >= deadline_
                          : !strokes.empty() && strokes.back().held.has_value();
    if (done) waiting_ = false;
    return done;
  }
  bool timed_out() {
    if (std::chrono::steady_clock::now() <= deadline_) return false;
    say("script: no hold snap in time");
    return true;
  }

  std::vector<ScriptCommand> commands_;
  std::size_t next_ = 0;
  bool waiting_ = false;
  std::chrono::steady_clock::time_point deadline_;
};

int run(const Options& o) {
  std::optional<ScriptRunner> script;
  if (o.script) script.emplace(read_script(*o.script));
  std::shared_ptr<grpc::Channel> channel;
  try {
    channel = cli::connect_to_daemon(o.address);
  } catch (const cli::DaemonUnavailable& e) {
    std::fprintf(stderr, "penshape-board: %s\n", e.what());
    return 1;
  }
  if (SDL_Init(SDL_INIT_VIDEO | SDL_INIT_EVENTS) != 0) {
    std::fprintf(stderr, "penshape-board: no display (%s)\n", SDL_GetError());
    return 1;
  }
  SDL_Window* window = SDL_CreateWindow("penshape board", SDL_WINDOWPOS_CENTERED,
                                        SDL_WINDOWPOS_CENTERED, o.width, o.height, 0);
  // Software rendering: the same pixels everywhere (Xvfb, CI, remote displays).
  SDL_Renderer* renderer = window ? SDL_CreateRenderer(window, -1, SDL_RENDERER_SOFTWARE) : nullptr;
  if (renderer == nullptr) {
    std::fprintf(stderr, "penshape-board: cannot open a window (%s)\n", SDL_GetError());
    if (window) SDL_DestroyWindow(window);
    SDL_Quit();
    return 1;
  }
  const Uint32 wake_event = SDL_RegisterEvents(1);
  int code = 0;
  {
    Board board(o, window, renderer, channel, wake_event);
    say("connected to " + o.address);
    while (board.running()) {
      if (script && !script->step(board)) {
        code = 1;
        break;
      }
      SDL_Event e;
      // Sleep until something happens (a script turn, or a pen resting down, does not wait long).
      const int timeout_ms = board.model().drawing() ? 5 : script ? 5 : 250;
      if (SDL_WaitEventTimeout(&e, timeout_ms) != 0) {
        board.handle(e);
        while (SDL_PollEvent(&e) != 0) board.handle(e);
      }
      board.keep_alive();
      board.poll_daemon();
      board.render_if_needed();
    }
  } // the stream ends here: the daemon's last answers arrive before the window closes
  SDL_DestroyRenderer(renderer);
  SDL_DestroyWindow(window);
  SDL_Quit();
  return code;
}

} // namespace

int main(int argc, char** argv) {
  try {
    return run(parse_options(argc, argv));
  } catch (const cli::UsageError& e) {
    std::fprintf(stderr, "penshape-board: %s (see --help)\n", e.what());
    return 2;
  } catch (const ScriptError& e) {
    std::fprintf(stderr, "penshape-board: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "penshape-board: internal error: %s\n", e.what());
    return 1;
  }
}
