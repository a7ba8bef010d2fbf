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
# Non-zero exit code expected: stderr must be one line "vtp_geodesics: error: ..." (matching the regular
# expression EXPECTED_ERROR if given), and neither OUTPUT nor JSON nor any of their temporary files may exist.
#
# OUTPUT "-" or "/dev/stdout": the output is read from the standard output (and /dev/stdout must still be a
# symbolic link after the run). SETUP prepares OUTPUT before the run:
#   symlink   OUTPUT is a symbolic link to the regular file OUTPUT.target (which holds one line)
#   dangling  OUTPUT is a symbolic link to OUTPUT.target, which does not exist
#   fifo      OUTPUT is a FIFO; the program runs next to "cat OUTPUT", whose output is checked
#   existing  OUTPUT is a regular file with mode 640
# CHECK (after the run; '|'-separated): symlink (OUTPUT is still a link, its target exists), fifo (OUTPUT is
# still a FIFO), mode640 (OUTPUT kept its mode), chardev:<path> (<path> is still a character device),
# ply (OUTPUT is a binary PLY with the properties distance, red, green, blue), png (OUTPUT is a PNG file).
# Every file these tests create is in the build tree.

if(NOT DEFINED EXE OR NOT DEFINED EXPECTED_EXIT)
  message(FATAL_ERROR "run_cli_test.cmake: EXE and EXPECTED_EXIT are required")
endif()

string(REPLACE "|" ";" arguments "${ARGS}")
set(output_on_stdout FALSE)
if(OUTPUT STREQUAL "-" OR OUTPUT STREQUAL "/dev/stdout")
  set(output_on_stdout TRUE)
endif()
foreach(f IN ITEMS "${OUTPUT}" "${JSON}")
  if(f AND NOT f STREQUAL "-" AND NOT f MATCHES "^/dev/")
    file(REMOVE "${f}" "${f}.target")
  endif()
endforeach()

if(SETUP STREQUAL "symlink")
  file(WRITE "${OUTPUT}.target" "old content\n")
  file(CREATE_LINK "${OUTPUT}.target" "${OUTPUT}" SYMBOLIC)
elseif(SETUP STREQUAL "dangling")
  file(CREATE_LINK "${OUTPUT}.target" "${OUTPUT}" SYMBOLIC)
elseif(SETUP STREQUAL "fifo")
  execute_process(COMMAND mkfifo "${OUTPUT}" RESULT_VARIABLE mkfifo_rc)
  if(NOT mkfifo_rc EQUAL 0)
    message(FATAL_ERROR "mkfifo ${OUTPUT} failed")
  endif()
elseif(SETUP STREQUAL "existing")
  file(WRITE "${OUTPUT}" "old content\n")
  execute_process(COMMAND chmod 640 "${OUTPUT}")
elseif(SETUP)
  message(FATAL_ERROR "unknown SETUP '${SETUP}'")
endif()

if(SETUP STREQUAL "fifo")
  # Both run at once: the program writes into the FIFO, cat reads it (the program's stdout goes to cat's stdin,
  # which cat ignores).
  execute_process(COMMAND "${EXE}" ${arguments}
                  COMMAND cat "${OUTPUT}"
                  RESULTS_VARIABLE rcs
                  OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  list(GET rcs 0 rc)
else()
  execute_process(COMMAND "${EXE}" ${arguments}
                  RESULT_VARIABLE rc
                  OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
endif()
message(STATUS "command: ${EXE} ${arguments}")
message(STATUS "exit code: ${rc}")
message(STATUS "stdout: ${out}")
message(STATUS "stderr: ${err}")

if(NOT "${rc}" STREQUAL "${EXPECTED_EXIT}")
  message(FATAL_ERROR "expected exit code ${EXPECTED_EXIT}, got '${rc}'")
endif()

if(EXISTS /dev/stdout AND NOT IS_SYMLINK /dev/stdout)
  message(FATAL_ERROR "/dev/stdout is no longer a symbolic link")
endif()

if(EXPECTED_EXIT EQUAL 0)
  if(OUTPUT)
    if(NOT output_on_stdout AND NOT SETUP STREQUAL "fifo" AND NOT EXISTS "${OUTPUT}")
      message(FATAL_ERROR "output file ${OUTPUT} was not written")
    endif()
    if(DEFINED EXPECTED_LINES)
      if(output_on_stdout OR SETUP STREQUAL "fifo")
        string(REGEX REPLACE "\n$" "" trimmed "${out}")
        string(REPLACE "\n" ";" lines "${trimmed}")
      else()
        file(STRINGS "${OUTPUT}" lines)
      endif()
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
  string(REPLACE "|" ";" checks "${CHECK}")
  foreach(check IN LISTS checks)
    if(check STREQUAL "symlink")
      if(NOT IS_SYMLINK "${OUTPUT}" OR NOT EXISTS "${OUTPUT}.target" OR IS_SYMLINK "${OUTPUT}.target")
        message(FATAL_ERROR "${OUTPUT} is no longer a symbolic link to the regular file ${OUTPUT}.target")
      endif()
    elseif(check STREQUAL "fifo")
      execute_process(COMMAND test -p "${OUTPUT}" RESULT_VARIABLE is_fifo)
      if(NOT is_fifo EQUAL 0)
        message(FATAL_ERROR "${OUTPUT} is no longer a FIFO")
      endif()
    elseif(check STREQUAL "mode640")
      execute_process(COMMAND stat -c %a "${OUTPUT}" OUTPUT_VARIABLE mode OUTPUT_STRIP_TRAILING_WHITESPACE)
      if(NOT mode STREQUAL "640")
        message(FATAL_ERROR "${OUTPUT} has mode ${mode}, expected 640 (the mode of the file it replaced)")
      endif()
    elseif(check MATCHES "^chardev:(.*)$")
      execute_process(COMMAND test -c "${CMAKE_MATCH_1}" RESULT_VARIABLE is_chardev)
      if(NOT is_chardev EQUAL 0)
        message(FATAL_ERROR "${CMAKE_MATCH_1} is no longer a character device")
      endif()
    elseif(check STREQUAL "ply")
      file(STRINGS "${OUTPUT}" header LIMIT_COUNT 16)
      foreach(line IN ITEMS "ply" "format binary_little_endian 1.0" "property double distance"
                            "property uchar red" "property uchar green" "property uchar blue"
                            "property list uchar int vertex_indices" "end_header")
        list(FIND header "${line}" found)
        if(found EQUAL -1)
          message(FATAL_ERROR "the PLY header has no line '${line}': ${header}")
        endif()
      endforeach()
    elseif(check STREQUAL "png")
      file(READ "${OUTPUT}" signature LIMIT 8 HEX)
      if(NOT signature STREQUAL "89504e470d0a1a0a")
        message(FATAL_ERROR "${OUTPUT} is not a PNG file (it starts with ${signature})")
      endif()
    else()
      message(FATAL_ERROR "unknown CHECK '${check}'")
    endif()
  endforeach()
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
  if(NOT err MATCHES "^vtp_geodesics: error: ([^\n]+)\n$")
    message(FATAL_ERROR "stderr is not one line 'vtp_geodesics: error: ...': '${err}'")
  endif()
  set(error_text "${CMAKE_MATCH_1}")
  if(DEFINED EXPECTED_ERROR AND NOT error_text MATCHES "${EXPECTED_ERROR}")
    message(FATAL_ERROR "the error '${error_text}' does not match '${EXPECTED_ERROR}'")
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
