#include "unix_socket.hpp"

#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace penshape::daemon {

std::string unix_socket_path(const std::string& address) {
  constexpr std::string_view prefix = "unix:";
  if (address.rfind(prefix, 0) != 0) return "";
  std::string path = address.substr(prefix.size());
  // "unix:///path" is the URI form of the same path.
  if (path.rfind("//", 0) == 0) path = path.substr(2);
  return path;
}

void refuse_if_in_use(const std::string& path) {
  sockaddr_un address{};
  if (path.size() >= sizeof address.sun_path) {
    throw std::runtime_error("socket path too long (" + std::to_string(path.size()) +
                             " bytes): " + path);
  }
  address.sun_family = AF_UNIX;
  std::memcpy(address.sun_path, path.c_str(), path.size() + 1);
  const int fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) throw std::runtime_error(std::string("socket: ") + std::strerror(errno));
  const int rc = ::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address);
  ::close(fd);
  if (rc == 0) {
    throw std::runtime_error("another daemon is listening on " + path +
                             " (stop it, or pass --listen with another address)");
  }
}

void make_owner_only(const std::string& path) {
  if (::chmod(path.c_str(), S_IRUSR | S_IWUSR) != 0) {
    throw std::runtime_error("chmod 0600 " + path + ": " + std::strerror(errno));
  }
}

} // namespace penshape::daemon
