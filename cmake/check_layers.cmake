# Checks that no source file crosses a layer the wrong way (cmake/layers.cmake).
# Run as a build step: cmake -DROOT=<source dir> -DSTAMP=<file> -P check_layers.cmake
cmake_minimum_required(VERSION 3.25)
include(${ROOT}/cmake/layers.cmake)

# Which layer owns each public header.
foreach(layer ${BREAKSHOT_LAYERS})
  foreach(h ${BREAKSHOT_LAYER_${layer}_HEADERS})
    set(owner_${h} ${layer})
  endforeach()
endforeach()
foreach(h ${BREAKSHOT_TOP_HEADERS})
  set(owner_${h} top)
endforeach()

# Every public header must belong somewhere.
set(problems "")
file(GLOB public_headers ${ROOT}/include/breakshot/*.hpp)
foreach(file ${public_headers})
  get_filename_component(h ${file} NAME_WE)
  if(NOT DEFINED owner_${h})
    list(APPEND problems "include/breakshot/${h}.hpp belongs to no layer: add it to cmake/layers.cmake")
  endif()
endforeach()

# The public headers of a layer, and its sources, may include only what
# the layer may see.
foreach(layer ${BREAKSHOT_LAYERS})
  set(allowed ${layer} ${BREAKSHOT_LAYER_${layer}_BELOW})
  set(files "")
  foreach(h ${BREAKSHOT_LAYER_${layer}_HEADERS})
    list(APPEND files ${ROOT}/include/breakshot/${h}.hpp)
  endforeach()
  file(GLOB_RECURSE sources ${ROOT}/src/${layer}/*.cpp ${ROOT}/src/${layer}/*.hpp)
  list(APPEND files ${sources})
  foreach(file ${files})
    if(NOT EXISTS ${file})
      continue()
    endif()
    file(RELATIVE_PATH rel ${ROOT} ${file})
    file(STRINGS ${file} includes REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<]")
    foreach(line ${includes})
      if(line MATCHES "[\"<]breakshot/([A-Za-z0-9_]+)\\.hpp[\">]")
        set(h ${CMAKE_MATCH_1})
        if(NOT DEFINED owner_${h})
          list(APPEND problems "${rel} includes breakshot/${h}.hpp, which belongs to no layer")
        elseif(NOT owner_${h} IN_LIST allowed)
          list(APPEND problems
            "${rel} (layer ${layer}) includes breakshot/${h}.hpp of layer ${owner_${h}}")
        endif()
      elseif(line MATCHES "[\"<]nlohmann/")
        if(NOT layer STREQUAL "io")
          list(APPEND problems "${rel} (layer ${layer}) includes nlohmann/json: JSON is io's")
        endif()
      elseif(line MATCHES "\"(physics|game|ai|io|web)/([A-Za-z0-9_]+)\\.hpp\"")
        set(other ${CMAKE_MATCH_1})
        set(h ${CMAKE_MATCH_2})
        if(rel MATCHES "^include/")
          # Internal headers are not installed: a public header that
          # needed one would break every program outside the tree.
          list(APPEND problems "${rel} is public but includes the internal ${other}/${h}.hpp")
        elseif(NOT other STREQUAL layer)
          # A layer below may share a few internal headers upward.
          if(NOT (other IN_LIST BREAKSHOT_LAYER_${layer}_BELOW AND
                  h IN_LIST BREAKSHOT_LAYER_${other}_SHARED))
            list(APPEND problems
              "${rel} (layer ${layer}) includes an internal header of ${other} (${other}/${h}.hpp)")
          endif()
        endif()
      endif()
    endforeach()
  endforeach()
endforeach()

if(problems)
  list(JOIN problems "\n  " text)
  message(FATAL_ERROR "breakshot layers are crossed the wrong way:\n  ${text}")
endif()
file(WRITE ${STAMP} "layers ok\n")
