"""Every failure of the library becomes an exception carrying its status, the status's name
and the library's message; statuses this package does not know are handled by name."""

from __future__ import annotations

import numpy as np
import pytest

import orthoslip
from orthoslip import Contact, Material, _ffi


def test_exceptions_carry_status_name_and_message(ply: Material) -> None:
    with pytest.raises(orthoslip.InvalidArgumentError) as raised:
        Contact(ply, -1.0)
    e = raised.value
    assert isinstance(e, orthoslip.OrthoslipError) and isinstance(e, ValueError)
    assert e.status == 2 and e.status_name == "ORTHOSLIP_ERROR_INVALID_ARGUMENT"
    assert e.message.startswith("orthoslip_contact_set_friction: ")
    assert "mu = -1" in e.message
    assert str(e) == f"{e.status_name}: {e.message}"


@pytest.mark.parametrize(
    "make, error, words",
    [
        (lambda: Material.plane_stress(1.0, 1.0, 1.0, 1.5), orthoslip.InadmissibleMaterialError,
         "nu12^2 < E11/E22"),
        (lambda: Material.effective(1.0, 0.3, 1.0, -0.5), orthoslip.InadmissibleMaterialError,
         "kappa"),
        (lambda: Material.plane_strain(1, 1, 1, 1, 0.6, 0.6, 0.6),
         orthoslip.InadmissibleMaterialError, "must be > 0"),
        (lambda: Material.plane_stress(float("nan"), 1.0, 1.0, 0.3),
         orthoslip.InvalidArgumentError, "E11 = NaN"),
        (lambda: Contact(Material.effective(1, 0.3, 1, 1), 0.3, tol=0.0),
         orthoslip.InvalidArgumentError, "tolerance"),
        (lambda: Contact(Material.effective(1, 0.3, 1, 1), 0.3, traction_tol=float("nan")),
         orthoslip.InvalidArgumentError, "traction tolerance NaN"),
        (lambda: Contact(Material.effective(1, 0.3, 1, 1), 0.3, traction_tol=-1e-6),
         orthoslip.InvalidArgumentError, "must be > 0"),
        (lambda: Contact(Material.effective(1, 0.3, 1, 1), float("inf")),
         orthoslip.InvalidArgumentError, "mu = inf"),
        (lambda: Contact(Material.effective(1, 0.3, 1, 1), 0.3, method=99),
         orthoslip.InvalidArgumentError, "method = 99"),
        (lambda: Contact(Material.effective(1, 0.3, 1, 1), 0.3, "coupled", 1e-15).solve(),
         orthoslip.ToleranceNotMetError, "error estimate"),
        (lambda: Contact(Material.effective(1, 0.9, 1, 1), 1.2, "coupled", 1e-12).solve(),
         orthoslip.NoConvergenceError, "too thin for the panels"),
    ],
)
def test_each_failure_raises_its_exception(make, error, words: str) -> None:
    with pytest.raises(error) as raised:
        make()
    assert words in raised.value.message


def test_bad_points_raise(ply: Material) -> None:
    s = Contact(ply, 0.3).solve()
    with pytest.raises(orthoslip.InvalidArgumentError, match="x\\[1\\] = NaN"):
        s.tractions([0.1, np.nan])
    with pytest.raises(orthoslip.InvalidArgumentError):
        s.tractions(np.inf)
    with pytest.raises(ValueError):
        s.tractions(["a"])


def test_every_status_the_library_names_becomes_its_exception() -> None:
    known = {}
    for status in range(1, 256):
        name = _ffi.status_name(status)
        if name == "ORTHOSLIP_STATUS_UNKNOWN":
            continue
        known[name] = status
        with pytest.raises(orthoslip.OrthoslipError) as raised:
            _ffi.check(status)
        assert raised.value.status == status and raised.value.status_name == name
        assert type(raised.value) is _ffi._EXCEPTIONS.get(name, orthoslip.OrthoslipError)
    # Every status the library names has its own class, and no class a status it lacks.
    assert set(_ffi._EXCEPTIONS) == set(known)
    assert _ffi.status_name(0) == "ORTHOSLIP_OK"
    _ffi.check(0)


def test_statuses_keep_their_numbers_names_and_classes() -> None:
    # The C ABI is append-only: listed by hand, not read from the library.
    expected = [
        ("ORTHOSLIP_ERROR_NULL_POINTER", orthoslip.NullPointerError),
        ("ORTHOSLIP_ERROR_INVALID_ARGUMENT", orthoslip.InvalidArgumentError),
        ("ORTHOSLIP_ERROR_INADMISSIBLE_MATERIAL", orthoslip.InadmissibleMaterialError),
        ("ORTHOSLIP_ERROR_NO_CONVERGENCE", orthoslip.NoConvergenceError),
        ("ORTHOSLIP_ERROR_TOLERANCE_NOT_MET", orthoslip.ToleranceNotMetError),
        ("ORTHOSLIP_ERROR_INTERNAL", orthoslip.InternalError),
        ("ORTHOSLIP_ERROR_PANIC", orthoslip.PanicError),
        ("ORTHOSLIP_ERROR_NO_ADMISSIBLE_SOLUTION", orthoslip.NoAdmissibleSolutionError),
    ]
    for status, (name, cls) in enumerate(expected, start=1):
        assert getattr(_ffi.lib, name) == status
        assert _ffi.status_name(status) == name
        with pytest.raises(cls) as raised:
            _ffi.check(status)
        assert type(raised.value) is cls and raised.value.status == status
    assert _ffi.status_name(len(expected) + 1) == "ORTHOSLIP_STATUS_UNKNOWN"


def test_a_status_unknown_to_the_library_is_still_an_error() -> None:
    with pytest.raises(orthoslip.OrthoslipError) as raised:
        Contact(Material.effective(1, 0.3, 1, 1), -2.0)
    with pytest.raises(orthoslip.OrthoslipError) as unknown:
        _ffi.check(1000)
    assert type(unknown.value) is orthoslip.OrthoslipError
    assert unknown.value.status == 1000
    assert unknown.value.status_name == "ORTHOSLIP_STATUS_UNKNOWN"
    # The message is this thread's last one.
    assert unknown.value.message == raised.value.message
