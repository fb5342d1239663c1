# cmake --install BUILD --prefix P: the afford program, the libraries
# (static), each library's headers in include/afford/<library>/, the shipped
# data in share/afford/ and a CMake package, so that another project can write
#   find_package(afford 0.11 REQUIRED)
#   target_link_libraries(app PRIVATE afford::session)
# and `#include <afford/session/session.h>`: the folder names the target to
# link. afford::engine links the engine's five libraries and the guides.
include(CMakePackageConfigHelpers)

# The libraries, each named by its source folder (afford::<name>).
set(AFFORD_INSTALLED_FOLDERS engine/base engine/load engine/model engine/rules engine/session guides devices render
    gap explore mjcf)
install(TARGETS afford RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS afford_engine EXPORT afford-targets)
foreach(path IN LISTS AFFORD_INSTALLED_FOLDERS)
  cmake_path(GET path FILENAME folder)
  install(TARGETS afford_${folder} EXPORT afford-targets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  file(GLOB headers CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${path}/*.h)
  # The MuJoCo harness is the tests' (afford_mjcf_mujoco), not the library's.
  list(FILTER headers EXCLUDE REGEX "/mujoco_harness\\.h$")
  install(FILES ${headers} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/afford/${folder})
  # A user writes <afford/model/model.h>; the headers include their own
  # library's and the libraries' below by name ("model.h"), as in the source
  # tree, which the library's own folder on the include path resolves.
  target_include_directories(afford_${folder} PUBLIC
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/afford/${folder}>)
endforeach()

# The shipped data, laid out as in the source tree (sessions name
# ../objects/... and so on).
set(AFFORD_DATA_DESTINATION ${CMAKE_INSTALL_DATADIR}/afford)
install(DIRECTORY rules agents actees objects sessions DESTINATION ${AFFORD_DATA_DESTINATION}
        FILES_MATCHING PATTERN "*.yaml" PATTERN "README.md")
install(DIRECTORY devices DESTINATION ${AFFORD_DATA_DESTINATION} FILES_MATCHING PATTERN "*.yaml")
# The page of `afford serve` (plain files, no build step).
install(DIRECTORY web DESTINATION ${AFFORD_DATA_DESTINATION})

set(AFFORD_CMAKE_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/afford)
install(EXPORT afford-targets NAMESPACE afford:: DESTINATION ${AFFORD_CMAKE_DESTINATION})
configure_package_config_file(cmake/afford-config.cmake.in ${PROJECT_BINARY_DIR}/afford-config.cmake
                              INSTALL_DESTINATION ${AFFORD_CMAKE_DESTINATION})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/afford-config-version.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/afford-config.cmake ${PROJECT_BINARY_DIR}/afford-config-version.cmake
        DESTINATION ${AFFORD_CMAKE_DESTINATION})
