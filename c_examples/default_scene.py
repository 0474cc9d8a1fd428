#!/usr/bin/env python3
"""The default scene through ctypes: a carbon/epoxy ply (plane stress) under a rigid flat
punch with mu = 0.3.

Usage: default_scene.py [path/to/liborthoslip.so]; without an argument the library is taken
from the environment variable ORTHOSLIP_LIB, else found by ctypes.util.find_library.
Every status is checked; on failure the library's message is printed and the exit code is 1.
"""
import ctypes
import ctypes.util
import os
import sys
from ctypes import POINTER, byref, c_char_p, c_double, c_int, c_size_t, c_void_p

OK = 0
METHOD_AUTO = 0
METHOD_NAMES = {0: "AUTO", 1: "GOODMAN", 2: "SPENCE", 3: "COUPLED", 4: "LCP"}
N_POINTS = 21


def load_library():
    """Loads liborthoslip from argv[1], $ORTHOSLIP_LIB or the system search path."""
    path = sys.argv[1] if len(sys.argv) > 1 else os.environ.get("ORTHOSLIP_LIB")
    if not path:
        path = ctypes.util.find_library("orthoslip")
    if not path:
        sys.exit("default_scene.py: liborthoslip not found: pass its path as the first "
                 "argument or set ORTHOSLIP_LIB")
    lib = ctypes.CDLL(path)
    handle_out = POINTER(c_void_p)
    d_out = POINTER(c_double)
    signatures = {
        # name: (restype, argtypes); enums are C ints, handles void pointers.
        "orthoslip_version": (c_char_p, []),
        "orthoslip_status_string": (c_char_p, [c_int]),
        "orthoslip_last_error_message": (c_size_t, [ctypes.c_char_p, c_size_t]),
        "orthoslip_material_new_plane_stress":
            (c_int, [c_double, c_double, c_double, c_double, handle_out]),
        "orthoslip_material_effective": (c_int, [c_void_p, d_out, d_out, d_out, d_out]),
        "orthoslip_material_green": (c_int, [c_void_p, d_out, d_out, d_out]),
        "orthoslip_material_free": (None, [c_void_p]),
        "orthoslip_contact_new": (c_int, [c_void_p, handle_out]),
        "orthoslip_contact_set_friction": (c_int, [c_void_p, c_double]),
        "orthoslip_contact_set_method": (c_int, [c_void_p, c_int]),
        "orthoslip_contact_solve": (c_int, [c_void_p, handle_out]),
        "orthoslip_contact_free": (None, [c_void_p]),
        "orthoslip_solution_stick_half_width": (c_int, [c_void_p, d_out]),
        "orthoslip_solution_slip_width": (c_int, [c_void_p, d_out]),
        "orthoslip_solution_method": (c_int, [c_void_p, POINTER(c_int)]),
        "orthoslip_solution_error_estimate": (c_int, [c_void_p, d_out]),
        "orthoslip_solution_tractions": (c_int, [c_void_p, d_out, c_size_t, d_out, d_out]),
        "orthoslip_solution_free": (None, [c_void_p]),
    }
    for name, (restype, argtypes) in signatures.items():
        fn = getattr(lib, name)
        fn.restype = restype
        fn.argtypes = argtypes
    return lib


class OrthoslipError(RuntimeError):
    """A failed call: status name and this thread's last error message."""


def check(lib, status, what):
    if status != OK:
        n = lib.orthoslip_last_error_message(None, 0)
        buf = ctypes.create_string_buffer(n + 1)
        lib.orthoslip_last_error_message(buf, n + 1)
        name = lib.orthoslip_status_string(status).decode()
        raise OrthoslipError(f"{what} failed: {name}: {buf.value.decode(errors='replace')}")


def run(lib):
    e11, e22, g12, nu12, mu = 181e9, 10.3e9, 7.17e9, 0.28, 0.3
    print(f"orthoslip {lib.orthoslip_version().decode()} (Python ctypes)")
    material, contact, solution = c_void_p(), c_void_p(), c_void_p()
    try:
        check(lib, lib.orthoslip_material_new_plane_stress(e11, e22, g12, nu12, byref(material)),
              "orthoslip_material_new_plane_stress")
        e, nu, delta, kappa = c_double(), c_double(), c_double(), c_double()
        check(lib, lib.orthoslip_material_effective(material, byref(e), byref(nu), byref(delta),
                                                    byref(kappa)),
              "orthoslip_material_effective")
        print(f"effective: E = {e.value!r}, nu = {nu.value!r}, delta = {delta.value!r}, "
              f"kappa = {kappa.value!r}")
        a, b, c_green = c_double(), c_double(), c_double()
        check(lib, lib.orthoslip_material_green(material, byref(a), byref(b), byref(c_green)),
              "orthoslip_material_green")
        print(f"green: A = {a.value!r}, B = {b.value!r}, C = {c_green.value!r}")

        check(lib, lib.orthoslip_contact_new(material, byref(contact)), "orthoslip_contact_new")
        check(lib, lib.orthoslip_contact_set_friction(contact, mu),
              "orthoslip_contact_set_friction")
        check(lib, lib.orthoslip_contact_set_method(contact, METHOD_AUTO),
              "orthoslip_contact_set_method")
        check(lib, lib.orthoslip_contact_solve(contact, byref(solution)),
              "orthoslip_contact_solve")

        c, one_minus_c, c_error, used = c_double(), c_double(), c_double(), c_int()
        check(lib, lib.orthoslip_solution_stick_half_width(solution, byref(c)),
              "orthoslip_solution_stick_half_width")
        check(lib, lib.orthoslip_solution_slip_width(solution, byref(one_minus_c)),
              "orthoslip_solution_slip_width")
        check(lib, lib.orthoslip_solution_method(solution, byref(used)),
              "orthoslip_solution_method")
        check(lib, lib.orthoslip_solution_error_estimate(solution, byref(c_error)),
              "orthoslip_solution_error_estimate")
        print(f"c = {c.value!r}")
        print(f"1 - c = {one_minus_c.value!r}")
        print(f"method = {METHOD_NAMES.get(used.value, 'unknown')}")
        print(f"error estimate = {c_error.value:.3e}")

        half = N_POINTS // 2
        x = (c_double * N_POINTS)(*[0.99 * (i - half) / half for i in range(N_POINTS)])
        p, q = (c_double * N_POINTS)(), (c_double * N_POINTS)()
        check(lib, lib.orthoslip_solution_tractions(solution, x, N_POINTS, p, q),
              "orthoslip_solution_tractions")
        print(f"{'x':>10} {'p':>24} {'q':>24}")
        for xi, pi, qi in zip(x, p, q):
            print(f"{xi:10.4f} {pi:24.17g} {qi:24.17g}")
    finally:
        lib.orthoslip_solution_free(solution)
        lib.orthoslip_contact_free(contact)
        lib.orthoslip_material_free(material)


def main():
    lib = load_library()
    try:
        run(lib)
    except OrthoslipError as err:
        print(f"default_scene.py: {err}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
