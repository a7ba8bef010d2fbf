# Checks the file map of the manual (doc/VTP_geodesics/file_map.txt) against the tree:
#  1. every header under include/ is named on the page, by its path relative to include/ (the path it is
#     included with, e.g. `CGAL/VTP_geodesics/internal/windows/Window.h`), written as a code span (between backquotes);
#  2. every path the page names exists: a code span made only of path characters and holding a `/` is a path,
#     relative to include/ when it starts with `CGAL/`, else relative to the root of the repository; a code
#     span that is a bare file name (`read_mesh.h`, `main.cpp`, ...) must be the name of a file of the
#     repository's source folders.
# Run by ctest as doc_file_map (test/doc/CMakeLists.txt); by hand, from anywhere:
#   cmake -DSOURCE_DIR=<repository> -P test/doc/check_file_map.cmake
# Optional: -DFILE_MAP=<page> checks another copy of the page against the same tree.
# Needs nothing built: only CMake.
cmake_minimum_required(VERSION 3.16)

if(NOT DEFINED SOURCE_DIR)
  get_filename_component(SOURCE_DIR "${CMAKE_CURRENT_LIST_DIR}/../.." ABSOLUTE)
endif()
if(NOT DEFINED FILE_MAP)
  set(FILE_MAP "${SOURCE_DIR}/doc/VTP_geodesics/file_map.txt")
endif()
if(NOT EXISTS "${FILE_MAP}")
  message(FATAL_ERROR "check_file_map: no file map page at ${FILE_MAP}")
endif()

file(READ "${FILE_MAP}" page)
# the code spans that may be paths or file names (no blank, no `:`, `*`, `(`: not code, not a pattern)
string(REGEX MATCHALL "`[A-Za-z0-9_./+-]+`" spans "${page}")
set(named "")
foreach(span IN LISTS spans)
  string(REGEX REPLACE "^`(.*)`$" "\\1" span "${span}")
  list(APPEND named "${span}")
endforeach()
list(REMOVE_DUPLICATES named)

set(errors "")

# 1. every header under include/ is on the page
file(GLOB_RECURSE headers RELATIVE "${SOURCE_DIR}/include" "${SOURCE_DIR}/include/*.h")
list(SORT headers)
list(LENGTH headers header_count)
if(header_count EQUAL 0)
  list(APPEND errors "no header found under ${SOURCE_DIR}/include")
endif()
foreach(h IN LISTS headers)
  if(NOT h IN_LIST named)
    list(APPEND errors "include/${h} is not in the file map: add a row | `${h}` | what it holds |")
  endif()
endforeach()

# 2. every path of the page exists
set(source_folders apps benchmark cmake data doc examples include package_info python scripts support test .ci)
set(repository_files "")
foreach(folder IN LISTS source_folders)
  if(IS_DIRECTORY "${SOURCE_DIR}/${folder}")
    file(GLOB_RECURSE found LIST_DIRECTORIES false "${SOURCE_DIR}/${folder}/*")
    list(APPEND repository_files ${found})
  endif()
endforeach()
file(GLOB found LIST_DIRECTORIES false "${SOURCE_DIR}/*")
list(APPEND repository_files ${found})
set(file_names "")
foreach(f IN LISTS repository_files)
  get_filename_component(n "${f}" NAME)
  list(APPEND file_names "${n}")
endforeach()
list(REMOVE_DUPLICATES file_names)

set(path_count 0)
foreach(p IN LISTS named)
  if(p MATCHES "/")
    math(EXPR path_count "${path_count} + 1")
    if(p MATCHES "^CGAL/")
      set(full "${SOURCE_DIR}/include/${p}")
    else()
      set(full "${SOURCE_DIR}/${p}")
    endif()
    if(NOT EXISTS "${full}")
      list(APPEND errors "the file map names `${p}`, which does not exist (${full})")
    elseif(p MATCHES "/$" AND NOT IS_DIRECTORY "${full}")
      list(APPEND errors "the file map names the folder `${p}`, which is not a folder")
    endif()
  elseif(p MATCHES "\\.(h|cpp|py|txt|cmake|sh|md|off|toml|cfg)$")
    math(EXPR path_count "${path_count} + 1")
    if(NOT p IN_LIST file_names)
      list(APPEND errors "the file map names the file `${p}`, and no file of the repository has that name")
    endif()
  endif()
endforeach()

if(errors)
  list(LENGTH errors error_count)
  string(REPLACE ";" "\n  " text "${errors}")
  message(FATAL_ERROR "check_file_map: ${error_count} problem(s) in ${FILE_MAP}:\n  ${text}\n")
endif()
message(STATUS "check_file_map: ${header_count} headers under include/ are in the file map, and the ${path_count} paths and file names it gives exist")
