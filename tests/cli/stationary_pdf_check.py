#!/usr/bin/env python3
"""Checks a stationary-pdf result against an exact stationary density.

usage: stationary_pdf_check.py DIR linear D c omega0
       stationary_pdf_check.py DIR impact D c omega0
       stationary_pdf_check.py DIR sd D c alpha
       stationary_pdf_check.py DIR p-bifurcation alpha1 alpha2 ...

The number of effectively independent samples is N_eff = T / (2 tau_c),
T the sampled time summed over the realizations and tau_c the correlation
time (1 / (zeta omega0) for the linear oscillator, given for the SD
oscillator). With it: the relative standard error of a variance estimate
is sqrt(2 / N_eff), and that of a bin probability P is
sqrt(P (1 - P) / N_eff). For the SD oscillator, whose correlation time is
set by the hops between the wells, the standard error of a bin comes from
the scatter of the independent realizations instead (batch means, the
realizations.csv rows). Tolerances: 4 standard errors.

impact: the same linear oscillator against a rigid barrier at its
equilibrium (x <= 0) with restitution e = 1, whose response is the linear
one folded, x = -|y| (Zhuravlev's transformation; Dimentberg & Iourtchenko,
Nonlinear Dynamics 36 (2004) 229): p(x) = 2 p_y(x) for x <= 0, the mean
-sigma sqrt(2/pi), the variance sigma^2 (1 - 2/pi) (its relative standard
error sqrt((kappa - 1)/N_eff) with the half-normal's kurtosis kappa =
3.869), v and the amplitude as the linear oscillator's.
"""
import csv
import json
import math
import sys


def fail(message):
    print("FAIL " + message)
    sys.exit(1)


def read(directory):
    with open(directory + "/summary.json") as f:
        summary = json.load(f)
    with open(directory + "/pdf.csv") as f:
        rows = list(csv.DictReader(f))
    return summary, rows


def effective_samples(summary, tau_c):
    sampled = summary["end_time_s"] - summary["burn_in_s"]
    return summary["completed_realizations"] * sampled / (2 * tau_c)


def check_bins(rows, column, value, cdf, n_eff, what):
    """Histogram bin probabilities against the exact CDF, within 4 SE."""
    centers = [float(r[value]) for r in rows]
    w = centers[1] - centers[0]
    worst = 0.0
    for r, x in zip(rows, centers):
        p = cdf(x + w / 2) - cdf(x - w / 2)
        se = math.sqrt(max(p, 1.0 / n_eff) * (1 - p) / n_eff)
        worst = max(worst, abs(float(r[column]) * w - p) / se)
    if worst > 4:
        fail("%s: a histogram bin is %.2f standard errors from the exact density" % (what, worst))
    print("ok   %s histogram: largest bin deviation %.2f standard errors (<= 4)" % (what, worst))


def check_variance(estimate, exact, n_eff, what):
    se = math.sqrt(2 / n_eff)
    error = abs(estimate / exact - 1)
    if error > 4 * se:
        fail("%s: variance %.5g, exact %.5g (relative error %.3g > %.3g)" % (what, estimate, exact, error, 4 * se))
    print("ok   %s variance %.5g, exact %.5g (relative error %.3g <= 4 SE = %.3g)" % (what, estimate, exact, error, 4 * se))


def normal_cdf(sigma):
    return lambda x: 0.5 * (1 + math.erf(x / (sigma * math.sqrt(2))))


def linear(directory, D, c, omega0):
    summary, rows = read(directory)
    zeta = c / (2 * omega0)
    n_eff = effective_samples(summary, 1 / (zeta * omega0))
    var_x, var_v = D / (c * omega0 ** 2), D / c
    check_variance(summary["x"]["variance"], var_x, n_eff, "x")
    check_variance(summary["v"]["variance"], var_v, n_eff, "v")
    check_bins(rows, "p_x_histogram_1_m", "x_m", normal_cdf(math.sqrt(var_x)), n_eff, "x")
    check_bins(rows, "p_v_histogram_s_m", "v_m_s", normal_cdf(math.sqrt(var_v)), n_eff, "v")
    # x and v / omega0 are independent with equal variance: a is Rayleigh
    rayleigh = lambda a: 1 - math.exp(-max(a, 0) ** 2 / (2 * var_x))
    check_bins(rows, "p_a_histogram_1_m", "a_m", rayleigh, n_eff, "amplitude")
    for q in ("x", "v"):
        peaks = summary[q]["peak_locations"]
        sigma = math.sqrt(var_x if q == "x" else var_v)
        if len(peaks) != 1 or abs(peaks[0]) > 0.3 * sigma:
            fail("%s: peaks %s, expected one within 0.3 sigma of 0" % (q, peaks))
        print("ok   %s: one peak, at %.3g (|.| <= 0.3 sigma = %.3g)" % (q, peaks[0], 0.3 * sigma))


def impact(directory, D, c, omega0):
    summary, rows = read(directory)
    zeta = c / (2 * omega0)
    n_eff = effective_samples(summary, 1 / (zeta * omega0))
    var_y, var_v = D / (c * omega0 ** 2), D / c
    sigma = math.sqrt(var_y)
    mean, variance = summary["x"]["mean"], summary["x"]["variance"]
    exact_mean, exact_variance = -sigma * math.sqrt(2 / math.pi), var_y * (1 - 2 / math.pi)
    se_mean = math.sqrt(exact_variance / n_eff)
    if abs(mean - exact_mean) > 4 * se_mean:
        fail("impact x: mean %.5g, exact %.5g (> 4 SE = %.3g)" % (mean, exact_mean, 4 * se_mean))
    print("ok   impact x mean %.5g, exact %.5g (within 4 SE = %.3g)" % (mean, exact_mean, 4 * se_mean))
    se = math.sqrt((3.869 - 1) / n_eff)
    error = abs(variance / exact_variance - 1)
    if error > 4 * se:
        fail("impact x: variance %.5g, exact %.5g (relative error %.3g > %.3g)" % (variance, exact_variance, error, 4 * se))
    print("ok   impact x variance %.5g, exact %.5g (relative error %.3g <= 4 SE = %.3g)" % (variance, exact_variance, error, 4 * se))
    check_variance(summary["v"]["variance"], var_v, n_eff, "impact v")
    folded = lambda x: min(1.0, 2 * normal_cdf(sigma)(x))
    check_bins(rows, "p_x_histogram_1_m", "x_m", folded, n_eff, "impact x")
    check_bins(rows, "p_v_histogram_s_m", "v_m_s", normal_cdf(math.sqrt(var_v)), n_eff, "impact v")
    rayleigh = lambda a: 1 - math.exp(-max(a, 0) ** 2 / (2 * var_y))
    check_bins(rows, "p_a_histogram_1_m", "a_m", rayleigh, n_eff, "impact amplitude")


def sd_potential(alpha):
    return lambda x: x * x / 2 - math.sqrt(x * x + alpha * alpha) + alpha


def sd_cdf(D, c, alpha):
    """CDF of p(x) ~ exp(-(c/D) U(x)), normalised numerically (trapezoid, 40001 points)."""
    U = sd_potential(alpha)
    top = 2 + 12 * math.sqrt(D / c)
    n = 40000
    h = 2 * top / n
    f = [math.exp(-(c / D) * U(-top + i * h)) for i in range(n + 1)]
    cumulative = [0.0]
    for i in range(n):
        cumulative.append(cumulative[-1] + h * (f[i] + f[i + 1]) / 2)
    total = cumulative[-1]

    def cdf(x):
        k = (x + top) / h
        i = min(n - 1, max(0, int(k)))
        t = min(1.0, max(0.0, k - i))
        return (cumulative[i] + t * (cumulative[i + 1] - cumulative[i])) / total
    return cdf


def batch_bins(directory, quantity):
    """Per bin: the pooled probability and its standard error from the
    scatter of the independent realizations (batch means)."""
    with open(directory + "/realizations.csv") as f:
        rows = [r for r in csv.DictReader(f) if r["completed"] == "1"]
    n_key = next(k for k in rows[0] if k.startswith("samples_steps_"))
    bins = sorted((k for k in rows[0] if k.startswith(quantity + "_bin")), key=lambda k: int(k[len(quantity) + 4:]))
    R = len(rows)
    result = []
    for key in bins:
        p = [float(r[key]) / float(r[n_key]) for r in rows]
        mean = sum(p) / R
        sd = math.sqrt(sum((x - mean) ** 2 for x in p) / (R - 1))
        result.append((mean, sd / math.sqrt(R)))
    return result, R * float(rows[0][n_key])


def check_batch_bins(directory, quantity, centers, cdf, what):
    estimates, n_total = batch_bins(directory, quantity)
    w = centers[1] - centers[0]
    worst = 0.0
    for (p_hat, se), x in zip(estimates, centers):
        p = cdf(x + w / 2) - cdf(x - w / 2)
        se = max(se, math.sqrt(p / n_total), 1.0 / n_total)
        worst = max(worst, abs(p_hat - p) / se)
    if worst > 4:
        fail("%s: a histogram bin is %.2f standard errors from the exact density" % (what, worst))
    print("ok   %s histogram: largest bin deviation %.2f standard errors (batch means of the realizations; <= 4)" % (what, worst))


def sd(directory, D, c, alpha):
    summary, rows = read(directory)
    x = [float(r["x_m"]) for r in rows]
    v = [float(r["v_m_s"]) for r in rows]
    check_batch_bins(directory, "x", x, sd_cdf(D, c, alpha), "SD x")
    check_batch_bins(directory, "v", v, normal_cdf(math.sqrt(D / c)), "SD v")
    peaks = summary["x"]["peak_locations"]
    expected = math.sqrt(1 - alpha * alpha) if alpha < 1 else 0
    w = x[1] - x[0]
    if alpha < 1:
        good = len(peaks) == 2 and peaks[0] < 0 < peaks[1] and all(abs(abs(p) - expected) <= w for p in peaks)
    else:
        good = len(peaks) == 1 and abs(peaks[0]) <= w
    if not good:
        fail("SD x: peaks %s, expected at +-%.4f (within one bin, %.3f)" % (peaks, expected, w))
    print("ok   SD x: peaks %s (exact +-%.4f, within one bin = %.3f)" % (["%.3f" % p for p in peaks], expected, w))


def p_bifurcation(directory, *alphas):
    """The SD oscillator's p(x) is bimodal exactly when alpha < 1 (U''(0) =
    1 - 1/alpha): the number of peaks per value, peaks of the bimodal values
    at +-sqrt(1 - alpha^2) within one bin, and the one change bracketing 1."""
    with open(directory + "/summary.json") as f:
        summary = json.load(f)
    got = [v["n_peaks"] for v in summary["values"]]
    expected = [2 if a < 1 else 1 for a in alphas]
    if got != expected:
        fail("P-bifurcation: peaks %s at alpha %s, expected %s" % (got, list(alphas), expected))
    for a, v in zip(alphas, summary["values"]):
        with open("%s/Springs_SD_springs_6_%s/pdf.csv" % (directory, v["value"] if v["value"] != int(v["value"]) else int(v["value"]))) as f:
            rows = list(csv.DictReader(f))
        w = float(rows[1]["x_m"]) - float(rows[0]["x_m"])
        target = [-math.sqrt(1 - a * a), math.sqrt(1 - a * a)] if a < 1 else [0.0]
        if any(abs(p - t) > w for p, t in zip(v["peak_locations"], target)):
            fail("P-bifurcation: alpha %g: peaks %s, exact %s (one bin %.3f)" % (a, v["peak_locations"], target, w))
    changes = summary["peak_count_changes"]
    if len(changes) != 1 or not (changes[0]["between"][0] < 1 < changes[0]["between"][1]):
        fail("P-bifurcation: changes %s, expected one bracketing alpha = 1" % changes)
    print("ok   P-bifurcation: peaks %s at alpha %s (exact: 2 below 1, 1 above), change between %s" %
          (got, list(alphas), changes[0]["between"]))
    # the support (where the kernel density is >= Support threshold of its
    # maximum; its closed form is unit/reliability's): ordered disjoint
    # intervals holding every peak, their hull in p_bifurcation.csv, and
    # support_changes exactly where their number changes
    with open(directory + "/p_bifurcation.csv") as f:
        table = list(csv.DictReader(f))
    counts = []
    for v, row in zip(summary["values"], table):
        ends = v["support_intervals"]
        if len(ends) != 2 * v["n_support_intervals"] or v["n_support_intervals"] < 1 or ends != sorted(ends):
            fail("P-bifurcation: value %g: support %s" % (v["value"], ends))
        if any(not any(ends[2 * k] < p < ends[2 * k + 1] for k in range(len(ends) // 2)) for p in v["peak_locations"]):
            fail("P-bifurcation: value %g: a peak %s outside the support %s" % (v["value"], v["peak_locations"], ends))
        if (int(row["n_support_intervals"]) != v["n_support_intervals"] or float(row["support_low_m"]) != ends[0]
                or float(row["support_high_m"]) != ends[-1]):
            fail("P-bifurcation: value %g: p_bifurcation.csv's support %s against %s" % (v["value"], row, ends))
        counts.append(v["n_support_intervals"])
    expected = [[summary["values"][j - 1]["value"], summary["values"][j]["value"]]
                for j in range(1, len(counts)) if counts[j] != counts[j - 1]]
    if [c["between"] for c in summary["support_changes"]] != expected:
        fail("P-bifurcation: support_changes %s, expected %s" % (summary["support_changes"], expected))
    print("ok   P-bifurcation: support intervals %s per value, changes %s" % (counts, expected))


if __name__ == "__main__":
    kind, directory = sys.argv[2], sys.argv[1]
    values = [float(v) for v in sys.argv[3:]]
    {"linear": linear, "impact": impact, "sd": sd, "p-bifurcation": p_bifurcation}[kind](directory, *values)
