"""The installed package: the bundled library, its declarations against the committed
header, and the files a typed package ships."""

from __future__ import annotations

import re
from pathlib import Path

import orthoslip
from orthoslip import _ffi
from conftest import REPO, bundled_library


def test_the_installed_package_is_tested_not_the_source_tree() -> None:
    installed = Path(orthoslip.__file__).parent
    assert installed != REPO / "python" / "orthoslip"
    assert bundled_library().is_file()
    assert (installed / "py.typed").is_file()


def test_declarations_are_the_headers() -> None:
    """Every function and enum constant of include/orthoslip.h is declared, and nothing else."""
    header = (REPO / "include" / "orthoslip.h").read_text()
    functions = set(re.findall(r"\b(orthoslip_\w+)\(", header))
    constants = set(re.findall(r"^\s*(ORTHOSLIP_\w+) = \d+,$", header, re.M))
    declared = {name for name in dir(_ffi.lib) if name.lower().startswith("orthoslip_")}
    assert functions and constants
    assert declared == functions | constants


def test_version_matches_cargo_toml() -> None:
    manifest = (REPO / "Cargo.toml").read_text()
    (version,) = re.findall(r'^version = "([^"]+)"', manifest, re.M)
    assert orthoslip.__version__ == version
