// The penshaped program itself: command line, config errors, systemd readiness, SIGTERM.
#include <fcntl.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "penshape/drivers/recording.hpp"
#include "penshape/drivers/replay.hpp"
#include "penshape/v1/config.grpc.pb.h"
#include "penshape/v1/live.grpc.pb.h"
#include "test_data.hpp"

namespace {

const std::string kPenshaped = std::string(PENSHAPE_BINARY_DIR) + "/daemon/penshaped";

class Sandbox {
 public:
  Sandbox() {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "penshaped-proc-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp");
    dir_ = pattern;
  }
  ~Sandbox() {
    if (notify_fd_ >= 0) ::close(notify_fd_);
    std::filesystem::remove_all(dir_);
  }
  [[nodiscard]] const std::string& dir() const { return dir_; }
  [[nodiscard]] std::string path(const std::string& name) const { return dir_ + "/" + name; }

  // A datagram socket standing in for systemd's notification socket.
  std::string listen_for_notifications() {
    notify_fd_ = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    std::string p = path("notify");
    std::strncpy(address.sun_path, p.c_str(), sizeof address.sun_path - 1);
    if (::bind(notify_fd_, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
      throw std::runtime_error("bind notify socket");
    }
    return p;
  }
  // The next notification, or "" after `timeout_ms`.
  [[nodiscard]] std::string next_notification(int timeout_ms) const {
    pollfd pfd{notify_fd_, POLLIN, 0};
    if (::poll(&pfd, 1, timeout_ms) != 1) return "";
    char buffer[512];
    const ssize_t n = ::recv(notify_fd_, buffer, sizeof buffer, 0);
    return n > 0 ? std::string(buffer, static_cast<std::size_t>(n)) : "";
  }

  // Starts penshaped with `args` and extra environment; stderr goes to a file.
  pid_t spawn(const std::vector<std::string>& args, const std::vector<std::string>& env) const {
    std::vector<std::string> argv_storage = {kPenshaped};
    argv_storage.insert(argv_storage.end(), args.begin(), args.end());
    std::vector<char*> argv;
    argv.reserve(argv_storage.size() + 1);
    for (auto& a : argv_storage) argv.push_back(a.data());
    argv.push_back(nullptr);
    std::vector<std::string> env_storage = env;
    env_storage.push_back("XDG_CONFIG_HOME=" + dir_ + "/config");
    for (char** e = environ; *e != nullptr; ++e) {
      const std::string entry = *e;
      if (entry.rfind("XDG_RUNTIME_DIR=", 0) != 0 && entry.rfind("NOTIFY_SOCKET=", 0) != 0 &&
          entry.rfind("JOURNAL_STREAM=", 0) != 0 && entry.rfind("XDG_CONFIG_HOME=", 0) != 0) {
        env_storage.push_back(entry);
      }
    }
    std::vector<char*> envp;
    envp.reserve(env_storage.size() + 1);
    for (auto& e : env_storage) envp.push_back(e.data());
    envp.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    const std::string err = path("stderr");
    posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    pid_t pid = -1;
    const int rc =
        posix_spawn(&pid, kPenshaped.c_str(), &actions, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    if (rc != 0) throw std::runtime_error("posix_spawn failed");
    return pid;
  }
  [[nodiscard]] std::string stderr_text() const {
    std::ifstream in(path("stderr"));
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }

 private:
  std::string dir_;
  int notify_fd_ = -1;
};

int exit_code(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

TEST(Penshaped, NotifiesReadinessServesAndStopsCleanlyOnSigterm) {
  Sandbox box;
  const std::string notify = box.listen_for_notifications();
  const pid_t pid = box.spawn({}, {"XDG_RUNTIME_DIR=" + box.dir(), "NOTIFY_SOCKET=" + notify});
  const std::string ready = box.next_notification(30'000);
  ASSERT_EQ(ready.rfind("READY=1\n", 0), 0U) << ready << box.stderr_text();
  const std::string socket = box.path("penshape.sock");
  EXPECT_NE(ready.find(socket), std::string::npos);

  struct stat st {};
  ASSERT_EQ(::stat(socket.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600U);
  auto config = penshape::v1::Config::NewStub(
      grpc::CreateChannel("unix:" + socket, grpc::InsecureChannelCredentials()));
  grpc::ClientContext ctx;
  ctx.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(10));
  penshape::v1::SettingsResponse settings;
  ASSERT_TRUE(config->GetSettings(&ctx, {}, &settings).ok());
  EXPECT_EQ(settings.effective().pen_radius_mm(), 1.0);

  ::kill(pid, SIGTERM);
  EXPECT_EQ(box.next_notification(30'000), "STOPPING=1");
  EXPECT_EQ(exit_code(pid), 0) << box.stderr_text();
  EXPECT_FALSE(std::filesystem::exists(socket));
  EXPECT_NE(box.stderr_text().find("shutting down"), std::string::npos);
}

TEST(Penshaped, ReadsItsConfigFile) {
  Sandbox box;
  const std::string notify = box.listen_for_notifications();
  std::ofstream(box.path("penshaped.conf"))
      << "listen = \"unix:" << box.path("custom.sock") << "\"\npen_radius_mm = 0.7\n";
  const pid_t pid = box.spawn({"--config", box.path("penshaped.conf")},
                              {"XDG_RUNTIME_DIR=" + box.dir(), "NOTIFY_SOCKET=" + notify});
  ASSERT_EQ(box.next_notification(30'000).rfind("READY=1", 0), 0U) << box.stderr_text();
  auto config = penshape::v1::Config::NewStub(
      grpc::CreateChannel("unix:" + box.path("custom.sock"), grpc::InsecureChannelCredentials()));
  grpc::ClientContext ctx;
  ctx.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(10));
  penshape::v1::SettingsResponse settings;
  ASSERT_TRUE(config->GetSettings(&ctx, {}, &settings).ok());
  EXPECT_EQ(settings.effective().pen_radius_mm(), 0.7);
  ::kill(pid, SIGINT);
  EXPECT_EQ(exit_code(pid), 0);
  EXPECT_FALSE(std::filesystem::exists(box.path("custom.sock")));
}

TEST(Penshaped, FindsItsConfigInXdgConfigHome) {
  Sandbox box;
  const std::string notify = box.listen_for_notifications();
  std::filesystem::create_directories(box.path("config/penshape"));
  std::ofstream(box.path("config/penshape/penshaped.conf")) << "tolerance_fraction = 0.3\n";
  const pid_t pid = box.spawn({}, {"XDG_RUNTIME_DIR=" + box.dir(), "NOTIFY_SOCKET=" + notify});
  ASSERT_EQ(box.next_notification(30'000).rfind("READY=1", 0), 0U) << box.stderr_text();
  auto config = penshape::v1::Config::NewStub(
      grpc::CreateChannel("unix:" + box.path("penshape.sock"), grpc::InsecureChannelCredentials()));
  grpc::ClientContext ctx;
  ctx.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(10));
  penshape::v1::SettingsResponse settings;
  ASSERT_TRUE(config->GetSettings(&ctx, {}, &settings).ok());
  EXPECT_EQ(settings.effective().tolerance_fraction(), 0.3);
  ::kill(pid, SIGTERM);
  EXPECT_EQ(exit_code(pid), 0);
}

TEST(Penshaped, ReplaysARecordingAsIfLive) {
  const std::string capture =
      (penshape::test::recordings_dir() / "generated-graphire.hidrec").string();
  const auto offline = penshape::drivers::replay(penshape::drivers::load_recording_file(capture),
                                                 penshape::drivers::ReplaySpeed::kAsFastAsPossible);
  ASSERT_GE(offline.strokes.size(), 3U);
  Sandbox box;
  const std::string notify = box.listen_for_notifications();
  // The capture lasts 12.7 s at its recorded pace; 2 s gives the client time to subscribe.
  const pid_t pid = box.spawn({"--replay", capture, "--replay-delay", "2"},
                              {"XDG_RUNTIME_DIR=" + box.dir(), "NOTIFY_SOCKET=" + notify});
  ASSERT_EQ(box.next_notification(30'000).rfind("READY=1", 0), 0U) << box.stderr_text();
  auto live = penshape::v1::Live::NewStub(
      grpc::CreateChannel("unix:" + box.path("penshape.sock"), grpc::InsecureChannelCredentials()));
  grpc::ClientContext ctx;
  ctx.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(60));
  auto reader = live->Subscribe(&ctx, {});
  std::vector<std::size_t> sizes;
  penshape::v1::LiveEvent event;
  while (sizes.size() < offline.strokes.size() && reader->Read(&event)) {
    if (event.has_stroke_finished()) {
      sizes.push_back(static_cast<std::size_t>(event.stroke_finished().stroke().samples_size()));
    }
  }
  ASSERT_EQ(sizes.size(), offline.strokes.size()) << box.stderr_text();
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    EXPECT_EQ(sizes[i], offline.strokes[i].samples.size());
  }
  ::kill(pid, SIGTERM);
  EXPECT_EQ(exit_code(pid), 0) << box.stderr_text();
  EXPECT_NE(box.stderr_text().find("replaying"), std::string::npos);
}

TEST(Penshaped, BadConfigAndCommandLineExitWithTwo) {
  Sandbox box;
  std::ofstream(box.path("bad.conf")) << "# ok\nworker_threads = \"many\"\n";
  pid_t pid = box.spawn({"--config", box.path("bad.conf")}, {"XDG_RUNTIME_DIR=" + box.dir()});
  EXPECT_EQ(exit_code(pid), 2);
  EXPECT_NE(box.stderr_text().find("bad.conf:2: worker_threads: expected an integer in 0..256, "
                                   "got 'many'"),
            std::string::npos)
      << box.stderr_text();

  pid = box.spawn({"--tcp", "192.0.2.1:7433"}, {"XDG_RUNTIME_DIR=" + box.dir()});
  EXPECT_EQ(exit_code(pid), 2);
  EXPECT_NE(box.stderr_text().find("not a loopback address"), std::string::npos);

  pid = box.spawn({"--replay-loop"}, {"XDG_RUNTIME_DIR=" + box.dir()});
  EXPECT_EQ(exit_code(pid), 2);
  EXPECT_NE(box.stderr_text().find("--replay-loop needs --replay"), std::string::npos);

  pid = box.spawn({"--frobnicate"}, {"XDG_RUNTIME_DIR=" + box.dir()});
  EXPECT_EQ(exit_code(pid), 2);
  EXPECT_FALSE(std::filesystem::exists(box.path("penshape.sock")));
}

// Files that are not recordings: each is bad input (exit 2) with a message naming the file and
// what is wrong, and nothing is left behind (the daemon never serves).
TEST(Penshaped, AFileThatIsNotARecordingExitsTwoNamingIt) {
  Sandbox box;
  const std::string good =
      (penshape::test::recordings_dir() / "generated-graphire.hidrec").string();
  const std::string text = penshape::test::read_file(good);
  std::ofstream(box.path("truncated.hidrec")) << text.substr(0, text.find("E: ") + 20);
  std::ofstream(box.path("no-events.hidrec")) << text.substr(0, text.find("E: "));
  std::ofstream(box.path("garbage.bin")) << std::string("\x05\x0d\x09\x02\xa1\x01\xff\xff", 8);
  std::ofstream(box.path("empty.hidrec")).close();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {box.path("missing.hidrec"), "cannot open"},
      {(penshape::test::recordings_dir() / "generated-graphire.expected").string(),
       "not a tablet recording"},
      {box.path("no-events.hidrec"), "no input reports"},
      {box.path("truncated.hidrec"), "truncated.hidrec"},
      {box.path("garbage.bin"), "not a tablet recording"},
      {box.path("empty.hidrec"), "empty.hidrec"},
  };
  for (const auto& [file, message] : cases) {
    SCOPED_TRACE(file);
    const pid_t pid = box.spawn({"--replay", file}, {"XDG_RUNTIME_DIR=" + box.dir()});
    EXPECT_EQ(exit_code(pid), 2) << box.stderr_text();
    EXPECT_NE(box.stderr_text().find(file), std::string::npos) << box.stderr_text();
    EXPECT_NE(box.stderr_text().find(message), std::string::npos) << box.stderr_text();
    EXPECT_EQ(box.stderr_text().find("terminate"), std::string::npos) << box.stderr_text();
    EXPECT_FALSE(std::filesystem::exists(box.path("penshape.sock")));
  }
}

// Several recordings play one after another, and --replay-loop starts over: the strokes of both
// arrive, then the first recording's again.
TEST(Penshaped, PlaysSeveralRecordingsAndLoops) {
  const auto dir = penshape::test::recordings_dir();
  const std::string a = (dir / "generated-graphire.hidrec").string();
  const std::string b = (dir / "generated-shapes.hidrec").string();
  const auto strokes_of = [](const std::string& file) {
    return penshape::drivers::replay(penshape::drivers::load_recording_file(file),
                                     penshape::drivers::ReplaySpeed::kAsFastAsPossible)
        .strokes.size();
  };
  const std::size_t want = strokes_of(a) + strokes_of(b) + strokes_of(a);
  Sandbox box;
  const std::string notify = box.listen_for_notifications();
  const pid_t pid =
      box.spawn({"--replay", a, "--replay", b, "--replay-loop", "--replay-delay", "2"},
                {"XDG_RUNTIME_DIR=" + box.dir(), "NOTIFY_SOCKET=" + notify});
  ASSERT_EQ(box.next_notification(30'000).rfind("READY=1", 0), 0U) << box.stderr_text();
  auto live = penshape::v1::Live::NewStub(
      grpc::CreateChannel("unix:" + box.path("penshape.sock"), grpc::InsecureChannelCredentials()));
  grpc::ClientContext ctx;
  ctx.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(120));
  auto reader = live->Subscribe(&ctx, {});
  std::size_t finished = 0;
  penshape::v1::LiveEvent event;
  while (finished < want && reader->Read(&event)) finished += event.has_stroke_finished() ? 1 : 0;
  EXPECT_EQ(finished, want) << box.stderr_text();
  ctx.TryCancel();
  ::kill(pid, SIGTERM);
  EXPECT_EQ(exit_code(pid), 0) << box.stderr_text();
}

} // namespace
