// The static file server of `breakshot serve`: request answers without a
// socket, then a real server on a free loopback port.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <future>
#include <string>
#include <thread>

#include "web/serve.hpp"

namespace test_serve {

namespace fs = std::filesystem;
using breakshot::http::answer;
using breakshot::http::resolve;

namespace {

// A temporary page: index.html, app.js, a sub folder, and a secret file
// next to (outside) the root that nothing may serve.
class Site : public ::testing::Test {
 protected:
  void SetUp() override {
    base_ = fs::temp_directory_path() /
            ("breakshot_serve_" + std::to_string(::getpid()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(base_);
    fs::create_directories(base_ / "root" / "sub");
    write(base_ / "root" / "index.html", "<!doctype html><title>t</title>");
    write(base_ / "root" / "app.js", "export const x = 1;\n");
    write(base_ / "root" / "sub" / "index.html", "sub page");
    write(base_ / "root" / "a b.css", "body{}");
    write(base_ / "secret.txt", "do not serve");
    fs::create_symlink(base_ / "secret.txt", base_ / "root" / "link.txt");
    root_ = fs::canonical(base_ / "root").string();
  }
  void TearDown() override { fs::remove_all(base_); }
  static void write(const fs::path& p, const std::string& text) {
    std::ofstream(p, std::ios::binary) << text;
  }
  breakshot::http::Reply get(const std::string& target, const std::string& method = "GET") {
    return answer(method + " " + target + " HTTP/1.1\r\nHost: x\r\n\r\n", root_);
  }
  fs::path base_;
  std::string root_;
};

TEST_F(Site, ServesIndexForTheRootAndFoldersWithTheirTypes) {
  auto r = get("/");
  EXPECT_EQ(r.status, 200);
  EXPECT_EQ(r.body, "<!doctype html><title>t</title>");
  EXPECT_EQ(r.content_type, "text/html; charset=utf-8");
  r = get("/app.js?v=3#frag");
  EXPECT_EQ(r.status, 200);
  EXPECT_EQ(r.content_type, "text/javascript; charset=utf-8");
  EXPECT_EQ(r.body, "export const x = 1;\n");
  r = get("/sub/");
  EXPECT_EQ(r.status, 200);
  EXPECT_EQ(r.body, "sub page");
  r = get("/a%20b.css");
  EXPECT_EQ(r.status, 200);
  EXPECT_EQ(r.content_type, "text/css; charset=utf-8");
}

TEST_F(Site, HeadGivesTheLengthWithoutTheBody) {
  const auto r = get("/app.js", "HEAD");
  EXPECT_EQ(r.status, 200);
  EXPECT_EQ(r.content_length, 20u);
  EXPECT_TRUE(r.body.empty());
  const std::string bytes = breakshot::http::format(r);
  EXPECT_NE(bytes.find("Content-Length: 20\r\n"), std::string::npos);
  EXPECT_EQ(bytes.substr(bytes.size() - 4), "\r\n\r\n");
}

TEST_F(Site, NothingOutsideTheRootIsServed) {
  for (const char* t : {"/../secret.txt", "/%2e%2e/secret.txt", "/sub/../../secret.txt",
                        "/./index.html", "/link.txt", "/..%2fsecret.txt", "/%2E%2E/secret.txt"}) {
    const auto r = get(t);
    EXPECT_EQ(r.status, 404) << t;
    EXPECT_EQ(r.body.find("do not serve"), std::string::npos) << t;
  }
  EXPECT_FALSE(resolve("/../secret.txt", root_));
  EXPECT_FALSE(resolve("/link.txt", root_));  // a symlink that leads out
  EXPECT_FALSE(resolve("relative", root_));
  EXPECT_FALSE(resolve("/bad%zzescape", root_));
  EXPECT_FALSE(resolve("/nul%00byte", root_));
  EXPECT_FALSE(resolve("/trailing%2", root_));
}

TEST_F(Site, BadRequestsGetTheirStatus) {
  EXPECT_EQ(get("/missing.js").status, 404);
  EXPECT_EQ(get("/sub").status, 404);  // a folder without the slash is not a file
  EXPECT_EQ(get("/", "POST").status, 405);
  EXPECT_NE(breakshot::http::format(get("/", "DELETE")).find("Allow: GET, HEAD"),
            std::string::npos);
  EXPECT_EQ(answer("garbage\r\n\r\n", root_).status, 400);
  EXPECT_EQ(answer("GET / HTTP/9.9\r\n\r\n", root_).status, 400);
  EXPECT_EQ(answer("", root_).status, 400);
}

TEST(ServeTypes, ByExtension) {
  using breakshot::http::content_type;
  EXPECT_EQ(content_type("a/b.wasm"), "application/wasm");
  EXPECT_EQ(content_type("x.json"), "application/json");
  EXPECT_EQ(content_type("x.png"), "image/png");
  EXPECT_EQ(content_type("x.svg"), "image/svg+xml");
  EXPECT_EQ(content_type("dir.v2/noext"), "application/octet-stream");
}

// A blocking HTTP/1.1 GET on 127.0.0.1:port; the whole response.
std::string fetch(int port, const std::string& raw_request) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) return {};
  sockaddr_in sa{};
  sa.sin_family = AF_INET;
  sa.sin_port = htons(static_cast<std::uint16_t>(port));
  ::inet_pton(AF_INET, "127.0.0.1", &sa.sin_addr);
  std::string out;
  if (::connect(fd, reinterpret_cast<sockaddr*>(&sa), sizeof sa) == 0) {
    ::send(fd, raw_request.data(), raw_request.size(), MSG_NOSIGNAL);
    char buf[4096];
    for (;;) {
      const ssize_t n = ::recv(fd, buf, sizeof buf, 0);
      if (n <= 0) break;
      out.append(buf, static_cast<std::size_t>(n));
    }
  }
  ::close(fd);
  return out;
}

TEST_F(Site, ARealServerOnAFreePortAnswersAndStops) {
  std::atomic<bool> stop{false};
  std::promise<int> ready;
  std::vector<std::string> log;
  breakshot::ServeOptions o;
  o.root = base_ / "root";
  o.port = 0;
  o.stop = &stop;
  o.on_ready = [&](int port) { ready.set_value(port); };
  o.log = [&](const std::string& line) { log.push_back(line); };
  std::thread server([&] { breakshot::serve(o); });
  auto fut = ready.get_future();
  ASSERT_EQ(fut.wait_for(std::chrono::seconds(10)), std::future_status::ready);
  const int port = fut.get();
  ASSERT_GT(port, 0);

  const std::string page = fetch(port, "GET / HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n");
  EXPECT_EQ(page.rfind("HTTP/1.1 200 OK\r\n", 0), 0u) << page;
  EXPECT_NE(page.find("<!doctype html>"), std::string::npos);
  const std::string out = fetch(port, "GET /../secret.txt HTTP/1.1\r\n\r\n");
  EXPECT_EQ(out.rfind("HTTP/1.1 404", 0), 0u) << out;
  // A request that never ends its headers and grows past the limit.
  const std::string huge = fetch(port, "GET / HTTP/1.1\r\nX: " + std::string(20000, 'a'));
  EXPECT_EQ(huge.rfind("HTTP/1.1 431", 0), 0u) << huge.substr(0, 40);

  stop = true;
  server.join();
  ASSERT_EQ(log.size(), 2u);
  EXPECT_EQ(log[0], "GET / HTTP/1.1 200");
  EXPECT_EQ(log[1], "GET /../secret.txt HTTP/1.1 404");
}

TEST_F(Site, RefusesARootWithoutAPageAndABadPortOrHost) {
  breakshot::ServeOptions o;
  o.root = (base_ / "root" / "sub" / "nothing").string();
  try {
    breakshot::serve(o);
    FAIL() << "served a missing root";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("scripts/web.sh"), std::string::npos) << e.what();
  }
  o.root = base_ / "root";
  o.port = 70000;
  EXPECT_THROW(breakshot::serve(o), std::runtime_error);
  o.port = 0;
  o.host = "localhost.invalid";
  EXPECT_THROW(breakshot::serve(o), std::runtime_error);
}

TEST_F(Site, APortInUseIsNamed) {
  std::atomic<bool> stop{false};
  std::promise<int> ready;
  breakshot::ServeOptions first;
  first.root = base_ / "root";
  first.port = 0;
  first.stop = &stop;
  first.on_ready = [&](int port) { ready.set_value(port); };
  std::thread server([&] { breakshot::serve(first); });
  auto fut = ready.get_future();
  ASSERT_EQ(fut.wait_for(std::chrono::seconds(10)), std::future_status::ready);
  breakshot::ServeOptions second = first;
  second.on_ready = nullptr;
  second.port = fut.get();
  try {
    breakshot::serve(second);
    ADD_FAILURE() << "two servers on one port";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("in use"), std::string::npos) << e.what();
  }
  stop = true;
  server.join();
}

}  // namespace

}  // namespace test_serve
