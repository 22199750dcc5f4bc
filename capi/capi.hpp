// The C API's handles and what its parts share (include/breakshot.h,
// docs/c-api.md). Internal: capi/*.cpp include it, and the static build of
// bench/capi_overhead.cpp, which times simulate() on the C API's own scenarios.
//
//   capi.cpp        status names, errors, strings, version, physics options
//   scenario.cpp    BsScenario: a scenario document built by calls or read
//                   from text, read by the scenario reader (io)
//   simulation.cpp  BsSimulation: a run, its events, the result file, the
//                   states at any time from its record; batches on threads
//   game.cpp        BsGame and BsPlayer: GameSession, the records' JSON
//                   (io/game_json.hpp), make_player
//   page.cpp        games as the browser page plays them (page.hpp): the
//                   config document, acts with their report, turns, undo,
//                   the table, placement, figures, the AI of a game
//   link.cpp        links: a game as "v2." text and back ("v1." read too)
//   playback.cpp    BsPlayback: a simulation advanced frame by frame
//
// Every entry point catches everything: a Failure becomes its status and
// message, std::bad_alloc BS_ERROR_NO_MEMORY, anything else
// BS_ERROR_INTERNAL. Messages go to the handle the call was given when
// that handle is valid, else to the calling thread's slot.

#ifndef BREAKSHOT_CAPI_HPP
#define BREAKSHOT_CAPI_HPP

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <exception>
#include <memory>
#include <new>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "breakshot.h"
#include "breakshot/player.hpp"
#include "breakshot/scenario.hpp"
#include "breakshot/session.hpp"
#include "breakshot/simulation.hpp"
#include "physics/run_record.hpp"

namespace capi {

namespace bs = breakshot;
using json = nlohmann::json;

// Each handle begins with its type's tag; bs_*_free writes kFreed over it
// before the memory is released.
enum Tag : std::uint32_t {
  kScenarioTag = 0x42735363,    // "BsSc"
  kSimulationTag = 0x42735369,  // "BsSi"
  kGameTag = 0x42734761,        // "BsGa"
  kPlayerTag = 0x4273506c,      // "BsPl"
  kPlaybackTag = 0x42735062,    // "BsPb"
  kFreed = 0xdeadbea7,
};

struct Handle {
  explicit Handle(Tag t) : tag(t) {}
  std::uint32_t tag;
  // The message of the last call on this handle ("" after a success).
  mutable std::string error;
};

/// A failure of a call: its status and message.
struct Failure {
  BsStatus status;
  std::string message;
};

[[noreturn]] inline void fail(BsStatus status, std::string message) {
  throw Failure{status, std::move(message)};
}

/// The value of an enum argument as an integer, read without loading it
/// as the enum: a C caller may pass any int, and a value outside the
/// enum's range is not a value of the C++ type.
template <class E>
long long raw(const E& e) {
  std::underlying_type_t<E> v;
  std::memcpy(&v, &e, sizeof v);
  return static_cast<long long>(v);
}

/// The calling thread's message slot.
std::string& thread_error();

/// A required pointer argument.
template <class T>
T* need(T* p, const char* what) {
  if (p == nullptr) fail(BS_ERROR_NULL, std::string(what) + ": a null pointer");
  return p;
}

/// Runs `body` and turns its outcome into a status and a message in `slot`.
template <class F>
BsStatus guarded(std::string& slot, F&& body) {
  try {
    body();
    slot.clear();
    return BS_OK;
  } catch (const Failure& f) {
    slot = f.message;
    return f.status;
  } catch (const std::bad_alloc&) {
    slot = "out of memory";
    return BS_ERROR_NO_MEMORY;
  } catch (const std::exception& e) {
    slot = std::string("internal error: ") + e.what();
    return BS_ERROR_INTERNAL;
  } catch (...) {
    slot = "internal error";
    return BS_ERROR_INTERNAL;
  }
}

/// A call without a handle (constructors, free functions).
template <class F>
BsStatus on_thread(F&& body) {
  return guarded(thread_error(), std::forward<F>(body));
}

/// A call on the handle `h` of type H (tag `tag`, named `what` in
/// messages): a null or wrong handle is reported on the thread, the rest
/// on the handle.
template <class H, class F>
BsStatus on_handle(H* h, Tag tag, const char* what, F&& body) {
  if (h == nullptr) {
    thread_error() = std::string(what) + ": a null handle";
    return BS_ERROR_NULL;
  }
  if (h->tag != tag) {
    thread_error() =
        std::string(what) + ": not a live " + what + " handle (freed, or a handle of another type)";
    return BS_ERROR_BAD_HANDLE;
  }
  return guarded(h->error, [&] { body(*h); });
}

/// A copy the caller owns (bs_string_free).
char* copy_out(const std::string& s);

/// Text of `len` bytes as a string (NUL-terminated or not).
std::string text_arg(const char* text, std::size_t len, const char* what);

}  // namespace capi

// ---------------------------------------------------------------------------
// The handles

struct BsScenario : capi::Handle {
  BsScenario() : Handle(capi::kScenarioTag) {}
  /// The scenario document, in the scenario format.
  capi::json doc = capi::json::object();
  /// The scenario read from doc, while doc has not changed since (shared
  /// with the simulations run from it).
  mutable std::shared_ptr<const breakshot::Scenario> read;
};

struct BsSimulation : capi::Handle {
  BsSimulation() : Handle(capi::kSimulationTag) {}
  /// The run's record ball by ball: each ball's trajectory after set-up
  /// and every change at an event (the engine's run record), ball i's
  /// changes being record.changes[order[k]] for k in [first[i],
  /// first[i + 1]), in time order.
  struct Trajectories {
    breakshot::detail::RunRecord record;
    std::vector<std::uint32_t> order;
    std::vector<std::size_t> first;
  };
  std::shared_ptr<const breakshot::Scenario> scenario;
  breakshot::RunResult result;
  /// Made by the first states query (capi::trajectories_of): a second
  /// run of the scenario, recorded, which is the same run. A run asked
  /// only for its result and events never records.
  mutable std::unique_ptr<const Trajectories> trajectories;
};

struct BsGame : capi::Handle {
  BsGame(const breakshot::GameConfig& config, const breakshot::Seats& seats, std::uint64_t seed,
         int breaker)
      : Handle(capi::kGameTag), session(config, seats, seed, breaker) {}
  BsGame(const breakshot::GameConfig& config, const breakshot::Seats& seats, std::uint64_t seed,
         std::uint64_t rack_seed, int breaker)
      : Handle(capi::kGameTag), session(config, seats, seed, rack_seed, breaker) {}
  breakshot::GameSession session;
  /// Simulations per decision of the game's computer players
  /// (bs_player_new_for_game), when the config or the link sets them.
  std::optional<std::int64_t> ai_budget;
};

struct BsPlayer : capi::Handle {
  explicit BsPlayer(std::unique_ptr<breakshot::Player> p)
      : Handle(capi::kPlayerTag), player(std::move(p)) {}
  std::unique_ptr<breakshot::Player> player;
};

struct BsPlayback : capi::Handle {
  explicit BsPlayback(const breakshot::Scenario& s)
      : Handle(capi::kPlaybackTag), scenario(s), sim(scenario) {}
  breakshot::Scenario scenario;
  breakshot::Simulation sim;
  bool limit = false;         // max_events stopped a frame
  std::vector<double> frame;  // the last frame (breakshot.h's layout)
  /// A three-cushion shot's playback (bs_game_shot_playback): the ball
  /// number of each scenario ball, and the ball struck; -1 otherwise.
  std::vector<int> numbers;
  int carom_struck = -1;
};

namespace capi {

/// The scenario of `s`, read (and cached) or a BS_ERROR_INVALID failure
/// naming the field.
const bs::Scenario& scenario_of(const BsScenario& s);

/// The scenario of `s` as a shared value (scenario_of's).
std::shared_ptr<const bs::Scenario> shared_scenario_of(const BsScenario& s);

/// A run of `scenario` (its scenario and result; the trajectories are
/// recorded when first asked for).
std::unique_ptr<BsSimulation> run(std::shared_ptr<const bs::Scenario> scenario);

/// The trajectories of `s`, recorded by the first call.
const BsSimulation::Trajectories& trajectories_of(const BsSimulation& s);

/// A ball's state in the C API's struct.
void to_c(const bs::BallState& s, BsBallState& o);

}  // namespace capi

#endif  // BREAKSHOT_CAPI_HPP
