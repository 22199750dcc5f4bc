// The static file server behind `breakshot serve` (include/breakshot/serve.hpp).
//
// Deliberately small: one thread, one request per connection
// ("Connection: close"), GET and HEAD only, files read whole. The page is a
// handful of files on the loopback interface, so nothing more is needed,
// and every path a request can take is short enough to test.
#include "breakshot/serve.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace breakshot {
namespace http {
namespace {

constexpr std::size_t kMaxRequest = 16 * 1024;  // request line and headers

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// Percent-decodes a path; nullopt for a bad escape or a NUL.
std::optional<std::string> decode(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    char c = s[i];
    if (c == '%') {
      if (i + 2 >= s.size()) return std::nullopt;
      const int hi = hex_value(s[i + 1]);
      const int lo = hex_value(s[i + 2]);
      if (hi < 0 || lo < 0) return std::nullopt;
      c = static_cast<char>(hi * 16 + lo);
      i += 2;
    }
    if (c == '\0') return std::nullopt;
    out.push_back(c);
  }
  return out;
}

std::optional<std::string> real_path(const std::string& p) {
  char buf[PATH_MAX];
  if (::realpath(p.c_str(), buf) == nullptr) return std::nullopt;
  return std::string(buf);
}

bool is_regular_file(const std::string& p) {
  struct stat st {};
  return ::stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

std::optional<std::string> read_file(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) return std::nullopt;
  return ss.str();
}

std::string_view reason_phrase(int status) {
  switch (status) {
    case 200: return "OK";
    case 400: return "Bad Request";
    case 403: return "Forbidden";
    case 404: return "Not Found";
    case 405: return "Method Not Allowed";
    case 431: return "Request Header Fields Too Large";
    case 500: return "Internal Server Error";
    default: return "Error";
  }
}

Reply error_reply(int status, bool head = false) {
  Reply r;
  r.status = status;
  r.content_type = "text/plain; charset=utf-8";
  const std::string text = std::to_string(status) + " " + std::string(reason_phrase(status)) + "\n";
  r.content_length = text.size();
  if (!head) r.body = text;
  return r;
}

}  // namespace

std::string_view content_type(std::string_view path) {
  const auto dot = path.rfind('.');
  const auto slash = path.rfind('/');
  if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash)) {
    return "application/octet-stream";
  }
  const std::string_view ext = path.substr(dot + 1);
  if (ext == "html" || ext == "htm") return "text/html; charset=utf-8";
  if (ext == "js" || ext == "mjs") return "text/javascript; charset=utf-8";
  if (ext == "css") return "text/css; charset=utf-8";
  if (ext == "json") return "application/json";
  if (ext == "wasm") return "application/wasm";
  if (ext == "png") return "image/png";
  if (ext == "svg") return "image/svg+xml";
  if (ext == "ico") return "image/x-icon";
  if (ext == "txt" || ext == "md") return "text/plain; charset=utf-8";
  return "application/octet-stream";
}

std::optional<std::string> resolve(std::string_view target, const std::string& root) {
  if (target.empty() || target.front() != '/') return std::nullopt;
  const auto cut = target.find_first_of("?#");
  if (cut != std::string_view::npos) target = target.substr(0, cut);
  const auto decoded = decode(target);
  if (!decoded) return std::nullopt;
  // Walk the segments: "." and ".." are refused outright, empty ones
  // (a doubled slash) skipped, a backslash refused (never a separator here,
  // but no reason to accept it).
  std::string rel;
  std::size_t i = 1;
  const std::string& d = *decoded;
  while (i <= d.size()) {
    std::size_t j = d.find('/', i);
    if (j == std::string::npos) j = d.size();
    const std::string seg = d.substr(i, j - i);
    if (seg == "." || seg == ".." || seg.find('\\') != std::string::npos) return std::nullopt;
    if (!seg.empty()) {
      if (!rel.empty()) rel += '/';
      rel += seg;
    }
    i = j + 1;
  }
  std::string path = root + "/" + (rel.empty() ? std::string("index.html") : rel);
  if (!d.empty() && d.back() == '/' && !rel.empty()) path += "/index.html";
  // The real path must stay under the root, whatever symlinks say.
  const auto real = real_path(path);
  if (!real) return path;  // does not exist: the caller answers 404
  if (real->size() <= root.size() || real->compare(0, root.size(), root) != 0 ||
      (*real)[root.size()] != '/') {
    return std::nullopt;
  }
  return *real;
}

Reply answer(std::string_view request, const std::string& root) {
  const auto eol = request.find("\r\n");
  const std::string_view line = request.substr(0, eol);
  const auto sp1 = line.find(' ');
  const auto sp2 = sp1 == std::string_view::npos ? sp1 : line.find(' ', sp1 + 1);
  if (sp1 == std::string_view::npos || sp2 == std::string_view::npos) return error_reply(400);
  const std::string_view method = line.substr(0, sp1);
  const std::string_view target = line.substr(sp1 + 1, sp2 - sp1 - 1);
  const std::string_view version = line.substr(sp2 + 1);
  if (version != "HTTP/1.1" && version != "HTTP/1.0") return error_reply(400);
  const bool head = method == "HEAD";
  if (method != "GET" && !head) {
    return error_reply(405);
  }
  const auto path = resolve(target, root);
  if (!path) return error_reply(404, head);  // outside the root: as if absent
  if (!is_regular_file(*path)) return error_reply(404, head);
  auto body = read_file(*path);
  if (!body) return error_reply(403, head);
  Reply r;
  r.status = 200;
  r.content_type = std::string(content_type(*path));
  r.content_length = body->size();
  if (!head) r.body = std::move(*body);
  return r;
}

std::string format(const Reply& reply) {
  std::string out = "HTTP/1.1 " + std::to_string(reply.status) + " " +
                    std::string(reason_phrase(reply.status)) + "\r\n";
  out += "Content-Type: " + reply.content_type + "\r\n";
  out += "Content-Length: " + std::to_string(reply.content_length) + "\r\n";
  out += "Cache-Control: no-cache\r\n";
  out += "X-Content-Type-Options: nosniff\r\n";
  if (reply.status == 405) out += "Allow: GET, HEAD\r\n";
  out += "Connection: close\r\n\r\n";
  out += reply.body;
  return out;
}

}  // namespace http

namespace {

// Closes a descriptor when it goes out of scope.
struct Fd {
  int fd = -1;
  explicit Fd(int f) : fd(f) {}
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

bool stopped(const ServeOptions& o) { return o.stop != nullptr && o.stop->load(); }

// Reads up to the blank line that ends the headers. Empty on timeout,
// a closed connection or an oversized request (then `too_big`).
std::string read_request(int fd, const ServeOptions& o, bool& too_big) {
  std::string req;
  char buf[4096];
  too_big = false;
  for (int waited = 0; waited < 5000;) {
    pollfd p{fd, POLLIN, 0};
    const int n = ::poll(&p, 1, 100);
    if (n < 0 && errno != EINTR) return {};
    if (stopped(o)) return {};
    if (n <= 0) {
      waited += 100;
      continue;
    }
    const ssize_t got = ::recv(fd, buf, sizeof buf, 0);
    if (got <= 0) return {};
    req.append(buf, static_cast<std::size_t>(got));
    if (req.find("\r\n\r\n") != std::string::npos) return req;
    if (req.size() > http::kMaxRequest) {
      too_big = true;
      return {};
    }
  }
  return {};
}

void send_all(int fd, const std::string& data) {
  std::size_t sent = 0;
  while (sent < data.size()) {
    const ssize_t n = ::send(fd, data.data() + sent, data.size() - sent, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // the client went away
    sent += static_cast<std::size_t>(n);
  }
}

}  // namespace

void serve(const ServeOptions& options) {
  const auto root = http::real_path(options.root);
  if (!root || !http::is_regular_file(*root + "/index.html")) {
    throw std::runtime_error("no page to serve in '" + options.root +
                             "' (no index.html there; build it with scripts/web.sh)");
  }
  if (options.port < 0 || options.port > 65535) {
    throw std::runtime_error("port " + std::to_string(options.port) +
                             " is out of range (0 to 65535)");
  }
  in_addr addr{};
  if (::inet_pton(AF_INET, options.host.c_str(), &addr) != 1) {
    throw std::runtime_error("host '" + options.host + "' is not an IPv4 address");
  }
  Fd listener(::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0));
  if (listener.fd < 0) throw std::runtime_error(std::string("socket: ") + std::strerror(errno));
  const int one = 1;
  ::setsockopt(listener.fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  sockaddr_in sa{};
  sa.sin_family = AF_INET;
  sa.sin_port = htons(static_cast<std::uint16_t>(options.port));
  sa.sin_addr = addr;
  if (::bind(listener.fd, reinterpret_cast<const sockaddr*>(&sa), sizeof sa) != 0) {
    const int e = errno;
    if (e == EADDRINUSE) {
      throw std::runtime_error("port " + std::to_string(options.port) +
                               " is in use; choose another with --port (0 picks a free one)");
    }
    throw std::runtime_error("cannot listen on " + options.host + ":" +
                             std::to_string(options.port) + ": " + std::strerror(e));
  }
  if (::listen(listener.fd, 16) != 0) {
    throw std::runtime_error(std::string("listen: ") + std::strerror(errno));
  }
  socklen_t len = sizeof sa;
  ::getsockname(listener.fd, reinterpret_cast<sockaddr*>(&sa), &len);
  if (options.on_ready) options.on_ready(ntohs(sa.sin_port));

  while (!stopped(options)) {
    pollfd p{listener.fd, POLLIN, 0};
    const int n = ::poll(&p, 1, 100);
    if (n <= 0) continue;  // timeout (check stop) or EINTR
    Fd client(::accept4(listener.fd, nullptr, nullptr, SOCK_CLOEXEC));
    if (client.fd < 0) continue;
    bool too_big = false;
    const std::string req = read_request(client.fd, options, too_big);
    if (req.empty()) {
      if (too_big) send_all(client.fd, http::format(http::error_reply(431)));
      continue;
    }
    const http::Reply reply = http::answer(req, *root);
    send_all(client.fd, http::format(reply));
    if (options.log) {
      const auto eol = req.find("\r\n");
      options.log(req.substr(0, eol) + " " + std::to_string(reply.status));
    }
  }
}

}  // namespace breakshot
