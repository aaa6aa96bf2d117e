#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The twenty steps of bench/derivations/twenty-steps.md, checked with SymPy (Debian's
python3-sympy), the baseline of issue 13's speed goal. Outside the test suite.

Each step is checked the way one checks a step with a computer-algebra system: the equation(s)
before are solved for one symbol each (sympy.solve), the solution is substituted into the step,
and simplify(lhs - rhs) must be 0 (for some root, where the equation before has several). The
definitions of the file (let:) are substituted first. That is the exact part of what
`impulselab check` does, without the converse, the conditions of a division, counterexamples or
the numeric second opinion.

Prints one line per step (whether it follows) and the seconds the twenty checks took, without
Python's start-up and SymPy's import (which `impulselab check` as a whole process is compared
against separately).

    /usr/bin/python3 bench/sympy_steps.py
"""
import sys
import time

import sympy as sp

m1, m2, m, I, p1, p2, F, dt, e, L = sp.symbols("m_1 m_2 m I p_1 p_2 F dt e L", real=True)
m1, m2, m, I = (sp.Symbol(s.name, positive=True) for s in (m1, m2, m, I))
dE, vvn, von, pn, u, v1, v2 = sp.symbols("DeltaE v_vn v_on p_n u v_1 v_2", real=True)
rx, ry, nx, ny, px, py, Jx, Jy = sp.symbols("r_x r_y n_x n_y p_x p_y J_x J_y", real=True)
Fdt = F * dt


def eq(lhs, rhs):
    return (sp.sympify(lhs), sp.sympify(rhs))


# Definitions (let:)
v1p = (p1 - Fdt) / m1
v2p = (-p2 + Fdt) / m2
det = rx * ny - ry * nx
nn = nx**2 + ny**2
pdotn = px * nx + py * ny
vv_n = (L - Fdt * det) / I * (-ry * nx + rx * ny) + ((px - nx * Fdt) * nx + (py - ny * Fdt) * ny) / m

E0 = eq((p1 - Fdt) ** 2 / (2 * m1) + (-p2 + Fdt) ** 2 / (2 * m2), p1**2 / (2 * m1) + p2**2 / (2 * m2))
E1 = eq((-2 * p1 * Fdt + Fdt**2) / (2 * m1) + (-2 * p2 * Fdt + Fdt**2) / (2 * m2), 0)
E2 = eq(Fdt * (1 / m1 + 1 / m2) - 2 * p1 / m1 - 2 * p2 / m2, 0)
E3 = eq(Fdt * (1 / m1 + 1 / m2), 2 * p1 / m1 + 2 * p2 / m2)
E4 = eq(Fdt, 2 * (m2 * p1 + m1 * p2) / (m1 + m2))
E5 = eq(Fdt - 2 * m2 * p1 / (m1 + m2), 2 * m1 * p2 / (m1 + m2))
I0 = eq(v1p, v2p)
I1 = eq((p1 - Fdt) / m1, (-p2 + Fdt) / m2)
I2 = eq(Fdt * (1 / m1 + 1 / m2), p1 / m1 + p2 / m2)
I3 = eq(Fdt, (m2 * p1 + m1 * p2) / (m1 + m2))
EF = eq(Fdt * (1 / m1 + 1 / m2), e * (p1 / m1 + p2 / m2))
EE = eq(dE, (p1 - Fdt) ** 2 / (2 * m1) + (p2 - Fdt) ** 2 / (2 * m2) - p1**2 / (2 * m1) - p2**2 / (2 * m2))
EE2 = eq(dE, Fdt**2 / 2 * (1 / m1 + 1 / m2) - Fdt * (p1 / m1 + p2 / m2))
EE3 = eq(dE, e * (e - 2) / 2 * (p1 / m1 + p2 / m2) ** 2 / (1 / m1 + 1 / m2))
R0 = eq(vvn, vv_n)
R1 = eq(vvn, (L - Fdt * det) / I * det + (pdotn - Fdt * nn) / m)
R2 = eq(vvn, (L - Fdt * det) / I * det + (pdotn - Fdt * nn) / m)
R3 = eq((L - Fdt * det) / I * det + (pdotn - Fdt * nn) / m, L * det / I + pdotn / m - Fdt * (det**2 / I + nn / m))
RG = eq(vvn, von)
R4 = eq(Fdt * (det**2 / I + nn / m) + von, L * det / I + pdotn / m)
C0 = eq(pn, pdotn)
C1 = eq(pn, px * nx + py * ny)
CJx = eq(Jx, -nx * Fdt)
CJy = eq(Jy, -ny * Fdt)
C3 = eq(Jx * nx + Jy * ny, -Fdt * nn)
M0 = eq(m1 * v1 + m2 * v2, (m1 + m2) * u)
M1 = eq(u, (m1 * v1 + m2 * v2) / (m1 + m2))
M2 = eq(m1 * (v1 - u), m2 * (u - v2))
M3 = eq(m1 / m2, (u - v2) / (v1 - u))

# (premises, unknowns solved for, one per premise, step): the twenty steps of the file.
STEPS = [
    ([E0], [p1], E1),
    ([E1], [p1], E2),
    ([E2], [p1], E3),
    ([E3], [p1], E4),
    ([E4], [p1], E5),
    ([I0], [p1], I1),
    ([I1], [p1], I2),
    ([I2], [p1], I3),
    ([EE], [dE], EE2),
    ([EF, EE2], [e, dE], EE3),
    ([R0], [vvn], R1),
    ([R1], [vvn], R2),
    ([R2], [vvn], R3),
    ([R0, RG], [vvn, von], R4),
    ([C0], [pn], C1),
    ([CJx, CJy], [Jx, Jy], ((-nx * Fdt, -ny * Fdt), None)),
    ([CJx, CJy], [Jx, Jy], C3),
    ([M0], [u], M1),
    ([M1], [u], M2),
    ([M2], [u], M3),
]


def follows(premises, unknowns, step):
    """Solve each premise for its unknown, substitute, simplify(lhs - rhs) == 0."""
    substitutions = [{}]
    for (lhs, rhs), unknown in zip(premises, unknowns):
        extended = []
        for sub in substitutions:
            roots = sp.solve(sp.Eq(lhs.subs(sub), rhs.subs(sub)), unknown, dict=True)
            for root in roots:
                extended.append({**sub, **root})
        substitutions = extended
    if step[1] is None:  # a vector step: both components
        components = [(sp.Symbol("J_x", real=True), step[0][0]), (sp.Symbol("J_y", real=True), step[0][1])]
        return any(all(sp.simplify((l - r).subs(sub)) == 0 for l, r in components) for sub in substitutions)
    lhs, rhs = step
    return any(sp.simplify((lhs - rhs).subs(sub)) == 0 for sub in substitutions)


def main():
    start = time.perf_counter()
    start_cpu = time.process_time()
    results = [follows(p, u_, s) for p, u_, s in STEPS]
    seconds = time.perf_counter() - start
    cpu = time.process_time() - start_cpu
    for n, ok in enumerate(results, start=1):
        print(f"step {n:2d}: {'follows' if ok else 'NOT SHOWN'}")
    print(f"sympy {sp.__version__}: {len(results)} steps in {seconds:.3f} s wall, {cpu:.3f} s cpu")
    return 0 if all(results) else 1


if __name__ == "__main__":
    sys.exit(main())
