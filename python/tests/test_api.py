"""The Pythonic API: materials against the paper's formulas, the contact's defaults and
validation, and the solution's quantities and vectorised tractions."""

from __future__ import annotations

import math

import numpy as np
import pytest

import orthoslip
from orthoslip import Contact, Material, Method


def test_plane_stress_constants_follow_eq_2(ply: Material) -> None:
    e11, e22, g12, nu12 = 181e9, 10.3e9, 7.17e9, 0.28
    k = ply.constants
    nu = math.sqrt(nu12 * nu12 * e22 / e11)
    assert k.e == pytest.approx(math.sqrt(e11 * e22), rel=1e-15)
    assert k.nu == pytest.approx(nu, rel=1e-14)
    assert k.delta**4 == pytest.approx(e11 / e22, rel=1e-14)
    assert k.kappa == pytest.approx(k.e / (2 * g12) - nu, rel=1e-14)
    a, b, c = ply.green
    root = math.sqrt(2 * (1 + k.kappa))
    assert (a, b, c) == pytest.approx(
        ((1 - k.nu) / k.e, root / (math.pi * k.delta * k.e), k.delta * root / (math.pi * k.e)),
        rel=1e-14,
    )


def test_isotropic_plane_strain_matches_johnson() -> None:
    e, nu = 210e9, 0.3
    steel = Material.plane_strain(e, e, e, e / (2 * (1 + nu)), nu, nu, nu)
    assert steel.constants.delta == pytest.approx(1.0, abs=1e-15)
    assert steel.constants.kappa == pytest.approx(1.0, abs=1e-14)
    a, b, c = steel.green
    assert a == pytest.approx((1 - 2 * nu) * (1 + nu) / e, rel=1e-14)
    assert b == pytest.approx(2 * (1 - nu * nu) / (math.pi * e), rel=1e-14)
    assert c == pytest.approx(b, rel=1e-14)


def test_effective_constants_round_trip() -> None:
    m = Material.effective(3.0, -0.2, 0.7, 0.4)
    assert m.constants == (3.0, -0.2, 0.7, 0.4)
    assert eval(repr(m), {"Material": Material}).constants == m.constants


def test_contact_keeps_its_scene_and_defaults(ply: Material) -> None:
    contact = Contact(ply, 0.3)
    assert (contact.mu, contact.method, contact.tol) == (0.3, Method.AUTO, 1e-8)
    assert contact.material is ply
    assert Contact(ply, 1, method="Coupled", tol=1e-6).method is Method.COUPLED
    assert Contact(ply, 1, method=Method.SPENCE).method is Method.SPENCE
    assert Contact(ply, 1, method=2).method is Method.SPENCE
    with pytest.raises(AttributeError):
        contact.mu = 0.5  # type: ignore[misc]
    with pytest.raises(ValueError, match="choose one of auto, goodman, spence, coupled, lcp"):
        Contact(ply, 0.3, method="newton")


def test_method_values_are_the_c_abi_values() -> None:
    assert [(m.name, int(m)) for m in Method] == [
        ("AUTO", 0), ("GOODMAN", 1), ("SPENCE", 2), ("COUPLED", 3), ("LCP", 4)
    ]


@pytest.mark.parametrize("method", ["goodman", "spence", "coupled", "auto"])
def test_solution_is_a_partial_slip_state(ply: Material, method: str) -> None:
    s = Contact(ply, 0.3, method=method).solve()
    assert 0 < s.c < 1
    assert s.c + s.slip_width == pytest.approx(1.0, abs=2e-16)
    assert s.method is not Method.AUTO
    assert s.method.name.lower() == method or method == "auto"
    assert 0 < s.error_estimate < 0.2
    # Friction law on the slip zones (E3): q = mu p sgn(x).
    x = np.array([-0.95, -0.5 * (1 + s.c), 0.5 * (1 + s.c), 0.95])
    p, q = s.tractions(x)
    np.testing.assert_allclose(q, 0.3 * p * np.sign(x), rtol=1e-12)


def test_coupled_solution_meets_the_tolerance_and_balances_the_load(ply: Material) -> None:
    s = Contact(ply, 0.3, method="coupled", tol=1e-10).solve()
    assert s.error_estimate <= 1e-10
    # int p dx = 1 (E4) by Gauss-Chebyshev quadrature of p sqrt(1 - x^2) (weight 1/sqrt(1 - x^2)
    # matches the edge singularity only roughly, so the rule is long and the check loose).
    n = 4000
    x = np.cos((2 * np.arange(n) + 1) * np.pi / (2 * n))
    p, q = s.tractions(x)
    assert np.pi / n * np.sum(p * np.sqrt(1 - x * x)) == pytest.approx(1.0, abs=2e-2)
    np.testing.assert_allclose(q, -q[::-1], atol=1e-14)
    np.testing.assert_allclose(p, p[::-1], rtol=1e-12)


def test_tractions_follow_the_shape_of_x(ply: Material) -> None:
    s = Contact(ply, 0.3).solve()
    p, q = s.tractions(0.5)
    assert isinstance(p, np.float64) and isinstance(q, np.float64)
    grid = np.linspace(-0.9, 0.9, 12).reshape(3, 4)
    pg, qg = s.tractions(grid)
    assert pg.shape == qg.shape == (3, 4) and pg.dtype == np.float64
    pf, qf = s.tractions(np.asfortranarray(grid))
    np.testing.assert_array_equal(pf, pg)
    p1, q1 = s.tractions(list(grid.ravel()))
    np.testing.assert_array_equal(p1, pg.ravel())
    np.testing.assert_array_equal(q1, qg.ravel())
    pe, qe = s.tractions([])
    assert pe.shape == qe.shape == (0,)
    pout, qout = s.tractions([-1.5, -1.0, 1.0, 2.0])
    np.testing.assert_array_equal(pout, [0.0, np.inf, np.inf, 0.0])
    np.testing.assert_array_equal(qout, [0.0, -np.inf, np.inf, 0.0])


def test_frictionless_contact_has_no_stick_zone(ply: Material) -> None:
    s = Contact(ply, 0.0).solve()
    assert s.c == 0.0 and s.slip_width == 1.0
    p, q = s.tractions([-0.5, 0.0, 0.5])
    np.testing.assert_array_equal(q, 0.0)
    # Frictionless flat punch: p = 1/(pi sqrt(1 - x^2)).
    np.testing.assert_allclose(p, 1 / (np.pi * np.sqrt(1 - np.array([0.25, 0, 0.25]))), rtol=1e-12)


def test_version_is_the_packages() -> None:
    from importlib.metadata import version

    assert orthoslip.__version__ == version("orthoslip")


def test_traction_tolerance_steers_auto() -> None:
    # b* = 0.2, mu~ = 100 (effective(1, 1 - 2 b*, 1, 1)): GOODMAN's c is within 1e-6, its
    # tractions are not.
    reduced = Material.effective(1.0, 0.6, 1.0, 1.0)
    default = Contact(reduced, 100.0, tol=1e-6)
    assert default.traction_tol is None
    s = default.solve()
    assert s.method is not Method.GOODMAN
    assert 0 <= s.traction_error_estimate <= 1e-6
    c_only = Contact(reduced, 100.0, tol=1e-6, traction_tol=math.inf)
    g = c_only.solve()
    assert g.method is Method.GOODMAN
    assert g.error_estimate <= 1e-6 < g.traction_error_estimate
    assert "traction_tol=inf" in repr(c_only)
    # the exact tractions differ from GOODMAN's by about what it claims at most
    x = np.linspace(-0.99, 0.99, 199)
    (p, q), (pg, qg) = s.tractions(x), g.tractions(x)
    l1 = np.sum(np.abs(p - pg) + np.abs(q - qg)) * (x[1] - x[0])
    assert 1e-3 < l1 <= g.traction_error_estimate
