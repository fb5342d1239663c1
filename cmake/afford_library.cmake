# afford_library(NAME SOURCES...): the static library afford_NAME of the
# calling folder, exported as afford::NAME, its folder on the include path
# (installed: include/afford/NAME/, cmake/install.cmake), built with the
# project's warnings.
function(afford_library name)
  add_library(afford_${name} STATIC ${ARGN})
  set_target_properties(afford_${name} PROPERTIES EXPORT_NAME ${name})
  target_include_directories(afford_${name} PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}>)
  target_link_libraries(afford_${name} PRIVATE $<BUILD_INTERFACE:afford_warnings>)
endfunction()

# afford_use_fcl(TARGET): TARGET's own sources include FCL. Its headers are
# included as system headers: they do not pass our warnings.
function(afford_use_fcl target)
  get_target_property(fcl_includes fcl INTERFACE_INCLUDE_DIRECTORIES)
  target_include_directories(${target} SYSTEM PRIVATE ${fcl_includes})
  target_link_libraries(${target} PRIVATE fcl)
endfunction()
