// What the facade of the browser version (web/api/web_api.hpp,
// docs/web.md) shares: its handles, each a C API handle with the slot of
// its last reply, and the turning of the C API's statuses and messages
// into the page's {"error"} replies and last-error string. Internal:
// only web/api/*.cpp include it.
//
//   facade.cpp    errors, and the C API's strings taken over
//   web_api.cpp   the entry points, each a call of breakshot.h's
//
// Replies are the C API's text, or written from it with
// nlohmann::ordered_json and dumped compactly: its number printing
// (Grisu2 on the bits, integer arithmetic only) and its parsing (strtod,
// correctly rounded in glibc and musl) are the same code native and wasm,
// so a reply is the same bytes on both.

#ifndef BREAKSHOT_WEB_FACADE_HPP
#define BREAKSHOT_WEB_FACADE_HPP

#include <exception>
#include <new>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "breakshot.h"

using ojson = nlohmann::ordered_json;

struct BsWebPlayback {
  explicit BsWebPlayback(BsPlayback* p) : pb(p) {}
  BsWebPlayback(const BsWebPlayback&) = delete;
  BsWebPlayback& operator=(const BsWebPlayback&) = delete;
  ~BsWebPlayback() { bs_playback_free(pb); }
  BsPlayback* pb;
  std::string reply;
  std::vector<BsBallState> states;  // bs_playback_states's
  std::vector<double> values;       // spins or motions (one more: a valid pointer with no ball)
};

struct BsWebGame {
  explicit BsWebGame(BsGame* g) : game(g) {}
  BsWebGame(const BsWebGame&) = delete;
  BsWebGame& operator=(const BsWebGame&) = delete;
  ~BsWebGame() { bs_game_free(game); }
  BsGame* game;
  std::string reply;
};

namespace facade {

/// A failure to answer with {"error": message}.
struct Error {
  std::string message;
};

[[noreturn]] inline void error(std::string message) { throw Error{std::move(message)}; }

/// A C API call's outcome: nothing when it succeeded, else its message
/// (on `handle`, or the thread's for NULL) thrown as an Error.
void check(BsStatus status, const void* handle);

/// A string the C API returned through a char**, taken over (freed).
std::string take(char* text);

/// {"error": message}; bytes of the message that are not UTF-8 written
/// as U+FFFD.
std::string error_json(const std::string& message);

/// bs_web_last_error's reply, and whether it holds an error: a failed
/// call that returns NULL sets both; every call that succeeds clears the
/// flag (a flag, so that clearing costs no allocation on the page's
/// per-frame calls), and bs_web_last_error then answers {"error": "no
/// error"}.
extern thread_local std::string g_last_error;
extern thread_local bool g_has_error;
const char* last_error();

/// Runs `body`, turning an Error (or any exception) into {"error"}; a
/// success clears bs_web_last_error.
template <class F>
std::string guarded(F&& body) {
  try {
    std::string reply = body();
    g_has_error = false;
    return reply;
  } catch (const Error& e) {
    return error_json(e.message);
  } catch (const std::bad_alloc&) {
    return error_json("out of memory");
  } catch (const std::exception& e) {
    return error_json(std::string("internal error: ") + e.what());
  } catch (...) {
    return error_json("internal error");
  }
}

template <class T>
T* fail_null(const std::string& message) {
  g_last_error = error_json(message);
  g_has_error = true;
  return nullptr;
}

/// Runs a body that returns a pointer: the pointer (bs_web_last_error
/// cleared), or NULL with bs_web_last_error set to the error.
template <class T, class F>
T* guarded_ptr(F&& body) {
  try {
    T* p = body();
    g_has_error = false;
    return p;
  } catch (const Error& e) {
    return fail_null<T>(e.message);
  } catch (const std::bad_alloc&) {
    return fail_null<T>("out of memory");
  } catch (const std::exception& e) {
    return fail_null<T>(std::string("internal error: ") + e.what());
  } catch (...) {
    return fail_null<T>("internal error");
  }
}

/// A reply kept in a handle's slot until the next call on it.
const char* keep(std::string& slot, std::string text);

/// The reply of calls on a NULL handle.
const char* null_handle();

/// A reply the caller owns (bs_web_free).
char* copy_out(const std::string& s);

}  // namespace facade

#endif  // BREAKSHOT_WEB_FACADE_HPP
