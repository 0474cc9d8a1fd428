"""What engineers compute from a solution: stresses inside the solid, the edge intensity and
the slip, checked against independent facts (closed forms, the load balance, the surface
conditions, a fit of p), not against earlier output."""

from __future__ import annotations

import math

import numpy as np
import pytest

from orthoslip import Contact, InvalidArgumentError, Material, Method

MATERIALS = {
    "ply (kappa > 1)": lambda: Material.plane_stress(181e9, 10.3e9, 7.17e9, 0.28),
    "isotropic (kappa = 1)": lambda: Material.effective(210e9, 0.3 / 0.7, 1.0, 1.0),
    "stiff shear (kappa < 1)": lambda: Material.plane_stress(100e9, 50e9, 80e9, 0.3),
}


def solve(material: Material, mu: float, method: Method) -> object:
    return Contact(material, mu, method=method).solve()


@pytest.mark.parametrize("name", MATERIALS)
@pytest.mark.parametrize("method", [Method.GOODMAN, Method.COUPLED])
def test_frictionless_slip_is_arcsin(name: str, method: Method) -> None:
    """mu = 0: c = 0, q = 0 and p = 1/(pi sqrt(1 - x^2)), so u = -(1 - nu) arcsin(x)/pi."""
    m = MATERIALS[name]()
    s = solve(m, 0.0, method)
    x = np.linspace(-1.0, 1.0, 41)
    exact = -(1.0 - m.constants.nu) * np.arcsin(x) / math.pi
    np.testing.assert_allclose(s.slip(x), exact, rtol=0, atol=1e-12)


@pytest.mark.parametrize("name", MATERIALS)
@pytest.mark.parametrize("method", [Method.GOODMAN, Method.SPENCE, Method.COUPLED])
def test_resultant_on_a_line_is_the_punch_load(name: str, method: Method) -> None:
    """int syy dx = -1 and int sxy dx = 0 over y = -h (x = h tan(theta), Gauss-Legendre in
    theta on 400 panels: the integrand is smooth in theta, on the scale of the depth below the
    punch edges)."""
    s = solve(MATERIALS[name](), 0.3, method)
    nodes, weights = np.polynomial.legendre.leggauss(20)
    edges = np.linspace(-math.pi / 2, math.pi / 2, 401)
    mid, half = (edges[1:] + edges[:-1]) / 2, (edges[1:] - edges[:-1]) / 2
    theta = (mid[:, None] + half[:, None] * nodes).ravel()
    w = (half[:, None] * weights).ravel()
    for h in (0.1, 1.0):
        x = h * np.tan(theta)
        _, syy, sxy = s.stresses(x, -h)
        dx = h / np.cos(theta) ** 2
        assert np.sum(syy * dx * w) == pytest.approx(-1.0, abs=1e-8)
        assert np.sum(sxy * dx * w) == pytest.approx(0.0, abs=1e-8)


@pytest.mark.parametrize("name", MATERIALS)
def test_surface_values_are_the_tractions(name: str) -> None:
    """At y = 0 on the punch, syy = -p and sxy = q; just below, the field tends to them."""
    s = solve(MATERIALS[name](), 0.3, Method.GOODMAN)
    x = np.array([-0.9, -0.5, 0.5 * s.c, 0.5 + 0.5 * s.c, 0.99])
    p, q = s.tractions(x)
    _, syy, sxy = s.stresses(x, 0.0)
    np.testing.assert_allclose(syy, -p, rtol=1e-11)
    np.testing.assert_allclose(sxy, q, rtol=0, atol=1e-11 * p.max())
    _, syy_near, sxy_near = s.stresses(x, -1e-9)
    np.testing.assert_allclose(syy_near, syy, rtol=1e-5)
    np.testing.assert_allclose(sxy_near, sxy, rtol=0, atol=1e-5)


@pytest.mark.parametrize("name", MATERIALS)
@pytest.mark.parametrize("method", [Method.GOODMAN, Method.SPENCE, Method.COUPLED])
def test_edge_intensity_matches_a_fit(name: str, method: Method) -> None:
    """(1 - x)^g p(x) -> k and the log slope of p -> -g near the edge; g = 1/2 -
    arctan(bp mu)/pi with bp = A/(pi C) (GOODMAN: 1/2, k = 1/(pi sqrt 2))."""
    m = MATERIALS[name]()
    s = solve(m, 0.3, method)
    k, g = s.edge_intensity()
    a, _, c = m.green
    expected_g = 0.5 if method == Method.GOODMAN else 0.5 - math.atan(a / (math.pi * c) * 0.3) / math.pi
    assert g == pytest.approx(expected_g, abs=1e-15)
    d = np.array([1e-8, 1e-9])
    x = 1.0 - d
    d = 1.0 - x
    p, _ = s.tractions(x)
    assert math.log(p[1] / p[0]) / math.log(d[1] / d[0]) == pytest.approx(-g, abs=1e-6)
    assert p[1] * d[1] ** g == pytest.approx(k, rel=1e-7)
    if method == Method.GOODMAN:
        assert k == pytest.approx(1.0 / (math.pi * math.sqrt(2.0)), rel=1e-14)


def test_stresses_broadcast_and_reject_bad_points(ply: Material) -> None:
    s = solve(ply, 0.3, Method.COUPLED)
    sxx, syy, sxy = s.stresses(np.linspace(-2, 2, 12).reshape(3, 4), -0.5)
    assert sxx.shape == syy.shape == sxy.shape == (3, 4)
    one = s.stresses(0.25, -0.5)
    assert all(np.ndim(v) == 0 for v in one)
    assert one == tuple(v[0] for v in s.stresses([0.25], [-0.5]))
    assert s.slip([]).shape == (0,)
    for x, y in [(math.nan, -1.0), (0.0, math.nan), (math.inf, -1.0), (0.0, 1e-300)]:
        with pytest.raises(InvalidArgumentError, match="orthoslip_solution_stresses"):
            s.stresses([0.0, x], [-1.0, y])
    with pytest.raises(InvalidArgumentError, match="orthoslip_solution_slip"):
        s.slip([0.5, math.nan])
    edge = s.stresses(1.0, 0.0)
    assert edge[0] == -math.inf and edge[1] == -math.inf and edge[2] == math.inf
