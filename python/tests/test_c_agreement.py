"""The package gives exactly what C gives through the same library: same c, same tractions,
same statuses and messages, to the last bit."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path
from collections.abc import Callable

import numpy as np
import pytest

import orthoslip
from conftest import REPO

X = [-0.999, -0.7, -0.2, 0.0, 0.05, 0.3, 0.9, 0.9999]

SCENES = [
    # (material kind and constants, mu, method, tol)
    (("stress", 181e9, 10.3e9, 7.17e9, 0.28), 0.3, "auto", 1e-8),
    (("stress", 181e9, 10.3e9, 7.17e9, 0.28), 0.3, "goodman", 1e-8),
    (("stress", 181e9, 10.3e9, 7.17e9, 0.28), 1.5, "spence", 1e-8),
    (("stress", 181e9, 10.3e9, 7.17e9, 0.28), 0.1, "coupled", 1e-10),
    (("stress", 20e9, 5e9, 3e9, -0.4), 0.5, "lcp", 1e-2),
    (("strain", 210e9, 210e9, 210e9, 80.8e9, 0.3, 0.3, 0.3), 0.2, "coupled", 1e-6),
    (("effective", 1.0, 0.3, 10.0, 0.4), 2.0, "auto", 1e-4),
    (("effective", 1.0, -0.5, 0.5, 3.0), 0.0, "auto", 1e-8),
]

CONSTRUCTORS = {
    "stress": orthoslip.Material.plane_stress,
    "strain": orthoslip.Material.plane_strain,
    "effective": orthoslip.Material.effective,
}


@pytest.fixture(scope="module")
def solve_in_c(build_c: Callable[[Path], Path]) -> Callable[..., dict[str, list[str]]]:
    """Runs tests/solve_scene.c on a scene; its output lines keyed by their first word."""
    exe = build_c(Path(__file__).parent / "solve_scene.c")

    def run(material: tuple, mu: float, method: str, tol: float, x: list[float]) -> dict:
        numbers = [float(v).hex() for v in material[1:]]
        args = [material[0], *numbers, mu.hex(), str(int(orthoslip.Method[method.upper()])),
                tol.hex(), *(float(v).hex() for v in x)]
        done = subprocess.run([str(exe), *args], capture_output=True, text=True)
        assert done.returncode in (0, 1), done.stderr
        lines: dict[str, list[str]] = {}
        for line in done.stdout.splitlines():
            key, _, rest = line.partition(" ")
            lines.setdefault(key, []).append(rest)
        return lines

    return run


@pytest.mark.parametrize("material, mu, method, tol", SCENES)
def test_solutions_match_c_bit_for_bit(solve_in_c, material, mu, method, tol) -> None:
    c_out = solve_in_c(material, mu, method, tol, X)
    solution = orthoslip.Contact(CONSTRUCTORS[material[0]](*material[1:]), mu, method, tol).solve()
    assert solution.c == float.fromhex(c_out["c"][0])
    assert solution.slip_width == float.fromhex(c_out["one_minus_c"][0])
    assert solution.error_estimate == float.fromhex(c_out["error_estimate"][0])
    assert solution.method == int(c_out["method"][0])
    p, q = solution.tractions(X)
    expected = np.array([[float.fromhex(v) for v in row.split()] for row in c_out["x"]])
    np.testing.assert_array_equal(expected[:, 0], X)
    np.testing.assert_array_equal(p, expected[:, 1])
    np.testing.assert_array_equal(q, expected[:, 2])


@pytest.mark.parametrize(
    "material, mu, method, tol, error",
    [
        (("stress", 1.0, 1.0, 1.0, 1.5), 0.3, "auto", 1e-8, orthoslip.InadmissibleMaterialError),
        (("effective", 1.0, 0.3, -1.0, 1.0), 0.3, "auto", 1e-8, orthoslip.InvalidArgumentError),
        (("effective", 1.0, 0.3, 1.0, 1.0), -0.1, "auto", 1e-8, orthoslip.InvalidArgumentError),
        (("effective", 1.0, 0.3, 1.0, 1.0), 0.3, "auto", 1.5, orthoslip.InvalidArgumentError),
        (("effective", 1.0, 0.9, 1.0, 1.0), 1.2, "coupled", 1e-12,
         orthoslip.NoConvergenceError),
    ],
)
def test_failures_match_c(solve_in_c, material, mu, method, tol, error) -> None:
    c_out = solve_in_c(material, mu, method, tol, [])
    with pytest.raises(error) as raised:
        orthoslip.Contact(CONSTRUCTORS[material[0]](*material[1:]), mu, method, tol).solve()
    assert raised.value.status_name == c_out["status"][0]
    assert raised.value.message == c_out["message"][0]


def test_default_scene_script_prints_what_the_c_example_prints(build_c) -> None:
    """python/examples/default_scene.py (the package) against c_examples/default_scene.c
    (the C API) on the same library: every line equal but the banner naming the language."""
    c_lines = subprocess.run([str(build_c(REPO / "c_examples" / "default_scene.c"))],
                             capture_output=True, text=True, check=True).stdout.splitlines()
    script = REPO / "python" / "examples" / "default_scene.py"
    py_lines = subprocess.run([sys.executable, str(script)],
                              capture_output=True, text=True, check=True).stdout.splitlines()
    assert c_lines[0].endswith("(C)") and py_lines[0].endswith("(Python)")
    assert py_lines[0].removesuffix("(Python)") == c_lines[0].removesuffix("(C)")
    assert len(py_lines) == len(c_lines) == 36
    for py, c in zip(py_lines[1:], c_lines[1:]):
        assert py == c
    assert any(line.startswith("c = 0.0891") for line in py_lines)
