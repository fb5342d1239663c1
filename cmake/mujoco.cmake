# MuJoCo (Debian libmujoco-dev, 2.2.2), optional: the benchmark's baseline
# and the tests that load exported scenes use it. Sets mujoco_FOUND and the
# imported target mujoco::mujoco.
find_package(mujoco CONFIG QUIET)
if(mujoco_FOUND)
  # Debian's 2.2.2 config names /usr/include/libqhull_r/, which only
  # libqhull-dev installs; MuJoCo's own header needs none of it.
  get_target_property(_mujoco_includes mujoco::mujoco INTERFACE_INCLUDE_DIRECTORIES)
  set(_mujoco_existing)
  foreach(_dir IN LISTS _mujoco_includes)
    if(EXISTS "${_dir}")
      list(APPEND _mujoco_existing "${_dir}")
    endif()
  endforeach()
  set_target_properties(mujoco::mujoco PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_mujoco_existing}")
endif()
