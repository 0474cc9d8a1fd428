"""A tangential load after the normal load, and fretting cycles: thin owners of the C
``orthoslip_history`` and ``orthoslip_cycles`` handles, vectorised over NumPy.

Units: x per a; p, q, tau_max and sigma_xx per P/a; displacements and slip amplitudes per
P/E (E: ``Material.constants.e``); energies per unit thickness in P^2/E; F1 in P^2/(a E),
F2 in P^3/(a^2 E). Profiles are panel values of the grid (piecewise constant in x); x must
lie on the contact [-1, 1]. Details: docs/fretting.md.
"""

from __future__ import annotations

import enum
from typing import TYPE_CHECKING, Any, NamedTuple, Union

import numpy as np
import numpy.typing as npt

from ._ffi import check, ffi, get, lib, new_handle

if TYPE_CHECKING:
    from ._api import Contact, Solution


class CycleMethod(enum.IntEnum):
    """How a load path or a cycle is solved (the C ABI's ``orthoslip_cycle_method``)."""

    LCP_HISTORY = lib.ORTHOSLIP_CYCLE_METHOD_LCP_HISTORY
    """The paper's grid LCP with a loading history (first order in panel width and step)."""
    EXACT = lib.ORTHOSLIP_CYCLE_METHOD_EXACT
    """The exact solvers, to the contact's ``tol`` and ``traction_tol``: for a :class:`History`
    the normal load, monotonic loading and the branches after each reversal where they keep
    one stick set with a slip zone at each end, at bp = 0 with their full-stick ranges (other
    loads raise, the history unchanged); :func:`solve_cycles` takes the cycle's load steps on
    that path and raises the path's error (:class:`NoConvergenceError`,
    :class:`NoAdmissibleSolutionError`, ...) where it refuses one (bp > 0: the corner
    structure is not built; a material has bp = 0 only with bq = 0).
    """


class CycleState(enum.IntEnum):
    """How a fretting run ended (the C ABI's ``orthoslip_cycle_state``)."""

    SHAKEDOWN = lib.ORTHOSLIP_CYCLE_SHAKEDOWN
    """The last cycle repeats its start state without dissipating: later cycles are elastic."""
    STEADY_SLIP = lib.ORTHOSLIP_CYCLE_STEADY_SLIP
    """The last cycle repeats its start state and dissipates: later cycles are the same."""
    LIMIT_REACHED = lib.ORTHOSLIP_CYCLE_LIMIT_REACHED
    """No cycle up to the limit repeated its start state."""


CycleMethodLike = Union[CycleMethod, str, int]


def _options(method: CycleMethodLike, panels: int, steps: int, repeat_tol: float) -> Any:
    if isinstance(method, str):
        try:
            method = CycleMethod[method.upper()]
        except KeyError:
            names = ", ".join(m.name.lower() for m in CycleMethod)
            raise ValueError(f"unknown cycle method {method!r}: choose one of {names}") from None
    o = new_handle("orthoslip_cycle_options", lib.orthoslip_cycle_options_free,
                   lib.orthoslip_cycle_options_new)
    check(lib.orthoslip_cycle_options_set_method(o, int(method)))
    check(lib.orthoslip_cycle_options_set_panels(o, panels))
    check(lib.orthoslip_cycle_options_set_steps(o, steps))
    check(lib.orthoslip_cycle_options_set_repeat_tolerance(o, repeat_tol))
    return o


def _points(x: npt.ArrayLike) -> tuple[np.ndarray, tuple[int, ...]]:
    a = np.ascontiguousarray(np.asarray(x, dtype=np.float64))
    return a.ravel(), a.shape


def _sample(function: Any, head: tuple[Any, ...], x: npt.ArrayLike, outputs: int,
            dtypes: tuple[Any, ...] | None = None) -> list[Any]:
    """Calls ``function(*head, x, n, out_0, ...)`` and returns the outputs in x's shape."""
    flat, shape = _points(x)
    dtypes = dtypes or (np.float64,) * outputs
    out = [np.empty(flat.size, dtype=d) for d in dtypes]
    if flat.size:
        cdecl = {np.float64: "double[]", np.intc: "int[]"}
        check(function(*head, ffi.from_buffer("double[]", flat), flat.size,
                       *(ffi.from_buffer(cdecl[d], a) for d, a in zip(dtypes, out))))
    return [a.reshape(shape)[()] for a in out]


class StickZones(NamedTuple):
    """The stick sets [c1, c2] of a cycle at Q = -Q* and Q = +Q*, and their error estimate."""

    minus: tuple[float, float]
    plus: tuple[float, float]
    error: float


class RuizPeaks(NamedTuple):
    """The peaks of F1 and F2 along the contact and where they are (NaN: no peak), with error
    estimates ``errors`` = (F1, x of F1, F2, x of F2)."""

    f1: float
    x_f1: float
    f2: float
    x_f2: float
    errors: tuple[float, float, float, float]


class EnergyBalance(NamedTuple):
    """A cycle's energy balance (P^2/E): the loop's area (the work of Q), the work of P, the
    change of elastic energy, and the residual of (T9) (rounding)."""

    loop_work: float
    normal_work: float
    energy_change: float
    residual: float


class History:
    """A load path: the normal load of ``contact`` (its material and friction), then the
    tangential load moved monotonically by :meth:`load`, ``steps`` grid steps per call.
    With ``method="exact"`` the exact solvers, to the contact's ``tol`` (the stick set's
    ends) and ``traction_tol`` (the tractions), without grid (``panels`` and ``steps``
    unused): exact p and q at any x, the zones since the current branch began, the punch
    displacement in :attr:`state` in the grid's gauge, and :attr:`dissipated_energy` over
    the loads the path took (the mean pressure per load step: exact when bp = 0, second
    order in the step otherwise).

    Raises:
        InvalidArgumentError: mu = 0, or panels (8 ..= 2000) or steps (2 ..= 10000) out of
            range.
    """

    def __init__(self, contact: Contact, panels: int = 100, steps: int = 10,
                 method: CycleMethodLike = "lcp_history") -> None:
        o = _options(method, panels, steps, 1e-8)
        self._handle = new_handle("orthoslip_history", lib.orthoslip_history_free,
                                  lib.orthoslip_history_new_with_options, contact._handle, o)

    def load(self, q_over_p: float) -> None:
        """Moves Q/P monotonically to ``q_over_p``.

        Raises:
            InvalidArgumentError: not finite, or |q_over_p| >= mu (gross sliding).
            NoAdmissibleSolutionError: the pressure turns negative (lift-off).
            With ``method="exact"``, a load the exact solvers do not answer raises their
            error (NoConvergenceError, NoAdmissibleSolutionError, InvalidArgumentError or
            ToleranceNotMetError) with a message saying what is missing; the LCP history
            answers it.
        On failure the path is unchanged."""
        check(lib.orthoslip_history_load(self._handle, q_over_p))

    @property
    def state(self) -> tuple[float, float, float]:
        """(Q/P, the punch's tangential displacement u per P/E, the moment int x p dx per P a)."""
        out = ffi.new("double[3]")
        check(lib.orthoslip_history_state(self._handle, out, out + 1, out + 2))
        return out[0], out[1], out[2]

    @property
    def stick_zone(self) -> tuple[float, float, float]:
        """(c1, c2, error estimate) of the step that reached the current state."""
        out = ffi.new("double[3]")
        check(lib.orthoslip_history_stick_zone(self._handle, out, out + 1, out + 2))
        return out[0], out[1], out[2]

    def tractions(self, x: npt.ArrayLike) -> tuple[Any, Any, Any]:
        """(p, q, zone) at ``x`` in [-1, 1]: zone 0 stick, +1 the solid slipped in +x
        relative to the punch (q = -mu p), -1 in -x."""
        p, q, z = _sample(lib.orthoslip_history_tractions, (self._handle,), x, 3,
                          (np.float64, np.float64, np.intc))
        return p, q, z

    @property
    def dissipated_energy(self) -> tuple[float, float]:
        """(energy dissipated since the normal load in P^2/E, its error estimate without the
        load-step error)."""
        out = ffi.new("double[2]")
        check(lib.orthoslip_history_dissipated_energy(self._handle, out, out + 1))
        return out[0], out[1]

    @property
    def traction_error_estimate(self) -> float:
        """Estimate of int (|dp| + |dq|) dx of the current tractions (units of P)."""
        return float(get("double", lib.orthoslip_history_traction_error_estimate, self._handle))

    def solution(self) -> Solution:
        """The current state as a :class:`Solution` (a copy: later loads do not change it):
        its tractions on [-1, 1] without symmetry, the stresses of their field, the stick
        set ``stick_zone`` with its error estimate ``error_estimate``, and
        ``traction_error_estimate``. ``c``, ``slip_width``, ``edge_intensity()`` and
        ``slip()`` raise :class:`InvalidArgumentError` (no single value without symmetry)."""
        from ._api import Solution

        return Solution(new_handle("orthoslip_solution", lib.orthoslip_solution_free,
                                   lib.orthoslip_history_solution, self._handle))


class Cycles:
    """A fretting run: the first loading 0 -> Q*, then cycles Q* -> -Q* -> Q* (index 0 is the
    first full cycle). Every per-cycle array has one entry per cycle."""

    def __init__(self, handle: Any) -> None:
        """Wraps an owned ``orthoslip_cycles *``; use :meth:`Contact.solve_cycles`."""
        self._handle = handle
        n = ffi.new("size_t *")
        steady = ffi.new("int *")
        check(lib.orthoslip_cycles_count(handle, n, steady))
        self.count: int = n[0]
        self.steady: bool = bool(steady[0])
        self.state = CycleState(get("orthoslip_cycle_state", lib.orthoslip_cycles_state, handle))
        self.method = CycleMethod(
            get("orthoslip_cycle_method", lib.orthoslip_cycles_method, handle))
        self.dissipated_energy = np.array([
            get("double", lambda h, o, i=i: lib.orthoslip_cycles_dissipated_energy(h, i, o),
                handle) for i in range(self.count)])
        """Energy dissipated per cycle (P^2/E)."""
        self.dissipated_energy_error = np.array([
            get("double", lambda h, o, i=i: lib.orthoslip_cycles_dissipated_energy_error(h, i, o),
                handle) for i in range(self.count)])
        """Error estimates of :attr:`dissipated_energy`."""
        out = ffi.new("double[2]")
        check(lib.orthoslip_cycles_first_loading_energy(handle, out, out + 1))
        self.first_loading_energy: tuple[float, float] = (out[0], out[1])
        """(energy dissipated in the first loading 0 -> Q*, its error estimate)."""

    def _cycle(self, cycle: int) -> int:
        if not 0 <= cycle < self.count:
            raise IndexError(f"cycle {cycle} is not in 0 .. {self.count - 1}")
        return cycle

    def slip_amplitude(self, cycle: int, x: npt.ArrayLike) -> Any:
        """Half the peak-to-peak relative tangential displacement over the cycle (P/E)."""
        (a,) = _sample(lib.orthoslip_cycles_slip_amplitude, (self._handle, self._cycle(cycle)),
                       x, 1)
        return a

    def slip_amplitude_error(self, cycle: int) -> float:
        """Error estimate of the slip amplitude (the largest over the panels, P/E)."""
        c = self._cycle(cycle)
        return float(get("double",
                         lambda h, o: lib.orthoslip_cycles_slip_amplitude_error(h, c, o),
                         self._handle))

    def ruiz(self, cycle: int, x: npt.ArrayLike) -> tuple[Any, Any]:
        """Ruiz's F1 = tau_max delta and F2 = max(sigma_xx,max, 0) tau_max delta at ``x``."""
        f1, f2 = _sample(lib.orthoslip_cycles_ruiz, (self._handle, self._cycle(cycle)), x, 2)
        return f1, f2

    def stress_peaks(self, cycle: int, x: npt.ArrayLike) -> tuple[Any, Any]:
        """(tau_max, sigma_xx,max) over the cycle at ``x`` (P/a; tension positive)."""
        t, s = _sample(lib.orthoslip_cycles_stress_peaks, (self._handle, self._cycle(cycle)),
                       x, 2)
        return t, s

    def ruiz_peaks(self, cycle: int) -> RuizPeaks:
        """The peaks of F1 and F2 along the contact, where, and their error estimates."""
        out = ffi.new("double[8]")
        check(lib.orthoslip_cycles_ruiz_peaks(self._handle, self._cycle(cycle), out, out + 1,
                                              out + 2, out + 3, out + 4))
        return RuizPeaks(out[0], out[1], out[2], out[3], (out[4], out[5], out[6], out[7]))

    def stick_zones(self, cycle: int) -> StickZones:
        """The stick sets at -Q* and +Q* and their error estimate."""
        out = ffi.new("double[5]")
        check(lib.orthoslip_cycles_stick_zones(self._handle, self._cycle(cycle), out, out + 1,
                                               out + 2, out + 3, out + 4))
        return StickZones((out[0], out[1]), (out[2], out[3]), out[4])

    def loop(self, cycle: int) -> tuple[np.ndarray, np.ndarray]:
        """The Q-displacement loop: (Q/P, u per P/E) at the cycle's start and each step."""
        c = self._cycle(cycle)
        n = ffi.new("size_t *")
        check(lib.orthoslip_cycles_loop_length(self._handle, c, n))
        q, u = np.empty(n[0]), np.empty(n[0])
        check(lib.orthoslip_cycles_loop(self._handle, c, n[0], ffi.from_buffer("double[]", q),
                                        ffi.from_buffer("double[]", u)))
        return q, u

    def loop_error(self, cycle: int) -> tuple[float, float]:
        """Error estimates of the loop: of u at its turning points (P/E) and of its area
        (P^2/E)."""
        out = ffi.new("double[2]")
        check(lib.orthoslip_cycles_loop_error(self._handle, self._cycle(cycle), out, out + 1))
        return out[0], out[1]

    def energy_balance(self, cycle: int) -> EnergyBalance:
        """The cycle's energy balance (P^2/E)."""
        out = ffi.new("double[4]")
        check(lib.orthoslip_cycles_energy_balance(self._handle, self._cycle(cycle), out,
                                                  out + 1, out + 2, out + 3))
        return EnergyBalance(out[0], out[1], out[2], out[3])

    def step(self, cycle: int, step: int) -> tuple[float, float, float, float]:
        """(Q/P, u, c1, c2) after load step ``step`` of the cycle (0-based; the first half
        of the steps unloads to -Q*)."""
        out = ffi.new("double[4]")
        check(lib.orthoslip_cycles_step(self._handle, self._cycle(cycle), step, out, out + 1,
                                        out + 2, out + 3))
        return out[0], out[1], out[2], out[3]

    def step_tractions(self, cycle: int, step: int, x: npt.ArrayLike) -> tuple[Any, Any, Any]:
        """(p, q, zone) after load step ``step`` of the cycle at ``x`` (as
        :meth:`History.tractions`)."""
        p, q, z = _sample(lib.orthoslip_cycles_step_tractions,
                          (self._handle, self._cycle(cycle), step), x, 3,
                          (np.float64, np.float64, np.intc))
        return p, q, z

    def __repr__(self) -> str:
        return (f"<Cycles count={self.count} state={self.state.name} "
                f"dissipated_energy={self.dissipated_energy!r}>")


def solve_cycles(contact: Contact, q_amp_over_p: float, max_cycles: int = 10,
                 panels: int = 100, steps: int = 10, repeat_tol: float = 1e-8,
                 method: CycleMethodLike = "lcp_history") -> Cycles:
    """The normal load, Q: 0 -> Q*, then cycles Q* -> -Q* -> Q* until the state repeats (to
    ``repeat_tol``) or ``max_cycles`` are done.

    Raises:
        InvalidArgumentError: ``q_amp_over_p`` not finite, <= 0 or >= mu (gross sliding),
            mu = 0, or an option out of range.
        NoAdmissibleSolutionError: the pressure turns negative on the path (lift-off).
    """
    o = _options(method, panels, steps, repeat_tol)
    return Cycles(new_handle("orthoslip_cycles", lib.orthoslip_cycles_free,
                             lib.orthoslip_contact_solve_cycles_with_options, contact._handle,
                             o, q_amp_over_p, max_cycles))
