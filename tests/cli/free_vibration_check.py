#!/usr/bin/env python3
"""Check of tests/cli/free_vibration.sh (pure Python): the floor
displacements of a run of input/three-storey-free-vibration.prm against the
closed-form damped free vibration by modal superposition.

  free_vibration_check.py RUN_DIR

The reference is written here, independently of poundfe: M = diag(m, m, m/2),
K of three storeys of stiffness k, the modes of M^-1/2 K M^-1/2 by Jacobi
rotations, modal coordinates q_i(0) = phi_i^T M u0, q_i'(0) = 0, and
q_i(t) = exp(-z w t) (q0 cos(wd t) + z w q0 / wd sin(wd t)), wd = w sqrt(1 - z^2)
(Chopra, Dynamics of Structures, 4th ed., §2.2 and §12.7).

Tolerance 1e-3 of the initial displacement: Newmark's average acceleration
rule keeps the amplitude but lengthens the period by (w dt)^2 / 12
(Chopra §5.5), 4.5e-6 for mode 1 at dt = 2e-4 s, a phase lag of 3.3e-4 rad
after 2 s; modes 2 and 3 carry 7 % of the mass and are damped out.
"""
import csv
import json
import math
import sys

M_FLOOR, K_STOREY, U0 = 1000.0, 5e6, 0.05
MASSES = [M_FLOOR, M_FLOOR, M_FLOOR / 2]
RATIOS = [0.03, 0.04, 0.05]
TOLERANCE = 1e-3 * U0


def stiffness():
    k = K_STOREY
    return [[2 * k, -k, 0.0], [-k, 2 * k, -k], [0.0, -k, k]]


def jacobi_eigen(a, sweeps=50):
    """Eigenvalues and eigenvectors (columns of v) of a symmetric matrix."""
    n = len(a)
    a = [row[:] for row in a]
    v = [[float(i == j) for j in range(n)] for i in range(n)]
    for _ in range(sweeps):
        off = sum(a[i][j] ** 2 for i in range(n) for j in range(n) if i != j)
        if off < 1e-30 * sum(a[i][i] ** 2 for i in range(n)):
            break
        for p in range(n):
            for q in range(p + 1, n):
                if a[p][q] == 0:
                    continue
                theta = 0.5 * math.atan2(2 * a[p][q], a[q][q] - a[p][p])
                c, s = math.cos(theta), math.sin(theta)
                for k in range(n):  # rotate columns p, q
                    akp, akq = a[k][p], a[k][q]
                    a[k][p], a[k][q] = c * akp - s * akq, s * akp + c * akq
                for k in range(n):  # rotate rows p, q
                    apk, aqk = a[p][k], a[q][k]
                    a[p][k], a[q][k] = c * apk - s * aqk, s * apk + c * aqk
                for k in range(n):
                    vkp, vkq = v[k][p], v[k][q]
                    v[k][p], v[k][q] = c * vkp - s * vkq, s * vkp + c * vkq
    return [a[i][i] for i in range(n)], v


def reference():
    """u(t) as a function: the sum over the modes of phi_i q_i(t)."""
    k = stiffness()
    root = [math.sqrt(m) for m in MASSES]
    scaled = [[k[i][j] / (root[i] * root[j]) for j in range(3)] for i in range(3)]
    values, vectors = jacobi_eigen(scaled)
    modes = sorted(range(3), key=lambda i: values[i])
    terms = []
    for rank, i in enumerate(modes):
        omega = math.sqrt(values[i])
        phi = [vectors[r][i] / root[r] for r in range(3)]  # mass-normalised
        q0 = sum(phi[r] * MASSES[r] * U0 for r in range(3))
        terms.append((omega, RATIOS[rank], phi, q0))

    def u(t):
        out = [0.0, 0.0, 0.0]
        for omega, zeta, phi, q0 in terms:
            wd = omega * math.sqrt(1 - zeta ** 2)
            q = math.exp(-zeta * omega * t) * (q0 * math.cos(wd * t)
                                               + zeta * omega * q0 / wd * math.sin(wd * t))
            for r in range(3):
                out[r] += phi[r] * q
        return out

    return u, [t[0] / (2 * math.pi) for t in terms]


def main():
    u, frequencies = reference()
    rows = list(csv.DictReader(open(sys.argv[1] + "/floor_displacement.csv")))
    columns = [c for c in rows[0] if c.endswith("_disp_m")]
    worst, worst_at = 0.0, None
    for row in rows:
        t = float(row["time_s"])
        exact = u(t)
        for r, column in enumerate(columns):
            error = abs(float(row[column]) - exact[r])
            if error > worst:
                worst, worst_at = error, (t, column)
    summary = json.load(open(sys.argv[1] + "/summary.json"))["buildings"][0]
    for got, want in zip(summary["modes"]["frequencies_hz"], frequencies):
        if abs(got - want) > 1e-9 * want:  # both exact eigenvalues of a 3x3 problem
            sys.exit(f"FAIL: summary frequency {got} Hz, the reference {want} Hz")
    if summary.get("modal_damping_ratios") != RATIOS:
        sys.exit(f"FAIL: summary modal_damping_ratios {summary.get('modal_damping_ratios')}")
    peak_late = max(abs(float(row[columns[2]])) for row in rows if float(row["time_s"]) > 1.5)
    print(f"reference modes {', '.join(f'{f:.4f}' for f in frequencies)} Hz; "
          f"largest difference {worst:.3e} m at t = {worst_at[0]} s ({worst_at[1]}); "
          f"roof amplitude after 1.5 s {peak_late:.3e} m")
    if worst > TOLERANCE:
        sys.exit(f"FAIL: {worst:.3e} m > {TOLERANCE:.1e} m")
    if peak_late < 1e-3:  # a run that ignored u0 (or over-damped it) is not free vibration
        sys.exit("FAIL: the roof barely moves after 1.5 s")


main()
