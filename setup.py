"""pip installation of the Python module vtp_geodesics, with Debian 12's packages only and no network:

    python3 -m venv --system-site-packages venv && . venv/bin/activate
    python3 -m pip install --no-build-isolation .

Builds python/src/*.cpp (the compiled layer, one file per topic; setuptools compiles them one by one, CMake as
one unity translation unit) with pybind11's setuptools helpers (Debian: python3-pybind11, pybind11-dev,
python3-setuptools, python3-dev), CGAL 5.5 header-only (libcgal-dev, libgmp-dev, libmpfr-dev,
libboost-dev) and OpenMP (GCC's -fopenmp), with the same flags as the CMake build (Release, -frounding-math as
CGAL requires), and installs the package python/vtp_geodesics (with the drop-ins gdist and pygeodesic).
"""

import glob
import os

from pybind11.setup_helpers import Pybind11Extension
from setuptools import setup

ROOT = os.path.dirname(os.path.abspath(__file__))
os.makedirs(os.path.join(ROOT, "build-pip"), exist_ok=True)  # setup.cfg: setuptools builds there, not in build/


extension = Pybind11Extension(
    "vtp_geodesics._core",
    # the module (its sources by topic), and the compiled part of the support layer (CMake: the static library
    # VTP_geodesics_support)
    sorted(glob.glob("python/src/*.cpp")) + ["support/src/read_mesh.cpp", "support/src/surface_locator.cpp",
                                                  "support/src/huge_page_new.cpp"],
    include_dirs=["include", "support/include"],  # the library; the support layer (readers, method table)
    define_macros=[("NDEBUG", None), ("CGAL_USE_GMPXX", "1"), ("CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP", None)],
    extra_compile_args=["-O3", "-frounding-math", "-fopenmp"],
    extra_link_args=["-fopenmp"],
    libraries=["gmpxx", "mpfr", "gmp"],
    cxx_std=17,
)

setup(
    name="vtp_geodesics",
    version="0.1.0",
    description="Exact geodesic distances on triangle meshes (VTP, PVTP, AVTP, PAVTP), numpy in and out",
    license="GPL-3.0-or-later",
    packages=["vtp_geodesics"],
    package_dir={"vtp_geodesics": "python/vtp_geodesics"},
    ext_modules=[extension],
    install_requires=["numpy", "scipy"],
    python_requires=">=3.7",
    zip_safe=False,
)
