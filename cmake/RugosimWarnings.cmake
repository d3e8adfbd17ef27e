# One interface target carries the project's compile options; every rugosim target links it.
add_library(rugosim_options INTERFACE)
add_library(rugosim::options ALIAS rugosim_options)

target_compile_options(rugosim_options INTERFACE
  -Wall -Wextra -Wpedantic
  -Wshadow -Wconversion -Wsign-conversion -Wdouble-promotion
  -Wnon-virtual-dtor -Wold-style-cast -Woverloaded-virtual
  -Wnull-dereference -Wimplicit-fallthrough -Wformat=2
  -Wmisleading-indentation -Wduplicated-cond -Wlogical-op
  # Determinism: no fused multiply-add contraction, so results do not depend on
  # what the optimiser chose to fuse (same scene + seed -> identical output).
  -ffp-contract=off)

if(RUGOSIM_WERROR)
  target_compile_options(rugosim_options INTERFACE -Werror)
endif()
