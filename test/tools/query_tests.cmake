# ctest tests of the kept field of vtp_geodesics (included by CMakeLists.txt after cli_tests.cmake, whose
# vtp_cli_test() runs each command and vtp_cli_check() checks files with vtp_geodesics_cli_check): --keep-field,
# --query-points, --query-output, and the curves from the one run that keeps the field.
#   - data/plane_grid.off, the unit square of the plane z = 0 (vertex 0 at the origin, vertex 120 at (1,1)), with
#     data/plane_grid_points.txt (19 points: at vertices, on edges, inside faces, off the plane, outside the
#     square): the answers are the Euclidean distances of the points' projections onto the square to the nearest
#     source, and that source's label (cli_check.cpp, plane_query, to 1e-9);
#   - data/two_components.off: a point on the component that no source reaches is "inf -1";
#   - bad lines of the file, bad combinations of options: one error line, exit code 2, no file written.
# Every file is in cli_dir; the query output is the OUTPUT of vtp_cli_test (its line "0" check is off).

set(query "${cli_dir}/query")
set(query_plane "${cli_data}/plane_grid.off")
set(query_points "${cli_data}/plane_grid_points.txt")

# One source (vertex 0, at the origin); two: vertex 0 and a point of the surface, labelled 0 and 1 (--source
# vertices first, as --labels numbers them); a distance limit; the samples of --farthest-points (labels: the
# sample numbers); PVTP.
vtp_cli_test(query_plane 0 "${query}.1.txt" "${query}.1.json" LINES 19 SOURCE_LINE none VALUES "0=0 0"
             JSON_MATCH "\"query_points\": 19, && \"field_pieces\": [1-9][0-9]*, && \"field_bytes\": [1-9][0-9]*[,}]"
             "${query_plane}" --source 0 --query-points "${query_points}" --query-output "${query}.1.txt"
             --stats-json "${query}.1.json")
vtp_cli_check(query_plane_euclidean AFTER query_plane ARGS plane_query "${query}.1.txt" "${query_points}" 0,0)
vtp_cli_test(query_plane_two_sources 0 "${query}.2.txt" "" LINES 19 SOURCE_LINE none VALUES "0=0 0|9=0 1"
             "${query_plane}" --source-point 0.73,0.41,0 --source 0 --keep-field --query-points "${query_points}"
             --query-output "${query}.2.txt")
vtp_cli_check(query_plane_two_sources_euclidean AFTER query_plane_two_sources
              ARGS plane_query "${query}.2.txt" "${query_points}" 0,0 0.73,0.41)
vtp_cli_test(query_plane_limit 0 "${query}.r.txt" "" LINES 19 SOURCE_LINE none
             "${query_plane}" --source 0 --max-distance 0.8 --query-points "${query_points}"
             --query-output "${query}.r.txt")
vtp_cli_check(query_plane_limit_euclidean AFTER query_plane_limit
              ARGS plane_query "${query}.r.txt" "${query_points}" limit=0.8 0,0)
vtp_cli_test(query_plane_samples 0 "${query}.s.txt" "${query}.s.json" LINES 19 SOURCE_LINE none
             JSON_MATCH "\"samples\": 2, && \"field_bytes\": [1-9][0-9]*[,}]"
             "${query_plane}" --farthest-points 2 --first 0 --query-points "${query_points}"
             --query-output "${query}.s.txt" --stats-json "${query}.s.json")
vtp_cli_check(query_plane_samples_euclidean AFTER query_plane_samples
              ARGS plane_query "${query}.s.txt" "${query_points}" 0,0 1,1)
vtp_cli_test(query_plane_stdout 0 "-" "" LINES 19 SOURCE_LINE none VALUES "0=0 0|9=0 1"
             "${query_plane}" --source 0 --source-point 0.73,0.41,0 --query-points "${query_points}"
             --query-output -)
if(TARGET CGAL::VTP_geodesics_OpenMP_support)
  vtp_cli_test(query_plane_pvtp 0 "${query}.p.txt" "" LINES 19 SOURCE_LINE none
               "${query_plane}" --method pvtp --threads 2 --source 0 --source-point 0.73,0.41,0
               --query-points "${query_points}" --query-output "${query}.p.txt")
  vtp_cli_check(query_plane_pvtp_euclidean AFTER query_plane_pvtp
                ARGS plane_query "${query}.p.txt" "${query_points}" 0,0 0.73,0.41)
endif()

# two_components.off: a right triangle (vertices 0, 1, 2; legs 1) and a unit square (vertices 3 to 6) apart. From
# vertex 0, the square is unreached: its points are "inf -1"; from vertex 4 and the point at the origin, each
# labels its own component (vertex 1 is at 1 from the point, label 1; vertex 3 at 1 from vertex 4, label 0; the
# point (5.5, 0.5) at sqrt(1/2) from vertex 4, label 0).
file(WRITE "${query}.cc.points" "1 0 0\n5.5 0.5 0.25\n5 0 0\n")
vtp_cli_test(query_unreached_component 0 "${query}.cc.txt" "" LINES 3 SOURCE_LINE none
             VALUES "0=1 0|1=inf -1|2=inf -1"
             "${cli_data}/two_components.off" --source 0 --query-points "${query}.cc.points"
             --query-output "${query}.cc.txt")
vtp_cli_test(query_two_components_labels 0 "${query}.cc2.txt" "" LINES 3 SOURCE_LINE none
             VALUES "0=1 1|2=1 0"
             "${cli_data}/two_components.off" --source 4 --source-point 0,0,0 --query-points "${query}.cc.points"
             --query-output "${query}.cc2.txt")

# The statistics: field_pieces and field_bytes are 0 without the kept field (a plain run, the curves of an
# approximate method: their record), not with it (--keep-field; the curves of vtp, from the one run that gives the
# statistics, with --curves-output or --picture).
vtp_cli_test(field_stats_none 0 "" "${query}.n.json" JSON_MATCH "\"field_pieces\": 0, && \"field_bytes\": 0[,}]"
             --source 3 --stats-json "${query}.n.json")
vtp_cli_test(field_stats_keep 0 "" "${query}.k.json"
             JSON_MATCH "\"field_pieces\": [1-9][0-9]*, && \"field_bytes\": [1-9][0-9]*[,}] && \"query_points\": 0,"
             --source 3 --keep-field --stats-json "${query}.k.json")
vtp_cli_test(field_stats_curves 0 "" "${query}.c.json" JSON_MATCH "\"field_bytes\": [1-9][0-9]*[,}]"
             --source 0,1000 --levels 0.1,0.2 --curves-output "${query}.c.obj" --stats-json "${query}.c.json")
vtp_cli_test(field_stats_picture 0 "" "${query}.pic.json" JSON_MATCH "\"field_bytes\": [1-9][0-9]*[,}]"
             --source 0,1000 --picture "${query}.pic.png" --picture-colour labels --stats-json "${query}.pic.json")
vtp_cli_test(field_stats_curves_avtp 0 "" "${query}.ca.json" JSON_MATCH "\"field_bytes\": 0[,}]"
             --method avtp --source 0,1000 --levels 0.1,0.2 --curves-output "${query}.ca.obj"
             --stats-json "${query}.ca.json")
vtp_cli_test(field_stats_samples_curves 0 "" "${query}.fc.json" JSON_MATCH "\"field_bytes\": [1-9][0-9]*[,}]"
             --farthest-points 4 --curves-output "${query}.fc.obj" --stats-json "${query}.fc.json")

# Bad lines of the points file (the message names the line; nothing is written) and bad combinations.
set(query_bad "${cli_dir}/query_bad")
file(WRITE "${query_bad}.word.points" "0.1 0.1 0\n0.2 0.2 0\n0.3 abc 0\n")
file(WRITE "${query_bad}.two.points" "0.1 0.1 0\n1 2\n")
file(WRITE "${query_bad}.four.points" "0.1 0.1 0 1\n")
file(WRITE "${query_bad}.nan.points" "0.1 0.1 0\n0.2 0.2 0\n0.3 0.3 0\nnan 0 0\n")
file(WRITE "${query_bad}.inf.points" "0.1 0.1 0\ninf 0 0\n")
file(WRITE "${query_bad}.comma.points" "0.1,0.1,0\n")
file(WRITE "${query_bad}.empty_line.points" "0.1 0.1 0\n\n0.2 0.2 0\n")
foreach(case IN ITEMS "word|3" "two|2" "four|1" "nan|4" "inf|2" "comma|1" "empty_line|2")
  string(REPLACE "|" ";" case "${case}")
  list(GET case 0 what)
  list(GET case 1 line)
  vtp_cli_test(query_bad_line_${what} 2 "${query_bad}.${what}.txt" "${query_bad}.${what}.json"
               ERROR "^--query-points file '.*${what}\\.points' line ${line}: expected three finite numbers"
               "${query_plane}" --source 0 --query-points "${query_bad}.${what}.points"
               --query-output "${query_bad}.${what}.txt" --output "${query_bad}.${what}.d.txt"
               --stats-json "${query_bad}.${what}.json")
endforeach()
vtp_cli_test(query_missing_file 2 "${query_bad}.missing.txt" "" ERROR "cannot read --query-points file"
             "${query_plane}" --query-points "${query_bad}.does_not_exist" --query-output "${query_bad}.missing.txt")
vtp_cli_test(keep_field_avtp 2 "${query_bad}.avtp.txt" ""
             ERROR "^--keep-field needs --method vtp or pvtp, not avtp"
             --method avtp --keep-field --output "${query_bad}.avtp.txt")
vtp_cli_test(query_points_avtp 2 "${query_bad}.avtp.q.txt" ""
             ERROR "^--query-points \\(which keeps the field\\) needs --method vtp or pvtp, not avtp"
             "${query_plane}" --method avtp --query-points "${query_points}" --query-output "${query_bad}.avtp.q.txt")
vtp_cli_test(keep_field_vsp 2 "${query_bad}.vsp.txt" "" ERROR "^--keep-field needs --method vtp or pvtp, not vsp"
             --method vsp --keep-field --output "${query_bad}.vsp.txt")
vtp_cli_test(query_output_alone 2 "${query_bad}.alone.txt" "" ERROR "^--query-output needs --query-points$"
             --query-output "${query_bad}.alone.txt")
vtp_cli_test(query_points_alone 2 "${query_bad}.alone2.txt" "" ERROR "^--query-points needs --query-output$"
             "${query_plane}" --query-points "${query_points}" --output "${query_bad}.alone2.txt")
vtp_cli_test(keep_field_through_pinches 2 "${query_bad}.pinch.txt" "" ERROR "--keep-field takes no --through-pinches"
             "${cli_data}/nonmanifold_vertex.off" --keep-field --through-pinches --output "${query_bad}.pinch.txt")
vtp_cli_test(query_output_same_file 2 "${query_bad}.same.txt" "" ERROR "must name different files"
             "${query_plane}" --query-points "${query_points}" --query-output "${query_bad}.same.txt"
             --output "${query_bad}.same.txt")
