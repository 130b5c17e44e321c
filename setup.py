# SPDX-License-Identifier: GPL-3.0-or-later
"""pip's entry to the Python module geodesic_ridge: CMake builds the extension
(python/CMakeLists.txt) for the interpreter that runs pip, offline, from the
Debian packages that scripts/install_dependencies.sh installs:

    python3 -m venv --system-site-packages ENV
    ENV/bin/pip install --no-build-isolation .
"""
import os
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        out = os.path.dirname(os.path.abspath(self.get_ext_fullpath(ext.name)))
        build = os.path.abspath(os.path.join(self.build_temp, "cmake"))
        subprocess.check_call(["cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release",
                               "-DGEODESIC_RIDGE_PYTHON=ON", "-DGEODESIC_RIDGE_BUILD_EXAMPLES=OFF",
                               "-DGEODESIC_RIDGE_BUILD_TESTS=OFF", "-DGEODESIC_RIDGE_BUILD_BENCHMARKS=OFF",
                               "-DPython_EXECUTABLE=" + sys.executable,
                               "-DGEODESIC_RIDGE_PYTHON_OUTPUT_DIR=" + out])
        subprocess.check_call(["cmake", "--build", build, "--target", "_geodesic_ridge", "-j2"])


setup(
    name="geodesic_ridge",
    version="0.1.0",
    description="The geodesic ridge (cut locus) of a source on a triangle mesh, and its region-wise distance field",
    license="GPL-3.0-or-later",
    python_requires=">=3.9",
    install_requires=["numpy"],
    packages=["geodesic_ridge"],
    package_dir={"": "python"},
    ext_modules=[CMakeExtension("geodesic_ridge._geodesic_ridge")],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
)
