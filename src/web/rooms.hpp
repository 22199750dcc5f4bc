// The rooms of online play behind `breakshot serve` (docs/web.md, "Online
// play"): games between two players on two computers, with watchers.
//
// This is the whole of online play but the sockets: it takes each client's
// messages (JSON text, as received from a WebSocket) and the passing of
// time, and answers with what to send to whom, which connections to close
// and which game records to write. It never touches a socket, a clock or
// the file system, so every rule of it is tested without them.
//
// Lockstep: only actions cross the network. A room's game is played by the
// browser facade (web/api/web_api.hpp) with two "human" seats, the same
// code the page runs in wasm; the room applies each action with the rules
// and is the authority: an action the rules refuse is refused with their
// reason, and every action it plays is sent to the whole room with the
// hash of the state after it (state_hash), which each page compares with
// its own.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace breakshot::online {

/// A connection, as the server numbers them (never 0).
using ClientId = std::uint64_t;

struct RoomLimits {
  std::size_t max_rooms = 1000;    ///< rooms at once; create is refused beyond
  std::size_t max_watchers = 16;   ///< watchers per room
  std::size_t max_message = 8192;  ///< bytes of one message; a longer one closes
  /// Seconds a seat of a game in progress may stay empty before its player
  /// forfeits (both empty: the game is abandoned, no winner).
  double seat_timeout = 120;
  /// Seconds a room nobody is connected to lives on once its game is over
  /// (or before the second player came).
  double room_timeout = 600;
  /// The start of every record file's name (the server's, never a client's).
  std::string record_prefix = "online";
};

/// What one step of the rooms asks of the server, in order: send the
/// messages, then close the connections named in `close` (after their
/// messages), and write the records.
struct Effects {
  struct Message {
    ClientId to = 0;
    std::string text;
  };
  struct Record {
    std::string name;  ///< a file name made by the rooms: prefix, serial, code
    std::string text;  ///< the game record (record_io.hpp's write_record)
  };
  std::vector<Message> messages;
  std::vector<ClientId> close;
  std::vector<Record> records;
};

/// FNV-1a, 64 bits, of `text`, as 16 lower-case hex digits: the hash of a
/// table state is state_hash of bs_web_game_state's reply.
std::string state_hash(std::string_view text);

class Rooms {
 public:
  /// `random` gives the room codes, seat tokens and game seeds (the server
  /// passes a source seeded from the system's randomness; tests a fixed one).
  Rooms(RoomLimits limits, std::function<std::uint64_t()> random);
  ~Rooms();
  Rooms(const Rooms&) = delete;
  Rooms& operator=(const Rooms&) = delete;

  /// A message of client `from` at `now` (seconds, any steady origin).
  Effects receive(ClientId from, std::string_view text, double now);
  /// The connection of `client` is gone (a second call is harmless).
  Effects disconnect(ClientId client, double now);
  /// Forfeits of seats left empty, and rooms expired, by `now`.
  Effects tick(double now);

  std::size_t rooms() const;
  std::size_t clients() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace breakshot::online
