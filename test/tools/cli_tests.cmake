# ctest tests of vtp_geodesics (included by CMakeLists.txt): each runs one command through
# run_cli_test.cmake, which checks the exit code, stderr and the files written.

set(VTP_GEODESICS_DEFAULT_MESH "${VTP_GEODESICS_BUILD_TREE_DEFAULT_MESH}")

# Command-line program: one successful run, and bad inputs that must fail with exit code 2
# without creating any output file.
set(cli_dir "${CMAKE_CURRENT_BINARY_DIR}/cli_test")  # every file the tests write is in here
file(MAKE_DIRECTORY "${cli_dir}")
set(cli_script "${CMAKE_CURRENT_SOURCE_DIR}/run_cli_test.cmake")
set(cli_data "${CMAKE_CURRENT_SOURCE_DIR}/data")
file(STRINGS "${VTP_GEODESICS_DEFAULT_MESH}" default_mesh_header LIMIT_COUNT 2 REGEX "^[0-9]")
string(REGEX MATCH "^[0-9]+" default_mesh_vertices "${default_mesh_header}")
set(stats_keys "vertices|faces|sources|source|max_distance_limit|targets|paths|stopped_early|method|threads|seconds|read_seconds|repair_seconds|propagation_seconds|write_seconds|total_seconds|other_seconds|outside_propagation_ratio|peak_rss_mb|windows_created|windows_propagated|peak_live_windows|peak_window_bytes|max_distance|preprocessing_seconds|mean_edge_length|anisotropy|field_pieces|field_bytes|query_points")

# vtp_cli_test(<name> <expected exit code> <output file> <json file>
#              [LINES <n>] [SOURCE_LINE <n>|none] [VALUES "<line>=<text>|..."] [NOTE <regex>] [ERROR <regex>]
#              [SETUP <what>] [CHECK <what>] [JSON_MATCH "<regex> && ..."] <args...>)
# LINES: number of lines of the output file (default: the vertices of the default mesh);
# SOURCE_LINE: the line of the output file that must be "0" (default: the first index of --source, else 0;
# none: no such line); VALUES: exact text of some lines of the output file (0-based line numbers);
# JSON_MATCH: regular expressions that the JSON statistics must match;
# NOTE: stderr must be one line "vtp_geodesics: note: ..." matching <regex> (default: stderr empty
# on success); ERROR: the error line must match <regex>; SETUP, CHECK: see run_cli_test.cmake.
# An output file "-" (or /dev/stdout) means the distances are read from the standard output.
function(vtp_cli_test name expected output json)
  cmake_parse_arguments(PARSE_ARGV 4 cli "" "LINES;SOURCE_LINE;VALUES;NOTE;ERROR;SETUP;CHECK;JSON_MATCH" "")
  string(REPLACE ";" "|" args "${cli_UNPARSED_ARGUMENTS}")
  set(extra)
  if(expected EQUAL 0 AND output AND NOT output MATCHES "\\.(ply|png)$")
    if(DEFINED cli_LINES)
      list(APPEND extra "-DEXPECTED_LINES=${cli_LINES}")
    else()
      list(APPEND extra "-DEXPECTED_LINES=${default_mesh_vertices}")
    endif()
    if(DEFINED cli_SOURCE_LINE)
      list(APPEND extra "-DSOURCE=${cli_SOURCE_LINE}")
    elseif(args MATCHES "--source\\|([0-9]+)")
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
  if(DEFINED cli_JSON_MATCH)
    list(APPEND extra "-DJSON_MATCH=${cli_JSON_MATCH}")
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
  if(VTP_GEODESICS_PICTURE_TEST_ENVIRONMENT)
    set_tests_properties(cli_${name} PROPERTIES ENVIRONMENT "${VTP_GEODESICS_PICTURE_TEST_ENVIRONMENT}")
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
vtp_cli_test(method_vsp 0 "${cli_dir}/vsp.txt" "" --method vsp --output "${cli_dir}/vsp.txt")
vtp_cli_test(method_vsp2 0 "${cli_dir}/vsp2.txt" "${cli_dir}/vsp2.json" JSON_MATCH "\"method\": \"vsp2\""
             --method vsp2 --output "${cli_dir}/vsp2.txt" --stats-json "${cli_dir}/vsp2.json")
vtp_cli_test(method_vsp_rejects_lambda 2 "" "" --method vsp --lambda 4 ERROR "need --method avtp or pavtp")
if(TARGET CGAL::VTP_geodesics_OpenMP_support)
  vtp_cli_test(method_pvtp 0 "${cli_dir}/pvtp.txt" "" --method pvtp --threads 2 --output "${cli_dir}/pvtp.txt")
  vtp_cli_test(method_pavtp 0 "${cli_dir}/pavtp.txt" "" --method pavtp --threads 3 --output "${cli_dir}/pavtp.txt")
  vtp_cli_test(method_pvsp 0 "${cli_dir}/pvsp.txt" "" --method pvsp --threads 2 --output "${cli_dir}/pvsp.txt")
  vtp_cli_test(method_pvsp2 0 "${cli_dir}/pvsp2.txt" "" --method pvsp2 --threads 2 --output "${cli_dir}/pvsp2.txt")
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
#   --through-pinches: the copies of vertex 0 are one point; from vertex 1, the other tetrahedron is reached
#   through it (vertex 0 at 1, its neighbours 4, 5, 6 at 2); refused with paths
vtp_cli_test(nonmanifold_vertex_through 0 "${cli_dir}/nmv2.txt" ""
             LINES 8 VALUES "0=1|1=0|4=2|5=2|6=2|7=inf" NOTE "duplicated 1 non-manifold vertex"
             "${cli_data}/nonmanifold_vertex.off" --through-pinches --source 1 --output "${cli_dir}/nmv2.txt")
vtp_cli_test(through_pinches_no_paths 2 "${bad_output}.40" "" ERROR "--through-pinches takes no --path-to"
             "${cli_data}/nonmanifold_vertex.off" --through-pinches --path-to 5 --path-output "${bad_output}.40")
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
#   a vertex line that CGAL's reader cannot read: its line of the file and its vertex (short_vertex_line.off: vertex 2,
#   on line 7 after a comment and a blank line, has two numbers; word_in_vertex_line.off: vertex 3, line 6, a word)
vtp_cli_test(short_vertex_line_off 2 "${bad_output}.22" ""
             ERROR "short_vertex_line.off': line 7: vertex 2 has 2 coordinates \\(expected 3\\)$"
             "${cli_data}/short_vertex_line.off" --output "${bad_output}.22")
vtp_cli_test(word_in_vertex_line_off 2 "${bad_output}.23" ""
             ERROR "word_in_vertex_line.off': line 6: vertex 3 has an invalid coordinate 'zero'$"
             "${cli_data}/word_in_vertex_line.off" --output "${bad_output}.23")
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

# vtp_cli_bad_sets(<first> <sets>): one failing test per set "name|arg|arg|...", each with --output and --stats-json
# files numbered from <first> that must not be created.
function(vtp_cli_bad_sets first sets)
  set(k ${first})
  foreach(set IN LISTS sets)
    string(REPLACE "|" ";" items "${set}")
    list(POP_FRONT items name)
    vtp_cli_test(${name} 2 "${bad_output}.${k}" "${bad_json}.${k}"
                 ${items} --output "${bad_output}.${k}" --stats-json "${bad_json}.${k}")
    math(EXPR k "${k} + 1")
  endforeach()
endfunction()

# vtp_cli_check(<name> AFTER <tests...> ARGS <arguments of vtp_geodesics_cli_check...>): checks the content of
# files written by the tests AFTER (run first, as the setup of a ctest fixture).
function(vtp_cli_check name)
  cmake_parse_arguments(PARSE_ARGV 1 chk "" "" "AFTER;ARGS")
  add_test(NAME cli_${name} COMMAND vtp_geodesics_cli_check ${chk_ARGS})
  set_tests_properties(cli_${name} PROPERTIES FIXTURES_REQUIRED cli_${name}_runs)
  foreach(t IN LISTS chk_AFTER)
    set_property(TEST cli_${t} APPEND PROPERTY FIXTURES_SETUP cli_${name}_runs)
  endforeach()
endfunction()

# Several sources: vertices and a point of the surface (--source-point), with their nearest-source labels; the
# distances are the minimum of the single-source runs and each label is a source at that distance.
set(point_a "0.3,0.1,0.0")     # located on an edge
set(point_b "0.1,0.2,0.3")     # located inside a face
set(point_c "0.26,0.11,0.03")  # located inside a face
set(several "${cli_dir}/several")
vtp_cli_test(several_sources 0 "${several}.txt" "${several}.json" JSON_MATCH "\"sources\": 4,"
             --source 0,1000 --source 2000 --source-point ${point_a} --labels "${several}.labels"
             --output "${several}.txt" --stats-json "${several}.json")
vtp_cli_test(several_sources_labels 0 "${several}.l.txt" "" VALUES "1000=1|2000=2"
             --source 0,1000 --source 2000 --source-point ${point_a} --labels "${several}.l.txt")
vtp_cli_test(several_single_0 0 "${several}.0.txt" "" --source 0 --output "${several}.0.txt")
vtp_cli_test(several_single_1 0 "${several}.1.txt" "" --source 1000 --output "${several}.1.txt")
vtp_cli_test(several_single_2 0 "${several}.2.txt" "" --source 2000 --output "${several}.2.txt")
vtp_cli_test(several_single_3 0 "${several}.3.txt" "" SOURCE_LINE none
             --source-point ${point_a} --output "${several}.3.txt")
vtp_cli_check(several_sources_nearest
              AFTER several_sources several_single_0 several_single_1 several_single_2 several_single_3
              ARGS nearest "${several}.txt" "${several}.labels" "${several}.0.txt" "${several}.1.txt"
                   "${several}.2.txt" "${several}.3.txt")
vtp_cli_test(several_sources_ply 0 "${several}.ply" "" CHECK "ply|ply_source"
             --source 0,1000,2000 --source-point ${point_a} --output "${several}.ply")
vtp_cli_test(several_sources_picture 0 "${several}.png" "" CHECK png
             --source 0,1000,2000 --source-point ${point_a} --picture "${several}.png")
#   CGAL's Surface_mesh_shortest_path is wrong from a source on an edge (point_a: its distances are below the
#   Euclidean ones there), hence points inside faces for the comparison
vtp_cli_test(source_points_check_cgal 0 "${cli_dir}/points_cgal.txt" "${cli_dir}/points_cgal.json"
             SOURCE_LINE none
             JSON_MATCH "\"max_rel_diff\": (0|[0-9.]+e-(1[0-9]|[2-9][0-9]))[,}] && \"mismatched_infinities\": 0[,}]"
             --source-point ${point_c} --source-point ${point_b} --check-cgal
             --output "${cli_dir}/points_cgal.txt" --stats-json "${cli_dir}/points_cgal.json")
#   the point nearest to (0.5,0.5,0.5): PMP::locate puts it 2.5e-16 inside a face, next to an edge (the library
#   takes it on the edge; CGAL's method takes it as given, and is right there)
vtp_cli_test(source_point_near_edge_check_cgal 0 "${cli_dir}/near_edge.txt" "${cli_dir}/near_edge.json"
             SOURCE_LINE none
             JSON_MATCH "\"max_rel_diff\": (0|[0-9.]+e-(1[0-9]|[2-9][0-9]))[,}] && \"mismatched_infinities\": 0[,}]"
             --source-point 0.5,0.5,0.5 --check-cgal
             --output "${cli_dir}/near_edge.txt" --stats-json "${cli_dir}/near_edge.json")
if(TARGET CGAL::VTP_geodesics_OpenMP_support)
  vtp_cli_test(several_sources_pvtp 0 "${several}.p.txt" ""
               --method pvtp --threads 2 --source 0,1000,2000 --source-point ${point_a}
               --labels "${several}.p.labels" --output "${several}.p.txt")
  vtp_cli_check(several_sources_pvtp_nearest
                AFTER several_sources_pvtp several_single_0 several_single_1 several_single_2 several_single_3
                ARGS nearest "${several}.p.txt" "${several}.p.labels" "${several}.0.txt" "${several}.1.txt"
                     "${several}.2.txt" "${several}.3.txt")
endif()
#   nonmanifold_vertex.off (see above): the two tetrahedra are cut apart at vertex 0, so each source labels its
#   own tetrahedron; vertex 7 (in no face) is reached by no source, unless it is one
vtp_cli_test(labels_repaired 0 "${cli_dir}/nmv.labels" "" LINES 8 VALUES "1=0|2=0|3=0|4=1|5=1|6=1|7=-1"
             NOTE "duplicated 1 non-manifold vertex"
             "${cli_data}/nonmanifold_vertex.off" --source 1,4 --labels "${cli_dir}/nmv.labels")
vtp_cli_test(labels_isolated_source 0 "${cli_dir}/nmv7.labels" "" LINES 8 VALUES "7=0|1=1|0=1|2=1|4=-1|5=-1"
             NOTE "duplicated 1 non-manifold vertex"
             "${cli_data}/nonmanifold_vertex.off" --source 7,1 --labels "${cli_dir}/nmv7.labels")

# Distance limit: inside, the distances of the full run; outside, inf; the run stops early.
set(limited "${cli_dir}/limited")
vtp_cli_test(max_distance 0 "${limited}.txt" "${limited}.json"
             JSON_MATCH "\"stopped_early\": true && \"max_distance_limit\": 0.2,"
             --source 1000 --max-distance 0.2 --output "${limited}.txt" --stats-json "${limited}.json")
vtp_cli_check(max_distance_equals_full AFTER max_distance several_single_1
              ARGS limit "${several}.1.txt" "${limited}.txt" 0.2)
vtp_cli_test(max_distance_zero 0 "${limited}.0.txt" "" VALUES "0=inf|999=inf|1001=inf"
             --source 1000 --max-distance 0 --output "${limited}.0.txt")
vtp_cli_test(max_distance_check_cgal 0 "${limited}.cgal.txt" "${limited}.cgal.json"
             JSON_MATCH "\"max_rel_diff\": (0|[0-9.]+e-(1[0-9]|[2-9][0-9]))[,}] && \"mismatched_infinities\": 0[,}]"
             --source 1000 --max-distance 0.25 --check-cgal
             --output "${limited}.cgal.txt" --stats-json "${limited}.cgal.json")
if(TARGET CGAL::VTP_geodesics_OpenMP_support)
  vtp_cli_test(max_distance_pvtp 0 "${limited}.p.txt" ""
               --method pvtp --threads 2 --source 1000 --max-distance 0.2 --output "${limited}.p.txt")
  vtp_cli_check(max_distance_pvtp_equals_full AFTER max_distance_pvtp several_single_1
                ARGS limit "${several}.1.txt" "${limited}.p.txt" 0.2)
endif()

# Targets: --target-output has one line per target (the --target list, then each --target-point); a vertex
# target's line is its line of --output (same run), and its distance in the full run; --output has every vertex.
set(targets "${cli_dir}/targets")
vtp_cli_test(targets 0 "${targets}.out" "${targets}.json" LINES 4 SOURCE_LINE 2
             JSON_MATCH "\"stopped_early\": true && \"targets\": 4,"
             --source 1000 --target 5,2000 --target 1000 --target-point ${point_b}
             --target-output "${targets}.out" --output "${targets}.txt" --stats-json "${targets}.json")
vtp_cli_check(targets_equal_output AFTER targets
              ARGS values "${targets}.out" 0,1,2 "${targets}.txt" 5,2000,1000 0)
vtp_cli_check(targets_equal_full_run AFTER targets several_single_1
              ARGS values "${targets}.out" 0,1,2 "${several}.1.txt" 5,2000,1000 1e-12)
vtp_cli_test(targets_output_stdout 0 "-" "" LINES 2 SOURCE_LINE none --source 1000 --target 5 --target-point ${point_b}
             --target-output -)

# Paths: one line per path (the --path-to list, then each --path-to-point), target first; each has the length of
# its distance (--target-output of the same targets); a path to a source is one point; the OBJ file holds the
# same paths; the picture draws them.
set(paths "${cli_dir}/paths")
set(path_args --source 1000,2000 --source-point ${point_a} --path-to 5,1000 --path-to 2700 --path-to-point ${point_b}
              --target 5,1000,2700 --target-point ${point_b} --target-output "${paths}.distances")
vtp_cli_test(paths 0 "${paths}.txt" "" LINES 4 SOURCE_LINE none ${path_args} --path-output "${paths}.txt")
vtp_cli_test(paths_obj 0 "" "" ${path_args} --path-output "${paths}.obj" --picture "${paths}.png")
vtp_cli_check(paths_length AFTER paths ARGS paths "${paths}.txt" "${paths}.distances" all)
vtp_cli_check(paths_obj_same AFTER paths paths_obj
              ARGS paths "${paths}.txt" "${paths}.distances" all "${paths}.obj")
#   without targets: the run goes to the end (paths from the full run); lengths against --output
vtp_cli_test(paths_full_run 0 "${paths}.full.txt" "" LINES 3 SOURCE_LINE none
             --source 1000,2000 --path-to 2700,5,1000 --path-output "${paths}.full.txt" --output "${paths}.d.txt")
vtp_cli_check(paths_full_run_length AFTER paths_full_run
              ARGS paths "${paths}.full.txt" "${paths}.d.txt" 2700,5,1000)
#   repaired input: the path from vertex 0 (cut apart) starts at its copy on the side of the source
vtp_cli_test(paths_repaired 0 "${paths}.nmv.txt" "" LINES 2 SOURCE_LINE none VALUES "0=2 0 0 0 1 0 0|1=1 1 0 0"
             NOTE "duplicated 1 non-manifold vertex"
             "${cli_data}/nonmanifold_vertex.off" --source 1 --path-to 0,1 --path-output "${paths}.nmv.txt")

# Farthest-point sampling: the samples file (K lines after a header; the first one --first; distinct; radii
# non-increasing, the last the largest distance; every sample at 0 with its own label); --radius stops early; one
# sample from --first is the plain run from that vertex; the Voronoi cells on the picture; bad combinations.
set(fps "${cli_dir}/fps")
vtp_cli_test(fps 0 "${fps}.txt" "${fps}.json" SOURCE_LINE none JSON_MATCH "\"samples\": 12, && \"sources\": 12,"
             --farthest-points 12 --first 1000 --samples-output "${fps}.samples" --output "${fps}.txt"
             --labels "${fps}.labels" --stats-json "${fps}.json")
vtp_cli_check(fps_samples AFTER fps ARGS samples "${fps}.samples" "${fps}.txt" "${fps}.labels" 12 1000)
vtp_cli_test(fps_radius 0 "${fps}.r.txt" "" SOURCE_LINE none
             --farthest-points 100 --radius 0.3 --samples-output "${fps}.r.samples" --output "${fps}.r.txt"
             --labels "${fps}.r.labels")
vtp_cli_check(fps_radius_samples AFTER fps_radius ARGS samples "${fps}.r.samples" "${fps}.r.txt" "${fps}.r.labels" 100 - 0.3)
vtp_cli_test(fps_one 0 "${fps}.1.txt" "" SOURCE_LINE 1000 --farthest-points 1 --first 1000 --output "${fps}.1.txt")
vtp_cli_check(fps_one_is_a_run AFTER fps_one several_single_1 ARGS values "${fps}.1.txt" all "${several}.1.txt" all 1e-12)
vtp_cli_test(fps_picture 0 "${fps}.png" "" CHECK png --farthest-points 8 --picture "${fps}.png" --picture-colour labels)
# K above the number of vertices: the sampling stops at covering radius 0, every vertex a sample (the 12 of the
# prism are at distinct points). Two components: the radius is inf until each has a sample; with one sample, the
# other component is at inf with label -1.
vtp_cli_test(fps_all_vertices 0 "${fps}.all.txt" "" LINES 12 SOURCE_LINE none
             "${cli_data}/hexagonal_prism.off" --farthest-points 50 --samples-output "${fps}.all.samples"
             --output "${fps}.all.txt" --labels "${fps}.all.labels" NOTE "triangulated 8 faces")
vtp_cli_check(fps_all_vertices_samples AFTER fps_all_vertices
              ARGS samples "${fps}.all.samples" "${fps}.all.txt" "${fps}.all.labels" 50 - 0)
vtp_cli_test(fps_components 0 "${fps}.cc.txt" "" LINES 7 SOURCE_LINE none
             "${cli_data}/two_components.off" --farthest-points 3 --samples-output "${fps}.cc.samples"
             --output "${fps}.cc.txt" --labels "${fps}.cc.labels")
vtp_cli_check(fps_components_samples AFTER fps_components
              ARGS samples "${fps}.cc.samples" "${fps}.cc.txt" "${fps}.cc.labels" 3 -)
vtp_cli_test(fps_components_one 0 "${fps}.cc1.txt" "" LINES 7 SOURCE_LINE 3
             "${cli_data}/two_components.off" --farthest-points 1 --first 3 --samples-output "${fps}.cc1.samples"
             --output "${fps}.cc1.txt" --labels "${fps}.cc1.labels")
vtp_cli_check(fps_components_one_samples AFTER fps_components_one
              ARGS samples "${fps}.cc1.samples" "${fps}.cc1.txt" "${fps}.cc1.labels" 1 3)
# With virtual sources (VSP): the same checks of the samples file; PVSP writes the same bits.
vtp_cli_test(fps_vsp 0 "${fps}.v.txt" "" SOURCE_LINE none --method vsp --farthest-points 12 --first 1000
             --samples-output "${fps}.v.samples" --output "${fps}.v.txt" --labels "${fps}.v.labels")
vtp_cli_check(fps_vsp_samples AFTER fps_vsp ARGS samples "${fps}.v.samples" "${fps}.v.txt" "${fps}.v.labels" 12 1000)
# With two virtual sources per vertex (VSP2): the same checks; PVSP2 writes the same bits.
vtp_cli_test(fps_vsp2 0 "${fps}.v2.txt" "" SOURCE_LINE none --method vsp2 --farthest-points 12 --first 1000
             --samples-output "${fps}.v2.samples" --output "${fps}.v2.txt" --labels "${fps}.v2.labels")
vtp_cli_check(fps_vsp2_samples AFTER fps_vsp2
              ARGS samples "${fps}.v2.samples" "${fps}.v2.txt" "${fps}.v2.labels" 12 1000)
if(TARGET CGAL::VTP_geodesics_OpenMP_support)
  vtp_cli_test(fps_pvtp 0 "${fps}.p.txt" "" SOURCE_LINE none --method pvtp --threads 2 --farthest-points 12
               --first 1000 --samples-output "${fps}.p.samples" --output "${fps}.p.txt" --labels "${fps}.p.labels")
  vtp_cli_check(fps_pvtp_equals_vtp AFTER fps fps_pvtp ARGS values "${fps}.p.txt" all "${fps}.txt" all 1e-12)
  vtp_cli_test(fps_pvsp 0 "${fps}.pv.txt" "" SOURCE_LINE none --method pvsp --threads 2 --farthest-points 12
               --first 1000 --samples-output "${fps}.pv.samples" --output "${fps}.pv.txt" --labels "${fps}.pv.labels")
  vtp_cli_check(fps_pvsp_equals_vsp AFTER fps_vsp fps_pvsp ARGS values "${fps}.pv.txt" all "${fps}.v.txt" all 0)
  vtp_cli_check(fps_pvsp_same_samples AFTER fps_vsp fps_pvsp
                ARGS values "${fps}.pv.samples" all "${fps}.v.samples" all 0)
  vtp_cli_test(fps_pvsp2 0 "${fps}.pv2.txt" "" SOURCE_LINE none --method pvsp2 --threads 2 --farthest-points 12
               --first 1000 --samples-output "${fps}.pv2.samples" --output "${fps}.pv2.txt")
  vtp_cli_check(fps_pvsp2_equals_vsp2 AFTER fps_vsp2 fps_pvsp2 ARGS values "${fps}.pv2.txt" all "${fps}.v2.txt" all 0)
  vtp_cli_check(fps_pvsp2_same_samples AFTER fps_vsp2 fps_pvsp2
                ARGS values "${fps}.pv2.samples" all "${fps}.v2.samples" all 0)
endif()
set(fps_bad_sets
  "fps_zero|--farthest-points|0"
  "fps_not_integer|--farthest-points|x"
  "fps_with_source|--farthest-points|3|--source|5"
  "fps_with_source_point|--farthest-points|3|--source-point|0.1,0.2,0.3"
  "fps_with_limit|--farthest-points|3|--max-distance|1"
  "fps_with_target|--farthest-points|3|--target|5|--target-output|${bad_output}.fps.t"
  "fps_first_out_of_range|--farthest-points|3|--first|99999999"
  "fps_radius_negative|--farthest-points|3|--radius|-1"
  "fps_radius_nan|--farthest-points|3|--radius|nan"
  "first_without_fps|--first|3"
  "radius_without_fps|--radius|0.5"
  "samples_output_without_fps|--samples-output|${bad_output}.fps.s"
  "picture_colour_unknown|--picture-colour|heights|--picture|${bad_output}.fps.png"
  "picture_colour_without_picture|--picture-colour|labels")
vtp_cli_bad_sets(100 "${fps_bad_sets}")

# Bad lists, points and limits; paths that do not exist: one error line, exit code 2, no file written.
set(bad_sets
  "source_empty_item|--source|0,,1"
  "source_trailing_comma|--source|0,"
  "source_leading_comma|--source|,1"
  "source_list_not_integer|--source|0,x"
  "source_list_out_of_range|--source|0,99999999"
  "source_point_two_coordinates|--source-point|1,2"
  "source_point_four_coordinates|--source-point|1,2,3,4"
  "source_point_nan|--source-point|1,nan,2"
  "source_point_infinite|--source-point|1,inf,2"
  "target_empty_item|--target|5,,6|--target-output|${bad_output}.t"
  "target_out_of_range|--target|99999999|--target-output|${bad_output}.t"
  "target_point_two_coordinates|--target-point|1,2|--target-output|${bad_output}.t"
  "path_out_of_range|--path-to|99999999|--path-output|${bad_output}.p"
  "path_not_integer|--path-to|-3|--path-output|${bad_output}.p"
  "path_point_two_coordinates|--path-to-point|1,2|--path-output|${bad_output}.p"
  "max_distance_negative|--max-distance|-1"
  "max_distance_nan|--max-distance|nan"
  "target_output_without_targets|--target-output|${bad_output}.t"
  "path_output_without_paths|--path-output|${bad_output}.p"
  "paths_without_output|--path-to|5")
vtp_cli_bad_sets(30 "${bad_sets}")
# Straightest geodesics (--straightest-geodesic, and --trace, its former name kept as an alias): bad values and a
# walk without --path-output are refused, under either name (the polylines themselves are checked against the
# Python module in test/python/test_straightest.py); the two names write the same file, byte for byte.
vtp_cli_test(trace_zero_direction 2 "${bad_output}.50" "" ERROR "direction must be finite and not zero"
             --trace 5,0,0,0,1 --path-output "${bad_output}.50")
vtp_cli_test(trace_negative_length 2 "${bad_output}.51" "" ERROR "length must be finite and >= 0"
             --trace 5,1,0,0,-1 --path-output "${bad_output}.51")
vtp_cli_test(trace_four_values 2 "${bad_output}.52" "" ERROR "expected V,X,Y,Z,LENGTH"
             --trace 5,1,0,0 --path-output "${bad_output}.52")
vtp_cli_test(trace_out_of_range 2 "${bad_output}.53" "" ERROR "--straightest-geodesic vertex 99999999 is out of range"
             --trace 99999999,1,0,0,1 --path-output "${bad_output}.53")
vtp_cli_test(trace_without_output 2 "" "" ERROR "--straightest-geodesic .--trace. needs --path-output"
             --trace 5,1,0,0,1)
vtp_cli_test(straightest_geodesic_zero_direction 2 "${bad_output}.54" "" ERROR "direction must be finite and not zero"
             --straightest-geodesic 5,0,0,0,1 --path-output "${bad_output}.54")
vtp_cli_test(straightest_geodesic_without_output 2 "" "" ERROR "needs --path-output" --straightest-geodesic 5,1,0,0,1)
set(walks "${cli_dir}/walks")
vtp_cli_test(straightest_geodesic 0 "" "" --straightest-geodesic 5,1,0,0,0.3 --straightest-geodesic 100,0,1,0,0.2
             --path-output "${walks}.new.txt")
vtp_cli_test(straightest_geodesic_alias_trace 0 "" "" --trace 5,1,0,0,0.3 --trace 100,0,1,0,0.2
             --path-output "${walks}.old.txt")
add_test(NAME cli_straightest_geodesic_alias_same
         COMMAND "${CMAKE_COMMAND}" -E compare_files "${walks}.new.txt" "${walks}.old.txt")
set_tests_properties(cli_straightest_geodesic_alias_same PROPERTIES FIXTURES_REQUIRED cli_straightest_alias_runs)
set_property(TEST cli_straightest_geodesic cli_straightest_geodesic_alias_trace APPEND
             PROPERTY FIXTURES_SETUP cli_straightest_alias_runs)
# The header of an OBJ --path-output says what each polyline is: a straightest geodesic (--straightest-geodesic, or
# its alias --trace) from its start vertex, its direction and its length (on the plane grid, along the diagonal of
# the squares from vertex 0: 5 points); after the geodesic paths of --path-to, each from its target (the header of
# paths alone is that of the paths tests).
set(trace_obj "${cli_dir}/trace")
vtp_cli_test(trace_obj_header 0 "${trace_obj}.obj" "" LINES 8 SOURCE_LINE none
             VALUES "0=# vtp_geodesics: 1 straightest geodesic (--straightest-geodesic), each from its start point, one 'l' element each|1=# 'l' element 1: straightest geodesic from vertex 0, direction (1, 1, 0) projected onto the tangent plane, length 0.5 (less if it reaches the border)|2=v 0 0 0|6=v 0.35355339059327373 0.35355339059327373 0|7=l 1 2 3 4 5"
             "${cli_data}/plane_grid.off" --straightest-geodesic 0,1,1,0,0.5 --path-output "${trace_obj}.obj")
vtp_cli_test(trace_obj_header_after_paths 0 "${trace_obj}.2.obj" "" LINES 28 SOURCE_LINE none
             VALUES "0=# vtp_geodesics: 1 geodesic path, from the target to the source, then 2 straightest geodesics (--straightest-geodesic), each from its start point, one 'l' element each|1=# 'l' element 2: straightest geodesic from vertex 0, direction (1, 1, 0) projected onto the tangent plane, length 0.5 (less if it reaches the border)|2=# 'l' element 3: straightest geodesic from vertex 60, direction (0, 1, 0) projected onto the tangent plane, length 2 (less if it reaches the border)"
             "${cli_data}/plane_grid.off" --source 0 --path-to 120 --straightest-geodesic 0,1,1,0,0.5 --trace 60,0,1,0,2
             --path-output "${trace_obj}.2.obj")
vtp_cli_test(paths_obj_header 0 "${trace_obj}.3.obj" "" LINES 13 SOURCE_LINE none
             VALUES "0=# vtp_geodesics: 1 geodesic paths, one 'l' element each, from the target to the source"
             "${cli_data}/plane_grid.off" --source 0 --path-to 120 --path-output "${trace_obj}.3.obj")
vtp_cli_test(labels_same_file_as_output 2 "${bad_output}.24" "" ERROR "must name different files"
             --labels "${bad_output}.24" --output "${bad_output}.24")
#   nonmanifold_vertex.off from vertex 1: the other tetrahedron (vertices 4, 5, 6) is unreachable, vertex 7 is in no
#   face, and vertex 2 is at distance sqrt(2) > 1
vtp_cli_test(path_unreachable 2 "${bad_output}.25" "${bad_json}.25" ERROR "no path from vertex 5"
             "${cli_data}/nonmanifold_vertex.off" --source 1 --path-to 2,5 --path-output "${bad_output}.25"
             --stats-json "${bad_json}.25")
vtp_cli_test(path_in_no_face 2 "${bad_output}.26" "" ERROR "no path from vertex 7"
             "${cli_data}/nonmanifold_vertex.off" --source 1 --path-to 7 --path-output "${bad_output}.26")
vtp_cli_test(path_beyond_limit 2 "${bad_output}.27" "" ERROR "no path from vertex 2 .*--max-distance"
             "${cli_data}/nonmanifold_vertex.off" --source 1 --max-distance 1 --path-to 0,2
             --path-output "${bad_output}.27")
vtp_cli_test(path_point_unreachable 2 "${bad_output}.28" "" ERROR "no path from point -1,-1,-1"
             "${cli_data}/nonmanifold_vertex.off" --source 1 --path-to-point -1,-1,-1 --path-output "${bad_output}.28")
#   degenerate_face.off: the point nearest to (1,0,1) is on a face of zero area
vtp_cli_test(target_point_degenerate_face 2 "${bad_output}.29" "" ERROR "cannot locate the point 1,0,1 of --target-point"
             "${cli_data}/degenerate_face.off" --source 0 --target-point 1,0,1 --target-output "${bad_output}.29")

# Installation: the installed tool (moved elsewhere) finds its default mesh relative to itself.
add_test(NAME cli_installed_tool
         COMMAND ${CMAKE_COMMAND} "-DBUILD_DIR=${CMAKE_BINARY_DIR}" "-DPREFIX=${cli_dir}/installed"
                 -P "${CMAKE_CURRENT_SOURCE_DIR}/install_test.cmake")
if(VTP_GEODESICS_PICTURE_TEST_ENVIRONMENT)
  set_tests_properties(cli_installed_tool PROPERTIES ENVIRONMENT "${VTP_GEODESICS_PICTURE_TEST_ENVIRONMENT}")
endif()

# --curves-output (the manual's page on curves): isolines and cell borders as OBJ polylines; bad levels and
# --levels alone are refused without writing anything.
set(curves "${cli_dir}/curves")
vtp_cli_test(curves_isolines 0 "" "" --source 0 --isolines 5 --curves-output "${curves}.iso.obj")
vtp_cli_test(curves_borders 0 "" "" --source 0,1000 --levels 0.1,0.2 --curves-output "${curves}.cells.obj")
vtp_cli_test(curves_bad_level 2 "${curves}.bad.obj" "" ERROR "--levels: every level must be finite and >= 0"
             --source 0 --levels 0.1,-1 --curves-output "${curves}.bad.obj")
vtp_cli_test(curves_levels_alone 2 "" "" ERROR "--levels needs --curves-output" --source 0 --levels 0.1)
