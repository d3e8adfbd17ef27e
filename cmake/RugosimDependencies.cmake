# Every dependency comes from a Debian 12 package (cmake/install-deps.sh installs them).
find_package(PkgConfig REQUIRED)

# Engine: linear algebra.
find_package(Eigen3 3.4 REQUIRED NO_MODULE)

# Application: command line, formatting, scene files.
find_package(fmt REQUIRED)
find_package(CLI11 REQUIRED)
find_package(nlohmann_json 3.11 REQUIRED)

# Renderer: off-screen GL (OSMesa, EGL), PNG, and FFmpeg for MP4 and GIF (libavfilter: the
# GIF palette).
pkg_check_modules(OSMESA REQUIRED IMPORTED_TARGET osmesa)
pkg_check_modules(EGL REQUIRED IMPORTED_TARGET egl)
pkg_check_modules(PNG REQUIRED IMPORTED_TARGET libpng)
# Text in frames: FreeType (the font is fonts-dejavu-core's DejaVu Sans).
pkg_check_modules(FREETYPE REQUIRED IMPORTED_TARGET freetype2)
# Vector stills (SVG and PDF): cairo's surfaces, with the same FreeType face for text.
pkg_check_modules(CAIRO REQUIRED IMPORTED_TARGET cairo cairo-svg cairo-pdf cairo-ft)
pkg_check_modules(LIBAV REQUIRED IMPORTED_TARGET libavcodec libavformat libavfilter libavutil
                  libswscale)

if(RUGOSIM_BUILD_TESTS)
  # The tests read animated WebP with libwebp's demux API (FFmpeg 5.1 cannot decode it).
  pkg_check_modules(WEBPDEMUX REQUIRED IMPORTED_TARGET libwebpdemux)
  find_package(GTest REQUIRED)
endif()
if(RUGOSIM_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()
