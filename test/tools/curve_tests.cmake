# ctest tests of the sources that are curves of vtp_geodesics (included by CMakeLists.txt after cli_tests.cmake,
# whose vtp_cli_test() runs one command and checks its exit code, its error line and that no file is written):
# --source-curve FILE, --source-border, --signed.
#   - source_curve_test.py: the distances against the Euclidean answer on a flat jittered 81 x 81 grid that it
#     writes (closed polygon, with vtp and pvtp, signed both ways, with a distance limit, an open segment signed, the
#     border, the labels of mixed sources);
#     one ctest per case, cli_source_curve_<case>;
#   - bad input: one error line, exit code 2, no output file.

set(curve_dir "${cli_dir}/curves")
file(MAKE_DIRECTORY "${curve_dir}")
set(curve_cases polygon signed signed_cw limit open_signed border labels offset_curves)
if(TARGET CGAL::VTP_geodesics_OpenMP_support)
  list(APPEND curve_cases polygon_pvtp)
endif()
foreach(case IN LISTS curve_cases)
  add_test(NAME cli_source_curve_${case}
           COMMAND "${VTP_GEODESICS_PYTHON_WITH_MATPLOTLIB}" "${CMAKE_CURRENT_SOURCE_DIR}/source_curve_test.py"
                   ${case} --tool "$<TARGET_FILE:vtp_geodesics>" --work "${curve_dir}/${case}")
  set_tests_properties(cli_source_curve_${case} PROPERTIES TIMEOUT 120)
endforeach()

# Bad input. data/plane_grid.off is the unit square of the plane z = 0 (11 x 11 vertices); every file is written
# here, at configure time.
set(curve_plane "${cli_data}/plane_grid.off")
set(curve_bad "${curve_dir}/bad")
file(WRITE "${curve_bad}.square.txt" "0.2 0.2 0\n0.8 0.2 0\n0.8 0.8 0\n0.2 0.8 0\n0.2 0.2 0\n")
file(WRITE "${curve_bad}.empty.txt" "")
file(WRITE "${curve_bad}.blank.txt" "\n  \n\n")
file(WRITE "${curve_bad}.word.txt" "0.2 0.2 0\n0.8 0.2 0\n0.8 abc 0\n")
file(WRITE "${curve_bad}.two_numbers.txt" "0.2 0.2 0\n0.8 0.2\n")
file(WRITE "${curve_bad}.comma.txt" "0.2,0.2,0\n0.8,0.2,0\n")
file(WRITE "${curve_bad}.nan.txt" "0.2 0.2 0\nnan 0.2 0\n")
file(WRITE "${curve_bad}.one_point.txt" "0.2 0.2 0\n0.8 0.2 0\n\n0.5 0.5 0\n")
file(WRITE "${curve_bad}.same_point.txt" "0.3 0.3 0\n0.3 0.3 0\n")
file(WRITE "${curve_bad}.off_surface.txt" "0.2 0.2 0\n0.5 0.5 0.25\n0.8 0.2 0\n")
# two nested squares, both counter-clockwise: the ring between them is on the left of the outer one and on the
# right of the inner one (off the grid's lines: vertices of the ring are nearer to one than to the other)
file(WRITE "${curve_bad}.nested.txt"
     "0.05 0.05 0\n0.95 0.07 0\n0.93 0.95 0\n0.07 0.93 0\n0.05 0.05 0\n\n0.41 0.42 0\n0.58 0.43 0\n0.57 0.59 0\n0.43 0.57 0\n0.41 0.42 0\n")
set(curve_bad_cases
  "missing|cannot read --source-curve file '.*does_not_exist.txt'|${curve_dir}/does_not_exist.txt"
  "empty|--source-curve file '.*empty.txt' has no point|${curve_bad}.empty.txt"
  "blank|--source-curve file '.*blank.txt' has no point|${curve_bad}.blank.txt"
  "word|--source-curve file '.*word.txt' line 3: expected three finite numbers|${curve_bad}.word.txt"
  "two_numbers|--source-curve file '.*two_numbers.txt' line 2: expected three finite numbers|${curve_bad}.two_numbers.txt"
  "comma|--source-curve file '.*comma.txt' line 1: expected three finite numbers|${curve_bad}.comma.txt"
  "nan|--source-curve file '.*nan.txt' line 2: expected three finite numbers|${curve_bad}.nan.txt"
  "one_point|--source-curve file '.*one_point.txt' line 4: a curve of one point|${curve_bad}.one_point.txt"
  "same_point|^curve 1 of --source-curve file '.*same_point.txt' \\(lines 1-2\\): .*at least two distinct points|${curve_bad}.same_point.txt"
  "off_surface|^curve 1 of --source-curve file '.*off_surface.txt' \\(lines 1-3\\): point 2 \\(0.5,0.5,0.25\\) is off the surface|${curve_bad}.off_surface.txt")
foreach(case IN LISTS curve_bad_cases)
  string(REPLACE "|" ";" case "${case}")
  list(GET case 0 what)
  list(GET case 1 error)
  list(GET case 2 file)
  vtp_cli_test(source_curve_bad_${what} 2 "${curve_bad}.${what}.out" "${curve_bad}.${what}.json" ERROR "${error}"
               "${curve_plane}" --source-curve "${file}" --output "${curve_bad}.${what}.out"
               --stats-json "${curve_bad}.${what}.json")
endforeach()
vtp_cli_test(signed_without_curve 2 "${curve_bad}.signed.out" ""
             ERROR "^--signed needs a source that is a curve \\(--source-curve or --source-border\\)$"
             "${curve_plane}" --source 3 --signed --output "${curve_bad}.signed.out")
vtp_cli_test(signed_not_oriented 2 "${curve_bad}.nested.out" ""
             ERROR "^signed distance: the curves are not oriented consistently"
             "${curve_plane}" --source-curve "${curve_bad}.nested.txt" --signed --output "${curve_bad}.nested.out")
vtp_cli_test(source_border_closed_mesh 2 "${curve_bad}.closed.out" ""
             ERROR "^--source-border: the mesh has no border$"
             "${cli_data}/tetrahedron.obj" --source-border --output "${curve_bad}.closed.out")
vtp_cli_test(source_curve_farthest_points 2 "${curve_bad}.fps.out" ""
             ERROR "^--farthest-points chooses the sources: it takes no --source, --source-point, --source-curve"
             "${curve_plane}" --source-curve "${curve_bad}.square.txt" --farthest-points 3
             --output "${curve_bad}.fps.out")
vtp_cli_test(source_curve_log_map 2 "${curve_bad}.log.out" ""
             ERROR "takes no --source-curve nor --source-border"
             "${curve_plane}" --source-border --log-map-output "${curve_bad}.log.out")
vtp_cli_test(source_curve_check_cgal 2 "${curve_bad}.cgal.out" ""
             ERROR "^--check-cgal takes no --source-curve nor --source-border"
             "${curve_plane}" --source-curve "${curve_bad}.square.txt" --check-cgal --output "${curve_bad}.cgal.out")
vtp_cli_test(source_curve_through_pinches 2 "${curve_bad}.pinch.out" ""
             ERROR "^--source-curve and --source-border take no --through-pinches"
             "${curve_plane}" --source-border --signed --through-pinches --output "${curve_bad}.pinch.out")
# A good run, checked by run_cli_test.cmake alone: the square's sides are at distance 0 (vertex 0, a corner, and
# vertex 12, at (0.1, 0.1), is 0.1 from them); the default source vertex 0 is not added to curves.
vtp_cli_test(source_border_plane 0 "${curve_dir}/border.txt" "${curve_dir}/border.json" LINES 121 SOURCE_LINE 0
             VALUES "0=0|12=0.1" JSON_MATCH "\"sources\": 1,"
             "${curve_plane}" --source-border --output "${curve_dir}/border.txt" --stats-json "${curve_dir}/border.json")
vtp_cli_test(source_curve_vsp 2 "${curve_bad}.vsp.out" ""
             ERROR "^--source-curve and --source-border need --method vtp, pvtp, avtp or pavtp, not vsp"
             "${curve_plane}" --source-border --method vsp --output "${curve_bad}.vsp.out")
# The picture of a signed run from a curve (the isolines interpolated: the library's curves need the kept field)
vtp_cli_test(source_curve_picture 0 "${curve_dir}/signed.png" "" CHECK png
             "${curve_plane}" --source-curve "${curve_bad}.square.txt" --signed --picture "${curve_dir}/signed.png")

# Two points of edges joined by a geodesic from right to left (the library's join once kept the end point traced
# as a point of a face: two consecutive points with no common face, a crash): one distance per vertex.
file(WRITE "${curve_dir}/leftwards.txt" "0.58 0.58 0\n0.42 0.58 0\n")
vtp_cli_test(source_curve_leftwards 0 "${curve_dir}/leftwards.out" "" LINES 121 SOURCE_LINE none
             "${curve_plane}" --source-curve "${curve_dir}/leftwards.txt" --output "${curve_dir}/leftwards.out")
