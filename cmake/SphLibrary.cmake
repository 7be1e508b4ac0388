# sph_add_library(NAME SOURCES ... [LINK ...])
#   A shared library libsph<NAME>.so whose headers are included as "folder/Header.hpp"
#   relative to libraries/ (include/sphSolid/ once installed). Installed and exported as
#   sphSolid::sph<NAME> (cmake/sphSolidConfig.cmake.in), so that a user's own library builds
#   against an installation.
function(sph_add_library name)
    cmake_parse_arguments(ARG "" "" "SOURCES;LINK" ${ARGN})
    add_library(sph${name} SHARED ${ARG_SOURCES})
    target_include_directories(sph${name} PUBLIC
        $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/libraries>
        $<INSTALL_INTERFACE:include/sphSolid>)
    target_link_libraries(sph${name} PUBLIC ${ARG_LINK})
    install(TARGETS sph${name} EXPORT sphSolidTargets LIBRARY DESTINATION lib)
endfunction()

# sph_add_family(NAME SOURCES ... [LINK ...])
#   A model family: a shared library that the solver loads by name (etc/defaultLibs) and whose
#   models register themselves while it loads. Nothing links to it, so its registrations cannot
#   be dropped by the linker; tests load it the same way the solver does.
function(sph_add_family name)
    cmake_parse_arguments(ARG "" "" "SOURCES;LINK" ${ARGN})
    sph_add_library(${name} SOURCES ${ARG_SOURCES} LINK sphCore ${ARG_LINK})
endfunction()
