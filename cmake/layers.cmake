# The layers of breakshot and the public headers each one owns
# (docs/architecture.md, "Layers"). A layer may include its own headers and
# those of the layers it is built on, never those above it:
#
#   physics  <-  game  <-  ai
#                  ^
#                  io (scenario I/O on physics; records and summaries on game)
#
# cmake/check_layers.cmake reads this list and fails the build when a
# source file in src/LAYER/ includes a header of a layer LAYER is not built
# on, a header that belongs to no layer, nlohmann/json outside io, or
# another layer's internal header (src/OTHER/*.hpp) other than the few a
# layer shares with the layers built on it (BREAKSHOT_LAYER_<layer>_SHARED).
set(BREAKSHOT_LAYERS physics game ai io)

set(BREAKSHOT_LAYER_physics_BELOW "")
set(BREAKSHOT_LAYER_game_BELOW physics)
set(BREAKSHOT_LAYER_ai_BELOW game physics)
set(BREAKSHOT_LAYER_io_BELOW game physics)

set(BREAKSHOT_LAYER_physics_HEADERS
  ball carom event lab physics pool scenario simulation snooker table vec version)
set(BREAKSHOT_LAYER_game_HEADERS batch game match noise player rack record session)
set(BREAKSHOT_LAYER_ai_HEADERS ai players pot_map)
set(BREAKSHOT_LAYER_io_HEADERS scenario_io record_io match_io plot)

# Internal headers (src/LAYER/NAME.hpp, not installed) that the layers
# built on LAYER may include: physics' deterministic maths (the rack's
# gaps, the noise and the AI's aim must round as the engine does) and its
# airborne impulses (the AI's jump shots). Every other internal header
# stays its layer's own.
set(BREAKSHOT_LAYER_physics_SHARED detmath airborne)
set(BREAKSHOT_LAYER_game_SHARED "")
set(BREAKSHOT_LAYER_ai_SHARED "")
set(BREAKSHOT_LAYER_io_SHARED "")
# The umbrella header; no layer may include it. (The server of `breakshot
# serve` and its rooms of online play, src/web/serve.hpp and rooms.hpp,
# sit on top of every layer: a layer that named "web/..." would cross.)
set(BREAKSHOT_TOP_HEADERS breakshot)
