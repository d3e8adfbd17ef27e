# Every dependency comes from a Debian 12 package (cmake/install-deps.sh installs them).
find_package(PkgConfig REQUIRED)

# Engine: linear algebra.
find_package(Eigen3 3.4 REQUIRED NO_MODULE)

# Application: command line, formatting, scene files.
find_package(fmt REQUIRED)
find_package(CLI11 REQUIRED)
find_package(nlohmann_json 3.11 REQUIRED)
# Sweeps: the arithmetic expressions of a sweep spec (render/app/sweep_expression.h).
pkg_check_modules(MUPARSER REQUIRED IMPORTED_TARGET muparser)

# Renderer: off-screen GL, PNG, MP4, text and vector stills, by pkg-config (one file, which the
# installed package config includes too).
include("${CMAKE_CURRENT_LIST_DIR}/rugosimRenderDependencies.cmake")

if(RUGOSIM_BUILD_TESTS)
  # The tests read animated WebP with libwebp's demux API (FFmpeg 5.1 cannot decode it).
  pkg_check_modules(WEBPDEMUX REQUIRED IMPORTED_TARGET libwebpdemux)
  find_package(GTest REQUIRED)
endif()
if(RUGOSIM_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()
