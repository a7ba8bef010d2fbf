# The Python examples of the log map, the polar patches, the straightest geodesics, the curves and the distance from
# a curve (examples/python/):
# each runs on the bundled elephant, checks its own results and exits non-zero if a check fails (kept_field.py is run
# by test_field.py).

import importlib.util
import os
import subprocess
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLES = os.path.join(HERE, "..", "..", "examples", "python")


@pytest.mark.parametrize("name,expected", [
    ("log_map.py", "largest |rho - distance|"),
    ("straightest_geodesic.py", "walks from the centroid of face 0"),
    ("isolines_and_cell_borders.py", "cell areas sum to"),
    ("polar_patch.py", "walked back to"),
    ("distance_from_curve.py", "largest excess over the distance to one of its points"),
])
def test_example_runs(name, expected, tmp_path):
    if name == "polar_patch.py" and importlib.util.find_spec("matplotlib") is None:
        pytest.skip("polar_patch.py draws with matplotlib")
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    run = subprocess.run([sys.executable, os.path.join(EXAMPLES, name)], capture_output=True, text=True, env=env,
                         cwd=str(tmp_path))
    assert run.returncode == 0, run.stdout + run.stderr
    assert expected in run.stdout
