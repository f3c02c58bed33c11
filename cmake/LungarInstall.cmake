# Installation in the Debian/FHS layout (GNUInstallDirs; scripts/package installs under /usr):
#   bin/                       lungar, lungar-bake, lungar-trk
#   share/lungar/              config/*.toml and *.xml; trackers/, scenarios/, cyclonedds/, lungs/ when present
#   share/man/man1/            a page per tool, made by help2man from --help
#   share/doc/lungar/          copyright, changelog
#   lib/udev/rules.d/          99-lungar.rules (the seated user gets the trackers)
#   lib/systemd/user/          lungar.service (full screen on the HMD at login)
# Shipped data is installed by folder, so a new profile, scenario or tracker file lands without a change here.
include(GNUInstallDirs)

install(TARGETS lungar lungar-bake lungar-trk RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

set(LUNGAR_DATADIR ${CMAKE_INSTALL_DATADIR}/lungar)
# lungar_install_glob(DESTINATION PATTERN...): every file matching, as found at configure time (and again whenever
# one is added: CONFIGURE_DEPENDS).
function(lungar_install_glob destination)
  file(GLOB files LIST_DIRECTORIES false CONFIGURE_DEPENDS ${ARGN})
  if(files)
    install(FILES ${files} DESTINATION ${destination})
  endif()
endfunction()
lungar_install_glob(${LUNGAR_DATADIR} ${PROJECT_SOURCE_DIR}/config/*.toml ${PROJECT_SOURCE_DIR}/config/*.xml)
lungar_install_glob(${LUNGAR_DATADIR}/trackers ${PROJECT_SOURCE_DIR}/config/trackers/*.toml)
lungar_install_glob(${LUNGAR_DATADIR}/scenarios ${PROJECT_SOURCE_DIR}/config/scenarios/*.toml)
lungar_install_glob(${LUNGAR_DATADIR}/cyclonedds ${PROJECT_SOURCE_DIR}/config/cyclonedds/*.xml)
lungar_install_glob(${LUNGAR_DATADIR}/lungs ${PROJECT_SOURCE_DIR}/sim/data/lungs/*)

# udev and systemd read these under the prefix's lib/ (/usr/lib/...), not the multiarch library folder.
install(FILES ${PROJECT_SOURCE_DIR}/scripts/99-lungar.rules DESTINATION lib/udev/rules.d)
set(LUNGAR_BINDIR ${CMAKE_INSTALL_FULL_BINDIR})
configure_file(${PROJECT_SOURCE_DIR}/scripts/lungar.service.in ${PROJECT_BINARY_DIR}/lungar.service @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/lungar.service DESTINATION lib/systemd/user)

# share/doc/lungar: the copyright (DEP-5; the CT label map's licence when it is shipped) and a Debian changelog.
file(READ ${PROJECT_SOURCE_DIR}/scripts/debian/copyright copyright_text)
file(GLOB shipped_lungs ${PROJECT_SOURCE_DIR}/sim/data/lungs/*)
if(shipped_lungs)
  file(READ ${PROJECT_SOURCE_DIR}/scripts/debian/copyright-lungs lungs_text)
  string(REPLACE "\nLicense: MIT\n" "\n${lungs_text}\nLicense: MIT\n" copyright_text "${copyright_text}")
endif()
file(WRITE ${PROJECT_BINARY_DIR}/doc/copyright "${copyright_text}")
string(TIMESTAMP LUNGAR_CHANGELOG_DATE "%a, %d %b %Y %H:%M:%S +0000" UTC)  # SOURCE_DATE_EPOCH when set
configure_file(${PROJECT_SOURCE_DIR}/scripts/debian/changelog.in ${PROJECT_BINARY_DIR}/doc/changelog @ONLY)
find_program(GZIP gzip REQUIRED)
add_custom_command(OUTPUT ${PROJECT_BINARY_DIR}/doc/changelog.gz
  COMMAND ${GZIP} -9nkf ${PROJECT_BINARY_DIR}/doc/changelog
  DEPENDS ${PROJECT_BINARY_DIR}/doc/changelog)
add_custom_target(lungar_doc ALL DEPENDS ${PROJECT_BINARY_DIR}/doc/changelog.gz)
install(FILES ${PROJECT_BINARY_DIR}/doc/copyright ${PROJECT_BINARY_DIR}/doc/changelog.gz DESTINATION ${CMAKE_INSTALL_DOCDIR})

# Man pages from each tool's --help and --version (help2man), when the tools can run here (not cross-compiled).
find_program(HELP2MAN help2man)
option(LUNGAR_MAN "Make a man page per tool with help2man" ON)
if(LUNGAR_MAN AND HELP2MAN AND NOT CMAKE_CROSSCOMPILING)
  set(man_names
    "lungar=breathing 3-D lungs on a patient simulator, for a head-mounted display"
    "lungar-bake=bake lung surfaces and CT label maps into the asset the lungar runtime draws"
    "lungar-trk=inspect, dump, cut and synthesise .trk tracker logs")
  set(man_pages "")
  foreach(entry ${man_names})
    string(REGEX REPLACE "=.*" "" tool "${entry}")
    string(REGEX REPLACE "^[^=]*=" "" name "${entry}")
    set(include_args "")
    set(h2m "")
    if(EXISTS ${PROJECT_SOURCE_DIR}/scripts/man/${tool}.h2m)  # extra sections: FILES, SEE ALSO
      set(h2m ${PROJECT_SOURCE_DIR}/scripts/man/${tool}.h2m)
      set(include_args --include=${h2m})
    endif()
    set(page ${PROJECT_BINARY_DIR}/man/${tool}.1)
    # Run by name from PATH, so that the usage line says "lungar", not the build folder.
    add_custom_command(OUTPUT ${page}.gz
      COMMAND ${CMAKE_COMMAND} -E make_directory ${PROJECT_BINARY_DIR}/man
      COMMAND ${CMAKE_COMMAND} -E env "PATH=$<TARGET_FILE_DIR:${tool}>:$ENV{PATH}" ASAN_OPTIONS=detect_leaks=0
              ${HELP2MAN} --no-info --no-discard-stderr --section=1 "--name=${name}" ${include_args}
              --output=${page} ${tool}
      COMMAND ${GZIP} -9nf ${page}
      DEPENDS ${tool} ${h2m}
      VERBATIM)
    list(APPEND man_pages ${page}.gz)
  endforeach()
  add_custom_target(lungar_man ALL DEPENDS ${man_pages})
  install(FILES ${man_pages} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
endif()
