// A small static file server for the browser version (docs/web.md):
// `breakshot serve` serves the built page on the loopback interface.
//
// It answers GET and HEAD for files under one root folder, one request
// per connection, on 127.0.0.1 only. Nothing outside the root is ever
// served: the path is percent-decoded, "." and ".." segments are refused,
// and the resolved file must lie under the root's real path (so a symlink
// cannot lead out either).
#pragma once
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace breakshot {

struct ServeOptions {
  std::string root;                ///< folder to serve; must hold index.html
  std::string host = "127.0.0.1";  ///< an IPv4 address to listen on
  int port = 8000;                 ///< 0: any free port (on_ready tells which)
  /// Called once the socket listens, with the port it got.
  std::function<void(int port)> on_ready;
  /// When set, the server returns once it becomes true (checked at least
  /// every 100 ms).
  const std::atomic<bool>* stop = nullptr;
  /// Each request line of the log, when set ("GET /index.html 200").
  std::function<void(const std::string& line)> log;
};

/// Serves until `stop` (or forever). Throws std::runtime_error with a
/// reason for a root without index.html, a bad host, a port out of range
/// or in use.
void serve(const ServeOptions& options);

/// The parts of serving that need no socket, for tests.
namespace http {

struct Reply {
  int status = 200;
  std::string content_type;
  std::string body;  ///< empty for HEAD (content_length keeps the size)
  std::size_t content_length = 0;
};

/// The reply to one request (its raw text up to the blank line) for files
/// under `root` (a real path, no trailing slash).
Reply answer(std::string_view request, const std::string& root);

/// The file a request target names under `root`, or nullopt if it is
/// malformed or would leave the root. "/" names index.html; the query and
/// fragment are ignored.
std::optional<std::string> resolve(std::string_view target, const std::string& root);

/// Content type by file extension ("text/html; charset=utf-8", ...).
std::string_view content_type(std::string_view path);

/// The whole response as bytes: status line, headers, body.
std::string format(const Reply& reply);

}  // namespace http
}  // namespace breakshot
