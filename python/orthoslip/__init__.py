"""orthoslip: partial-slip contact of a rigid flat-ended punch pressed into an orthotropic
elastic half-plane with Coulomb friction.

The solid sticks to the punch on ``|x| < c`` and slips on ``c < |x| < 1`` (x in units of
the punch half-width a). The package calls the orthoslip C library bundled with it::

    import numpy as np
    import orthoslip

    ply = orthoslip.Material.plane_stress(181e9, 10.3e9, 7.17e9, 0.28)  # E11, E22, G12, nu12
    solution = orthoslip.Contact(ply, mu=0.3).solve()
    solution.c, solution.slip_width, solution.method, solution.error_estimate
    p, q = solution.tractions(np.linspace(-0.99, 0.99, 199))  # per P/a

Fretting (a tangential load Q cycled between +-Q* after the normal load P)::

    cycles = orthoslip.Contact(ply, mu=0.3).solve_cycles(0.18)  # Q*/P
    cycles.state, cycles.dissipated_energy  # per cycle, in P^2/E

Every failure of the library raises an :class:`OrthoslipError` subclass carrying the status
and the library's message.
"""

from . import _ffi
from ._api import Contact, Effective, Green, Material, Method, MethodLike, Solution
from ._fretting import (
    CycleMethod,
    Cycles,
    CycleState,
    EnergyBalance,
    History,
    RuizPeaks,
    StickZones,
)
from ._ffi import (
    InadmissibleMaterialError,
    InternalError,
    InvalidArgumentError,
    NoAdmissibleSolutionError,
    NoConvergenceError,
    NullPointerError,
    OrthoslipError,
    PanicError,
    ToleranceNotMetError,
)

__version__: str = _ffi.ffi.string(_ffi.lib.orthoslip_version()).decode()
"""The version of the bundled library (and of this package)."""

__all__ = [
    "Contact",
    "Effective",
    "Green",
    "Material",
    "Method",
    "MethodLike",
    "Solution",
    "CycleMethod",
    "CycleState",
    "Cycles",
    "History",
    "EnergyBalance",
    "RuizPeaks",
    "StickZones",
    "OrthoslipError",
    "NullPointerError",
    "InvalidArgumentError",
    "InadmissibleMaterialError",
    "NoConvergenceError",
    "ToleranceNotMetError",
    "NoAdmissibleSolutionError",
    "InternalError",
    "PanicError",
]
