#!/usr/bin/env python3
"""The default scene through the Python package: a carbon/epoxy ply (plane stress) under a
rigid flat punch with mu = 0.3. Prints what c_examples/default_scene.c prints, in the same
format: the constants, c, 1 - c, the method used, its error estimate, p, q at 21 points, the
edge intensity, the stresses at (0, -0.5), the slip at x = 0.99 and the energy dissipated in
the first cycle of Q between +-0.6 mu P.

Run it after ``pip install ./python``; a failure raises orthoslip.OrthoslipError.
"""
import numpy as np

import orthoslip

e11, e22, g12, nu12, mu = 181e9, 10.3e9, 7.17e9, 0.28, 0.3
print(f"orthoslip {orthoslip.__version__} (Python)")
print(f"ply: E11 = {e11:g} Pa, E22 = {e22:g} Pa, G12 = {g12:g} Pa, nu12 = {nu12:g}, "
      f"plane stress; mu = {mu:g}")
ply = orthoslip.Material.plane_stress(e11, e22, g12, nu12)
print("effective: E = {:.17g}, nu = {:.17g}, delta = {:.17g}, kappa = {:.17g}"
      .format(*ply.constants))
print("green: A = {:.17g}, B = {:.17g}, C = {:.17g}".format(*ply.green))

solution = orthoslip.Contact(ply, mu, method="auto").solve()
print(f"c = {solution.c:.17g}")
print(f"1 - c = {solution.slip_width:.17g}")
print(f"method = {solution.method.name}")
print(f"error estimate = {solution.error_estimate:.3e}")

x = 0.99 * np.arange(-10, 11) / 10
p, q = solution.tractions(x)
print(f"{'x':>10} {'p':>24} {'q':>24}")
for row in zip(x, p, q):
    print("{:10.4f} {:24.17g} {:24.17g}".format(*row))

# what engineers compute from it: the edge singularity p ~ k (1 - |x|)^(-g), the stresses
# half a punch width below the centre, the slip at x = 0.99
k, g = solution.edge_intensity()
sxx, syy, sxy = solution.stresses(0.0, -0.5)
print(f"edge intensity: k = {k:.17g}, g = {g:.17g}")
print(f"stresses at (0, -0.5): sxx = {sxx:.17g}, syy = {syy:.17g}, sxy = {sxy:.17g}")
print(f"slip at x = 0.99: {solution.slip(0.99):.17g}")

# fretting: Q cycled between +-0.6 mu P after the normal load, on a coarse, quick grid (32
# panels per half-width, 4 load steps per quarter cycle); energies per P^2/E
cycles = orthoslip.Contact(ply, mu).solve_cycles(0.6 * mu, max_cycles=10, panels=32, steps=4)
print(f"fretting cycles = {cycles.count}")
print(f"fretting W1 = {cycles.dissipated_energy[0]:.17g}")
print(f"fretting W1 error = {cycles.dissipated_energy_error[0]:.3e}")
