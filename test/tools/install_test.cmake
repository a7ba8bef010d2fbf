# Installs the build tree into PREFIX (a folder of the build tree), then runs the installed vtp_geodesics from a
# copy of the installation moved elsewhere: it must find its default mesh next to itself, and write a PLY and a
# PNG file (used by ctest).
#
#   cmake -DBUILD_DIR=<build tree> -DPREFIX=<folder> -P install_test.cmake

file(REMOVE_RECURSE "${PREFIX}" "${PREFIX}.moved")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}"
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed")
endif()
if(NOT EXISTS "${PREFIX}/bin/vtp_geodesics" OR NOT EXISTS "${PREFIX}/share/VTP_geodesics/elephant.off")
  message(FATAL_ERROR "the tool or its default mesh is not installed")
endif()
file(RENAME "${PREFIX}" "${PREFIX}.moved")
set(tool "${PREFIX}.moved/bin/vtp_geodesics")
execute_process(COMMAND "${tool}" --stats-json - --output "${PREFIX}.moved/out.ply" --picture "${PREFIX}.moved/out.png"
                WORKING_DIRECTORY "/"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the installed tool failed: ${err}")
endif()
if(NOT out MATCHES "\"mesh\": \"${PREFIX}.moved/share/VTP_geodesics/elephant.off\"")
  message(FATAL_ERROR "the installed tool did not use the installed default mesh: ${out}")
endif()
foreach(f IN ITEMS out.ply out.png)
  if(NOT EXISTS "${PREFIX}.moved/${f}")
    message(FATAL_ERROR "${f} was not written")
  endif()
endforeach()
file(REMOVE_RECURSE "${PREFIX}.moved")
