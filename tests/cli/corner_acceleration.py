"""Floor accelerations at the slab corners of a 3D model (issue 22 item 8;
doc/verification.md, "Corner accelerations"):

 1. Free vibration in one mode, against the closed form. A one-storey
    torsionally coupled shear building (eccentric mass, four unequal
    resisting planes, no damping, no ground motion) starts from rest at
    u0 = A phi, phi its first mode, which the test finds itself from the
    planes' stiffness K = sum k b b^T, b = (n_x, n_y, -n_x (p_y - C_y) +
    n_y (p_x - C_x)) (Chopra, Dynamics of Structures, 4th ed., §9.5) and a
    Jacobi rotation of M^-1/2 K M^-1/2. Newmark's average acceleration rule
    keeps the mode and its amplitude and shifts its frequency to
    tan(w' dt / 2) = w dt / 2 (Hughes, The Finite Element Method, §9.3), so
    every step's corner acceleration is exactly
        a_k(t_n) = -w^2 A (phi_x - phi_t (y_k - C_y)) cos(w' t_n)   (x)
        a_k(t_n) = -w^2 A (phi_y + phi_t (x_k - C_x)) cos(w' t_n)   (y)
    for the four corners (x_k, y_k) of the slab: each recorded column must
    be one corner's closed form to 1e-9 of the peak (a linear model solved
    directly: round-off, amplified by the rounding of w'), and the summary's
    peaks must be the largest |a_k| (reached at t = 0) to 1e-12.
 2. The ground's part. The same building with its mass at the plan centre
    under a generated ground motion along x and y: the mean of the four
    corners of the rectangle is the mass centre, so it must equal the
    floor's absolute acceleration of floor_acceleration.csv (along x) at every
    step, to 1e-12 of the peak, while the corners differ (the floor twists).
 3. A 2D model's request of 'corner acceleration' is refused (exit 1,
    nothing written).

  corner_acceleration.py POUNDFE
"""
import csv
import json
import math
import os
import subprocess
import sys
import tempfile

poundfe = sys.argv[1]
work = tempfile.mkdtemp()
L_x, L_y, mass, J = 12.0, 9.0, 2e5, 4.1e6
planes = [(-6, 0, 90, 6e7), (6, 0, 90, 2e7), (0, -4.5, 0, 5e7), (0, 4.5, 0, 3e7)]
dt = 0.002


def fail(message):
    print("FAIL " + message)
    sys.exit(1)


def model(eccentricity, ground, initial):
    plane_text = "; ".join(f"{x} {y} {a} {k}" for x, y, a, k in planes)
    return f"""
subsection Model
  set Dimension = 3
end
subsection Building 1
  set Name               = T
  set Type               = shear
  set Number of storeys  = 1
  set Storey heights     = 3.5
  set Floor masses       = {mass}
  set Storey stiffnesses = 1e8
  subsection Plan
    set Plan dimensions   = {L_x}, {L_y}
    set Position          = 0, 0
    set Mass eccentricity = {eccentricity[0]}, {eccentricity[1]}
    set Polar moments     = {J}
    set Resisting planes  = {plane_text}
  end
  subsection Damping
    set Type = none
  end
end
{ground}
subsection Time integration
  set Time step = {dt}
  set End time  = 1.5
end
{initial}
subsection Output
  set Output interval = 0
  set VTU interval    = 0
  subsection Recorders
    set Record = corner acceleration
  end
end
"""


def run(name, text):
    prm = os.path.join(work, name + ".prm")
    with open(prm, "w") as f:
        f.write(text)
    out = os.path.join(work, name)
    result = subprocess.run([poundfe, "run", prm, "--output", out], capture_output=True, text=True)
    return result, out


def columns(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def jacobi_eigen(a):
    """Eigenvalues and eigenvectors (columns) of a symmetric 3x3 matrix."""
    a = [row[:] for row in a]
    v = [[float(i == j) for j in range(3)] for i in range(3)]
    for _ in range(100):
        p, q = max(((0, 1), (0, 2), (1, 2)), key=lambda ij: abs(a[ij[0]][ij[1]]))
        if abs(a[p][q]) < 1e-300:
            break
        theta = 0.5 * math.atan2(2 * a[p][q], a[q][q] - a[p][p])
        c, s = math.cos(theta), math.sin(theta)
        for k in range(3):  # A <- A R, then R^T A
            a[k][p], a[k][q] = c * a[k][p] - s * a[k][q], s * a[k][p] + c * a[k][q]
        for k in range(3):
            a[p][k], a[q][k] = c * a[p][k] - s * a[q][k], s * a[p][k] + c * a[q][k]
        for k in range(3):
            v[k][p], v[k][q] = c * v[k][p] - s * v[k][q], s * v[k][p] + c * v[k][q]
    return [a[i][i] for i in range(3)], v


# 1. one mode in free vibration
e = (1.5, 0.8)
K = [[0.0] * 3 for _ in range(3)]
for x, y, angle, k in planes:
    n = (math.cos(math.radians(angle)), math.sin(math.radians(angle)))
    b = (n[0], n[1], -n[0] * (y - e[1]) + n[1] * (x - e[0]))
    for i in range(3):
        for j in range(3):
            K[i][j] += k * b[i] * b[j]
m = (mass, mass, J)
scaled = [[K[i][j] / math.sqrt(m[i] * m[j]) for j in range(3)] for i in range(3)]
values, vectors = jacobi_eigen(scaled)
first = min(range(3), key=lambda i: values[i])
omega = math.sqrt(values[first])
phi = [vectors[i][first] / math.sqrt(m[i]) for i in range(3)]
A = 0.02 / max(abs(phi[0]), abs(phi[1]))
u0 = [A * p for p in phi]
initial = ("subsection Initial conditions\n  set Equation displacements = " +
           "; ".join(f"{i} = {u0[i]!r}" for i in range(3)) + "\nend")
result, out = run("mode", model(e, "subsection Ground motion\n  set Type = none\nend", initial))
if result.returncode != 0:
    fail("free vibration: " + result.stderr)
series = columns(os.path.join(out, "corner_acceleration.csv"))
time = series["time_s"]
omega_bar = 2 / dt * math.atan(omega * dt / 2)
corners = [(sx * L_x / 2 - e[0], sy * L_y / 2 - e[1]) for sx in (-1, 1) for sy in (-1, 1)]
closed = {}
for k, (dx, dy) in enumerate(corners):
    closed[(k, "x")] = -omega**2 * (u0[0] - u0[2] * dy)
    closed[(k, "y")] = -omega**2 * (u0[1] + u0[2] * dx)
peak = max(abs(v) for v in closed.values())
matched, worst = set(), 0.0
for corner in sorted({n.split("_acc_")[0] for n in series if n != "time_s"}):
    def error(k):
        return max(abs(a - closed[(k, axis)] * math.cos(omega_bar * t))
                   for axis in "xy" for a, t in zip(series[f"{corner}_acc_{axis}_m_s2"], time))
    best = min(range(4), key=error)
    worst = max(worst, error(best) / peak)
    if error(best) > 1e-9 * peak:
        fail(f"free vibration: {corner} is no corner's closed form (off by {error(best) / peak:.2e})")
    matched.add(best)
if len(matched) != 4:
    fail(f"free vibration: the columns are not the slab's four corners: {sorted(matched)}")
with open(os.path.join(out, "summary.json")) as f:
    plan = json.load(f)["buildings"][0]["plan"]
for axis in "xy":
    want = max(abs(closed[(k, axis)]) for k in range(4))
    got = plan[f"peak_corner_acceleration_{axis}_m_s2"][0]
    if abs(got - want) > 1e-12 * want:
        fail(f"free vibration: summary peak along {axis} {got} against {want}")
print(f"ok   free vibration in mode 1 (T = {2 * math.pi / omega:.4f} s): 4 corners (x, y) "
      f"= closed form to {worst:.1e} of the peak; summary peaks exact")

# 2. under ground motion: the corners' mean is the mass centre's acceleration
ground = """subsection Ground motion
  set Type       = kanai-tajimi
  set Components = 2
  subsection Stochastic
    set Target PGA = 0.3
    set Duration   = 1.5
    set Seed       = 11
  end
end"""
result, out = run("ground", model((0, 0), ground, ""))
if result.returncode != 0:
    fail("ground motion: " + result.stderr)
series = columns(os.path.join(out, "corner_acceleration.csv"))
centre = columns(os.path.join(out, "floor_acceleration.csv"))["T_floor1_acc_x_m_s2"]
xs = [v for n, v in series.items() if n.endswith("_acc_x_m_s2")]
peak = max(abs(a) for a in centre)
mean_error = max(abs(sum(c[i] for c in xs) / 4 - centre[i]) for i in range(len(centre)))
spread = max(max(c[i] for c in xs) - min(c[i] for c in xs) for i in range(len(centre)))
if mean_error > 1e-12 * peak:
    fail(f"ground motion: the corners' mean is {mean_error / peak:.1e} of the peak off the floor's")
if spread < 0.05 * peak:
    fail(f"ground motion: the floor does not twist (corner spread {spread / peak:.1e} of the peak)")
print(f"ok   ground motion: the corners' mean = the floor acceleration to {mean_error / peak:.1e} "
      f"of the peak; corners spread {spread / peak:.2f} of it")

# 3. a 2D model has no slab corners
prm2d = os.path.join(work, "plane.prm")
with open(prm2d, "w") as f:
    f.write("""subsection Building 1
  set Type = shear
  set Number of storeys = 1
  set Floor masses = 1e5
  set Storey stiffnesses = 1e7
  subsection Damping
    set Type = none
  end
end
subsection Ground motion
  subsection Stochastic
    set Duration = 0.5
  end
end
subsection Output
  subsection Recorders
    set Record = corner acceleration
  end
end
""")
result = subprocess.run([poundfe, "run", prm2d, "--output", os.path.join(work, "plane")],
                        capture_output=True, text=True)
if result.returncode != 1 or "Dimension = 3" not in result.stderr or \
        os.path.exists(os.path.join(work, "plane")):
    fail(f"2D corner acceleration: exit {result.returncode}, {result.stderr.strip()}")
print("ok   2D: 'corner acceleration' refused, nothing written")
