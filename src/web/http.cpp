// The parts of `breakshot serve` that need no socket
// (src/web/serve.hpp, namespace http): which file a request
// names under the root, its content type, and the reply's bytes.
#include <sys/stat.h>

#include <climits>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "web/serve.hpp"

namespace breakshot {
namespace http {
namespace {

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
    case 200:
      return "OK";
    case 400:
      return "Bad Request";
    case 403:
      return "Forbidden";
    case 404:
      return "Not Found";
    case 405:
      return "Method Not Allowed";
    case 426:
      return "Upgrade Required";
    case 431:
      return "Request Header Fields Too Large";
    case 503:
      return "Service Unavailable";
    case 500:
      return "Internal Server Error";
    default:
      return "Error";
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

Reply refusal(int status) { return error_reply(status); }

std::optional<std::string> page_root(const std::string& root) {
  auto real = real_path(root);
  if (!real || !is_regular_file(*real + "/index.html")) return std::nullopt;
  return real;
}

bool same_origin(std::string_view origin, std::string_view host) {
  if (origin.empty()) return true;
  const auto scheme = origin.find("://");
  if (scheme == std::string_view::npos) return false;
  std::string_view authority = origin.substr(scheme + 3);
  if (!authority.empty() && authority.back() == '/') authority.remove_suffix(1);
  return !host.empty() && authority == host;
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

}  // namespace breakshot
