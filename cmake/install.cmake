# What `cmake --install BUILD --prefix P` puts where (GNUInstallDirs; included by the top-level
# CMakeLists.txt after kernels/ and src/):
#   P/bin/rollspec                                  src/CMakeLists.txt
#   P/lib/librollspec_<area>.a (one per kernel area) kernels/CMakeLists.txt (EXPORT rollspecTargets)
#   P/include/rollspec/kernels/<area>/*.hpp         kernels/CMakeLists.txt
#   P/lib/cmake/rollspec/rollspecConfig.cmake, rollspecConfigVersion.cmake, rollspecTargets.cmake,
#     rollspecFFTW3.cmake: find_package(rollspec) -> rollspec::kernels          here
#   P/share/man/man1/rollspec.1                     here, help2man on the built binary
#   P/share/bash-completion/completions/rollspec    here, from the built binary's help texts
#   P/share/rollspec/studies/*.ini, data/**         here: the example studies and the files they read
#   P/share/rollspec/studies/templates/SCENE.ini    here, `rollspec init SCENE` of the built binary
#   P/bin/rollspec-post, P/share/rollspec/python/rollspec_post  here (python-post)
#   P/share/doc/rollspec/html/               here, once the target rollspec_docs has built the site
# Nothing here needs the tests or the benchmarks.
include(CMakePackageConfigHelpers)

# --- CMake package --------------------------------------------------------------------------------
set(ROLLSPEC_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/rollspec)
install(EXPORT rollspecTargets NAMESPACE rollspec:: DESTINATION ${ROLLSPEC_CMAKE_DIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/rollspecConfig.cmake.in
  ${CMAKE_BINARY_DIR}/package/rollspecConfig.cmake INSTALL_DESTINATION ${ROLLSPEC_CMAKE_DIR})
# 0.x: a minor version may change the kernels' interfaces, so only the same 0.minor is compatible.
write_basic_package_version_file(${CMAKE_BINARY_DIR}/package/rollspecConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/package/rollspecConfig.cmake ${CMAKE_BINARY_DIR}/package/rollspecConfigVersion.cmake
  ${CMAKE_CURRENT_LIST_DIR}/rollspecFFTW3.cmake DESTINATION ${ROLLSPEC_CMAKE_DIR})

# --- Man page and bash completion, generated from the built rollspec's own help ---------------------
# cmake/cli_docs.cmake runs `rollspec --help`, `rollspec COMMAND --help` for every command it lists,
# `rollspec keys` and `rollspec --version`, and writes the completion (template
# cmake/rollspec-completion.bash.in) and, with help2man, the man page (cmake/rollspec.h2m plus
# every command's help as the COMMANDS section), and `rollspec init SCENE` for every scene as the
# study templates. All are rebuilt whenever rollspec is.
find_program(HELP2MAN_EXECUTABLE help2man)
set(ROLLSPEC_COMPLETION ${CMAKE_BINARY_DIR}/share/bash-completion/completions/rollspec)
set(ROLLSPEC_MAN_PAGE ${CMAKE_BINARY_DIR}/share/man/man1/rollspec.1)
set(ROLLSPEC_TEMPLATES ${CMAKE_BINARY_DIR}/share/rollspec/studies/templates)
# One template stands for all: cli_docs.cmake writes one per scene into the directory.
set(cli_docs_outputs ${ROLLSPEC_COMPLETION} ${ROLLSPEC_TEMPLATES}/ball-on-beam.ini)
set(cli_docs_args -DROLLSPEC=$<TARGET_FILE:rollspec> -DCOMPLETION=${ROLLSPEC_COMPLETION}
  -DCOMPLETION_TEMPLATE=${CMAKE_CURRENT_LIST_DIR}/rollspec-completion.bash.in -DTEMPLATES=${ROLLSPEC_TEMPLATES})
if(HELP2MAN_EXECUTABLE)
  set(ROLLSPEC_MAN_PAGE_BUILT ON)
  list(APPEND cli_docs_outputs ${ROLLSPEC_MAN_PAGE})
  list(APPEND cli_docs_args -DHELP2MAN=${HELP2MAN_EXECUTABLE} -DMAN=${ROLLSPEC_MAN_PAGE}
    -DMAN_INCLUDE=${CMAKE_CURRENT_LIST_DIR}/rollspec.h2m)
else()
  set(ROLLSPEC_MAN_PAGE_BUILT OFF)
  message(STATUS "help2man not found: no man page (apt-get install help2man, or bash .ci/setup)")
endif()
add_custom_command(OUTPUT ${cli_docs_outputs}
  COMMAND ${CMAKE_COMMAND} ${cli_docs_args} -P ${CMAKE_CURRENT_LIST_DIR}/cli_docs.cmake
  DEPENDS rollspec ${CMAKE_CURRENT_LIST_DIR}/cli_docs.cmake ${CMAKE_CURRENT_LIST_DIR}/rollspec-completion.bash.in
          ${CMAKE_CURRENT_LIST_DIR}/rollspec.h2m
  COMMENT "rollspec man page and bash completion from its help texts")
add_custom_target(rollspec_cli_docs ALL DEPENDS ${cli_docs_outputs})
install(FILES ${ROLLSPEC_COMPLETION} DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions)
if(ROLLSPEC_MAN_PAGE_BUILT)
  install(FILES ${ROLLSPEC_MAN_PAGE} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
endif()

# --- Example studies ---------------------------------------------------------------------------------
# Installed as in the sources: a study's relative paths (data/..., its tables/ cache) resolve against
# the study file's directory, so `rollspec run P/share/rollspec/studies/X.ini` works from anywhere
# (tables are written beside it: copy the study to a writable directory when P is read-only).
set(ROLLSPEC_STUDIES_DIR ${CMAKE_INSTALL_DATADIR}/rollspec/studies)
file(GLOB ROLLSPEC_STUDIES CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/studies/*.ini)
install(FILES ${ROLLSPEC_STUDIES} DESTINATION ${ROLLSPEC_STUDIES_DIR})
install(DIRECTORY ${CMAKE_SOURCE_DIR}/studies/data DESTINATION ${ROLLSPEC_STUDIES_DIR}
  PATTERN "__pycache__" EXCLUDE PATTERN "*.pyc" EXCLUDE)
install(DIRECTORY ${ROLLSPEC_TEMPLATES} DESTINATION ${ROLLSPEC_STUDIES_DIR} FILES_MATCHING PATTERN "*.ini")
install(FILES ${CMAKE_SOURCE_DIR}/studies/templates/README.md DESTINATION ${ROLLSPEC_STUDIES_DIR}/templates)

# --- python-post: the package and the rollspec-post command ----------------------------------------
#   P/share/rollspec/python/rollspec_post/*.py   the package (no pip, no venv)
#   P/bin/rollspec-post                          launcher: ROLLSPEC_POST_PYTHON (Debian's /usr/bin/python3,
#                                                which has numpy, scipy, h5py, matplotlib) on the package
# Component python_post: `cmake --install BUILD --component python_post` installs only these.
set(ROLLSPEC_POST_PYTHON /usr/bin/python3 CACHE FILEPATH "Python that runs the installed rollspec-post")
set(ROLLSPEC_POST_DIR ${CMAKE_INSTALL_DATADIR}/rollspec/python)
# Relative, so the launcher finds the package under whatever --prefix the install is given.
file(RELATIVE_PATH ROLLSPEC_POST_RELATIVE /root/${CMAKE_INSTALL_BINDIR} /root/${ROLLSPEC_POST_DIR})
configure_file(${CMAKE_SOURCE_DIR}/python-post/launcher/rollspec-post.in ${CMAKE_BINARY_DIR}/python-post/rollspec-post
  @ONLY)
install(DIRECTORY ${CMAKE_SOURCE_DIR}/python-post/rollspec_post DESTINATION ${ROLLSPEC_POST_DIR}
  COMPONENT python_post FILES_MATCHING PATTERN "*.py" PATTERN "__pycache__" EXCLUDE)
install(PROGRAMS ${CMAKE_BINARY_DIR}/python-post/rollspec-post DESTINATION ${CMAKE_INSTALL_BINDIR}
  COMPONENT python_post)

# --- HTML documentation -----------------------------------------------------------------------------
#   P/share/doc/rollspec/html/index.html   the documentation site (component docs)
# `cmake --build BUILD --target rollspec_docs` runs docs/build.sh against this build's rollspec into
# BUILD/docs (Sphinx from Debian: .ci/setup installs it); `cmake --install BUILD --component docs`
# then installs the site. A plain `cmake --install` installs it too once it is built, and skips it if not.
add_custom_target(rollspec_docs
  COMMAND ${CMAKE_COMMAND} -E env ROLLSPEC_BIN=$<TARGET_FILE:rollspec> bash ${CMAKE_SOURCE_DIR}/docs/build.sh
          ${CMAKE_BINARY_DIR}/docs
  DEPENDS rollspec USES_TERMINAL COMMENT "documentation site (docs/build.sh)")
install(DIRECTORY ${CMAKE_BINARY_DIR}/docs/html/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/html COMPONENT docs OPTIONAL)
