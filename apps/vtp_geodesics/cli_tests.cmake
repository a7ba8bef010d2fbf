# ctest tests of vtp_geodesics (included by CMakeLists.txt): each runs one command through
# run_cli_test.cmake, which checks the exit code, stderr and the files written.

set(VTP_GEODESICS_DEFAULT_MESH "${build_tree_default_mesh}")

# Command-line program: one successful run, and bad inputs that must fail with exit code 2
# without creating any output file.
set(cli_dir "${CMAKE_CURRENT_BINARY_DIR}/cli_test")  # every file the tests write is in here
file(MAKE_DIRECTORY "${cli_dir}")
set(cli_script "${CMAKE_CURRENT_SOURCE_DIR}/run_cli_test.cmake")
set(cli_data "${CMAKE_CURRENT_SOURCE_DIR}/data")
file(STRINGS "${VTP_GEODESICS_DEFAULT_MESH}" default_mesh_header LIMIT_COUNT 2 REGEX "^[0-9]")
string(REGEX MATCH "^[0-9]+" default_mesh_vertices "${default_mesh_header}")
set(stats_keys "vertices|faces|method|threads|seconds|read_seconds|repair_seconds|propagation_seconds|write_seconds|total_seconds|peak_rss_mb|windows_created|windows_propagated|peak_live_windows|peak_window_bytes|max_distance|preprocessing_seconds|mean_edge_length|anisotropy")

# vtp_cli_test(<name> <expected exit code> <output file> <json file>
#              [LINES <n>] [VALUES "<line>=<text>|..."] [NOTE <regex>] [ERROR <regex>] [SETUP <what>]
#              [CHECK <what>] <args...>)
# LINES: number of lines of the output file (default: the vertices of the default mesh);
# VALUES: exact text of some lines of the output file (0-based line numbers);
# NOTE: stderr must be one line "vtp_geodesics: note: ..." matching <regex> (default: stderr empty
# on success); ERROR: the error line must match <regex>; SETUP, CHECK: see run_cli_test.cmake.
# An output file "-" (or /dev/stdout) means the distances are read from the standard output.
function(vtp_cli_test name expected output json)
  cmake_parse_arguments(PARSE_ARGV 4 cli "" "LINES;VALUES;NOTE;ERROR;SETUP;CHECK" "")
  string(REPLACE ";" "|" args "${cli_UNPARSED_ARGUMENTS}")
  set(extra)
  if(expected EQUAL 0 AND output AND NOT output MATCHES "\\.(ply|png)$")
    if(DEFINED cli_LINES)
      list(APPEND extra "-DEXPECTED_LINES=${cli_LINES}")
    else()
      list(APPEND extra "-DEXPECTED_LINES=${default_mesh_vertices}")
    endif()
    if(args MATCHES "--source\\|([0-9]+)")
      list(APPEND extra "-DSOURCE=${CMAKE_MATCH_1}")
    endif()
    if(DEFINED cli_VALUES)
      list(APPEND extra "-DEXPECTED_VALUES=${cli_VALUES}")
    endif()
  endif()
  if(expected EQUAL 0)
    if(DEFINED cli_NOTE)
      list(APPEND extra "-DEXPECTED_NOTE=${cli_NOTE}")
    else()
      list(APPEND extra "-DEXPECTED_NOTE=")
    endif()
  endif()
  if(DEFINED cli_ERROR)
    list(APPEND extra "-DEXPECTED_ERROR=${cli_ERROR}")
  endif()
  if(DEFINED cli_SETUP)
    list(APPEND extra "-DSETUP=${cli_SETUP}")
  endif()
  if(DEFINED cli_CHECK)
    list(APPEND extra "-DCHECK=${cli_CHECK}")
  endif()
  if(expected EQUAL 0 AND args MATCHES "--stats-json")
    set(keys "${stats_keys}")
    if(args MATCHES "--check-cgal")
      string(APPEND keys "|cgal_seconds|max_abs_diff|max_rel_diff")
    endif()
    list(APPEND extra "-DJSON_KEYS=${keys}")
  endif()
  add_test(NAME cli_${name}
           COMMAND ${CMAKE_COMMAND} "-DEXE=$<TARGET_FILE:vtp_geodesics>" "-DARGS=${args}"
                   "-DEXPECTED_EXIT=${expected}" "-DOUTPUT=${output}" "-DJSON=${json}" ${extra}
                   -P "${cli_script}")
  if(VTP_TOOLS_TEST_ENVIRONMENT)
    set_tests_properties(cli_${name} PROPERTIES ENVIRONMENT "${VTP_TOOLS_TEST_ENVIRONMENT}")
  endif()
endfunction()

vtp_cli_test(help 0 "" "" --help)
vtp_cli_test(default_mesh 0 "${cli_dir}/default.txt" "${cli_dir}/default.json"
             --output "${cli_dir}/default.txt" --stats-json "${cli_dir}/default.json")
vtp_cli_test(check_cgal 0 "${cli_dir}/check.txt" "${cli_dir}/check.json"
             "${VTP_GEODESICS_DEFAULT_MESH}" --source 7 --check-cgal
             --output "${cli_dir}/check.txt" --stats-json "${cli_dir}/check.json")
vtp_cli_test(stats_stdout 0 "" "" "${VTP_GEODESICS_DEFAULT_MESH}" --source 3 --stats-json -)
vtp_cli_test(method_avtp 0 "${cli_dir}/avtp.txt" "" --method avtp --lambda 4 --output "${cli_dir}/avtp.txt")
if(TARGET CGAL::VTP_geodesics_OpenMP_support)
  vtp_cli_test(method_pvtp 0 "${cli_dir}/pvtp.txt" "" --method pvtp --threads 2 --output "${cli_dir}/pvtp.txt")
  vtp_cli_test(method_pavtp 0 "${cli_dir}/pavtp.txt" "" --method pavtp --threads 3 --output "${cli_dir}/pavtp.txt")
endif()

set(bad_output "${cli_dir}/bad.txt")
set(bad_json "${cli_dir}/bad.json")
vtp_cli_test(missing_file 2 "${bad_output}.1" "${bad_json}.1"
             "${cli_dir}/does_not_exist.off" --output "${bad_output}.1" --stats-json "${bad_json}.1")
vtp_cli_test(source_out_of_range 2 "${bad_output}.2" "${bad_json}.2"
             --source 999999999 --output "${bad_output}.2" --stats-json "${bad_json}.2")
vtp_cli_test(source_not_integer 2 "${bad_output}.3" "${bad_json}.3"
             --source abc --output "${bad_output}.3" --stats-json "${bad_json}.3")
vtp_cli_test(source_negative 2 "${bad_output}.4" "" --source -1 --output "${bad_output}.4")
vtp_cli_test(unknown_option 2 "${bad_output}.5" "" --frobnicate --output "${bad_output}.5")
vtp_cli_test(missing_value 2 "${bad_output}.6" "" --output "${bad_output}.6" --source)
vtp_cli_test(garbage_file 2 "${bad_output}.8" "${bad_json}.8"
             "${cli_data}/garbage.off" --output "${bad_output}.8" --stats-json "${bad_json}.8")
vtp_cli_test(bad_lambda 2 "${bad_output}.9" "" --method avtp --lambda 0 --output "${bad_output}.9")
vtp_cli_test(unknown_method 2 "${bad_output}.10" "" --method dijkstra --output "${bad_output}.10")
vtp_cli_test(two_meshes 2 "${bad_output}.11" ""
             "${VTP_GEODESICS_DEFAULT_MESH}" "${VTP_GEODESICS_DEFAULT_MESH}" --output "${bad_output}.11")
vtp_cli_test(unwritable_output 2 "${cli_dir}/no_such_dir/out.txt" "" --output "${cli_dir}/no_such_dir/out.txt")

# Input that is not a triangle mesh: repaired (one note line on stderr; the output has one line per
# vertex of the file, in file order), or refused when it cannot be repaired.
#   quad.off: a 2 x 1 grid of unit quads (vertex 2 is (2,0,0), vertex 3 is (0,1,0))
vtp_cli_test(quad_mesh 0 "${cli_dir}/quad.txt" "${cli_dir}/quad.json"
             LINES 6 VALUES "0=0|1=1|2=2|3=1" NOTE "^triangulated 2 faces$"
             "${cli_data}/quad.off" --output "${cli_dir}/quad.txt" --stats-json "${cli_dir}/quad.json")
#   hexagonal_prism.off: closed, two hexagons and six quads
vtp_cli_test(polygon_mesh 0 "${cli_dir}/prism.txt" "" LINES 12 VALUES "0=0" NOTE "^triangulated 8 faces$"
             "${cli_data}/hexagonal_prism.off" --check-cgal --output "${cli_dir}/prism.txt")
#   nonmanifold_vertex.off: two tetrahedra sharing vertex 0, and the isolated vertex 7; from vertex 0 (both
#   copies are sources) every vertex of a face is at distance 1; from vertex 1, the other tetrahedron is
#   unreachable (paths do not cross the cut at vertex 0)
vtp_cli_test(nonmanifold_vertex 0 "${cli_dir}/nmv.txt" ""
             LINES 8 VALUES "0=0|1=1|3=1|4=1|6=1|7=inf"
             NOTE "^removed 1 isolated point; duplicated 1 non-manifold vertex$"
             "${cli_data}/nonmanifold_vertex.off" --output "${cli_dir}/nmv.txt")
vtp_cli_test(nonmanifold_vertex_cut 0 "${cli_dir}/nmv1.txt" ""
             LINES 8 VALUES "0=1|1=0|4=inf|5=inf|6=inf|7=inf" NOTE "duplicated 1 non-manifold vertex"
             "${cli_data}/nonmanifold_vertex.off" --source 1 --output "${cli_dir}/nmv1.txt")
#   nonmanifold_edge.off: three triangles sharing the edge (0,1) of length 1; every other vertex is at
#   distance 1 from vertex 0
vtp_cli_test(nonmanifold_edge 0 "${cli_dir}/nme.txt" "" LINES 5 VALUES "0=0|1=1|2=1|3=1|4=1"
             NOTE "cut 1 non-manifold edge; duplicated 2 non-manifold vertices"
             "${cli_data}/nonmanifold_edge.off" --check-cgal --output "${cli_dir}/nme.txt")
#   degenerate_only.off: every face has a repeated vertex: nothing is left after the repair
vtp_cli_test(degenerate_faces_only 2 "${bad_output}.12" "" "${cli_data}/degenerate_only.off" --output "${bad_output}.12")
#   a folder named like a mesh, a file with an unknown extension, an empty file, a truncated file
file(MAKE_DIRECTORY "${cli_dir}/folder.off")
vtp_cli_test(unreadable_file 2 "${bad_output}.13" "" "${cli_dir}/folder.off" --output "${bad_output}.13")
configure_file("${cli_data}/quad.off" "${cli_dir}/quad.xyz" COPYONLY)
vtp_cli_test(unknown_extension 2 "${bad_output}.14" "" "${cli_dir}/quad.xyz" --output "${bad_output}.14")
file(WRITE "${cli_dir}/empty.off" "")
vtp_cli_test(empty_file 2 "${bad_output}.15" "" ERROR "the file is empty" "${cli_dir}/empty.off" --output "${bad_output}.15")
vtp_cli_test(truncated_file 2 "${bad_output}.16" "" "${cli_data}/truncated.off" --output "${bad_output}.16")
vtp_cli_test(index_out_of_range 2 "${bad_output}.17" "" ERROR "face 0 refers to vertex 3, out of range"
             "${cli_data}/bad_index.obj" --output "${bad_output}.17")

# Specific messages for bad input: non-finite coordinates (which vertex), bad indices (which face), empty files.
vtp_cli_test(index_out_of_range_off 2 "${bad_output}.18" "" ERROR "face 1 refers to vertex 9, out of range"
             "${cli_data}/bad_index.off" --output "${bad_output}.18")
vtp_cli_test(non_finite_off 2 "${bad_output}.19" "" ERROR "vertex 2 has a non-finite coordinate"
             "${cli_data}/non_finite.off" --output "${bad_output}.19")
vtp_cli_test(non_finite_obj 2 "${bad_output}.20" "" ERROR "vertex 1 has a non-finite coordinate"
             "${cli_data}/non_finite.obj" --output "${bad_output}.20")
vtp_cli_test(bad_view 2 "${bad_output}.21" "" ERROR "--view" --view 1,2 --picture "${bad_output}.21")

# Other formats that CGAL reads as polygon soups: STL (points merged by the reader, numbered in the order they
# first appear: the vertex (1,0,0) is vertex 2), OBJ, PLY and GOCAD TS.
#   tetrahedron.stl / tetrahedron.obj: the regular tetrahedron of edge length 1
vtp_cli_test(stl_input 0 "${cli_dir}/stl.txt" "" LINES 4 VALUES "2=1"
             "${cli_data}/tetrahedron.stl" --output "${cli_dir}/stl.txt")
vtp_cli_test(obj_input 0 "${cli_dir}/obj.txt" "" LINES 4 VALUES "1=1"
             "${cli_data}/tetrahedron.obj" --check-cgal --output "${cli_dir}/obj.txt")
vtp_cli_test(ply_input 0 "${cli_dir}/ply.txt" "" LINES 4 VALUES "1=1"
             "${cli_data}/tetrahedron.ply" --output "${cli_dir}/ply.txt")
vtp_cli_test(gocad_input 0 "${cli_dir}/ts.txt" "" LINES 4 VALUES "1=1"
             "${cli_data}/tetrahedron.ts" --output "${cli_dir}/ts.txt")

# Outputs by file name: text (a file, or - for stdout), PLY, PNG.
vtp_cli_test(output_stdout 0 "-" "" --output -)
vtp_cli_test(output_ply 0 "${cli_dir}/distances.ply" "" CHECK ply --output "${cli_dir}/distances.ply")
vtp_cli_test(output_ply_repaired 0 "${cli_dir}/nmv.ply" "" CHECK ply NOTE "duplicated 1 non-manifold vertex"
             "${cli_data}/nonmanifold_vertex.off" --output "${cli_dir}/nmv.ply")
vtp_cli_test(picture 0 "${cli_dir}/picture.png" "" CHECK png --picture "${cli_dir}/picture.png" --isolines 5)
vtp_cli_test(picture_view 0 "${cli_dir}/picture_view.png" "" CHECK png
             --picture "${cli_dir}/picture_view.png" --view 1,-1,-1 --isolines 0)

# Outputs that are not regular files are written through and never replaced; a regular file is replaced
# atomically (a symbolic link to it is followed and stays).
vtp_cli_test(output_dev_stdout 0 "/dev/stdout" "" --output /dev/stdout)
vtp_cli_test(output_dev_null 0 "" "" CHECK "chardev:/dev/null" --output /dev/null)
vtp_cli_test(output_fifo 0 "${cli_dir}/fifo.txt" "" SETUP fifo CHECK fifo --output "${cli_dir}/fifo.txt")
vtp_cli_test(output_symlink 0 "${cli_dir}/link.txt" "" SETUP symlink CHECK symlink --output "${cli_dir}/link.txt")
vtp_cli_test(output_dangling_symlink 0 "${cli_dir}/dangling.txt" "" SETUP dangling CHECK symlink
             --output "${cli_dir}/dangling.txt")
vtp_cli_test(output_existing_file 0 "${cli_dir}/existing.txt" "" SETUP existing CHECK mode640
             --output "${cli_dir}/existing.txt")

# Installation: the installed tool (moved elsewhere) finds its default mesh relative to itself.
add_test(NAME cli_installed_tool
         COMMAND ${CMAKE_COMMAND} "-DBUILD_DIR=${CMAKE_BINARY_DIR}" "-DPREFIX=${cli_dir}/installed"
                 -P "${CMAKE_CURRENT_SOURCE_DIR}/install_test.cmake")
if(VTP_TOOLS_TEST_ENVIRONMENT)
  set_tests_properties(cli_installed_tool PROPERTIES ENVIRONMENT "${VTP_TOOLS_TEST_ENVIRONMENT}")
endif()
