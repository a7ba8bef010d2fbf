"""Writes a C++ header with a colour map of matplotlib (default: viridis), sampled at 256 points.

Run at configure time by apps/vtp_geodesics/CMakeLists.txt:
    python3 make_colour_map.py OUTPUT.h [NAME]
The table is generated, never committed: the colours come from the installed matplotlib.
"""
import os
import sys

import matplotlib

output = sys.argv[1]
name = sys.argv[2] if len(sys.argv) > 2 else "viridis"
colour_map = matplotlib.colormaps[name]
rows = []
for i in range(256):
    r, g, b, _ = colour_map(i / 255.0)
    rows.append("{%d, %d, %d}" % tuple(int(round(255 * c)) for c in (r, g, b)))
lines = [
    "// Generated at configure time by apps/vtp_geodesics/make_colour_map.py from matplotlib %s's \"%s\"."
    % (matplotlib.__version__, name),
    "// Do not edit; not part of the sources.",
    "#ifndef VTP_GEODESICS_APP_GENERATED_COLOUR_MAP_H",
    "#define VTP_GEODESICS_APP_GENERATED_COLOUR_MAP_H",
    "namespace vtp_geodesics_app {",
    "namespace generated {",
    "constexpr const char* colour_map_name = \"%s\";" % name,
    "constexpr const char* colour_map_source = \"matplotlib %s\";" % matplotlib.__version__,
    "constexpr unsigned char colour_map[256][3] = {",
]
for i in range(0, 256, 8):
    lines.append("  " + ", ".join(rows[i:i + 8]) + ",")
lines += ["};", "} // namespace generated", "} // namespace vtp_geodesics_app", "#endif", ""]
os.makedirs(os.path.dirname(os.path.abspath(output)), exist_ok=True)
with open(output, "w") as f:
    f.write("\n".join(lines))
