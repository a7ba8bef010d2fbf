# Runs one vtp_geodesics command and checks its exit code and its files (used by ctest).
#
#   cmake -DEXE=<program> -DARGS="a|b|c" -DEXPECTED_EXIT=<n>
#         [-DOUTPUT=<file>] [-DJSON=<file>] [-DEXPECTED_LINES=<n>] [-DSOURCE=<n>] [-DJSON_KEYS="k1|k2"]
#         [-DEXPECTED_VALUES="line=text|line=text"] [-DEXPECTED_NOTE=<regex>]
#         -P run_cli_test.cmake
#
# ARGS, JSON_KEYS, EXPECTED_VALUES: lists separated by '|'. OUTPUT / JSON are removed before the run.
# Exit code 0 expected: OUTPUT (if given) must exist, with EXPECTED_LINES lines if given, and
# line SOURCE (default 0) of OUTPUT must be "0", and each listed line (0-based) must be exactly the
# given text; JSON (if given) must exist and contain every key of JSON_KEYS. If EXPECTED_NOTE is
# defined, stderr must be empty when it is empty, and else one line "vtp_geodesics: note: ..." whose
# text matches the regular expression EXPECTED_NOTE.
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
      string(REPLACE "|" ";" values "${EXPECTED_VALUES}")
      foreach(value IN LISTS values)
        string(REGEX MATCH "^([0-9]+)=(.*)$" pair "${value}")
        if(NOT pair)
          message(FATAL_ERROR "bad EXPECTED_VALUES entry '${value}'")
        endif()
        set(line_number "${CMAKE_MATCH_1}")
        set(expected_text "${CMAKE_MATCH_2}")
        list(GET lines ${line_number} actual_text)
        if(NOT actual_text STREQUAL expected_text)
          message(FATAL_ERROR "line ${line_number} of the output is '${actual_text}', expected '${expected_text}'")
        endif()
      endforeach()
    endif()
  endif()
  if(DEFINED EXPECTED_NOTE)
    if(EXPECTED_NOTE STREQUAL "")
      if(NOT err STREQUAL "")
        message(FATAL_ERROR "expected nothing on stderr, got '${err}'")
      endif()
    else()
      if(NOT err MATCHES "^vtp_geodesics: note: ([^\n]+)\n$")
        message(FATAL_ERROR "stderr is not one line 'vtp_geodesics: note: ...': '${err}'")
      endif()
      set(note "${CMAKE_MATCH_1}")
      if(NOT note MATCHES "${EXPECTED_NOTE}")
        message(FATAL_ERROR "the note '${note}' does not match '${EXPECTED_NOTE}'")
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
