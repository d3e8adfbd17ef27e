# What `cmake --install` puts where (GNUInstallDirs), and the .deb that CPack builds from it.
#
# Two components, so that a render worker gets the program without a compiler's worth of
# headers:
#   program  bin/rugosim, the built-in scenes (share/rugosim/scenes) and the docs; the .deb
#            "rugosim", its shared-library dependencies found by dpkg-shlibdeps.
#   dev      the engine's and renderer's headers and static libraries with a CMake package
#            config (find_package(rugosim) gives rugosim::engine and rugosim::render); the
#            .deb "rugosim-dev", depending on the -dev packages those headers and libraries
#            need (the same Debian packages cmake/install-deps.sh installs to build them).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(RUGOSIM_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/rugosim")
set(RUGOSIM_INSTALL_INCLUDEDIR "${CMAKE_INSTALL_INCLUDEDIR}/rugosim")

install(TARGETS rugosim RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}" COMPONENT program)
install(DIRECTORY "${PROJECT_SOURCE_DIR}/scenes/" DESTINATION "${CMAKE_INSTALL_DATADIR}/rugosim/scenes"
        COMPONENT program FILES_MATCHING PATTERN "*.json")
install(FILES "${PROJECT_SOURCE_DIR}/README.md" "${PROJECT_SOURCE_DIR}/docs/scene-format.md"
        DESTINATION "${CMAKE_INSTALL_DOCDIR}" COMPONENT program)

# Headers keep their paths under include/rugosim, so that "engine/dynamics/world.h" resolves
# the same installed as in the source tree. The program's own commands (render/app) are not a
# library for others: they stay out.
install(DIRECTORY "${PROJECT_SOURCE_DIR}/engine/" DESTINATION "${RUGOSIM_INSTALL_INCLUDEDIR}/engine"
        COMPONENT dev FILES_MATCHING PATTERN "*.h")
install(DIRECTORY "${PROJECT_SOURCE_DIR}/render/" DESTINATION "${RUGOSIM_INSTALL_INCLUDEDIR}/render"
        COMPONENT dev FILES_MATCHING PATTERN "*.h" PATTERN "app" EXCLUDE)
install(FILES "${PROJECT_BINARY_DIR}/generated/engine/core/version.h"
        DESTINATION "${RUGOSIM_INSTALL_INCLUDEDIR}/engine/core" COMPONENT dev)

set_target_properties(rugosim_engine PROPERTIES EXPORT_NAME engine)
set_target_properties(rugosim_render PROPERTIES EXPORT_NAME render)
install(TARGETS rugosim_engine rugosim_render EXPORT rugosimTargets
        ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}" COMPONENT dev
        LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}" COMPONENT dev
        INCLUDES DESTINATION "${RUGOSIM_INSTALL_INCLUDEDIR}")
install(EXPORT rugosimTargets NAMESPACE rugosim:: DESTINATION "${RUGOSIM_INSTALL_CMAKEDIR}"
        COMPONENT dev)
configure_package_config_file("${PROJECT_SOURCE_DIR}/cmake/rugosimConfig.cmake.in"
                              "${PROJECT_BINARY_DIR}/rugosimConfig.cmake"
                              INSTALL_DESTINATION "${RUGOSIM_INSTALL_CMAKEDIR}")
write_basic_package_version_file("${PROJECT_BINARY_DIR}/rugosimConfigVersion.cmake"
                                 COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/rugosimConfig.cmake"
              "${PROJECT_BINARY_DIR}/rugosimConfigVersion.cmake"
              "${PROJECT_SOURCE_DIR}/cmake/rugosimRenderDependencies.cmake"
        DESTINATION "${RUGOSIM_INSTALL_CMAKEDIR}" COMPONENT dev)

# CPack: `cpack -G DEB` in the build folder writes rugosim_<version>_<arch>.deb and
# rugosim-dev_<version>_<arch>.deb.
set(CPACK_PACKAGE_NAME rugosim)
set(CPACK_PACKAGE_VENDOR "rugosim developers")
set(CPACK_PACKAGE_CONTACT "rugosim developers <rugosim@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_GENERATOR DEB)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL program dev)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PROGRAM_PACKAGE_NAME rugosim)
set(CPACK_DEBIAN_PROGRAM_PACKAGE_SHLIBDEPS ON)
# Found at run time, not linked: the font of titles and captions (RUGOSIM_DEFAULT_FONT).
set(CPACK_DEBIAN_PROGRAM_PACKAGE_DEPENDS "fonts-dejavu-core")
# `render --backend egl` only: Mesa's EGL driver and its software rasteriser, loaded at run time (the default
# backend, OSMesa, carries its own).
set(CPACK_DEBIAN_PROGRAM_PACKAGE_RECOMMENDS "libegl-mesa0, libgl1-mesa-dri")
set(CPACK_DEBIAN_DEV_PACKAGE_NAME rugosim-dev)
# What rugosimConfig.cmake finds: the headers' and static libraries' own dependencies.
set(CPACK_DEBIAN_DEV_PACKAGE_DEPENDS
    "cmake, pkg-config, libeigen3-dev, nlohmann-json3-dev, libosmesa6-dev, libegl-dev, \
libpng-dev, libavcodec-dev, libavformat-dev, libavfilter-dev, libavutil-dev, libswscale-dev, \
libfreetype-dev, libcairo2-dev, fonts-dejavu-core")
set(CPACK_COMPONENT_PROGRAM_DESCRIPTION
    "The rugosim command: simulate, render, snapshot, plot (README.md in /usr/share/doc/rugosim)")
set(CPACK_COMPONENT_DEV_DESCRIPTION
    "rugosim's engine and renderer as static libraries with headers and a CMake package config")
include(CPack)
