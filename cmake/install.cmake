# cmake --install BUILD --prefix P: the afford program, the five libraries
# (static), their headers in include/afford/, the shipped data in
# share/afford/ and a CMake package, so that another project can write
#   find_package(afford 0.10 REQUIRED)
#   target_link_libraries(app PRIVATE afford::engine)
# and `#include <afford/model.h>`.
include(CMakePackageConfigHelpers)

set(AFFORD_LIBRARIES afford_engine afford_devices afford_gap afford_render afford_explore)
install(TARGETS afford RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS ${AFFORD_LIBRARIES} EXPORT afford-targets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
foreach(folder engine devices gap render explore)
  file(GLOB headers CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${folder}/*.h)
  install(FILES ${headers} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/afford)
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
