# Where the Debian package puts HSM Planner (HSM_PACKAGE, `make deb`). The workbench goes where Debian's
# FreeCAD looks for system modules, as FreeCAD reports it (getResourceDir() + "Mod"), with its python/ folder
# inside it: FreeCAD restores the proxies of a saved document only from modules under its Mod folders. The
# core library is architecture-dependent, so it lives in /usr/lib; a link beside the package's modules lets
# Python import it as hsmplanner._core. Our posts are linked into CAM's own folder of posts, the one folder
# every user's Job looks in.
find_program(HSM_FREECADCMD freecadcmd)
if(NOT HSM_FREECADCMD)
  message(FATAL_ERROR "HSM_PACKAGE needs FreeCAD's freecadcmd to ask where FreeCAD looks for modules: "
    "install Debian's freecad (scripts/install-deps.sh)")
endif()
execute_process(
  COMMAND ${HSM_FREECADCMD} ${CMAKE_CURRENT_LIST_DIR}/freecad_layout.py
  OUTPUT_VARIABLE hsm_answer ERROR_VARIABLE hsm_errors RESULT_VARIABLE hsm_status)
if(NOT hsm_answer MATCHES "HSM_MOD=([^\n]+)\nHSM_POSTS=([^\n]+)\nHSM_FREECAD=([0-9.]+)\nHSM_PYSIDE=(pyside[0-9])")
  message(FATAL_ERROR "freecadcmd did not say where FreeCAD's modules are (exit ${hsm_status}): "
    "${hsm_answer}${hsm_errors}")
endif()
set(HSM_FREECAD_MOD_DIR "${CMAKE_MATCH_1}")
set(HSM_FREECAD_POSTS_DIR "${CMAKE_MATCH_2}")
# The package is for one FreeCAD of one Debian release: FreeCAD 1.0 (Qt 5, PySide2) on trixie, 1.1 (Qt 6,
# PySide6) on forky. Its version carries the release (0.9.0+trixie, 0.9.0+forky), so both can sit in one folder.
set(HSM_FREECAD_RELEASE "${CMAKE_MATCH_3}")
set(HSM_PYSIDE "${CMAKE_MATCH_4}")
execute_process(COMMAND sh -c ". /etc/os-release && echo \"$VERSION_CODENAME\""
  OUTPUT_VARIABLE HSM_DEBIAN_SUITE OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT HSM_DEBIAN_SUITE MATCHES "^[a-z]+$")
  message(FATAL_ERROR "/etc/os-release names no Debian release (VERSION_CODENAME): the package is built on the "
    "Debian it is for (scripts/freecad-env.sh)")
endif()

# Relative to the prefix (/usr), as CPack installs into its staging folder.
function(hsm_relative_to_prefix variable path)
  file(RELATIVE_PATH relative "${CMAKE_INSTALL_PREFIX}" "${path}")
  if(relative MATCHES "^\\.\\./")
    message(FATAL_ERROR "${path} (from FreeCAD) is outside CMAKE_INSTALL_PREFIX ${CMAKE_INSTALL_PREFIX}: "
      "configure with -DCMAKE_INSTALL_PREFIX=/usr")
  endif()
  set(${variable} "${relative}" PARENT_SCOPE)
endfunction()

hsm_relative_to_prefix(HSM_INSTALL_MOD_DIR "${HSM_FREECAD_MOD_DIR}/HSMPlanner")
hsm_relative_to_prefix(HSM_INSTALL_POSTS_DIR "${HSM_FREECAD_POSTS_DIR}")
# A folder below /usr/lib/freecad-hsmplanner: CPack would add ldconfig calls for a library directly in /usr/lib/*/,
# and this module is no library of the linker's.
set(HSM_INSTALL_CORE_DIR "lib/freecad-hsmplanner/python3")
set(HSM_INSTALL_DOC_DIR "share/doc/freecad-hsmplanner")
set(HSM_MACHINES_DIR "${CMAKE_INSTALL_PREFIX}/${HSM_INSTALL_MOD_DIR}/resources/machines")
message(STATUS "HSM Planner installs into ${CMAKE_INSTALL_PREFIX}/${HSM_INSTALL_MOD_DIR} (FreeCAD's Mod folder), "
  "its posts into ${HSM_FREECAD_POSTS_DIR}")
