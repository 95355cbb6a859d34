# What `cmake --install` adds beyond the targets (man pages from the programs' own --help, udev
# rules, bundled recordings), and the Debian package: `cpack -G DEB` in the build folder.
# Man pages, written after the programs are built by running them.
set(man_dir ${PROJECT_BINARY_DIR}/man)
set(man_pages)
foreach(spec "penshape|penshape|recognize shapes in pen strokes, offline and live|ON"
             "penshaped|penshaped|the penshape daemon: tablets in, certified shapes out over gRPC|OFF")
  string(REPLACE "|" ";" spec "${spec}")
  list(GET spec 0 target)
  list(GET spec 1 name)
  list(GET spec 2 summary)
  list(GET spec 3 with_subcommands)
  add_custom_command(OUTPUT ${man_dir}/${name}.1.gz
    COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:${target}> -DNAME=${name}
      "-DSUMMARY=${summary}" -DWITH_SUBCOMMANDS=${with_subcommands} -DOUT=${man_dir}/${name}.1
      -P ${PROJECT_SOURCE_DIR}/cmake/WriteManPage.cmake
    COMMAND gzip -9nf ${man_dir}/${name}.1 # compressed, as Debian installs man pages
    DEPENDS ${target} ${PROJECT_SOURCE_DIR}/cmake/WriteManPage.cmake
    COMMENT "man page ${name}.1 from its --help" VERBATIM)
  list(APPEND man_pages ${man_dir}/${name}.1.gz)
endforeach()
add_custom_target(penshape_man_pages ALL DEPENDS ${man_pages})
install(FILES ${man_pages} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)

# udev rules: not multiarch, where udev looks below the prefix (/usr/lib/udev/rules.d in the
# package).
install(FILES ${PROJECT_SOURCE_DIR}/packaging/70-penshape-tablets.rules
  DESTINATION lib/udev/rules.d)
# The generated recordings (recordings/generate.sh), to try penshaped without a tablet
# (penshaped --replay FILE).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/recordings/ DESTINATION ${CMAKE_INSTALL_DATADIR}/penshape/recordings
  FILES_MATCHING PATTERN "*.hidrec" PATTERN "*.expected" PATTERN "SOURCES.md")

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME penshape)
set(CPACK_PACKAGE_VENDOR "penshape")
set(CPACK_PACKAGE_CONTACT "penshape developers <penshape@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
  "recovers the shapes people meant from wide-tip pen strokes, with certificates")
set(CPACK_PACKAGE_DESCRIPTION
  "penshaped reads pen tablets (hidapi, libusb), turns each stroke's ink into the clean shape it
was meant to be by certified offset deconstruction, and serves the shapes over gRPC; penshape is
its command-line client and an offline tool on polygon and stroke files.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT) # penshape_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
# Runtime dependencies: the shared libraries the binaries link (gRPC, protobuf, hidapi, libusb,
# pugixml, libzip...), found by dpkg-shlibdeps. The header-only libraries (CGAL, nlohmann-json,
# CLI11) are build dependencies only, installed by scripts/setup.sh.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# The Python client's imports, and the apps the extensions plug into.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "python3-grpcio, python3-protobuf")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "inkscape, xournalpp")
set(CPACK_STRIP_FILES ON)
include(CPack)
