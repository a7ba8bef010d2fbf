# Runs one vtp_geodesics command and checks its exit code and its files (used by ctest).
#
#   cmake -DEXE=<program> -DARGS="a|b|c" -DEXPECTED_EXIT=<n>
#         [-DOUTPUT=<file>] [-DJSON=<file>] [-DEXPECTED_LINES=<n>] [-DSOURCE=<n>] [-DJSON_KEYS="k1|k2"]
#         -P run_cli_test.cmake
#
# ARGS, JSON_KEYS: lists separated by '|'. OUTPUT / JSON are removed before the run.
# Exit code 0 expected: OUTPUT (if given) must exist, with EXPECTED_LINES lines if given, and
# line SOURCE (default 0) of OUTPUT must be "0", and JSON (if given) must exist and contain every key of JSON_KEYS.
# Non-zero exit code expected: stderr must be one line "vtp_geodesics: error: ...", and neither
# OUTPUT nor JSON nor any of their temporary files may exist.

if(NOT DEFINED EXE OR NOT DEFINED EXPECTED_EXIT)
  message(FATAL_ERROR "run_cli_test.cmake: EXE and EXPECTED_EXIT are required")
endif()

string(REPLACE "|" ";" arguments "${ARGS}")
foreach(f IN ITEMS "${OUTPUT}" "${JSON}")
  if(f)
    file(REMOVE "${f}")
  endif()
endforeach()

execute_process(COMMAND "${EXE}" ${arguments}
                RESULT_VARIABLE rc
                OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
message(STATUS "command: ${EXE} ${arguments}")
message(STATUS "exit code: ${rc}")
message(STATUS "stdout: ${out}")
message(STATUS "stderr: ${err}")

if(NOT "${rc}" STREQUAL "${EXPECTED_EXIT}")
  message(FATAL_ERROR "expected exit code ${EXPECTED_EXIT}, got '${rc}'")
endif()

if(EXPECTED_EXIT EQUAL 0)
  if(OUTPUT)
    if(NOT EXISTS "${OUTPUT}")
      message(FATAL_ERROR "output file ${OUTPUT} was not written")
    endif()
    if(DEFINED EXPECTED_LINES)
      file(STRINGS "${OUTPUT}" lines)
      list(LENGTH lines n)
      if(NOT n EQUAL EXPECTED_LINES)
        message(FATAL_ERROR "output file has ${n} lines, expected ${EXPECTED_LINES}")
      endif()
      if(NOT DEFINED SOURCE)
        set(SOURCE 0)
      endif()
      list(GET lines ${SOURCE} source_line)
      if(NOT source_line STREQUAL "0")
        message(FATAL_ERROR "distance of the source is '${source_line}', expected 0")
      endif()
    endif()
  endif()
  if(JSON)
    if(NOT EXISTS "${JSON}")
      message(FATAL_ERROR "JSON file ${JSON} was not written")
    endif()
    file(READ "${JSON}" json)
  else()
    set(json "${out}")
  endif()
  string(REPLACE "|" ";" keys "${JSON_KEYS}")
  foreach(key IN LISTS keys)
    string(FIND "${json}" "\"${key}\":" pos)
    if(pos EQUAL -1)
      message(FATAL_ERROR "key '${key}' missing in the JSON statistics: ${json}")
    endif()
  endforeach()
else()
  if(NOT err MATCHES "^vtp_geodesics: error: [^\n]+\n$")
    message(FATAL_ERROR "stderr is not one line 'vtp_geodesics: error: ...': '${err}'")
  endif()
  foreach(f IN ITEMS "${OUTPUT}" "${JSON}")
    if(f)
      if(EXISTS "${f}")
        message(FATAL_ERROR "${f} was created although the command failed")
      endif()
      file(GLOB leftovers "${f}.tmp.*")
      if(leftovers)
        message(FATAL_ERROR "temporary files left behind: ${leftovers}")
      endif()
    endif()
  endforeach()
endif()
