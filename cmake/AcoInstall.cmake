# Installation: the programs, the public headers and libraries, and a CMake
# package, so that another project can
#   find_package(acodrill 0.1 CONFIG REQUIRED)
#   target_link_libraries(x PRIVATE aco::aco)   # or aco::job: a whole job in one call
# and the Debian package built from the same rules by CPack (scripts/package).
include(CMakePackageConfigHelpers)

set(ACO_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/acodrill)

set(ACO_PROGRAMS acodrill acobench)
if(NOT WIN32)
  list(APPEND ACO_PROGRAMS acodrill-linuxcnc-filter)
endif()
install(TARGETS ${ACO_PROGRAMS} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS aco_geometry aco aco_dxf aco_gcode aco_formats aco_planning aco_job
        EXPORT acodrillTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
foreach(dir libaco dxf gcode formats planning job)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()
# The page (issue 65: scripts/web writes it), installed where it has been built:
# /usr/share/acodrill/acodrill.html in the package.
set(ACO_WEB_PAGE "${PROJECT_SOURCE_DIR}/build-web/acodrill.html" CACHE FILEPATH "The page to install (scripts/web)")
install(FILES ${ACO_WEB_PAGE} DESTINATION ${CMAKE_INSTALL_DATADIR}/acodrill OPTIONAL)
install(EXPORT acodrillTargets NAMESPACE aco:: DESTINATION ${ACO_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/acodrillConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/acodrillConfig.cmake INSTALL_DESTINATION ${ACO_CMAKE_DIR})
# 0.x: only the same minor version promises the same API.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/acodrillConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/acodrillConfig.cmake ${PROJECT_BINARY_DIR}/acodrillConfigVersion.cmake
        DESTINATION ${ACO_CMAKE_DIR})

# Man pages made from the programs' own --help by help2man (Debian), so they
# never drift from the options; skipped with a note where help2man is missing.
find_program(ACO_HELP2MAN help2man)
if(ACO_HELP2MAN AND NOT CMAKE_CROSSCOMPILING)
  set(man_pages)
  foreach(prog ${ACO_PROGRAMS})
    set(page ${PROJECT_BINARY_DIR}/man/${prog}.1)
    set(gz ${page}.gz)
    if(prog STREQUAL "acodrill")
      set(what "order drill holes for the shortest spindle travel and write the G-code")
      set(help_option --help-option=--help-all)  # every command's options, not only the list of commands
    elseif(prog STREQUAL "acodrill-linuxcnc-filter")
      set(help_option --help-option=--help)
      set(what "LinuxCNC filter program: open drill files and DXF in AXIS through acodrill")
    else()
      set(help_option --help-option=--help)
      set(what "benchmark the ant colony over algorithms, parameters and threads")
    endif()
    add_custom_command(OUTPUT ${page} ${gz}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${PROJECT_BINARY_DIR}/man
      COMMAND ${ACO_HELP2MAN} --no-info --no-discard-stderr --section 1 --name "${what}" ${help_option} --output ${page}
              $<TARGET_FILE:${prog}>
      COMMAND gzip -9nkf ${page}  # Debian installs man pages compressed; -n keeps the package reproducible
      DEPENDS ${prog} VERBATIM)
    list(APPEND man_pages ${gz})
  endforeach()
  add_custom_target(man_pages ALL DEPENDS ${man_pages})
  install(FILES ${man_pages} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
else()
  message(STATUS "help2man not found: no man pages (scripts/package installs it)")
endif()

# The KiCad plugin (plugins/kicad): the Python package acodrill_kicad where
# Debian's python3 finds it (`python3 -m acodrill_kicad`), and the file that
# makes pcbnew load it from its bundled plugin folder.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/plugins/kicad/acodrill_kicad DESTINATION lib/python3/dist-packages
        FILES_MATCHING PATTERN "*.py" PATTERN "*.png" PATTERN "__pycache__" EXCLUDE)
install(FILES ${PROJECT_SOURCE_DIR}/plugins/kicad/kicad_loader/acodrill_kicad_plugin.py
        DESTINATION share/kicad/scripting/plugins)

# The FreeCAD post-processor (plugins/freecad, issue 83): copied into FreeCAD's
# macro folder by the user, as its header says.
install(FILES ${PROJECT_SOURCE_DIR}/plugins/freecad/acodrill_post.py DESTINATION share/acodrill/freecad)

# Debian package (scripts/package): dependencies computed by dpkg-shlibdeps.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME acodrill)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "acodrill developers <acodrill@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "orders drill holes with an ant colony and writes drilling G-code")
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "acodrill reads the drill holes of a part (DXF, Excellon, Gerber, CSV, XML),\n orders them so the spindle travels as little as possible with a\n thread-parallel ant colony, and writes HAAS, Fanuc or LinuxCNC programs\n with canned drilling cycles. Also installs the libaco solver and readers\n as static libraries with a CMake package, and a KiCad plugin\n (Tools > External Plugins > Drill with acodrill).")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # acodrill_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# The KiCad plugin needs KiCad; acodrill itself does not.
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "kicad (>= 6.0)")
# Python leaves byte code beside the plugin when KiCad runs it: removed with the package.
configure_file(${PROJECT_SOURCE_DIR}/cmake/prerm.in ${PROJECT_BINARY_DIR}/debian/prerm @ONLY)
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA ${PROJECT_BINARY_DIR}/debian/prerm)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_OUTPUT_FILE_PREFIX ${PROJECT_BINARY_DIR})
include(CPack)
