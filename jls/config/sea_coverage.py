"""The energy-outside-the-RAO-range rule of the parametric sea states
(:func:`jls.response.coverage.check_coverage`: more than 0.1 % of a sea state's energy
outside the RAO's frequency range and the stated zero-motion bands is an error) applied
at parse time to the seas a leg gives otherwise: measured or hindcast spectra, record by
record, and the partitions of a metocean file (wind sea and swell), each as a JONSWAP of
its own period. Errors name the data file, the record, and the key and configuration
file that give the file.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from jls.config.loader import origin_finder
from jls.errors import InputError


def origin(field, layers) -> str | None:
    return origin_finder(list(layers))(field) if layers else None


def check_measured_coverage(cfg: dict, lo: float, hi: float, layers=(), base_dir=".") -> None:
    """The energy-outside-the-RAO-range rule of the parametric sea states
    (:func:`jls.response.coverage.check_coverage`) applied to every record of every spectra
    leg (:func:`jls.response.coverage.check_spectra_coverage`): the measured response
    integrates those spectra over the RAO range. Errors name the spectra file, the record
    and the key that gives the file."""
    from jls.response.coverage import check_spectra_coverage
    from jls.sea.records import read_leg_spectra
    for route, spec in cfg["routes"].items():
        for i, leg in enumerate(spec["legs"]):
            if "metocean" in leg:
                check_partition_coverage(cfg, leg, route, i, lo, hi, layers, base_dir)
            if "spectra" not in leg:
                continue
            efth = read_leg_spectra(leg, base_dir)
            key = f"routes.{route}.legs[{i}].spectra.file"
            try:
                check_spectra_coverage(efth, lo, hi, cfg["vessel"].get("outside_rao_range"),
                                       source=str(Path(base_dir) / leg["spectra"]["file"]))
            except InputError as exc:
                raise InputError(f"route '{route}', leg '{leg['name']}': {exc.message} (the file "
                                 f"given by {key} in {origin(key, list(layers)) or 'config'}; "
                                 "the RAO file is vessel.rao_file)", file=exc.file,
                                 field=exc.field, value=exc.value) from None


#: Partitions of a metocean file: (Hs column, period column, which period) for ERA5's wind
#: sea and swell and WAVEWATCH III's partitions 0-9 (jls.sea.metocean).
PARTITIONS = [("wind_hs", "wind_te", "te"), ("swell_hs", "swell_te", "te")] + [
    (f"p{k}_hs", f"p{k}_tp", "tp") for k in range(10)]


def check_partition_coverage(cfg: dict, leg: dict, route: str, index: int, lo: float, hi: float,
                             layers=(), base_dir=".") -> None:
    """The energy-outside-the-RAO-range rule for a metocean leg whose file gives its sea
    partitions (ERA5 wind sea and swell, WAVEWATCH III partitions): the leg is assessed on
    the total Hs and period, whose JONSWAP may hide a long swell below the RAO range.
    Each partition is taken as a JONSWAP of its own period (converted to Tz with sea.gamma,
    as the leg's period), weighted by its share of the energy, Hs_k^2 / sum Hs_k^2; a
    record with more than 0.1 % of its energy outside the RAO range and the stated bands
    is an error naming the file, the record and the partition."""
    from jls.response.coverage import ENERGY_OUTSIDE_LIMIT, coverage
    from jls.sea.metocean import read_metocean
    from jls.sea.periods import tp_from_period
    from jls.sea.spectra import tz_from_tp
    m = leg["metocean"]
    path = Path(base_dir) / m["file"]
    if m["format"] == "partitions":              # the partitions CSV (jls.sea.partitions): Tp each
        from jls.sea.partitions import PARTITION_COLUMNS, read_partitions
        df = read_partitions(path)
        parts = [(h, h.replace("hs_", "tp_"), "tp") for h in PARTITION_COLUMNS if h.startswith("hs_")]
    else:
        df = read_metocean(path, m["format"])
        parts = [(h, t, kind) for h, t, kind in PARTITIONS if h in df and t in df]
    if not parts:
        return
    gamma = float(cfg["sea"]["gamma"])
    policy = cfg["vessel"].get("outside_rao_range")
    energy = np.zeros(len(df))
    outside = np.zeros(len(df))
    worst = np.zeros(len(df), dtype=int)
    share_max = np.zeros(len(df))
    for k, (h, t, kind) in enumerate(parts):
        hs, period = df[h].to_numpy(float), df[t].to_numpy(float)
        ok = np.isfinite(hs) & np.isfinite(period) & (hs > 0) & (period > 0)
        ratio = float(tz_from_tp(tp_from_period("jonswap", kind, 1.0, gamma=gamma), gamma))
        tz = np.round(np.where(ok, period * ratio, 1.0), 2)
        values, inverse = np.unique(tz[ok], return_inverse=True)
        frac = np.zeros(len(df))
        if values.size:
            _, unexplained = coverage(lo, hi, values, gamma, policy, str(path))
            frac[ok] = np.asarray(unexplained)[inverse]
        e = np.where(ok, hs ** 2, 0.0)
        energy += e
        part = e * frac
        worse = part > share_max
        worst[worse], share_max[worse] = k, part[worse]
        outside += part
    with np.errstate(invalid="ignore", divide="ignore"):
        fraction = np.where(energy > 0, outside / energy, 0.0)
    bad = fraction > ENERGY_OUTSIDE_LIMIT
    if bad.any():
        j = int(np.argmax(fraction))
        h, t, _ = parts[worst[j]]
        key = f"routes.{route}.legs[{index}].metocean.file"
        raise InputError(
            f"route '{route}', leg '{leg['name']}': {int(bad.sum())} of the {len(df)} records have "
            f"more than {100 * ENERGY_OUTSIDE_LIMIT:g} % of their energy outside the RAO range "
            f"[{lo:.3f}, {hi:.3f}] rad/s and the stated zero-motion bands when their partitions "
            f"are taken each as a JONSWAP, the largest at {df.index[j].isoformat()[:16]} with "
            f"{100 * fraction[j]:.2f} %, most of it in the partition {h} {df[h].iloc[j]:g} m, "
            f"{t} {df[t].iloc[j]:g} s (the total Hs and period the leg is assessed on hide it): as "
            "for parametric sea states, extend the RAOs or state the band where the vessel does "
            f"not move (the file given by {key} in {origin(key, list(layers)) or 'config'})",
            file=path, field="vessel.outside_rao_range", value=round(float(fraction[j]), 6))
