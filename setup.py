# SPDX-License-Identifier: GPL-3.0-or-later
"""Build hook of `pip install .` (see pyproject.toml and docs/python-install.md).

The module is the CMake target dfchaos_python, one extension module dfchaos.<EXT_SUFFIX>. This
script does not compile anything itself: it configures (if needed) and builds that target in the
CMake build directory, DFCHAOS_BUILD_DIR or build/ under the source, and copies the file into the
wheel. Nothing is downloaded; every dependency is a Debian package (scripts/install-deps.sh build).
setuptools' own scratch files go under that build directory too, so the clone stays clean.
"""
import os
import re
import shutil
import subprocess
import sysconfig
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = Path(__file__).resolve().parent


def _fail(message):
    raise SystemExit(f"dfchaos setup.py: {message}")


def _version():
    text = (SOURCE / "CMakeLists.txt").read_text(encoding="utf-8")
    match = re.search(r"^project\(dfchaos VERSION ([0-9.]+)", text, re.MULTILINE)
    if not match:
        _fail("no 'project(dfchaos VERSION x.y.z' line in CMakeLists.txt")
    return match.group(1)


def _build_dir():
    given = os.environ.get("DFCHAOS_BUILD_DIR", "build")
    path = Path(given)
    return path if path.is_absolute() else SOURCE / path


class CMakeBuild(build_ext):
    """Builds dfchaos_python with CMake and copies the module to where setuptools expects it."""

    def build_extension(self, ext):
        build = _build_dir()
        cmake = shutil.which("cmake")
        if cmake is None:
            _fail("cmake not found: run scripts/install-deps.sh build")
        if not (build / "CMakeCache.txt").is_file():
            subprocess.run([cmake, "-S", str(SOURCE), "-B", str(build)], check=True)
        jobs = str(os.cpu_count() or 1)
        subprocess.run([cmake, "--build", str(build), "--target", "dfchaos_python", "-j", jobs], check=True)
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        built = build / "python" / f"dfchaos{suffix}"
        if not built.is_file():
            found = sorted(p.name for p in (build / "python").glob("dfchaos*.so"))
            _fail(f"{built} not built for this interpreter (suffix {suffix}; found {found}): "
                  "the module is built for Debian's /usr/bin/python3, so create the venv with "
                  "'/usr/bin/python3 -m venv --system-site-packages VENV'")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


_scratch = _build_dir() / "pip"
_scratch.mkdir(parents=True, exist_ok=True)

setup(
    version=_version(),
    packages=[],
    py_modules=[],
    ext_modules=[Extension("dfchaos", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": str(_scratch / "build")},
             "egg_info": {"egg_base": str(_scratch)}},
)
