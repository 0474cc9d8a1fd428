"""Shared fixtures of the tests of the installed ``orthoslip`` package.

The tests exercise the package as installed, never the source tree: cargo test's slow tier
runs them after ``pip install ./python`` in a fresh virtual environment, its fast tier on the
same layout assembled around the library cargo built (see ``tests/python.rs``). C programs
built against the very library bundled in the package give the reference results.
"""

from __future__ import annotations

import os
import re
import subprocess
from pathlib import Path
from collections.abc import Callable

import pytest

import orthoslip

REPO = Path(__file__).resolve().parents[2]
"""The source checkout (for the header, the C examples and the README)."""


def bundled_library() -> Path:
    """The shared library inside the installed package."""
    (lib,) = (Path(orthoslip.__file__).parent / "_native").glob("lib*.so")
    return lib


@pytest.fixture(scope="session")
def ply() -> orthoslip.Material:
    """The default scene's carbon/epoxy ply (plane stress)."""
    return orthoslip.Material.plane_stress(181e9, 10.3e9, 7.17e9, 0.28)


@pytest.fixture(scope="session")
def build_c(tmp_path_factory: pytest.TempPathFactory) -> Callable[[Path], Path]:
    """Compiles a C file against the bundled library and returns the executable.

    The programs find the library through a symlink named by its SONAME (which `readelf`
    reads from the bundled file) to the bundled file.
    """
    out = tmp_path_factory.mktemp("c")
    dynamic = subprocess.run(["readelf", "-d", str(bundled_library())], capture_output=True,
                             text=True, check=True).stdout
    soname = re.search(r"Library soname: \[([^\]]+)\]", dynamic)
    assert soname, f"no SONAME in {bundled_library()}:\n{dynamic}"
    (out / soname.group(1)).symlink_to(bundled_library())

    def build(source: Path) -> Path:
        exe = out / source.stem
        cc = os.environ.get("CC", "cc")
        cmd = [cc, "-std=c11", "-I", str(REPO / "include"), str(source), str(bundled_library()),
               f"-Wl,-rpath,{out}", "-o", str(exe)]
        built = subprocess.run(cmd, capture_output=True, text=True)
        assert built.returncode == 0, f"{' '.join(cmd)} failed:\n{built.stderr}"
        return exe

    return build
