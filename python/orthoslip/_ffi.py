"""The C ABI as this package sees it: the bundled library, its declarations, and how status
codes become exceptions.

The declarations are the C header itself. At build time maturin runs cbindgen on the
library's ``src/ffi/`` (the source of ``include/orthoslip.h``) and cffi turns the header into
``_native/ffi.py``; ``_native`` then loads the shared library bundled next to it, in cffi's
ABI mode. Every function of the C ABI is therefore declared here exactly as in the header,
and nothing else is: a function appended to the C ABI is callable as ``lib.orthoslip_<name>``
without touching this file.

Status codes map to exceptions by their names (``orthoslip_status_string``). A status this
package does not know, e.g. one appended to the C ABI later, raises :class:`OrthoslipError`
with the library's name and message; mapping it to its own class is one line in
``_EXCEPTIONS``.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from ._native import ffi as ffi, lib as lib  # re-exported: the one home of the bindings


class OrthoslipError(Exception):
    """A failed call into the library.

    Attributes:
        status: the C status code (``orthoslip_status``).
        status_name: its name, e.g. ``"ORTHOSLIP_ERROR_INVALID_ARGUMENT"``.
        message: the library's message, naming the function and the violated condition.
    """

    def __init__(self, status: int, status_name: str, message: str) -> None:
        super().__init__(f"{status_name}: {message}")
        self.status = status
        self.status_name = status_name
        self.message = message


class NullPointerError(OrthoslipError):
    """A required pointer was NULL (a bug in this package, never the caller's input)."""


class InvalidArgumentError(OrthoslipError, ValueError):
    """A number was NaN, infinite, negative or out of range, or a method value was invalid."""


class InadmissibleMaterialError(OrthoslipError, ValueError):
    """The elastic constants do not give a positive definite in-plane strain energy."""


class NoConvergenceError(OrthoslipError):
    """An iterative method stopped without converging."""


class ToleranceNotMetError(OrthoslipError):
    """The method ran, but its error estimate exceeds the requested tolerance."""


class NoAdmissibleSolutionError(OrthoslipError):
    """The solver found the stick-edge root of the assumed form, but that solution violates an
    admissibility condition (p < 0, |q| > mu p on the stick zone, or slip against the
    friction): no solution of this form exists for this input."""


class InternalError(OrthoslipError):
    """A bug in the library: an internal invariant failed (or, as :class:`PanicError`, a
    panic was caught at the C boundary)."""


class PanicError(InternalError):
    """A bug in the library: a panic caught at the C boundary."""


_EXCEPTIONS: dict[str, type[OrthoslipError]] = {
    "ORTHOSLIP_ERROR_NULL_POINTER": NullPointerError,
    "ORTHOSLIP_ERROR_INVALID_ARGUMENT": InvalidArgumentError,
    "ORTHOSLIP_ERROR_INADMISSIBLE_MATERIAL": InadmissibleMaterialError,
    "ORTHOSLIP_ERROR_NO_CONVERGENCE": NoConvergenceError,
    "ORTHOSLIP_ERROR_TOLERANCE_NOT_MET": ToleranceNotMetError,
    "ORTHOSLIP_ERROR_INTERNAL": InternalError,
    "ORTHOSLIP_ERROR_PANIC": PanicError,
    "ORTHOSLIP_ERROR_NO_ADMISSIBLE_SOLUTION": NoAdmissibleSolutionError,
}


def status_name(status: int) -> str:
    """The library's name for a status code (``"ORTHOSLIP_STATUS_UNKNOWN"`` if it has none)."""
    name: bytes = ffi.string(lib.orthoslip_status_string(status))
    return name.decode()


def last_error_message() -> str:
    """The message of the last failed call on this thread."""
    length = lib.orthoslip_last_error_message(ffi.NULL, 0)
    buf = ffi.new("char[]", length + 1)
    lib.orthoslip_last_error_message(buf, length + 1)
    message: bytes = ffi.string(buf)
    return message.decode(errors="replace")


def check(status: int) -> None:
    """Raises the exception for ``status`` unless it is ``ORTHOSLIP_OK``."""
    if status != lib.ORTHOSLIP_OK:
        name = status_name(status)
        raise _EXCEPTIONS.get(name, OrthoslipError)(status, name, last_error_message())


def new_handle(
    ctype: str, free: Callable[[Any], None], create: Callable[..., int], *args: Any
) -> Any:
    """Calls ``create(*args, out)`` for a ``ctype **out`` handle and returns the handle, freed
    by ``free`` when it is garbage collected."""
    out = ffi.new(f"{ctype} **")
    check(create(*args, out))
    return ffi.gc(out[0], free)


def get(ctype: str, getter: Callable[[Any, Any], int], handle: Any) -> Any:
    """Calls ``getter(handle, out)`` for one ``ctype *out`` value and returns the value."""
    out = ffi.new(f"{ctype} *")
    check(getter(handle, out))
    return out[0]
