// The server of the browser version (docs/web.md): `breakshot serve`
// serves the built page and hosts online games (rooms.hpp) over a
// WebSocket on the same port, at kWebSocketPath.
//
// One thread runs an event loop (Boost.Asio) that serves many connections
// at once; a client that sends its request slowly, or not at all, or
// never reads, holds only its own connection, until its timeout closes it.
// Files: GET and HEAD under one root folder, one request per connection.
// Nothing outside the root is ever served: the path is percent-decoded,
// "." and ".." segments are refused, and the resolved file must lie under
// the root's real path (so a symlink cannot lead out either). Nothing a
// client sends reaches the file system: the records of online games are
// written under names the server makes.
#pragma once
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "web/rooms.hpp"

namespace breakshot {

/// The path of the WebSocket of online play.
inline constexpr std::string_view kWebSocketPath = "/ws";

struct ServeOptions {
  std::string root;                ///< folder to serve; must hold index.html
  std::string host = "127.0.0.1";  ///< an IPv4 address to listen on
  /// Folder the records of online games are written to (it must exist);
  /// empty: none are written.
  std::string records;
  /// The rooms' limits and timeouts (record_prefix is the server's).
  online::RoomLimits rooms;
  /// Connections at once (HTTP and WebSocket); more are closed at once.
  std::size_t max_connections = 512;
  /// Seconds a client has to send a request's headers (or a WebSocket
  /// handshake).
  double request_timeout = 10;
  /// Seconds a client has to read a file's reply (the engine is over a
  /// megabyte: a slow network needs time).
  double reply_timeout = 120;
  /// Seconds a WebSocket may stay silent: it is pinged at half of it and
  /// closed when nothing came back.
  double idle_timeout = 30;
  /// Bytes a WebSocket client may leave unread before it is closed.
  std::size_t max_unread = 1 << 20;
  int port = 8000;  ///< 0: any free port (on_ready tells which)
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
/// or in use, a records folder that is not one.
void serve(const ServeOptions& options);

/// Whether an IPv4 address (as text) is a loopback one (127.0.0.0/8).
bool is_loopback(const std::string& host);

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

/// The plain-text reply of an error status (400, 403, 431, 503, ...).
Reply refusal(int status);

/// The real path of a page's root folder, or nullopt if it holds no
/// index.html.
std::optional<std::string> page_root(const std::string& root);

/// Whether a WebSocket handshake's Origin header (empty: none) may open a
/// game: none, or one whose host and port are the Host header's, so that
/// a page of another site cannot use a player's server.
bool same_origin(std::string_view origin, std::string_view host);

/// The whole response as bytes: status line, headers, body.
std::string format(const Reply& reply);

}  // namespace http
}  // namespace breakshot
