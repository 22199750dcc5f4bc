// The facade's errors, and the C API's strings taken over (facade.hpp).

#include "facade.hpp"

#include <cstdlib>
#include <cstring>
#include <string>
#include <utility>

namespace facade {

void check(BsStatus status, const void* handle) {
  if (status != BS_OK) error(bs_error_message(handle));
}

std::string take(char* text) {
  if (text == nullptr) return std::string();
  std::string s(text);
  bs_string_free(text);
  return s;
}

std::string error_json(const std::string& message) {
  ojson j = ojson::object();
  j["error"] = message;
  // A message may quote the input's bytes (a link's decoded text is any
  // bytes, and the JSON parser's message shows the last ones read): bytes
  // that are not UTF-8 are written as U+FFFD rather than thrown about
  // from inside a catch handler, which would cross the C boundary.
  return j.dump(-1, ' ', false, ojson::error_handler_t::replace);
}

thread_local std::string g_last_error;
thread_local bool g_has_error = false;

const char* last_error() {
  static const std::string none = error_json("no error");
  return g_has_error ? g_last_error.c_str() : none.c_str();
}

const char* keep(std::string& slot, std::string text) {
  slot = std::move(text);
  return slot.c_str();
}

const char* null_handle() {
  static const std::string reply = error_json("handle: a null handle");
  return reply.c_str();
}

char* copy_out(const std::string& s) {
  char* p = static_cast<char*>(std::malloc(s.size() + 1));
  if (p != nullptr) std::memcpy(p, s.c_str(), s.size() + 1);
  return p;
}

}  // namespace facade
