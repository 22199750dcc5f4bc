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
# another layer's internal header (src/OTHER/*.hpp).
set(BREAKSHOT_LAYERS physics game ai io)

set(BREAKSHOT_LAYER_physics_BELOW "")
set(BREAKSHOT_LAYER_game_BELOW physics)
set(BREAKSHOT_LAYER_ai_BELOW game physics)
set(BREAKSHOT_LAYER_io_BELOW game physics)

set(BREAKSHOT_LAYER_physics_HEADERS
  airborne ball carom cluster_impact detmath event lab physics pool roots scenario simulation snooker
  table vec
  version)
set(BREAKSHOT_LAYER_game_HEADERS batch game match noise player rack record session)
set(BREAKSHOT_LAYER_ai_HEADERS ai players pot_map)
set(BREAKSHOT_LAYER_io_HEADERS scenario_io record_io match_io plot)
# Headers of the programs on top (src/web is the server of `breakshot
# serve` and its rooms of online play) and the umbrella header; no layer
# may include them.
set(BREAKSHOT_TOP_HEADERS serve rooms breakshot)
