"""Load paths and fretting cycles through the package, checked against facts the library does
not use: the uncoupled closed form (theory_tangential (T10)), the loop's area computed here
with NumPy against the dissipation of a closed cycle, mirror symmetry under Q -> -Q, and bad
input."""

from __future__ import annotations

import math

import numpy as np
import pytest

from orthoslip import (
    Contact,
    CycleMethod,
    CycleState,
    InvalidArgumentError,
    Material,
    NoAdmissibleSolutionError,
    NoConvergenceError,
)


def test_uncoupled_limit_sticks_with_the_closed_form_shear() -> None:
    """b* -> 0 (nu -> 1): q = (Q/P) / (pi sqrt(1 - x^2)), all stick, nothing dissipated."""
    k = Contact(Material.effective(1.0, 1.0 - 1e-6, 1.0, 1.0), mu=0.3)
    h = k.history(panels=40, steps=3)
    h.load(0.25)
    x = np.array([-0.8, -0.3, 0.1, 0.6])
    p, q, zone = h.tractions(x)
    p0 = 1.0 / (math.pi * np.sqrt(1.0 - x * x))
    np.testing.assert_allclose(p, p0, atol=2.0 / 40)
    np.testing.assert_allclose(q, 0.25 * p0, atol=0.5 / 40)
    assert np.all(zone == 0) and zone.dtype == np.intc
    assert h.stick_zone[:2] == (-1.0, 1.0)
    assert h.dissipated_energy[0] < 1e-9
    cy = k.solve_cycles(0.25, max_cycles=4, panels=40, steps=3)
    assert cy.state == CycleState.SHAKEDOWN and cy.count == 1 and cy.steady
    assert cy.method == CycleMethod.LCP_HISTORY
    assert cy.dissipated_energy[0] < 1e-9


def test_closed_cycle_dissipates_its_loop_area() -> None:
    """b* = 0.5, mu = 0.5, Q* = 0.9 mu P: a steady slip cycle, whose loop area (trapezoidal
    rule here) equals its dissipation within the estimate, with no net work of P."""
    k = Contact(Material.effective(1.0, 0.0, 1.0, 1.0), mu=0.5)
    cy = k.solve_cycles(0.45, max_cycles=8, panels=40, steps=4)
    assert cy.state == CycleState.STEADY_SLIP
    last = cy.count - 1
    q, u = cy.loop(last)
    area = float(np.sum(0.5 * (q[1:] + q[:-1]) * np.diff(u)))
    balance = cy.energy_balance(last)
    assert area == pytest.approx(balance.loop_work, abs=1e-14)
    assert abs(balance.normal_work) + abs(balance.energy_change) < 1e-8
    w, err = cy.dissipated_energy[last], cy.dissipated_energy_error[last]
    assert w > 1e-3 and abs(area - w) <= err
    u_err, work_err = cy.loop_error(last)
    assert 0.0 < u_err < 1.0 and 0.0 < work_err < 1.0


def test_ply_cycle_outputs() -> None:
    """The ply at 0.6 mu P shakes down after one cycle; the unloading slips at x = -1."""
    ply = Material.plane_stress(181e9, 10.3e9, 7.17e9, 0.28)
    cy = Contact(ply, mu=0.3).solve_cycles(0.18, max_cycles=4, panels=32, steps=4)
    assert cy.state == CycleState.SHAKEDOWN and cy.count == 2
    assert cy.dissipated_energy[0] > 1e-3 and cy.dissipated_energy[1] < 1e-12
    x = np.linspace(-0.99, 0.99, 9).reshape(3, 3)
    amp = cy.slip_amplitude(0, x)
    f1, f2 = cy.ruiz(0, x)
    tau, sxx = cy.stress_peaks(0, x)
    assert amp.shape == f1.shape == (3, 3)
    np.testing.assert_array_equal(f1, tau * amp)
    np.testing.assert_array_equal(f2, np.maximum(sxx, 0.0) * f1)
    assert amp[0, 0] > 0.0 and cy.ruiz_peaks(0).x_f1 < -0.9
    assert math.isnan(cy.ruiz_peaks(1).x_f1)
    zones = cy.stick_zones(0)
    assert zones.minus[1] == 1.0 and -1.0 < zones.minus[0] < 0.0 and zones.error < 0.1
    qp, _, c1, c2 = cy.step(0, 7)
    assert qp == -0.18 and (c1, c2) == zones.minus


def test_mirror_symmetry() -> None:
    k = Contact(Material.effective(1.0, 0.2, 1.3, 1.1), mu=0.4)
    up, down = k.history(panels=24, steps=3), k.history(panels=24, steps=3)
    up.load(0.2)
    down.load(-0.2)
    x = np.array([-0.77, -0.3, 0.21, 0.62])
    p, q, z = up.tractions(x)
    pm, qm, zm = down.tractions(-x)
    np.testing.assert_allclose(p, pm, atol=1e-10)
    np.testing.assert_allclose(q, -qm, atol=1e-10)
    np.testing.assert_array_equal(z, -zm)
    (a1, a2, _), (b1, b2, _) = up.stick_zone, down.stick_zone
    assert a1 == pytest.approx(-b2, abs=1e-10) and a2 == pytest.approx(-b1, abs=1e-10)


@pytest.mark.parametrize("amp", [math.nan, math.inf, -0.1, 0.0, 0.3, 0.5])
def test_bad_amplitudes_are_refused(amp: float) -> None:
    k = Contact(Material.effective(1.0, 0.2, 1.3, 1.1), mu=0.3)
    with pytest.raises(InvalidArgumentError, match="amplitude"):
        k.solve_cycles(amp, panels=8, steps=2)


def test_bad_input_is_refused() -> None:
    m = Material.effective(1.0, 0.2, 1.3, 1.1)
    with pytest.raises(InvalidArgumentError, match="mu > 0"):
        Contact(m, mu=0.0).solve_cycles(0.1, panels=8, steps=2)
    k = Contact(m, mu=0.3)
    with pytest.raises(InvalidArgumentError):
        k.solve_cycles(0.1, panels=7)
    with pytest.raises(ValueError, match="unknown cycle method"):
        k.history(method="implicit")
    h = k.history(panels=8, steps=2)
    h.load(0.1)
    with pytest.raises(InvalidArgumentError, match="gross sliding"):
        h.load(0.3)
    assert h.state[0] == 0.1
    with pytest.raises(InvalidArgumentError, match="contact"):
        h.tractions([0.0, 1.5])
    cy = k.solve_cycles(0.1, max_cycles=1, panels=8, steps=2)
    with pytest.raises(IndexError):
        cy.slip_amplitude(1, 0.0)


def test_history_solution() -> None:
    """A load-path state as a Solution: the uncoupled closed form q = (Q/P) / (pi
    sqrt(1 - x^2)) within the grid's accuracy, the surface conditions syy = -p, sxy = q, the
    mirror image under Q -> -Q, the history's stick set and estimates, and the getters
    without meaning for an asymmetric state refused."""
    k = Contact(Material.effective(1.0, 1.0 - 1e-6, 1.0, 1.0), mu=0.3)
    h = k.history(panels=40, steps=3)
    h.load(0.25)
    s = h.solution()
    x = np.array([-0.8, -0.3, 0.1, 0.6])
    p, q = s.tractions(x)
    p0 = 1.0 / (math.pi * np.sqrt(1.0 - x * x))
    np.testing.assert_allclose(p, p0, atol=2.0 / 40)
    np.testing.assert_allclose(q, 0.25 * p0, atol=0.5 / 40)
    assert s.stick_zone == h.stick_zone[:2] and s.error_estimate == h.stick_zone[2]
    assert s.traction_error_estimate == h.traction_error_estimate
    xs = np.linspace(-0.97, 0.97, 23)
    ps, qs = s.tractions(xs)
    _, syy, sxy = s.stresses(xs, 0.0)
    np.testing.assert_allclose(syy, -ps, rtol=0, atol=1e-12)
    np.testing.assert_allclose(sxy, qs, rtol=0, atol=1e-12)
    k2 = Contact(Material.plane_stress(181e9, 10.3e9, 7.17e9, 0.28), mu=0.3)
    up, down = k2.history(panels=24, steps=3), k2.history(panels=24, steps=3)
    up.load(0.15)
    down.load(-0.15)
    a, b = up.solution(), down.solution()
    pa, qa = a.tractions(xs)
    pb, qb = b.tractions(-xs)
    np.testing.assert_allclose(pa, pb, rtol=0, atol=1e-10)
    np.testing.assert_allclose(qa, -qb, rtol=0, atol=1e-10)
    sa = np.array(a.stresses(xs, -0.2))
    sb = np.array(b.stresses(-xs, -0.2))
    np.testing.assert_allclose(sa, sb * np.array([[1.0], [1.0], [-1.0]]), rtol=0, atol=1e-10)
    up.load(0.0)  # the solution is a copy of the state it was made from
    np.testing.assert_array_equal(a.tractions(xs)[1], qa)
    for refused in (lambda: a.c, lambda: a.slip_width, a.edge_intensity,
                    lambda: a.slip(0.5)):
        with pytest.raises(InvalidArgumentError, match="symmetric"):
            refused()


def test_exact_history() -> None:
    """method="exact" at b* = 0.9, mu = 1, Q = 0.3 mu P: the grid at 50 and 100 panels
    approaches the exact stick set's end c2 and punch displacement u; int q = Q/P by the trapezoidal rule in a graded
    variable, the zones' friction, the dissipation (positive, the same for -Q) and the
    refusal of a fretting run."""
    m = Material.effective(1.0, -0.8, 1.0, 1.0)
    k = Contact(m, mu=1.0, tol=1e-10, traction_tol=1e-8)
    h = k.history(method="exact")
    h.load(0.3)
    qp, u, moment = h.state
    assert qp == 0.3 and math.isfinite(u) and u > 0.0 and moment < 0.0
    c1, c2, err = h.stick_zone
    assert -0.95 < c1 < -0.9 and err < 1e-10
    prev, prev_u = math.inf, math.inf
    for panels in (50, 100):
        g = k.history(panels=panels)
        g.load(0.3)
        d, du = abs(g.stick_zone[1] - c2), abs(g.state[1] - u)
        assert d < prev and du < prev_u
        prev, prev_u = d, du
    # int q: x = -cos(t) takes out the edges' singularities (p ~ (1 -+ x)^(-g), g < 1/2)
    t = np.linspace(0.0, math.pi, 40001)[1:-1]
    x = -np.cos(t)
    p, q, zone = h.tractions(x)
    dt = t[1] - t[0]
    assert abs(np.sum(q * np.sin(t)) * dt - 0.3) < 1e-4
    assert abs(np.sum(p * np.sin(t)) * dt - 1.0) < 1e-4
    assert np.all(np.abs(q[zone == 1] + p[zone == 1]) <= 1e-12 * p[zone == 1])
    assert np.all(np.abs(q[zone == -1] - p[zone == -1]) <= 1e-12 * p[zone == -1])
    assert np.all(np.abs(q[zone == 0]) <= p[zone == 0])
    w, werr = h.dissipated_energy
    mirror = k.history(method="exact")
    mirror.load(-0.3)
    assert w > 0.0 and math.isfinite(werr)
    assert abs(mirror.dissipated_energy[0] - w) <= 1e-10 * w
    # a fretting run: refused at its first unloading step (the corner structure, not built)
    with pytest.raises(
        (NoAdmissibleSolutionError, NoConvergenceError), match="cycle 0, unloading"
    ):
        k.solve_cycles(0.3, method=CycleMethod.EXACT)
    s = h.solution()
    assert s.stick_zone == (c1, c2)
