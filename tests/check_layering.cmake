# Fails when a file includes a project header from a layer above its own (DESIGN.md, Layers).
# Layers, bottom to top; a file in layer k may include headers from layers 0..k.
set(layers engine/core engine/geometry engine/collision engine/dynamics engine/scene render
           render/app)

function(layer_index path out)
  set(best -1)
  set(i 0)
  foreach(layer IN LISTS layers)
    string(LENGTH "${layer}/" len)
    string(SUBSTRING "${path}" 0 ${len} prefix)
    if(prefix STREQUAL "${layer}/")
      set(best ${i})  # later (more specific) layers win: render/app over render
    endif()
    math(EXPR i "${i} + 1")
  endforeach()
  set(${out} ${best} PARENT_SCOPE)
endfunction()

file(GLOB_RECURSE files RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/engine/*.h"
     "${SOURCE_DIR}/engine/*.cpp" "${SOURCE_DIR}/render/*.h" "${SOURCE_DIR}/render/*.cpp")
set(violations "")
foreach(file IN LISTS files)
  layer_index("${file}" own)
  file(STRINGS "${SOURCE_DIR}/${file}" includes REGEX "^#include \"")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^#include \"([^\"]+)\".*" "\\1" header "${line}")
    layer_index("${header}" target)
    if(target GREATER own)
      string(APPEND violations "  ${file} includes ${header}\n")
    endif()
  endforeach()
endforeach()
if(violations)
  message(FATAL_ERROR "includes that point up the layers:\n${violations}")
endif()
list(LENGTH files count)
message(STATUS "layering: ${count} files, every include points down")
