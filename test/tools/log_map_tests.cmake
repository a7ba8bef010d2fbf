# ctest tests of the log map of vtp_geodesics (included by CMakeLists.txt after cli_tests.cmake, whose
# vtp_cli_test() runs each command): --log-map-output, --log-map-strict, --reference-direction and
# --picture-colour angle. The content of the files is checked by vtp_geodesics_log_map_check (log_map_check.cpp):
# the format and the distances of --output, the analytic values on a flat jittered grid (data/jittered_plane.off:
# rho the Euclidean distance to the nearest source, theta the Euclidean angle minus the reference's), a reference
# direction turning theta by the angle between the references, the strict theta of a vertex equal to its via
# vertex's, the distance limit. Every file is in cli_dir; the log map file is the OUTPUT of vtp_cli_test (its line
# "0" check is off: a source's line is "0 0 -1").

add_executable(vtp_geodesics_log_map_check log_map_check.cpp)

# vtp_log_map_check(<name> AFTER <tests...> ARGS <arguments of vtp_geodesics_log_map_check...>)
function(vtp_log_map_check name)
  cmake_parse_arguments(PARSE_ARGV 1 chk "" "" "AFTER;ARGS")
  add_test(NAME cli_${name} COMMAND vtp_geodesics_log_map_check ${chk_ARGS})
  set_tests_properties(cli_${name} PROPERTIES FIXTURES_REQUIRED cli_${name}_runs)
  foreach(t IN LISTS chk_AFTER)
    set_property(TEST cli_${t} APPEND PROPERTY FIXTURES_SETUP cli_${name}_runs)
  endforeach()
endfunction()

set(lm "${cli_dir}/log_map")
set(lm_plane "${cli_data}/jittered_plane.off")  # 81 vertices, vertex 40 near the centre

# The elephant from vertex 7: the format, rho = --output's text, the statistics; strict: the same rho and via,
# theta equal off the shadows, in a shadow the via vertex's theta; a limit.
vtp_cli_test(log_map 0 "${lm}.txt" "${lm}.json" SOURCE_LINE none VALUES "7=0 0 -1"
             JSON_MATCH "\"log_map\": \"default\" && \"log_map_behind_vertices\": [1-9]"
             --source 7 --log-map-output "${lm}.txt" --output "${lm}.d.txt" --stats-json "${lm}.json")
vtp_log_map_check(log_map_format AFTER log_map ARGS format "${lm}.txt" ${default_mesh_vertices} "${lm}.d.txt")
vtp_cli_test(log_map_strict 0 "${lm}.s.txt" "${lm}.s.json" SOURCE_LINE none VALUES "7=0 0 -1"
             JSON_MATCH "\"log_map\": \"strict\""
             --source 7 --log-map-strict --log-map-output "${lm}.s.txt" --stats-json "${lm}.s.json")
vtp_log_map_check(log_map_strict_format AFTER log_map_strict ARGS format "${lm}.s.txt" ${default_mesh_vertices})
vtp_log_map_check(log_map_strict_shadows AFTER log_map log_map_strict ARGS strict "${lm}.txt" "${lm}.s.txt")
vtp_cli_test(log_map_limit 0 "${lm}.r.txt" "" SOURCE_LINE none
             --source 7 --max-distance 0.2 --log-map-output "${lm}.r.txt")
vtp_log_map_check(log_map_limit_equals_full AFTER log_map log_map_limit ARGS limit "${lm}.txt" "${lm}.r.txt" 0.2)

# The plane: analytic values from a vertex, for two reference directions (1,1,5 projects to 1,1: theta turns by
# pi / 4); several sources (vertices and a point): each vertex relative to the nearest; PVTP the same.
vtp_cli_test(log_map_plane 0 "${lm}.p0.txt" "" LINES 81 SOURCE_LINE none VALUES "40=0 0 -1"
             "${lm_plane}" --source 40 --reference-direction 1,0,0 --log-map-output "${lm}.p0.txt")
vtp_cli_test(log_map_plane_reference 0 "${lm}.p1.txt" "" LINES 81 SOURCE_LINE none
             "${lm_plane}" --source 40 --reference-direction 1,1,5 --log-map-output "${lm}.p1.txt")
vtp_log_map_check(log_map_plane_values AFTER log_map_plane ARGS plane "${lm}.p0.txt" "${lm_plane}" 1,0 40)
vtp_log_map_check(log_map_plane_reference_values AFTER log_map_plane_reference
                  ARGS plane "${lm}.p1.txt" "${lm_plane}" 1,1 40)
vtp_log_map_check(log_map_reference_turns AFTER log_map_plane log_map_plane_reference
                  ARGS shift "${lm}.p0.txt" "${lm}.p1.txt" 0.78539816339744830962)
set(lm_several --source 10,70 --source-point 0.62,0.31,0 --reference-direction 0,1,0)
vtp_cli_test(log_map_plane_several 0 "${lm}.ps.txt" "" LINES 81 SOURCE_LINE none
             "${lm_plane}" ${lm_several} --log-map-output "${lm}.ps.txt" --labels "${lm}.ps.labels")
vtp_log_map_check(log_map_plane_several_values AFTER log_map_plane_several
                  ARGS plane "${lm}.ps.txt" "${lm_plane}" 0,1 10 70 0.62,0.31)
if(TARGET CGAL::VTP_geodesics_OpenMP_support)
  vtp_cli_test(log_map_plane_several_pvtp 0 "${lm}.pp.txt" "" LINES 81 SOURCE_LINE none
               "${lm_plane}" ${lm_several} --method pvtp --threads 2 --log-map-output "${lm}.pp.txt")
  vtp_log_map_check(log_map_plane_several_pvtp_values AFTER log_map_plane_several_pvtp
                    ARGS plane "${lm}.pp.txt" "${lm_plane}" 0,1 10 70 0.62,0.31)
  vtp_cli_test(log_map_strict_pvtp 0 "${lm}.sp.txt" "" SOURCE_LINE none
               --method pvtp --threads 2 --source 7 --log-map-strict --log-map-output "${lm}.sp.txt")
  vtp_cli_check(log_map_strict_pvtp_equals_vtp AFTER log_map_strict log_map_strict_pvtp
                ARGS values "${lm}.sp.txt" all "${lm}.s.txt" all 0)
endif()

# Repaired input (nonmanifold_vertex.off, see cli_tests.cmake): from vertex 1 the other tetrahedron and the vertex
# in no face are "inf nan -1"; from vertex 0 (both copies are sources) every vertex of a face is reached, each
# line's rho the text of --output.
vtp_cli_test(log_map_repaired 0 "${lm}.nmv.txt" "" LINES 8 SOURCE_LINE none NOTE "duplicated 1 non-manifold vertex"
             VALUES "1=0 0 -1|4=inf nan -1|5=inf nan -1|6=inf nan -1|7=inf nan -1"
             "${cli_data}/nonmanifold_vertex.off" --source 1 --log-map-output "${lm}.nmv.txt")
vtp_cli_test(log_map_repaired_split_source 0 "${lm}.nmv0.txt" "" LINES 8 SOURCE_LINE none
             NOTE "duplicated 1 non-manifold vertex" VALUES "0=0 0 -1|7=inf nan -1"
             "${cli_data}/nonmanifold_vertex.off" --source 0 --log-map-output "${lm}.nmv0.txt"
             --output "${lm}.nmv0.d.txt")
vtp_log_map_check(log_map_repaired_format AFTER log_map_repaired_split_source
                  ARGS format "${lm}.nmv0.txt" 8 "${lm}.nmv0.d.txt")

# A source vertex in no face (data/tetrahedron_isolated.off, vertex 4, read as it is): at 0, and it reaches nothing.
vtp_cli_test(log_map_isolated_source 0 "${lm}.iso.txt" "" LINES 5 SOURCE_LINE none VALUES "1=0 0 -1|4=0 0 -1"
             "${cli_data}/tetrahedron_isolated.off" --source 4,1 --log-map-output "${lm}.iso.txt")
vtp_log_map_check(log_map_isolated_source_format AFTER log_map_isolated_source ARGS format "${lm}.iso.txt" 5)
vtp_cli_test(log_map_isolated_source_alone 0 "${lm}.iso4.txt" "" LINES 5 SOURCE_LINE none
             VALUES "0=inf nan -1|3=inf nan -1|4=0 0 -1"
             "${cli_data}/tetrahedron_isolated.off" --source 4 --log-map-output "${lm}.iso4.txt")

# The picture of theta (a hue wheel, with the isolines); the output machinery of the other files (a symbolic
# link followed, standard output).
vtp_cli_test(log_map_picture 0 "${lm}.png" "" CHECK png --source 7 --picture "${lm}.png" --picture-colour angle)
vtp_cli_test(log_map_picture_points 0 "${lm}.pts.png" "" CHECK png --source 7 --source-point 0.1,0.2,0.3
             --log-map-strict --picture "${lm}.pts.png" --picture-colour angle)
vtp_cli_test(log_map_symlink 0 "${lm}.link.txt" "" SETUP symlink CHECK symlink SOURCE_LINE none
             --source 7 --log-map-output "${lm}.link.txt")
vtp_cli_test(log_map_stdout 0 "-" "" LINES 81 SOURCE_LINE none VALUES "40=0 0 -1"
             "${lm_plane}" --source 40 --log-map-output -)

# Refused: the methods that carry no direction, options without the log map, bad reference directions (zero,
# two numbers, orthogonal to the plane: the library's error), sampling, an unwritable file (no file is written,
# the distances neither).
vtp_cli_test(log_map_avtp 2 "${lm}.bad1.txt" "" ERROR "needs --method vtp or pvtp, not avtp"
             --method avtp --log-map-output "${lm}.bad1.txt")
vtp_cli_test(log_map_pavtp 2 "${lm}.bad2.txt" "" ERROR "needs --method vtp or pvtp, not pavtp"
             --method pavtp --log-map-output "${lm}.bad2.txt")
vtp_cli_test(log_map_vsp 2 "${lm}.bad3.txt" "" ERROR "needs --method vtp or pvtp, not vsp"
             --method vsp --log-map-output "${lm}.bad3.txt")
vtp_cli_test(log_map_picture_pvsp 2 "${lm}.bad4.png" "" ERROR "needs --method vtp or pvtp, not pvsp"
             --method pvsp --picture "${lm}.bad4.png" --picture-colour angle)
vtp_cli_test(log_map_strict_alone 2 "${lm}.bad5.txt" "" ERROR "need --log-map-output or --picture-colour angle"
             --log-map-strict --output "${lm}.bad5.txt")
vtp_cli_test(log_map_reference_alone 2 "${lm}.bad6.txt" "" ERROR "need --log-map-output"
             --reference-direction 1,0,0 --output "${lm}.bad6.txt")
vtp_cli_test(log_map_reference_zero 2 "${lm}.bad7.txt" "" ERROR "--reference-direction is zero"
             --reference-direction 0,0,0 --log-map-output "${lm}.bad7.txt")
vtp_cli_test(log_map_reference_two_numbers 2 "${lm}.bad8.txt" "" ERROR "expected three numbers"
             --reference-direction 1,0 --log-map-output "${lm}.bad8.txt")
vtp_cli_test(log_map_reference_normal 2 "${lm}.bad9.txt" "${lm}.bad9.d.txt" ERROR "reference direction"
             "${lm_plane}" --source 40 --reference-direction 0,0,1 --log-map-output "${lm}.bad9.txt"
             --output "${lm}.bad9.d.txt")
vtp_cli_test(log_map_sampling 2 "${lm}.bad10.txt" "" ERROR "takes no --farthest-points"
             --farthest-points 3 --log-map-output "${lm}.bad10.txt")
vtp_cli_test(log_map_same_file 2 "${lm}.bad11.txt" "" ERROR "must name different files"
             --log-map-output "${lm}.bad11.txt" --output "${lm}.bad11.txt")
vtp_cli_test(log_map_unwritable 2 "${cli_dir}/no_such_dir/log_map.txt" "${lm}.bad12.d.txt" ERROR "cannot write"
             --log-map-output "${cli_dir}/no_such_dir/log_map.txt" --output "${lm}.bad12.d.txt")
