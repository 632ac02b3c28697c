#!/usr/bin/env python3
"""Independent references for the response spectra (pure Python, no NumPy).

rk4_peak: classical fourth-order Runge-Kutta on
  u'' + 2 zeta w u' + w^2 u = -a(t),  a(t) linear between samples,
with n_sub sub-steps per sample and the peak |u| at every sub-step;
optionally followed by free vibration for one period (a = 0 after the last
sample: poundfe's convention for a record that has ended).
intensity: PGA, PGV, Arias intensity and D5-95 by the trapezoidal rule on a
fine linear interpolation of the samples.
Used by tests/cli/spectrum.sh (floor spectra of a run) and
bench/spectrum_elcentro.py (El Centro).
"""
import math

G = 9.80665


def rk4_peak(a, dt, period, zeta, n_sub=20, free_vibration=True):
    w = 2 * math.pi / period
    h = dt / n_sub

    def f(u, v, ag):
        return v, -2 * zeta * w * v - w * w * u - ag

    u = v = peak = 0.0
    # the record's intervals, then free vibration (a = 0 from the last sample on)
    intervals = list(zip(a[:-1], a[1:]))
    if free_vibration:
        intervals += [(0.0, 0.0)] * int(math.ceil(period / dt))
    for a0, a1 in intervals:
        for j in range(n_sub):
            g0 = a0 + (a1 - a0) * j / n_sub
            g1 = a0 + (a1 - a0) * (j + 0.5) / n_sub
            g2 = a0 + (a1 - a0) * (j + 1) / n_sub
            k1u, k1v = f(u, v, g0)
            k2u, k2v = f(u + 0.5 * h * k1u, v + 0.5 * h * k1v, g1)
            k3u, k3v = f(u + 0.5 * h * k2u, v + 0.5 * h * k2v, g1)
            k4u, k4v = f(u + h * k3u, v + h * k3v, g2)
            u += h / 6 * (k1u + 2 * k2u + 2 * k3u + k4u)
            v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v)
            peak = max(peak, abs(u))
    return peak


def intensity(a, dt, n_fine=20):
    """PGA, PGV, Arias intensity, D5-95 by the trapezoidal rule on a fine grid."""
    fine = []
    for i in range(len(a) - 1):
        for j in range(n_fine):
            fine.append(a[i] + (a[i + 1] - a[i]) * j / n_fine)
    fine.append(a[-1])
    h = dt / n_fine
    v, pgv, energy, husid = 0.0, 0.0, 0.0, [0.0]
    for i in range(len(fine) - 1):
        v += 0.5 * h * (fine[i] + fine[i + 1])
        pgv = max(pgv, abs(v))
        energy += 0.5 * h * (fine[i] ** 2 + fine[i + 1] ** 2)
        husid.append(energy)

    def time_at(p):
        level = p * energy
        for i in range(1, len(husid)):
            if husid[i] >= level:
                return (i - 1 + (level - husid[i - 1]) / (husid[i] - husid[i - 1])) * h
        return (len(husid) - 1) * h

    return {"pga_m_s2": max(abs(x) for x in a), "pgv_m_s": pgv,
            "arias_intensity_m_s": math.pi / (2 * G) * energy,
            "significant_duration_5_95_s": time_at(0.95) - time_at(0.05)}
