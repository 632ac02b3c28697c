#!/usr/bin/env python3
"""Independent references for the OpenSees corpus of tests/opensees/, and
the comparison of poundfe's recorder files with them.

    reference.py OUTPUT_DIR SCRIPT_NAME

Each model is built here again from its numbers (numpy), and integrated with
the discrete equations OpenSees 3.8 solves: Newmark's average acceleration
with OpenSees's initial acceleration of zero, its Newton iteration and
convergence test, LoadControl's load factors, and the uniaxial laws as
OpenSees's sources define them (ElasticPPGap, ImpactMaterial, Steel01,
ViscousDamper's Dormand-Prince sub-steps, Series's incremental iteration). The
linear models (sdof_linear, stick3_linear, portal_frame) must agree to
1e-10 of their peak (round-off of a few thousand steps of the recursion),
the nonlinear ones (pounding_sticks, steel01_cyclic) to 1e-6 of their peak
(both codes stop Newton at the same test; the difference is that of two
converged iterates). Exit 1 naming the file and the largest difference."""
import math
import sys

import numpy as np

PI = 3.14159265358979


def synthetic_record(dt, n, scale=1.0):
    t = np.arange(n + 1) * dt
    return scale * (3.0 * np.sin(2 * PI * 1.3 * t) * np.exp(-0.3 * t)
                    + 1.5 * np.sin(2 * PI * 4.1 * t) * np.exp(-0.5 * t))


def path_factor(values, dt, time, factor=1.0):
    """OpenSees PathSeries::getFactor."""
    if time < 0:
        return 0.0
    position = time / dt
    i = math.floor(position)
    if i + 1 >= len(values):
        return 0.0
    return factor * (values[i] + (values[i + 1] - values[i]) * (position - i))


def newmark_linear(M, C, K, r, ground, dt, n, u0=None, gamma=0.5, beta=0.25):
    """u, a at steps 1..n of M a + C v + K u = K u0 - M r ag (u(0) = u0)."""
    size = len(M)
    u = np.zeros(size) if u0 is None else u0.copy()
    static = K @ u
    v, a = np.zeros(size), np.zeros(size)
    keff = K + gamma / (beta * dt) * C + M / (beta * dt * dt)
    us, accs, t = [], [], 0.0
    for i in range(1, n + 1):
        t += dt  # accumulated, as OpenSees's domain time
        ag = ground(t)
        rhs = static - M @ r * ag \
            + M @ (u / (beta * dt * dt) + v / (beta * dt) + (0.5 / beta - 1) * a) \
            + C @ (gamma / (beta * dt) * u - (1 - gamma / beta) * v
                   - dt * (1 - 0.5 * gamma / beta) * a)
        un = np.linalg.solve(keff, rhs)
        an = (un - u) / (beta * dt * dt) - v / (beta * dt) - (0.5 / beta - 1) * a
        v = v + dt * ((1 - gamma) * a + gamma * an)
        u, a = un, an
        us.append(u.copy())
        accs.append(a.copy())
    return np.array(us), np.array(accs)


def sdof_linear():
    dt, n = 0.01, 1000
    ag = synthetic_record(dt, n)
    M, K = np.array([[2.0]]), np.array([[800.0]])
    C = 0.05 * 20.0 * M + 0.05 / 20.0 * K
    u, a = newmark_linear(M, C, K, np.ones(1), lambda t: path_factor(ag, dt, t), dt, n)
    t = dt * np.arange(1, n + 1)
    return {"sdof_disp.out": np.column_stack([t, u]),
            "sdof_accel.out": np.column_stack([t, a])}


def stick3_linear():
    m = np.array([1.0e5, 1.0e5, 0.8e5])
    k = np.array([2.0e8, 1.8e8, 1.5e8])
    M = np.diag(m)
    K = np.zeros((3, 3))
    for i in range(3):
        K[i, i] += k[i]
        if i > 0:
            K[i - 1, i - 1] += k[i]
            K[i - 1, i] -= k[i]
            K[i, i - 1] -= k[i]
    lam = np.sort(np.linalg.eigvals(np.linalg.solve(M, K)).real)
    w1, w3 = math.sqrt(lam[0]), math.sqrt(lam[2])
    C = 2 * 0.05 * w1 * w3 / (w1 + w3) * M + 2 * 0.05 / (w1 + w3) * K
    dt, n = 0.005, 1600
    ag = [float(f"{x:.17g}") for x in synthetic_record(dt, n, 0.1)]
    u, _ = newmark_linear(M, C, K, np.ones(3), lambda t: path_factor(ag, dt, t, 9.81), dt, n)
    t = dt * np.arange(1, n + 1)
    return {"stick3_disp.out": np.column_stack([t, u]),
            "stick3_base.out": np.column_stack([t, -k[0] * u[:, 0]]),
            "stick3_eigen.out": np.array([lam])}


def frame_stiffness(nodes, members, n_dofs):
    """Global stiffness of 2D Euler-Bernoulli members (3 DOFs a node)."""
    K = np.zeros((n_dofs, n_dofs))
    for i, j, A, E, I in members:
        (xi, yi), (xj, yj) = nodes[i], nodes[j]
        L = math.hypot(xj - xi, yj - yi)
        c, s = (xj - xi) / L, (yj - yi) / L
        a, b, d, e = E * A / L, 12 * E * I / L**3, 6 * E * I / L**2, E * I / L
        k = np.array([[a, 0, 0, -a, 0, 0], [0, b, d, 0, -b, d], [0, d, 4 * e, 0, -d, 2 * e],
                      [-a, 0, 0, a, 0, 0], [0, -b, -d, 0, b, -d], [0, d, 2 * e, 0, -d, 4 * e]])
        R = np.zeros((6, 6))
        for n in range(2):
            R[3 * n:3 * n + 3, 3 * n:3 * n + 3] = [[c, s, 0], [-s, c, 0], [0, 0, 1]]
        dofs = [3 * i, 3 * i + 1, 3 * i + 2, 3 * j, 3 * j + 1, 3 * j + 2]
        K[np.ix_(dofs, dofs)] += R.T @ k @ R
    return K


def portal_frame():
    nodes = [(0.0, 0.0), (6.0, 0.0), (0.0, 3.0), (6.0, 3.0)]
    E = 2.0e11
    members = [(0, 2, 0.01, E, 2.0e-4), (1, 3, 0.01, E, 2.0e-4), (2, 3, 0.012, E, 4.0e-4)]
    Kfull = frame_stiffness(nodes, members, 12)
    free = list(range(6, 12))
    K = Kfull[np.ix_(free, free)]
    M = np.diag([2.0e4, 2.0e4, 0.0, 2.0e4, 2.0e4, 0.0])
    P = np.array([0.0, -1.962e5, 0.0, 0.0, -1.962e5, 0.0])
    lam, rows_d, rows_r = 0.0, [], []

    def rows(t, u):
        full = np.zeros(12)
        full[6:] = u
        rows_d.append([t] + list(u))
        rows_r.append([t] + list((Kfull @ full)[:6]))
    for _ in range(10):
        lam += 0.1
        rows(lam, np.linalg.solve(K, lam * P))
    u0 = np.linalg.solve(K, lam * P)
    mu = np.sort(np.linalg.eigvals(np.linalg.solve(K, M)).real)[::-1]
    w = np.sqrt(1 / mu[:2])
    C = 2 * 0.02 * w[0] * w[1] / (w[0] + w[1]) * M + 2 * 0.02 / (w[0] + w[1]) * K
    dt, n = 0.01, 800
    ag = synthetic_record(dt, n)
    r = np.array([1.0, 0, 0, 1.0, 0, 0])
    u, _ = newmark_linear(M, C, K, r, lambda t: path_factor(ag, dt, t), dt, n, u0)
    for i in range(n):
        rows((i + 1) * dt, u[i])
    return {"portal_disp.out": np.array(rows_d), "portal_base.out": np.array(rows_r),
            "portal_eigen.out": np.array([1 / mu[:2]])}


def eppgap(E, fy, gap, eta, damage):
    """OpenSees EPPGapMaterial: respond(state, strain) -> (stress, tangent, state')."""
    def respond(state, strain):
        lo, hi = state
        sign = 1 if fy >= 0 else -1
        if sign * strain > sign * hi:
            stress, tangent = fy + (strain - gap - fy / E) * eta * E, eta * E
        elif sign * strain < sign * lo:
            stress, tangent = 0.0, 0.0
        else:
            stress, tangent = E * (strain - lo), E
        if sign * strain > sign * hi:
            lo, hi = strain - stress / E, strain
        elif sign * strain < sign * lo and sign * strain > sign * gap and not damage:
            lo, hi = strain, (strain - eta * gap) / (1 - eta) + fy / E
        return stress, tangent, (lo, hi)
    return respond, (gap, fy / E + gap)


def impact(K1, K2, dy, gap):
    """OpenSees ImpactMaterial (state: committed strain, stress, tangent)."""
    def respond(state, strain):
        cs, cf, ct = state
        d = strain - cs
        f, t = cf, ct
        if strain >= gap:
            f, t = 0.0, 0.0
        elif d < 0:
            f, t = cf + K1 * d, K1
            line = K1 * dy + K2 * (strain - gap - dy)
            if f < line:
                f, t = line, K2
        elif d > 0:
            f, t = cf + K1 * d, K1
            if f > K2 * (strain - gap):
                f, t = K2 * (strain - gap), K2
        return f, t, (strain, f, t)
    return respond, (0.0, 0.0, K1)


def steel01(fy, E0, b):
    """OpenSees Steel01 without isotropic hardening (a1 = a3 = 0)."""
    def respond(state, strain):
        cs, cf, ct = state
        d = strain - cs
        if abs(d) <= sys.float_info.epsilon:
            return cf, ct, state
        c1, c = b * E0 * strain, cf + E0 * d
        f = c1 + fy * (1 - b) if c1 + fy * (1 - b) < c else c
        if c1 - fy * (1 - b) > f:
            f = c1 - fy * (1 - b)
        t = E0 if abs(f - c) < sys.float_info.epsilon else b * E0
        return f, t, (strain, f, t)
    return respond, (0.0, 0.0, E0)


class CommittedLaw:
    """A law whose trial is a function of its committed state and strain."""
    def __init__(self, respond, state):
        self.respond, self.state, self.trial_state = respond, state, state

    def trial(self, strain, rate):
        stress, tangent, self.trial_state = self.respond(self.state, strain)
        return stress, tangent

    def commit(self):
        self.state = self.trial_state


class ViscousDamper:
    """OpenSees ViscousDamper with NM = 1 (Dormand-Prince), RelTol 1e-6,
    AbsTol 1e-10, MaxHalf 15, no LGap: dF/dt = K (v - sign(F) (|F|/C)^(1/alpha))
    over the step dt, v linear from the committed rate to the trial one;
    tangent 0."""
    def __init__(self, K, C, alpha, dt):
        self.K, self.C, self.alpha, self.dt = K, C, alpha, dt
        self.state = self.trial_state = (0.0, 0.0)  # force, rate

    def f(self, v, F):
        return (v - (-1.0 if F < 0 else 1.0) * (abs(F) / self.C) ** (1.0 / self.alpha)) * self.K

    def dormand_prince(self, v0, v1, y0, h):
        f, dv = self.f, v1 - v0
        k1 = f(v0, y0) * h
        k2 = f(dv * (1 / 5) + v0, y0 + (1 / 5) * k1) * h
        k3 = f(dv * (3 / 10) + v0, y0 + (3 / 40) * k1 + (9 / 40) * k2) * h
        k4 = f(dv * (4 / 5) + v0, y0 + (44 / 45) * k1 + (-56 / 15) * k2 + (32 / 9) * k3) * h
        k5 = f(dv * (8 / 9) + v0, y0 + (19372 / 6561) * k1 + (-25360 / 2187) * k2
               + (64448 / 6561) * k3 + (-212 / 729) * k4) * h
        k6 = f(dv + v0, y0 + (9017 / 3168) * k1 + (-355 / 33) * k2 + (46732 / 5247) * k3
               + (49 / 176) * k4 + (-5103 / 18656) * k5) * h
        y = y0 + (35 / 384) * k1 + (500 / 1113) * k3 + (125 / 192) * k4 \
            + (-2187 / 6784) * k5 + (11 / 84) * k6
        k7 = f(dv + v0, y) * h
        error = (71 / 57600) * k1 + (-71 / 16695) * k3 + (71 / 1920) * k4 \
            + (-17253 / 339200) * k5 + (22 / 525) * k6 + (-1 / 40) * k7
        return y, error, abs(error / y) if y != 0 else math.inf

    def trial(self, strain, rate):
        force, rate0 = self.state
        acc = 0.0 if rate == 0 else (rate - rate0) / self.dt
        s, done, v0, y0, smallest = 1.0, 0.0, rate0, force, 0.5 ** 15
        while done != 1.0:
            v1 = v0 + acc * s * self.dt
            y, error, relative = self.dormand_prince(v0, v1, y0, s * self.dt)
            if relative <= 1e-6 or s == smallest or abs(error) <= 1e-10:
                v0, y0, done = v1, y, done + s
            else:
                s = 0.5 * s if s > smallest else smallest
        self.trial_state = (y0, 0.0 if rate == 0 else rate)
        return y0, 0.0

    def commit(self):
        self.state = self.trial_state


class Series:
    """OpenSees SeriesMaterial of two laws (maxIter 1, tol 1e-10): from the
    last trial, not the committed state."""
    def __init__(self, laws, initial_tangent, max_iterations=1, tolerance=1e-10):
        self.laws, self.max_iterations, self.tolerance = laws, max_iterations, tolerance
        self.strain, self.stress, self.tangent = 0.0, 0.0, initial_tangent
        self.strains, self.stresses = [0.0] * len(laws), [0.0] * len(laws)
        self.compliances = [0.0] * len(laws)

    @staticmethod
    def inverse(x):
        return 1.0 / x if abs(x) > 1e-12 else (-1e12 if x < 0 else 1e12)

    def trial(self, strain, rate):
        dv = strain - self.strain
        if abs(dv) < sys.float_info.epsilon:
            return self.stress, self.tangent
        self.strain = strain
        dq = self.tangent * dv
        self.stress += dq
        for _ in range(self.max_iterations):
            compliance, total = 0.0, 0.0
            for i, law in enumerate(self.laws):
                self.strains[i] += self.compliances[i] * (self.stress - self.stresses[i])
                self.stresses[i], tangent = law.trial(self.strains[i], 0.0)
                self.compliances[i] = self.inverse(tangent)
                compliance += self.compliances[i]
                total += self.strains[i] + self.compliances[i] * (self.stress - self.stresses[i])
            self.tangent = self.inverse(compliance)
            dv = self.strain - total
            dq = self.tangent * dv
            if abs(dq * dv) < self.tolerance:
                break
        self.stress += dq
        return self.stress, self.tangent

    def commit(self):
        for law in self.laws:
            law.commit()


def gap_law(law, dt):
    if law == "ElasticPPGap":
        return CommittedLaw(*eppgap(2.0e9, -4.0e6, -0.01, 0.1, True))
    if law == "ImpactMaterial":
        return CommittedLaw(*impact(2.0e9, 6.0e8, -0.002, -0.01))
    if law == "ViscousDamper":
        return ViscousDamper(1.0e8, 2.0e6, 0.5, dt)
    spring = CommittedLaw(lambda state, strain: (1.0e8 * strain, 1.0e8, state), None)
    return Series([CommittedLaw(*steel01(2.0e5, 5.0e7, 0.05)), spring],
                  5.0e7 * 1.0e8 / (5.0e7 + 1.0e8))


def pounding_sticks(law, algorithm="Newton", test="NormDispIncr"):
    m = 1.0e5
    k = np.array([m * (2 * PI / 0.5) ** 2, m * (2 * PI / 1.0) ** 2])
    c = 0.05 * 2 * np.sqrt(k * m)
    dt, n, gamma, beta = 0.002, 4000, 0.5, 0.25
    gap = gap_law(law, dt)
    ag = synthetic_record(dt, n, 0.6)
    t_gap = np.array([-1.0, 1.0])
    u, v, a = np.zeros(2), np.zeros(2), np.zeros(2)
    rows, rows_v = [], []
    tolerance = 1e-14 if test == "EnergyIncr" else 1e-10

    def forces(u, v):
        s, tangent = gap.trial(t_gap @ u, t_gap @ v)
        return k * u + c * v + s * t_gap, np.diag(k) + tangent * np.outer(t_gap, t_gap)
    time = 0.0
    for i in range(1, n + 1):
        time += dt
        g = path_factor(ag, dt, time)
        vn = (1 - gamma / beta) * v + dt * (1 - 0.5 * gamma / beta) * a
        a = (1 - 0.5 / beta) * a - v / (beta * dt)
        v = vn
        f, kt = forces(u, v)
        keff = kt + gamma / (beta * dt) * np.diag(c) + m / (beta * dt * dt) * np.eye(2)
        for iteration in range(50):
            if algorithm == "Newton":
                keff = kt + gamma / (beta * dt) * np.diag(c) + m / (beta * dt * dt) * np.eye(2)
            dx = np.linalg.solve(keff, -m * (a + g) - f)
            u, v, a = u + dx, v + gamma / (beta * dt) * dx, a + dx / (beta * dt * dt)
            f, kt = forces(u, v)
            norm = (0.5 * abs(dx @ (-m * (a + g) - f)) if test == "EnergyIncr"
                    else np.linalg.norm(dx))
            if norm <= tolerance:
                break
        else:
            sys.exit(f"reference: pounding {law} did not converge at step {i}")
        gap.commit()
        rows.append([time, u[0], u[1]])
        rows_v.append([time, v[0], v[1]])
    return {f"pounding_{law}.out": np.array(rows), f"pounding_{law}_vel.out": np.array(rows_v)}


def steel01_cyclic():
    respond, state = steel01(100.0, 1000.0, 0.05)
    protocol = [0.0]
    for amplitude in [50, 90, 110, 130, 150, 150, 170]:
        protocol += [amplitude, -amplitude]
    protocol.append(0.0)
    lam, u, rows_u, rows_f = 0.0, 0.0, [], []
    for _ in range(50 * (len(protocol) - 1)):
        lam += 0.02
        load = path_factor(protocol, 1.0, lam)
        s, t, trial = respond(state, u)
        for iteration in range(25):
            du = (load - s) / t
            u += du
            s, t, trial = respond(state, u)
            if abs(load - s) <= 1e-10:
                break
        else:
            sys.exit(f"reference: steel01 did not converge at lambda {lam}")
        state = trial
        rows_u.append([lam, u])
        rows_f.append([lam, -s])
    return {"steel01_disp.out": np.array(rows_u), "steel01_force.out": np.array(rows_f)}


MODELS = {
    "sdof_linear": (sdof_linear, 1e-10),
    "stick3_linear": (stick3_linear, 1e-10),
    "portal_frame": (portal_frame, 1e-10),
    "pounding_ElasticPPGap": (lambda: pounding_sticks("ElasticPPGap"), 1e-6),
    "pounding_ImpactMaterial": (lambda: pounding_sticks("ImpactMaterial"), 1e-6),
    "steel01_cyclic": (steel01_cyclic, 1e-6),
    "pounding_ViscousDamper": (lambda: pounding_sticks("ViscousDamper"), 1e-6),
    "pounding_Series": (lambda: pounding_sticks("Series"), 1e-6),
    "pounding_ImpactMaterial_ModifiedNewton_EnergyIncr":
        (lambda: pounding_sticks("ImpactMaterial", "ModifiedNewton", "EnergyIncr"), 1e-6),
}


def main():
    directory, name = sys.argv[1], sys.argv[2]
    build, tolerance = MODELS[name]
    failed = False
    for file, expected in build().items():
        got = np.loadtxt(f"{directory}/{file}", ndmin=2)
        if got.shape != expected.shape:
            print(f"FAIL {file}: {got.shape} values, the reference has {expected.shape}")
            failed = True
            continue
        worst = 0.0
        for j in range(expected.shape[1]):
            scale = max(np.max(np.abs(expected[:, j])), 1e-300)
            worst = max(worst, np.max(np.abs(got[:, j] - expected[:, j])) / scale)
        ok = worst <= tolerance
        failed = failed or not ok
        print(f"{'ok  ' if ok else 'FAIL'} {file}: largest difference {worst:.2e} of the peak"
              f" (tolerance {tolerance:g})")
    sys.exit(1 if failed else 0)


def portal_pdelta():
    """The P-Delta portal (portal_pdelta.tcl): OpenSees's PDeltaCrdTransf2d
    on columns (local transverse forces +-N (v_i - v_j)/L, geometric
    stiffness N/L), Newton on the whole history."""
    nodes = [(0.0, 0.0), (6.0, 0.0), (0.0, 3.0), (6.0, 3.0)]
    members = [(0, 2, 0.01, 2.0e11, 2.0e-4, True), (1, 3, 0.01, 2.0e11, 2.0e-4, True),
               (2, 3, 0.012, 2.0e11, 4.0e-4, False)]
    free = list(range(6, 12))
    K0 = frame_stiffness(nodes, [m[:5] for m in members], 12)[np.ix_(free, free)]

    def internal(u):
        full = np.zeros(12)
        full[6:] = u
        f, K = np.zeros(12), np.zeros((12, 12))
        for i, j, A, E, I, p_delta in members:
            (xi, yi), (xj, yj) = nodes[i], nodes[j]
            L = math.hypot(xj - xi, yj - yi)
            c, s = (xj - xi) / L, (yj - yi) / L
            R = np.zeros((6, 6))
            for n in range(2):
                R[3 * n:3 * n + 3, 3 * n:3 * n + 3] = [[c, s, 0], [-s, c, 0], [0, 0, 1]]
            dofs = [3 * i, 3 * i + 1, 3 * i + 2, 3 * j, 3 * j + 1, 3 * j + 2]
            ul = R @ full[dofs]
            kl = frame_stiffness([(0.0, 0.0), (L, 0.0)], [(0, 1, A, E, I)], 6)
            pl = kl @ ul
            if p_delta:
                N = E * A / L * (ul[3] - ul[0])
                pl[1] += N * (ul[1] - ul[4]) / L
                pl[4] -= N * (ul[1] - ul[4]) / L
                kl = kl.copy()
                kl[1, 1] += N / L
                kl[4, 4] += N / L
                kl[1, 4] -= N / L
                kl[4, 1] -= N / L
            f[dofs] += R.T @ pl
            K[np.ix_(dofs, dofs)] += R.T @ kl @ R
        return f[6:], K[np.ix_(free, free)]
    M = np.diag([2.0e4, 2.0e4, 0.0, 2.0e4, 2.0e4, 0.0])
    P = np.array([0.0, -1.962e6, 0.0, 0.0, -1.962e6, 0.0])
    u, rows, lam = np.zeros(6), [], 0.0
    for _ in range(10):
        lam += 0.1
        for iteration in range(10):
            f, K = internal(u)
            du = np.linalg.solve(K, lam * P - f)
            u = u + du
            if np.linalg.norm(du) <= 1e-12:
                break
        rows.append([lam] + list(u))
    C = 0.002 * K0
    dt, n, gamma, beta = 0.01, 600, 0.5, 0.25
    ag = synthetic_record(dt, n)
    r = np.array([1.0, 0, 0, 1.0, 0, 0])
    v, a, time, load = np.zeros(6), np.zeros(6), 0.0, lam * P
    for i in range(n):
        time += dt
        g = path_factor(ag, dt, time)
        v, a = (1 - gamma / beta) * v + dt * (1 - 0.5 * gamma / beta) * a, \
            (1 - 0.5 / beta) * a - v / (beta * dt)
        for iteration in range(10):
            f, K = internal(u)
            keff = K + gamma / (beta * dt) * C + M / (beta * dt * dt)
            du = np.linalg.solve(keff, load - f - C @ v - M @ (a + r * g))
            u, v, a = u + du, v + gamma / (beta * dt) * du, a + du / (beta * dt * dt)
            if np.linalg.norm(du) <= 1e-12:
                break
        else:
            sys.exit(f"reference: portal_pdelta did not converge at {time}")
        rows.append([time] + list(u))
    return {"pdelta_disp.out": np.array(rows)}


MODELS["portal_pdelta"] = (portal_pdelta, 1e-6)


def newmark_history(M, C, K, load, dt, n, gamma, beta):
    """u, v at steps 1..n of M a + C v + K u = load(t), at rest at 0."""
    size = len(M)
    u, v, a, t, us, vs = np.zeros(size), np.zeros(size), np.zeros(size), 0.0, [], []
    keff = K + gamma / (beta * dt) * C + M / (beta * dt * dt)
    for _ in range(n):
        t += dt
        rhs = load(t) + M @ (u / (beta * dt * dt) + v / (beta * dt) + (0.5 / beta - 1) * a) \
            + C @ (gamma / (beta * dt) * u - (1 - gamma / beta) * v
                   - dt * (1 - 0.5 * gamma / beta) * a)
        un = np.linalg.solve(keff, rhs)
        an = (un - u) / (beta * dt * dt) - v / (beta * dt) - (0.5 / beta - 1) * a
        v = v + dt * ((1 - gamma) * a + gamma * an)
        u, a = un, an
        us.append((t, u.copy()))
        vs.append((t, v.copy()))
    return us, vs


def cantilever_trig():
    nodes = [(0.0, 0.0), (0.0, 2.0), (0.0, 4.0)]
    members = [(0, 1, 0.02, 2.0e11, 1.0e-4), (1, 2, 0.02, 2.0e11, 1.0e-4)]
    free = list(range(3, 9))
    K = frame_stiffness(nodes, members, 9)[np.ix_(free, free)]
    # lumped: 150 kg/m x 2 m / 2 at each end of each member, plus the tip's 500 kg
    M = np.diag([300.0, 300.0, 0.0, 150.0 + 500.0, 150.0 + 500.0, 0.0])
    C = 0.0015 * K

    def load(t):
        if t < 0.1 or t > 1.5:
            return np.zeros(6)
        phi = 0.3 - 0.25 / (2 * math.pi) * math.asin(0.0)
        return np.array([0, 0, 0, 2.0e4 * math.sin(2 * math.pi * (t - 0.1) / 0.25 + phi), 0, 0])
    us, vs = newmark_history(M, C, K, load, 0.005, 400, 0.6, 0.3025)
    return {"cantilever_disp.out": np.array([[t, u[0], u[2], u[3], u[5]] for t, u in us]),
            "cantilever_vel.out": np.array([[t, v[3]] for t, v in vs])}


MODELS["cantilever_trig"] = (cantilever_trig, 1e-10)


if __name__ == "__main__":
    main()
