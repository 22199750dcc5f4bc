// The server behind `breakshot serve` (src/web/serve.hpp): the
// sockets, and nothing else. What a file request is answered with is
// http.cpp's; what online play does with a message is rooms.cpp's.
//
// One thread runs a Boost.Asio event loop. Each connection is a session
// object kept alive by its pending operations:
//   HttpSession  reads one request's headers (bounded in size and time)
//                and answers it, or hands a WebSocket handshake at
//                kWebSocketPath to a WsSession
//   WsSession    reads messages (bounded in size; idle ones are pinged,
//                then closed), gives them to the rooms, and writes what
//                the rooms send, one write at a time from a queue
//                bounded in bytes
// A timer checks `stop` and ticks the rooms (forfeits, expiry).
// Boost 1.74's asio/awaitable.hpp uses std::exchange without <utility>.
#include <utility>
// clang-format off
#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
// clang-format on
#include <sys/stat.h>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <deque>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>
#include <random>
#include <stdexcept>
#include <unordered_map>

#include "web/serve.hpp"

namespace breakshot {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace bhttp = boost::beast::http;
namespace websocket = boost::beast::websocket;
using tcp = asio::ip::tcp;

bool is_loopback(const std::string& host) {
  boost::system::error_code ec;
  const auto a = asio::ip::make_address_v4(host, ec);
  return !ec && a.is_loopback();
}

namespace {

constexpr std::size_t kMaxHeader = 16 * 1024;  // request line and headers

std::chrono::milliseconds millis(double seconds) {
  return std::chrono::milliseconds(static_cast<long long>(seconds * 1000));
}

class WsSession;

// What the sessions share: the options, the rooms, the live WebSockets.
class Server {
 public:
  Server(const ServeOptions& o, std::string page_root)
      : options(o), root(std::move(page_root)), rooms(room_limits(o), system_random()) {}

  const ServeOptions& options;
  const std::string root;
  std::size_t connections = 0;
  bool shutting_down = false;
  online::Rooms rooms;
  std::unordered_map<online::ClientId, std::weak_ptr<WsSession>> sockets;
  online::ClientId next_client = 0;
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();

  double now() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  void log(const std::string& line) const {
    if (options.log) options.log(line);
  }
  void apply(online::Effects fx);
  void write_record(const online::Effects::Record& r) const;

 private:
  static online::RoomLimits room_limits(const ServeOptions& o) {
    online::RoomLimits l = o.rooms;
    char stamp[32];
    const std::time_t t = std::time(nullptr);
    std::tm tm{};
    ::gmtime_r(&t, &tm);
    std::strftime(stamp, sizeof stamp, "online-%Y%m%dT%H%M%SZ", &tm);
    l.record_prefix = stamp;
    return l;
  }
  // Room codes, seat tokens and seeds: each straight from the system's
  // randomness (std::random_device: getrandom or the CPU's), never from a
  // generator whose state the tokens it gave away would reveal.
  static std::function<std::uint64_t()> system_random() {
    auto rd = std::make_shared<std::random_device>();
    return [rd] { return (std::uint64_t{(*rd)()} << 32) ^ (*rd)(); };
  }
};

// Counts a connection while it lives.
class Counted {
 public:
  explicit Counted(Server& s) : server_(s) { ++server_.connections; }
  ~Counted() { --server_.connections; }
  Counted(const Counted&) = delete;
  Counted& operator=(const Counted&) = delete;

 protected:
  Server& server_;
};

class WsSession : public Counted, public std::enable_shared_from_this<WsSession> {
 public:
  WsSession(Server& s, beast::tcp_stream&& stream)
      : Counted(s), ws_(std::move(stream)), id_(++s.next_client) {}

  void start(bhttp::request<bhttp::empty_body> req) {
    req_ = std::move(req);
    websocket::stream_base::timeout t{};
    t.handshake_timeout = millis(server_.options.request_timeout);
    t.idle_timeout = millis(server_.options.idle_timeout);
    t.keep_alive_pings = true;
    beast::get_lowest_layer(ws_).expires_never();
    ws_.set_option(t);
    ws_.read_message_max(server_.options.rooms.max_message);
    ws_.async_accept(req_, [self = shared_from_this()](beast::error_code ec) {
      if (ec) return;
      self->server_.sockets[self->id_] = self;
      self->read();
    });
  }

  void send(const std::string& text) {
    if (closing_) return;
    queued_ += text.size();
    if (queued_ > server_.options.max_unread) {
      // A client that does not read its messages: cut it off.
      closing_ = true;
      beast::get_lowest_layer(ws_).socket().close();
      return;
    }
    queue_.push_back(text);
    if (queue_.size() == 1) write();
  }

  // Sends what is queued, then closes.
  void close_after_sending() {
    if (closing_) return;
    close_pending_ = true;
    if (queue_.empty()) close();
  }

 private:
  void read() {
    ws_.async_read(buffer_, [self = shared_from_this()](beast::error_code ec, std::size_t) {
      self->on_read(ec);
    });
  }

  void on_read(beast::error_code ec) {
    if (ec) {
      // Closed, timed out, too big, not WebSocket: this connection ends.
      gone();
      return;
    }
    std::string text = beast::buffers_to_string(buffer_.data());
    buffer_.consume(buffer_.size());
    if (!ws_.got_text()) {
      server_.apply(server_.rooms.receive(id_, "binary message", server_.now()));
    } else {
      server_.apply(server_.rooms.receive(id_, text, server_.now()));
    }
    if (!closing_ && !close_pending_) read();
  }

  void write() {
    ws_.text(true);
    ws_.async_write(
        asio::buffer(queue_.front()),
        [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_write(ec); });
  }

  void on_write(beast::error_code ec) {
    if (ec) {
      gone();
      return;
    }
    queued_ -= queue_.front().size();
    queue_.pop_front();
    if (!queue_.empty()) {
      write();
    } else if (close_pending_) {
      close();
    }
  }

  void close() {
    closing_ = true;
    ws_.async_close(websocket::close_code::policy_error,
                    [self = shared_from_this()](beast::error_code) { self->gone(); });
  }

  void gone() {
    closing_ = true;
    if (left_) return;
    left_ = true;
    server_.sockets.erase(id_);
    if (!server_.shutting_down) server_.apply(server_.rooms.disconnect(id_, server_.now()));
  }

  websocket::stream<beast::tcp_stream> ws_;
  bhttp::request<bhttp::empty_body> req_;
  beast::flat_buffer buffer_;
  std::deque<std::string> queue_;
  std::size_t queued_ = 0;
  online::ClientId id_;
  bool closing_ = false;
  bool close_pending_ = false;
  bool left_ = false;
};

void Server::apply(online::Effects fx) {
  for (auto& m : fx.messages) {
    const auto it = sockets.find(m.to);
    if (it == sockets.end()) continue;
    if (const auto s = it->second.lock()) s->send(m.text);
  }
  for (const online::ClientId c : fx.close) {
    const auto it = sockets.find(c);
    if (it == sockets.end()) continue;
    if (const auto s = it->second.lock()) s->close_after_sending();
  }
  for (const auto& r : fx.records) write_record(r);
}

void Server::write_record(const online::Effects::Record& r) const {
  if (options.records.empty()) return;
  // The name is the rooms' (prefix, serial, room code): no client text.
  const std::string path = options.records + "/" + r.name;
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << r.text;
    if (!out) {
      log("cannot write the record " + tmp);
      return;
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) log("cannot write the record " + path);
}

class HttpSession : public Counted, public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(Server& s, tcp::socket&& socket) : Counted(s), stream_(std::move(socket)) {}

  void start() {
    parser_.emplace();
    parser_->header_limit(kMaxHeader);
    parser_->body_limit(0);
    stream_.expires_after(millis(server_.options.request_timeout));
    bhttp::async_read(
        stream_, buffer_, *parser_,
        [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_read(ec); });
  }

 private:
  void on_read(beast::error_code ec) {
    if (ec == bhttp::error::header_limit) {
      reply(http::refusal(431));
      return;
    }
    if (ec == beast::error::timeout || ec == bhttp::error::end_of_stream ||
        ec == asio::error::eof || ec == asio::error::connection_reset) {
      return;  // the client is gone or too slow: close
    }
    if (ec) {
      reply(http::refusal(400));
      return;
    }
    auto& req = parser_->get();
    const std::string target(req.target());
    const std::string path = target.substr(0, target.find_first_of("?#"));
    if (path == kWebSocketPath) {
      if (!websocket::is_upgrade(req)) {
        reply(http::refusal(426));
        return;
      }
      const auto origin = req[bhttp::field::origin];
      const auto host = req[bhttp::field::host];
      if (!http::same_origin(std::string_view(origin.data(), origin.size()),
                             std::string_view(host.data(), host.size()))) {
        server_.log(std::string(req.method_string()) + " " + target + " 403 (another origin)");
        reply(http::refusal(403));
        return;
      }
      server_.log("WebSocket " + target);
      std::make_shared<WsSession>(server_, std::move(stream_))->start(parser_->release());
      return;
    }
    const std::string line = std::string(req.method_string()) + " " + target + " HTTP/" +
                             std::to_string(req.version() / 10) + "." +
                             std::to_string(req.version() % 10);
    const http::Reply r = http::answer(line + "\r\n\r\n", server_.root);
    server_.log(line + " " + std::to_string(r.status));
    reply(r);
  }

  void reply(const http::Reply& r) {
    out_ = http::format(r);
    stream_.expires_after(millis(server_.options.reply_timeout));
    asio::async_write(stream_, asio::buffer(out_),
                      [self = shared_from_this()](beast::error_code, std::size_t) {
                        beast::error_code ignored;
                        self->stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
                      });
  }

  beast::tcp_stream stream_;
  beast::flat_buffer buffer_{kMaxHeader};
  std::optional<bhttp::request_parser<bhttp::empty_body>> parser_;
  std::string out_;
};

class Listener {
 public:
  Listener(asio::io_context& ioc, Server& server, tcp::acceptor& acceptor)
      : server_(server), acceptor_(acceptor), retry_(ioc) {}

  void accept() {
    acceptor_.async_accept([this](beast::error_code ec, tcp::socket s) {
      if (ec) {
        // Out of descriptors, or the like: wait a little, then go on.
        retry_.expires_after(std::chrono::milliseconds(100));
        retry_.async_wait([this](beast::error_code) { accept(); });
        return;
      }
      if (server_.connections >= server_.options.max_connections) {
        beast::error_code ignored;
        asio::write(s, asio::buffer(http::format(http::refusal(503))), ignored);
        s.close(ignored);
      } else {
        std::make_shared<HttpSession>(server_, std::move(s))->start();
      }
      accept();
    });
  }

 private:
  Server& server_;
  tcp::acceptor& acceptor_;
  asio::steady_timer retry_;
};

}  // namespace

void serve(const ServeOptions& options) {
  const auto root = http::page_root(options.root);
  if (!root) {
    throw std::runtime_error("no page to serve in '" + options.root +
                             "' (no index.html there; build it with scripts/web.sh)");
  }
  if (options.port < 0 || options.port > 65535) {
    throw std::runtime_error("port " + std::to_string(options.port) +
                             " is out of range (0 to 65535)");
  }
  boost::system::error_code ec;
  const auto address = asio::ip::make_address_v4(options.host, ec);
  if (ec) throw std::runtime_error("host '" + options.host + "' is not an IPv4 address");
  if (!options.records.empty()) {
    struct stat st {};
    if (::stat(options.records.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) {
      throw std::runtime_error("records folder '" + options.records + "' is not a folder");
    }
  }

  Server server(options, *root);
  asio::io_context ioc(1);
  tcp::acceptor acceptor(ioc);
  const tcp::endpoint endpoint(address, static_cast<unsigned short>(options.port));
  acceptor.open(endpoint.protocol());
  acceptor.set_option(asio::socket_base::reuse_address(true));
  acceptor.bind(endpoint, ec);
  if (ec == asio::error::address_in_use) {
    throw std::runtime_error("port " + std::to_string(options.port) +
                             " is in use; choose another with --port (0 picks a free one)");
  }
  if (ec) {
    throw std::runtime_error("cannot listen on " + options.host + ":" +
                             std::to_string(options.port) + ": " + ec.message());
  }
  acceptor.listen(asio::socket_base::max_listen_connections, ec);
  if (ec) throw std::runtime_error("listen: " + ec.message());
  if (options.on_ready) options.on_ready(acceptor.local_endpoint().port());

  Listener listener(ioc, server, acceptor);
  listener.accept();

  asio::steady_timer ticker(ioc);
  std::function<void()> tick = [&] {
    ticker.expires_after(std::chrono::milliseconds(100));
    ticker.async_wait([&](beast::error_code) {
      if (options.stop != nullptr && options.stop->load()) {
        ioc.stop();
        return;
      }
      server.apply(server.rooms.tick(server.now()));
      tick();
    });
  };
  tick();
  ioc.run();
  // The sessions die with the event loop's pending operations: they must
  // not call into the rooms then.
  server.shutting_down = true;
}

}  // namespace breakshot
