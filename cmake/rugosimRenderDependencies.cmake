# The renderer's libraries, by pkg-config: found by the build (RugosimDependencies.cmake) and
# again by programs that link the installed, static rugosim::render (rugosimConfig.cmake).
find_package(PkgConfig REQUIRED)
# Off-screen GL (OSMesa, EGL), PNG, and FFmpeg for MP4 and GIF (libavfilter: the GIF palette).
pkg_check_modules(OSMESA REQUIRED IMPORTED_TARGET osmesa)
pkg_check_modules(EGL REQUIRED IMPORTED_TARGET egl)
pkg_check_modules(PNG REQUIRED IMPORTED_TARGET libpng)
# Text in frames: FreeType (the font is fonts-dejavu-core's DejaVu Sans).
pkg_check_modules(FREETYPE REQUIRED IMPORTED_TARGET freetype2)
# Vector stills (SVG and PDF): cairo's surfaces, with the same FreeType face for text.
pkg_check_modules(CAIRO REQUIRED IMPORTED_TARGET cairo cairo-svg cairo-pdf cairo-ft)
pkg_check_modules(LIBAV REQUIRED IMPORTED_TARGET libavcodec libavformat libavfilter libavutil
                  libswscale)
