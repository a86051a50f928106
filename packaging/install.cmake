# The Debian package's files (HSM_PACKAGE, `make deb`; the folders from packaging/layout.cmake) and CPack's DEB
# generator, which writes freecad-hsmplanner_<version>_<arch>.deb with dependencies found by dpkg-shlibdeps.

# Everything a control field or the changelog says about the project is read from package.xml.
function(hsm_package_xml variable pattern)
  if(NOT HSM_PACKAGE_XML MATCHES "${pattern}")
    message(FATAL_ERROR "package.xml does not match ${pattern}")
  endif()
  set(${variable} "${CMAKE_MATCH_1}" PARENT_SCOPE)
endfunction()
hsm_package_xml(hsm_email "<maintainer email=\"([^\"]+)\"")
hsm_package_xml(hsm_maintainer_name "<maintainer[^>]*>([^<]+)</maintainer>")
hsm_package_xml(hsm_homepage "<url type=\"repository\"[^>]*>([^<]+)</url>")
hsm_package_xml(hsm_description "<description>([^<]+)</description>")
hsm_package_xml(hsm_date "<date>([0-9-]+)</date>")
set(HSM_MAINTAINER "${hsm_maintainer_name} <${hsm_email}>")
execute_process(COMMAND date -R -u -d "${hsm_date}" OUTPUT_VARIABLE HSM_CHANGELOG_DATE
  OUTPUT_STRIP_TRAILING_WHITESPACE COMMAND_ERROR_IS_FATAL ANY)
set(HSM_PYTHON_DIR "${CMAKE_INSTALL_PREFIX}/${HSM_INSTALL_MOD_DIR}/python")

# A relative symbolic link, made at install time: CPack installs into its staging folder as the prefix.
function(hsm_install_link link_dir link_name target_dir target_name)
  file(RELATIVE_PATH relative "/${link_dir}" "/${target_dir}")
  install(CODE "
    set(link \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${link_dir}/${link_name}\")
    message(STATUS \"Installing: \${link} -> ${relative}/${target_name}\")
    file(MAKE_DIRECTORY \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${link_dir}\")
    file(CREATE_LINK \"${relative}/${target_name}\" \"\${link}\" SYMBOLIC)")
endfunction()

# Stripped as Debian's dh_strip strips (CPack's strip keeps the .comment and .note sections).
function(hsm_install_stripped file)
  install(CODE "execute_process(COMMAND ${CMAKE_STRIP} --remove-section=.comment --remove-section=.note
    --strip-unneeded \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${file}\" COMMAND_ERROR_IS_FATAL ANY)")
endfunction()

# A Debian control field's text: lines of at most 79 characters (paragraphs kept).
function(hsm_wrap variable text)
  set(wrapped "")
  string(REPLACE "\n\n" ";" paragraphs "${text}")
  foreach(paragraph IN LISTS paragraphs)
    string(REGEX REPLACE "[ \n]+" ";" words "${paragraph}")
    set(line "")
    foreach(word IN LISTS words)
      string(LENGTH "${line} ${word}" length)
      if(line AND length GREATER 79)
        string(APPEND wrapped "${line}\n")
        set(line "${word}")
      elseif(line)
        set(line "${line} ${word}")
      else()
        set(line "${word}")
      endif()
    endforeach()
    string(APPEND wrapped "${line}\n\n")
  endforeach()
  string(STRIP "${wrapped}" wrapped)
  set(${variable} "${wrapped}" PARENT_SCOPE)
endfunction()

# The workbench: entry points and metadata, icons and machine presets, the Python package and the core.
install(FILES Init.py InitGui.py package.xml DESTINATION ${HSM_INSTALL_MOD_DIR})
install(DIRECTORY resources/ DESTINATION ${HSM_INSTALL_MOD_DIR}/resources)
install(DIRECTORY python/ DESTINATION ${HSM_INSTALL_MOD_DIR}/python
  FILES_MATCHING PATTERN "*.py" PATTERN "__pycache__" EXCLUDE)
install(TARGETS _core LIBRARY DESTINATION ${HSM_INSTALL_CORE_DIR})
hsm_install_stripped(${HSM_INSTALL_CORE_DIR}/$<TARGET_FILE_NAME:_core>)
hsm_install_link(${HSM_INSTALL_MOD_DIR}/python/hsmplanner "$<TARGET_FILE_NAME:_core>"
  ${HSM_INSTALL_CORE_DIR} "$<TARGET_FILE_NAME:_core>")
foreach(post siemens840d linuxcnc5x)
  hsm_install_link(${HSM_INSTALL_POSTS_DIR} hsm_${post}_post.py
    ${HSM_INSTALL_MOD_DIR}/python/hsmplanner/app/posts ${post}_post.py)
endforeach()

# The commands, with their manual pages.
install(TARGETS hsm-feedsim RUNTIME DESTINATION bin)
hsm_install_stripped(bin/hsm-feedsim)
configure_file(packaging/hsm-study.in hsm-study @ONLY)
install(PROGRAMS ${CMAKE_BINARY_DIR}/hsm-study DESTINATION bin)
set(HSM_DATE "${hsm_date}")
set(HSM_DOC_DIR "${CMAKE_INSTALL_PREFIX}/${HSM_INSTALL_DOC_DIR}")
set(hsm_gzipped)
foreach(name hsm-feedsim.1 hsm-study.1 changelog)
  set(file ${CMAKE_BINARY_DIR}/${name})
  configure_file(packaging/${name}.in ${file} @ONLY)
  add_custom_command(OUTPUT ${file}.gz COMMAND gzip -9nf ${file} -c > ${file}.gz DEPENDS ${file})
  list(APPEND hsm_gzipped ${file}.gz)
endforeach()
add_custom_target(hsm_package_gzipped ALL DEPENDS ${hsm_gzipped})
install(FILES ${CMAKE_BINARY_DIR}/hsm-feedsim.1.gz ${CMAKE_BINARY_DIR}/hsm-study.1.gz DESTINATION share/man/man1)

# The documentation: the README and docs/ (their links kept), the examples, copyright and changelog.
install(FILES README.md packaging/copyright ${CMAKE_BINARY_DIR}/changelog.gz DESTINATION ${HSM_INSTALL_DOC_DIR})
install(DIRECTORY docs/ DESTINATION ${HSM_INSTALL_DOC_DIR}/docs)
install(DIRECTORY examples/ DESTINATION ${HSM_INSTALL_DOC_DIR}/examples
  FILES_MATCHING PATTERN "*.py" PATTERN "__pycache__" EXCLUDE)

# Byte-compiled on installation (a user's FreeCAD cannot write the caches there), removed before removal.
configure_file(packaging/postinst.in postinst @ONLY)
configure_file(packaging/prerm.in prerm @ONLY)

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME freecad-hsmplanner)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION}+${HSM_DEBIAN_SUITE})
set(CPACK_PACKAGING_INSTALL_PREFIX ${CMAKE_INSTALL_PREFIX})
set(CPACK_PACKAGE_DIRECTORY ${CMAKE_BINARY_DIR}/package)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${HSM_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "${hsm_homepage}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "FreeCAD workbench for high-speed milling strategies (HSM Planner)")
hsm_wrap(CPACK_PACKAGE_DESCRIPTION "${hsm_description}

The HSM Planner workbench in FreeCAD's module folder, the hsm-feedsim and hsm-study commands, the machine \
presets and the examples.")
# The core's libraries by dpkg-shlibdeps; what the Python layer imports, by hand; the core is built for one
# Python version.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
math(EXPR hsm_next_minor "${Python3_VERSION_MINOR} + 1")
set(CPACK_DEBIAN_PACKAGE_DEPENDS "freecad (>= ${HSM_FREECAD_RELEASE}), \
python3 (>= ${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}~), python3 (<< ${Python3_VERSION_MAJOR}.${hsm_next_minor}), \
python3-numpy, python3-matplotlib, python3-pivy, \
python3-${HSM_PYSIDE}.qtcore, python3-${HSM_PYSIDE}.qtgui, python3-${HSM_PYSIDE}.qtwidgets")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "python3-distributed")
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA ${CMAKE_BINARY_DIR}/postinst ${CMAKE_BINARY_DIR}/prerm)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION TRUE)
set(CPACK_DEBIAN_COMPRESSION_TYPE xz)
include(CPack)
