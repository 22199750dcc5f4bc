// `breakshot serve` through real sockets on 127.0.0.1: many connections
// at once, and online play over its WebSocket with scripted clients that
// play each action themselves (lockstep) and compare hashes with the
// server's. Every test is bounded: a watchdog stops the server when its
// bound passes, which closes every socket, so a hang fails instead of
// waiting forever.
#include <gtest/gtest.h>
#include <sys/socket.h>

#include <utility>  // before Boost 1.74's asio (std::exchange)
// clang-format off
#include <atomic>
#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
// clang-format on
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <future>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "web/rooms.hpp"
#include "web/serve.hpp"
#include "web_api.hpp"

namespace test_online {

namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace bhttp = boost::beast::http;
namespace websocket = boost::beast::websocket;
namespace fs = std::filesystem;
using tcp = asio::ip::tcp;
using json = nlohmann::json;

// A server on a free port of 127.0.0.1, serving a one-file page, with
// records written to a folder of its own.
class Server {
 public:
  explicit Server(std::function<void(breakshot::ServeOptions&)> tune = nullptr) {
    base_ = fs::temp_directory_path() /
            ("breakshot_online_" + std::to_string(::getpid()) + "_" + std::to_string(++count_));
    fs::remove_all(base_);
    fs::create_directories(base_ / "root");
    fs::create_directories(base_ / "records");
    std::ofstream(base_ / "root" / "index.html") << "<!doctype html><title>t</title>";
    options_.root = (base_ / "root").string();
    options_.records = (base_ / "records").string();
    options_.port = 0;
    options_.stop = &stop_;
    options_.on_ready = [this](int port) { ready_.set_value(port); };
    if (tune) tune(options_);
    thread_ = std::thread([this] { breakshot::serve(options_); });
    auto fut = ready_.get_future();
    if (fut.wait_for(std::chrono::seconds(30)) != std::future_status::ready) {
      throw std::runtime_error("the server did not start");
    }
    port_ = fut.get();
  }
  ~Server() {
    stop();
    thread_.join();
    fs::remove_all(base_);
  }
  void stop() { stop_ = true; }
  int port() const { return port_; }
  fs::path records() const { return base_ / "records"; }

  // Runs `body`; if it has not finished after `seconds`, stops the server
  // (every socket closes, so the body ends) and fails.
  void bounded(double seconds, const std::function<void()>& body) {
    auto fut = std::async(std::launch::async, body);
    if (fut.wait_for(std::chrono::duration<double>(seconds)) != std::future_status::ready) {
      ADD_FAILURE() << "not done within " << seconds << " s: the server is stopped";
      stop();
    }
    fut.get();  // rethrows what the body threw
  }

 private:
  static inline int count_ = 0;
  fs::path base_;
  std::atomic<bool> stop_{false};
  std::promise<int> ready_;
  breakshot::ServeOptions options_;
  std::thread thread_;
  int port_ = 0;
};

// A scripted WebSocket client (synchronous).
class WsClient {
 public:
  explicit WsClient(int port, const std::string& origin = "") : ws_(ioc_) {
    ws_.next_layer().connect(
        tcp::endpoint(asio::ip::make_address("127.0.0.1"), static_cast<unsigned short>(port)));
    if (!origin.empty()) {
      ws_.set_option(websocket::stream_base::decorator(
          [origin](websocket::request_type& r) { r.set(bhttp::field::origin, origin); }));
    }
    ws_.handshake("127.0.0.1:" + std::to_string(port), "/ws");
  }
  void send(const std::string& text) {
    ws_.text(true);
    ws_.write(asio::buffer(text));
  }
  void send(const json& j) { send(j.dump()); }
  void send(const char* text) { send(std::string(text)); }
  void send_binary(const std::string& bytes) {
    ws_.binary(true);
    ws_.write(asio::buffer(bytes));
  }
  // The next message, or nullopt once the connection is closed.
  std::optional<json> read() {
    beast::flat_buffer b;
    beast::error_code ec;
    ws_.read(b, ec);
    if (ec) return std::nullopt;
    return json::parse(beast::buffers_to_string(b.data()));
  }
  // The next message of `type` (others are skipped); throws if closed.
  json next(const std::string& type) {
    for (;;) {
      auto m = read();
      if (!m) throw std::runtime_error("closed while waiting for '" + type + "'");
      if ((*m)["type"] == type) return *m;
      if ((*m)["type"] == "refused" || (*m)["type"] == "error") {
        if (type != "refused" && type != "error") {
          throw std::runtime_error("waiting for '" + type + "': " + m->dump());
        }
      }
    }
  }
  void close() {
    beast::error_code ec;
    ws_.next_layer().shutdown(tcp::socket::shutdown_both, ec);
    ws_.next_layer().close(ec);
  }

 private:
  asio::io_context ioc_;
  websocket::stream<tcp::socket> ws_;
};

// A player: a client and its own copy of the game, played in lockstep.
struct Player {
  std::unique_ptr<WsClient> ws;
  BsWebGame* game = nullptr;
  int seat = -1;
  std::string room;
  std::string token;

  ~Player() { bs_web_game_free(game); }

  // Takes the "joined" reply: builds the game and plays its log.
  void joined(const json& j) {
    room = j["room"];
    if (j["seat"].is_number()) seat = j["seat"];
    if (j.contains("token")) token = j["token"];
    bs_web_game_free(game);
    game = bs_web_game_new(j["config"].dump().c_str());
    if (game == nullptr) throw std::runtime_error(bs_web_last_error());
    for (const json& a : j["actions"]) play(a);
    check_hash(j["hash"]);
  }
  void play(const json& action) {
    const json r = json::parse(bs_web_game_act(game, action.dump().c_str()));
    if (r.contains("error")) throw std::runtime_error("the rules refuse " + action.dump());
  }
  void check_hash(const json& hash) const {
    const std::string mine = breakshot::online::state_hash(bs_web_game_state(game));
    if (mine != hash.get<std::string>()) {
      throw std::runtime_error("hash mismatch: " + mine + " here, " + hash.dump() +
                               " on the server");
    }
  }
  // Takes an "action" message: plays it and compares the hashes.
  void played(const json& m) {
    play(m["action"]);
    check_hash(m["hash"]);
  }
  json state() const { return json::parse(bs_web_game_state(game)); }
  bool to_act() const { return state()["player"] == seat; }
};

std::string quick_game(int target, int innings) {
  return R"({"type": "create", "game": {"game": "three_cushion", "carom": {"target": )" +
         std::to_string(target) + R"(, "innings_limit": )" + std::to_string(innings) +
         R"(, "equalizing_inning": false}}})";
}

json shot(std::size_t index, double phi) {
  return {{"type", "act"},
          {"index", index},
          {"action",
           {{"type", "shoot"},
            {"strike", {{"speed", 3.0}, {"phi", phi}, {"theta", 0.0}, {"a", 0.0}, {"b", 0.0}}},
            {"call", nullptr},
            {"safety", false},
            {"push_out", false}}}};
}

// Whether `breakshot replay` finds the record identical.
bool replays(const fs::path& record) {
#ifdef BREAKSHOT_CLI
  const std::string cmd =
      std::string(BREAKSHOT_CLI) + " replay '" + record.string() + "' >/dev/null 2>&1";
  return std::system(cmd.c_str()) == 0;
#else
  (void)record;
  return true;
#endif
}

std::vector<fs::path> records_in(const fs::path& dir) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() == ".json") out.push_back(e.path());
  }
  return out;
}

// An HTTP GET on 127.0.0.1; the whole response.
std::string get(int port, const std::string& target) {
  asio::io_context ioc;
  beast::tcp_stream s(ioc);
  s.connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), static_cast<unsigned short>(port)));
  const std::string req = "GET " + target + " HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n";
  asio::write(s, asio::buffer(req));
  std::string out;
  beast::error_code ec;
  char buf[4096];
  for (;;) {
    const std::size_t n = s.read_some(asio::buffer(buf), ec);
    if (ec) break;
    out.append(buf, n);
  }
  return out;
}

TEST(OnlineServe, HalfSentRequestsDoNotKeepThePageFromLoading) {
  Server server([](breakshot::ServeOptions& o) { o.request_timeout = 2; });
  // 100 clients that open a connection and send half a request.
  asio::io_context ioc;
  std::vector<std::unique_ptr<tcp::socket>> idle;
  for (int i = 0; i < 100; ++i) {
    auto s = std::make_unique<tcp::socket>(ioc);
    s->connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"),
                             static_cast<unsigned short>(server.port())));
    asio::write(*s, asio::buffer(std::string("GET / HTTP/1.1\r\nHost: 127.")));
    idle.push_back(std::move(s));
  }
  // While they hang on, the page loads (a hang guard, not a timing test).
  server.bounded(60, [&] {
    const std::string page = get(server.port(), "/");
    EXPECT_EQ(page.rfind("HTTP/1.1 200 OK\r\n", 0), 0u) << page;
    EXPECT_NE(page.find("<!doctype html>"), std::string::npos);
    EXPECT_EQ(get(server.port(), "/../etc/passwd").rfind("HTTP/1.1 404", 0), 0u);
    EXPECT_EQ(get(server.port(), "/ws").rfind("HTTP/1.1 426", 0), 0u);
    // Their timeout closes the half-sent ones.
    char c;
    beast::error_code ec;
    idle[0]->read_some(asio::buffer(&c, 1), ec);
    EXPECT_TRUE(ec) << "a half-sent request was answered";
  });
}

TEST(OnlineServe, ConnectionsBeyondTheLimitAreRefusedUntilOthersClose) {
  Server server([](breakshot::ServeOptions& o) {
    o.max_connections = 5;
    o.request_timeout = 1;
  });
  asio::io_context ioc;
  std::vector<std::unique_ptr<tcp::socket>> idle;
  for (int i = 0; i < 5; ++i) {
    auto s = std::make_unique<tcp::socket>(ioc);
    s->connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"),
                             static_cast<unsigned short>(server.port())));
    idle.push_back(std::move(s));
  }
  server.bounded(60, [&] {
    // The server may not have accepted all five yet: one more connection
    // is refused once it has.
    std::string busy;
    for (int tries = 0; tries < 100 && busy.rfind("HTTP/1.1 503", 0) != 0; ++tries) {
      busy = get(server.port(), "/");
    }
    EXPECT_EQ(busy.rfind("HTTP/1.1 503", 0), 0u) << busy.substr(0, 40);
    // The idle ones time out, and the page loads again.
    std::string page;
    for (int tries = 0; tries < 100 && page.rfind("HTTP/1.1 200", 0) != 0; ++tries) {
      page = get(server.port(), "/");
      if (page.rfind("HTTP/1.1 200", 0) != 0)
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    EXPECT_EQ(page.rfind("HTTP/1.1 200", 0), 0u) << page.substr(0, 40);
  });
}

TEST(OnlineServe, AWebSocketFromAnotherSiteIsRefused) {
  Server server;
  server.bounded(60, [&] {
    EXPECT_THROW(WsClient(server.port(), "http://evil.example"), boost::system::system_error);
    WsClient same(server.port(), "http://127.0.0.1:" + std::to_string(server.port()));
    same.send(R"({"type": "ping"})");
    EXPECT_EQ(same.next("pong")["type"], "pong");
  });
}

// Plays a whole game: a creator, a friend, a watcher; the friend drops
// mid-game and rejoins with its token; bad messages on the way are
// refused or closed while the game goes on; the record replays.
TEST(OnlineServe, AWholeGameWithARejoinAndBadMessages) {
  Server server;
  server.bounded(240, [&] {
    Player a, b, w;
    a.ws = std::make_unique<WsClient>(server.port());
    a.ws->send(quick_game(3, 4));
    a.joined(a.ws->next("joined"));
    b.ws = std::make_unique<WsClient>(server.port());
    b.ws->send(json{{"type", "join"}, {"room", a.room}});
    b.joined(b.ws->next("joined"));
    w.ws = std::make_unique<WsClient>(server.port());
    w.ws->send(json{{"type", "join"}, {"room", a.room}});
    w.joined(w.ws->next("joined"));
    ASSERT_EQ(a.seat, 0);
    ASSERT_EQ(b.seat, 1);
    ASSERT_EQ(w.seat, -1);

    // A stranger sends garbage, too much, binary: each is closed alone.
    for (const std::string& bad : {std::string("{oops"), std::string(20000, 'x')}) {
      WsClient stranger(server.port());
      stranger.send(bad);
      for (;;) {
        const auto m = stranger.read();
        if (!m) break;  // closed
        EXPECT_EQ((*m)["type"], "error");
      }
    }
    {
      WsClient stranger(server.port());
      stranger.send_binary("\x01\x02");
      while (stranger.read()) {
      }
    }

    bool rejoined = false;
    std::size_t i = 0;
    for (; i < 40; ++i) {
      Player& actor = a.to_act() ? a : b;
      Player& other = a.to_act() ? b : a;
      // The one not to act tries anyway, and an illegal action: refused.
      other.ws->send(shot(i, 0));
      EXPECT_EQ(other.ws->next("refused")["reason"], "not your turn");
      json illegal = shot(i, 0);
      illegal["action"]["strike"]["speed"] = -1;
      actor.ws->send(illegal);
      EXPECT_EQ(actor.ws->next("refused")["reason"].get<std::string>().rfind("action: ", 0), 0u);

      actor.ws->send(shot(i, 90.0 + 37.0 * static_cast<double>(i)));
      for (Player* p : {&a, &b, &w}) p->played(p->ws->next("action"));
      if (a.state()["phase"] == "game_over") break;

      if (i == 1 && !rejoined) {
        // The friend's tab closes, and comes back with its token.
        b.ws->close();
        EXPECT_EQ(a.ws->next("seats")["connected"], json({true, false}));
        b.ws = std::make_unique<WsClient>(server.port());
        b.ws->send(json{{"type", "rejoin"}, {"room", a.room}, {"token", b.token}});
        const json back = b.ws->next("joined");
        EXPECT_EQ(back["actions"].size(), i + 1);
        b.joined(back);  // replays the log and checks the hash
        EXPECT_EQ(a.ws->next("seats")["connected"], json({true, true}));
        rejoined = true;
      }
    }
    ASSERT_EQ(a.state()["phase"], "game_over");
    const json over = a.ws->next("over");
    EXPECT_FALSE(over["forfeit"]);
    EXPECT_EQ(w.ws->next("over")["winner"], over["winner"]);
    const auto files = records_in(server.records());
    ASSERT_EQ(files.size(), 1u);
    EXPECT_TRUE(replays(files[0])) << files[0];
  });
}

TEST(OnlineServe, ASeatLeftEmptyForfeits) {
  Server server([](breakshot::ServeOptions& o) { o.rooms.seat_timeout = 1; });
  server.bounded(60, [&] {
    Player a, b;
    a.ws = std::make_unique<WsClient>(server.port());
    a.ws->send(quick_game(5, 10));
    a.joined(a.ws->next("joined"));
    b.ws = std::make_unique<WsClient>(server.port());
    b.ws->send(json{{"type", "join"}, {"room", a.room}});
    b.joined(b.ws->next("joined"));
    b.ws->close();
    const json over = a.ws->next("over");
    EXPECT_EQ(over["winner"], 0);
    EXPECT_TRUE(over["forfeit"]);
  });
}

// 100 rooms at once, their actions interleaved; every game ends and its
// record replays identical.
TEST(OnlineServe, AHundredRoomsAtOnce) {
  constexpr std::size_t kRooms = 100;
  Server server;
  server.bounded(300, [&] {
    std::vector<Player> creators(kRooms), friends(kRooms);
    for (std::size_t r = 0; r < kRooms; ++r) {
      creators[r].ws = std::make_unique<WsClient>(server.port());
      creators[r].ws->send(quick_game(1, 2));
      creators[r].joined(creators[r].ws->next("joined"));
      friends[r].ws = std::make_unique<WsClient>(server.port());
      friends[r].ws->send(json{{"type", "join"}, {"room", creators[r].room}});
      friends[r].joined(friends[r].ws->next("joined"));
    }
    std::vector<std::size_t> actions(kRooms, 0);
    std::vector<bool> over(kRooms, false);
    std::size_t left = kRooms;
    while (left > 0) {
      // Each room's player to act sends a shot ...
      for (std::size_t r = 0; r < kRooms; ++r) {
        if (over[r]) continue;
        Player& actor = creators[r].to_act() ? creators[r] : friends[r];
        actor.ws->send(shot(actions[r], 60.0 + 41.0 * static_cast<double>(actions[r] + r)));
      }
      // ... and then both players of every room take it.
      for (std::size_t r = 0; r < kRooms; ++r) {
        if (over[r]) continue;
        for (Player* p : {&creators[r], &friends[r]}) p->played(p->ws->next("action"));
        ++actions[r];
        if (creators[r].state()["phase"] == "game_over") {
          over[r] = true;
          --left;
        }
      }
    }
    const auto files = records_in(server.records());
    ASSERT_EQ(files.size(), kRooms);
    for (const fs::path& f : files) EXPECT_TRUE(replays(f)) << f;
  });
}

}  // namespace

}  // namespace test_online
