"""Material, Contact and Solution: thin owners of the C handles, vectorised over NumPy."""

from __future__ import annotations

import enum
from typing import TYPE_CHECKING, Any, NamedTuple, Union

import numpy as np
import numpy.typing as npt

from ._ffi import check, ffi, get, lib, new_handle

if TYPE_CHECKING:
    from matplotlib.axes import Axes

    from ._fretting import CycleMethodLike, Cycles, History

class Method(enum.IntEnum):
    """Solution methods (the C ABI's ``orthoslip_method`` values)."""

    AUTO = lib.ORTHOSLIP_METHOD_AUTO
    """The cheapest method whose error estimate meets the tolerance."""
    GOODMAN = lib.ORTHOSLIP_METHOD_GOODMAN
    """Goodman's approximation (closed form; its empirical model-error bound as the estimate)."""
    SPENCE = lib.ORTHOSLIP_METHOD_SPENCE
    """Spence's approximation (closed form; its empirical model-error bound as the estimate)."""
    COUPLED = lib.ORTHOSLIP_METHOD_COUPLED
    """The high-order solver of the full coupled equations."""
    LCP = lib.ORTHOSLIP_METHOD_LCP
    """The paper's linear-complementarity method (first order)."""


MethodLike = Union[Method, str, int]
"""A method given as a :class:`Method`, its name (``"auto"``, ``"coupled"``, ...) or its C
value."""


def _method_value(method: MethodLike) -> int:
    if isinstance(method, str):
        try:
            return Method[method.upper()]
        except KeyError:
            names = ", ".join(m.name.lower() for m in Method)
            raise ValueError(f"unknown method {method!r}: choose one of {names}") from None
    return int(method)  # an unknown integer is rejected by the library


class Effective(NamedTuple):
    """The effective constants of the paper's eq. (1)."""

    e: float
    """Effective stiffness E = 1/sqrt(s11 s22), in the unit of the moduli given."""
    nu: float
    """Effective Poisson's ratio, in (-1, 1)."""
    delta: float
    """Stiffness ratio, delta^4 = s22/s11 (= E11/E22 in plane stress)."""
    kappa: float
    """Shear parameter, kappa = E/(2 G12) - nu (isotropic: 1)."""


class Green(NamedTuple):
    """The surface Green's function constants of the paper's eqs. (4)-(5) (1/modulus unit)."""

    a: float
    """A = (1 - nu)/E."""
    b: float
    """B = sqrt(2 (1 + kappa))/(pi delta E)."""
    c: float
    """C = delta sqrt(2 (1 + kappa))/(pi E)."""


class Material:
    """An orthotropic elastic half-plane with principal axes along the surface (x, index 1)
    and the depth (y, index 2). Create it with :meth:`plane_stress`, :meth:`plane_strain` or
    :meth:`effective`; moduli may be in any one unit (c, p and q do not depend on it).

    Raises:
        InvalidArgumentError: a value is NaN, infinite or a modulus is not positive.
        InadmissibleMaterialError: the compliance is not positive definite.
    """

    def __init__(self, handle: Any) -> None:
        """Wraps an owned ``orthoslip_material *``; use the class methods instead."""
        self._handle = handle

    @classmethod
    def plane_stress(cls, e11: float, e22: float, g12: float, nu12: float) -> Material:
        """Plane stress from engineering constants (paper eq. (2), E = sqrt(E11 E22)):
        Young's moduli ``e11`` (x) and ``e22`` (y), shear modulus ``g12`` and Poisson's
        ratio ``nu12`` (admissible iff nu12^2 < e11/e22)."""
        return cls(cls._new(lib.orthoslip_material_new_plane_stress, e11, e22, g12, nu12))

    @classmethod
    def plane_strain(
        cls, e11: float, e22: float, e33: float, g12: float, nu12: float, nu13: float, nu23: float
    ) -> Material:
        """Plane strain from the orthotropic constants (paper eq. (3)): moduli ``e11`` (x),
        ``e22`` (y), ``e33`` (out of plane), shear modulus ``g12`` and Poisson's ratios
        ``nu12``, ``nu13``, ``nu23`` (nu_ij: contraction along j under stress along i)."""
        return cls(
            cls._new(lib.orthoslip_material_new_plane_strain, e11, e22, e33, g12, nu12, nu13, nu23)
        )

    @classmethod
    def effective(cls, e: float, nu: float, delta: float, kappa: float) -> Material:
        """From the effective constants of paper eq. (1): ``e`` > 0, -1 < ``nu`` < 1,
        ``delta`` > 0 and ``kappa`` > -nu (isotropic: delta = kappa = 1)."""
        return cls(cls._new(lib.orthoslip_material_new_effective, e, nu, delta, kappa))

    @staticmethod
    def _new(create: Any, *constants: float) -> Any:
        return new_handle("orthoslip_material", lib.orthoslip_material_free, create, *constants)

    @property
    def constants(self) -> Effective:
        """The effective constants (E, nu, delta, kappa)."""
        out = ffi.new("double[4]")
        check(lib.orthoslip_material_effective(self._handle, out, out + 1, out + 2, out + 3))
        return Effective(*out)

    @property
    def green(self) -> Green:
        """The Green's function constants (A, B, C)."""
        out = ffi.new("double[3]")
        check(lib.orthoslip_material_green(self._handle, out, out + 1, out + 2))
        return Green(*out)

    def __repr__(self) -> str:
        e, nu, delta, kappa = self.constants
        return f"Material.effective({e!r}, {nu!r}, {delta!r}, {kappa!r})"


class Contact:
    """A scene: a rigid flat punch pressed into ``material`` with Coulomb friction ``mu``.

    Args:
        material: the half-plane (copied; later changes to it do not matter).
        mu: friction coefficient, finite and >= 0 (0 is the frictionless limit, c = 0).
        method: a :class:`Method` or its name; ``"auto"`` picks the cheapest method whose
            error estimate meets ``tol``.
        tol: target for |c - c_exact| (0 < tol < 1), and for the traction error unless
            ``traction_tol`` is given; ``"coupled"`` and ``"lcp"`` refine until they meet
            it, ``"goodman"`` and ``"spence"`` ignore it.
        traction_tol: target for the traction error int (|dp| + |dq|) dx in units of the
            load (> 0; ``math.inf``: tractions not needed); None follows ``tol``.

    Raises:
        InvalidArgumentError: ``mu``, ``tol``, ``traction_tol`` or an integer ``method`` is
            out of range.
        ValueError: ``method`` is an unknown name.
    """

    def __init__(
        self,
        material: Material,
        mu: float,
        method: MethodLike = "auto",
        tol: float = 1e-8,
        traction_tol: float | None = None,
    ) -> None:
        value = _method_value(method)
        handle = new_handle(
            "orthoslip_contact",
            lib.orthoslip_contact_free,
            lib.orthoslip_contact_new,
            material._handle,
        )
        check(lib.orthoslip_contact_set_friction(handle, mu))
        check(lib.orthoslip_contact_set_method(handle, value))
        check(lib.orthoslip_contact_set_tolerance(handle, tol))
        if traction_tol is not None:
            check(lib.orthoslip_contact_set_traction_tolerance(handle, traction_tol))
        self._handle = handle
        self._traction_tol = traction_tol
        self._material = material
        self._mu = float(mu)
        self._method = Method(value)
        self._tol = float(tol)

    @property
    def material(self) -> Material:
        """The material given."""
        return self._material

    @property
    def mu(self) -> float:
        """The friction coefficient."""
        return self._mu

    @property
    def method(self) -> Method:
        """The method asked for."""
        return self._method

    @property
    def tol(self) -> float:
        """The tolerance."""
        return self._tol

    @property
    def traction_tol(self) -> float | None:
        """The traction tolerance given (None: it follows ``tol``)."""
        return self._traction_tol

    def solve(self) -> Solution:
        """Solves the scene.

        Raises:
            NoConvergenceError: the method did not converge (e.g. a stick zone below 1e-35).
            ToleranceNotMetError: an error estimate exceeds ``tol`` or ``traction_tol``.
            NoAdmissibleSolutionError: the root found for c gives an inadmissible solution
                (p < 0, |q| > mu p on the stick zone, or slip against the friction).
        """
        return Solution(
            new_handle(
                "orthoslip_solution",
                lib.orthoslip_solution_free,
                lib.orthoslip_contact_solve,
                self._handle,
            )
        )

    def solve_cycles(
        self,
        q_amp_over_p: float,
        max_cycles: int = 10,
        panels: int = 100,
        steps: int = 10,
        repeat_tol: float = 1e-8,
        method: CycleMethodLike = "lcp_history",
    ) -> Cycles:
        """Fretting: the normal load, Q: 0 -> Q*, then cycles Q* -> -Q* -> Q* (Q* =
        ``q_amp_over_p`` P) until the state repeats or ``max_cycles`` are done, on ``panels``
        panels per half-width with ``steps`` load steps per quarter cycle. Uses the material
        and friction (not ``method``/``tol`` of the contact). See :class:`Cycles`."""
        from ._fretting import solve_cycles

        return solve_cycles(self, q_amp_over_p, max_cycles, panels, steps, repeat_tol, method)

    def history(
        self, panels: int = 100, steps: int = 10, method: CycleMethodLike = "lcp_history"
    ) -> History:
        """A load path from the normal-load state: see :class:`History`."""
        from ._fretting import History

        return History(self, panels, steps, method)

    def __repr__(self) -> str:
        return (
            f"Contact({self.material!r}, mu={self.mu!r}, method={self.method.name.lower()!r}, "
            f"tol={self.tol!r}, traction_tol={self.traction_tol!r})"
        )


class Solution:
    """A solved contact: the stick zone is ``|x| < c``, the slip zones ``c < |x| < 1``, with
    x in units of the punch half-width a.

    A load-path state (:meth:`History.solution`) has no symmetry: its stick set is
    :attr:`stick_zone` ``(c1, c2)``, and ``c``, ``slip_width``, :meth:`edge_intensity` and
    :meth:`slip` raise :class:`InvalidArgumentError`.

    Attributes:
        c: the stick half-width c (0 <= c < 1).
        slip_width: 1 - c with full relative accuracy (never computed as 1 - c).
        method: the method that produced the solution (never ``Method.AUTO``).
        error_estimate: the estimated |c - c_exact| against the exact coupled problem
            (``inf`` where the model-error table gives no bound for an approximation).
        traction_error_estimate: the estimated int (|p - p_exact| + |q - q_exact|) dx over
            the punch, in units of the load (``inf`` where an approximation has no bound).
    """

    def __init__(self, handle: Any) -> None:
        """Wraps an owned ``orthoslip_solution *``; use :meth:`Contact.solve` instead."""
        self._handle = handle
        self.method = Method(get("orthoslip_method", lib.orthoslip_solution_method, handle))
        self.error_estimate: float = get("double", lib.orthoslip_solution_error_estimate, handle)
        self.traction_error_estimate: float = get(
            "double", lib.orthoslip_solution_traction_error_estimate, handle
        )

    @property
    def c(self) -> float:
        """The stick half-width c (0 <= c < 1).

        Raises:
            InvalidArgumentError: a load-path state (no single c: see :attr:`stick_zone`).
        """
        return float(get("double", lib.orthoslip_solution_stick_half_width, self._handle))

    @property
    def slip_width(self) -> float:
        """1 - c with full relative accuracy (never computed as 1 - c).

        Raises:
            InvalidArgumentError: a load-path state (no single c).
        """
        return float(get("double", lib.orthoslip_solution_slip_width, self._handle))

    @property
    def stick_zone(self) -> tuple[float, float]:
        """The stick set (c1, c2): (-c, c), or a load-path state's own (NaN when nothing
        sticks); its ends' error estimate is :attr:`error_estimate`."""
        out = ffi.new("double[2]")
        check(lib.orthoslip_solution_stick_zone(self._handle, out, out + 1))
        return out[0], out[1]

    def _evaluate(self, function: Any, inputs: list[npt.ArrayLike], outputs: int) -> list[Any]:
        """Calls ``function(handle, in_0, ..., n, out_0, ...)`` of the C ABI over the inputs
        broadcast against each other; returns the outputs in their shape (NumPy scalars for
        scalar inputs)."""
        arrays = np.broadcast_arrays(*(np.asarray(v, dtype=np.float64) for v in inputs))
        shape = arrays[0].shape
        flat = [np.ascontiguousarray(a.ravel()) for a in arrays]
        out = [np.empty(flat[0].size) for _ in range(outputs)]
        if flat[0].size:
            buffers = [ffi.from_buffer("double[]", a) for a in flat]
            results = [ffi.from_buffer("double[]", a) for a in out]
            check(function(self._handle, *buffers, flat[0].size, *results))
        return [a.reshape(shape)[()] for a in out]

    def tractions(self, x: npt.ArrayLike) -> tuple[Any, Any]:
        """The tractions (p(x), q(x)) per P/a at ``x`` (any shape; units of a):
        sigma_yy(x, 0) = -(P/a) p(x/a) and sigma_xy(x, 0) = (P/a) q(x/a) (paper eq. (6)).

        p integrates to 1 and q is odd, positive for x > c. Outside the punch p = q = 0;
        at x = +-1, p = inf (the edge singularity). Returns two float64 arrays of the shape
        of ``x`` (NumPy scalars for a scalar ``x``).

        Raises:
            InvalidArgumentError: some x is NaN or infinite.
        """
        p, q = self._evaluate(lib.orthoslip_solution_tractions, [x], 2)
        return p, q

    def stresses(self, x: npt.ArrayLike, y: npt.ArrayLike) -> tuple[Any, Any, Any]:
        """The stresses (sxx, syy, sxy) per P/a inside the solid at the points (x, y) in
        units of a (``x`` and ``y`` broadcast against each other). The solid is y < 0;
        y = 0 gives the surface values as limits from inside (syy = -p, sxy = q on the
        punch), and so do depths below 1e-150. Tension is positive. Each method's stresses
        are those of its own tractions. At the punch edges on the surface (|x| = 1, y = 0
        or a depth below 1e-150) sxx = syy = -inf.

        Raises:
            InvalidArgumentError: some x or y is NaN or infinite, or some y > 0.
        """
        sxx, syy, sxy = self._evaluate(lib.orthoslip_solution_stresses, [x, y], 3)
        return sxx, syy, sxy

    def edge_intensity(self) -> tuple[float, float]:
        """(k, g) of the punch-edge singularity p ~ k (1 - |x|)^(-g) (k per P/a); on a slip
        edge q ~ mu p sgn x. g = 1/2 - arctan(bp mu)/pi (GOODMAN: 1/2). The surface stress
        there, sxx(x, 0) ~ -k (delta^2 + (1 - nu) mu^2) (1 - |x|)^(-g), has the same exponent."""
        k = ffi.new("double *")
        g = ffi.new("double *")
        check(lib.orthoslip_solution_edge_intensity(self._handle, k, g))
        return k[0], g[0]

    def slip(self, x: npt.ArrayLike) -> Any:
        """The tangential surface displacement of the solid relative to the punch at ``x``
        (units of a), per P/E (E: ``Material.effective().e``; P: the normal force per unit
        thickness): 0 on the stick zone, the slip on the slip zones (negative for x > c: the
        solid slides inward), odd in x.

        Raises:
            InvalidArgumentError: some x is NaN or infinite.
        """
        (u,) = self._evaluate(lib.orthoslip_solution_slip, [x], 1)
        return u

    def plot(self, ax: Axes | None = None, points: int = 801) -> Axes:
        """Plots p and q across the punch, with the stick zone shaded, on ``ax`` (a new
        figure if None) and returns the axes. Needs matplotlib
        (``pip install "orthoslip[plot]"``)."""
        try:
            import matplotlib.pyplot as plt
        except ImportError as e:
            raise ImportError(
                "Solution.plot needs matplotlib: pip install matplotlib "
                '(or pip install "orthoslip[plot]")'
            ) from e
        if ax is None:
            _, ax = plt.subplots()
        x = np.linspace(-1.0, 1.0, points + 2)[1:-1]
        p, q = self.tractions(x)
        ax.axvspan(-self.c, self.c, color="0.9", label=f"stick zone, c = {self.c:.4g}")
        ax.plot(x, p, label="p (pressure)")
        ax.plot(x, q, label="q (shear)")
        ax.set_xlabel("x / a")
        ax.set_ylabel("traction per P/a")
        ax.set_title(f"{self.method.name} (c error estimate {self.error_estimate:.1e})")
        ax.legend()
        return ax

    def __repr__(self) -> str:
        return (
            f"<Solution c={self.c!r} slip_width={self.slip_width!r} "
            f"method={self.method.name} error_estimate={self.error_estimate!r}>"
        )
