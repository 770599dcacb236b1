"""Several wave records (seeds) of one sea state: the runs, their pooled statistics and
their spread.

With random (Rayleigh) component amplitudes each seed is an independent realisation of
the sea state, so the spread of a statistic over seeds is the scatter a real record of
that length carries. The expected spread of sigma follows from the linear model on the
record's grid (:func:`jls.timedomain.resolution.linear_grid`): sigma^2 = sum_k v_k E_k
with E_k standard exponential, so var(sigma^2) = sum v_k^2, the relative standard
deviation of sigma^2 is 1 / sqrt(N_eff) and that of sigma about 1 / (2 sqrt(N_eff)).

The pooled statistics treat the seeds as one long record of n equally long pieces:
sigma = sqrt(mean sigma_s^2), the velocity variance likewise (so the spectral Tz), the
MPMs from the pooled sigma with N from one piece's duration (the exposure the record
stands for), up-crossings and slack events summed, fractions and mean power averaged,
extremes over all pieces.
"""

from __future__ import annotations

import numpy as np

from jls.threads import thread_map

#: How each run statistic pools over seeds (statistics not listed are recomputed).
MEAN = ("mean", "limit_fraction", "at_max_fraction", "at_min_fraction", "power_mean",
        "slack_fraction", "line_contact_fraction")
MAX = ("max_observed", "power_peak", "wire_tension_max", "line_tension_max")
MIN = ("wire_tension_min", "line_tension_min", "line_length_min")
SUM = ("slack_events", "wall_time", "n_upcrossings")


def record_seed(base, j: int) -> tuple:
    """Seed of a cell's record j: the cell's seed for the first, the seed and j after."""
    base = tuple(np.atleast_1d(base).tolist())
    return base if j == 0 else base + (int(j),)


def pool(runs: list[dict], duration_s: float) -> dict:
    """Pooled statistics of one tugger setting's runs on the seeds (module docstring)."""
    with np.errstate(all="ignore"):
        out = {}
        for k in MEAN:
            out[k] = float(np.mean([r[k] for r in runs]))
        for k in MAX:
            out[k] = float(np.nanmax([r[k] for r in runs])) if not all(np.isnan(r[k]) for r in runs) else np.nan
        for k in MIN:
            out[k] = float(np.nanmin([r[k] for r in runs])) if not all(np.isnan(r[k]) for r in runs) else np.nan
        for k in SUM:
            out[k] = type(runs[0][k])(np.sum([r[k] for r in runs]))
        sig = np.array([r["sigma"] for r in runs])
        sv = 2 * np.pi * sig / np.array([r["tz_spectral"] for r in runs])
        sigma = float(np.sqrt(np.mean(sig**2)))
        sv_pool = float(np.sqrt(np.mean(sv**2)))
        tz = 2 * np.pi * sigma / sv_pool if sv_pool > 0 else np.nan
        n_spec = duration_s / tz if np.isfinite(tz) else 1.0
        n_up = out["n_upcrossings"] / len(runs)
        out.update(sigma=sigma, tz_spectral=tz,
                   tz_upcrossing=duration_s / n_up if n_up else np.nan,
                   mpm_sigma=sigma * np.sqrt(2 * np.log(max(n_spec, 1.0))),
                   mpm_upcrossing=sigma * np.sqrt(2 * np.log(max(n_up, 1.0))))
    return out


def run_seeds(make_case, tuggers, n_seeds: int, workers=1, keep_first=False):
    """Run every tugger setting on ``n_seeds`` records: make_case(j) builds record j's
    :class:`jls.timedomain.run.Case` (one at a time, so one record's excitation is in
    memory at once). Returns (runs[seed][tugger] dicts, the first case); the first seed's
    runs keep their records when ``keep_first``."""
    runs, first = [], None
    for j in range(int(n_seeds)):
        case = make_case(j)
        keep = keep_first and j == 0
        runs.append(thread_map(lambda t, c=case, k=keep: c.run(t, keep_record=k), tuggers, workers))
        if j == 0:
            first = case
    return runs, first


def spread(runs: list[list[dict]]) -> dict:
    """Per-seed sigma and MPM (from sigma) as (tugger, seed) arrays, with their mean and
    standard deviation (ddof 1; NaN for one seed) over seeds per tugger."""
    sigma = np.array([[r["sigma"] for r in seed] for seed in runs]).T
    mpm = np.array([[r["mpm_sigma"] for r in seed] for seed in runs]).T
    ddof = 1 if sigma.shape[1] > 1 else 0
    nan = np.full(sigma.shape[0], np.nan)
    return {"sigma_seed": sigma, "mpm_seed": mpm,
            "sigma_seed_mean": sigma.mean(axis=1), "mpm_seed_mean": mpm.mean(axis=1),
            "sigma_seed_std": sigma.std(axis=1, ddof=ddof) if ddof else nan,
            "mpm_seed_std": mpm.std(axis=1, ddof=ddof) if ddof else nan}


__all__ = ["pool", "run_seeds", "spread", "record_seed"]
