"""Write the SYNTHETIC partitioned-sea example: one week of hourly wind-sea and swell
partitions (no measurement, no model run: a smooth made-up series with a seeded jitter),
in the three forms jls reads them:

    tests/data/partitions/era5_partitions_synthetic.nc   ERA5-like single-level NetCDF: swh,
        pp1d, mwp, mwd and the partitions shww/mpww/mdww, shts/mpts/mdts with ERA5's names,
        units, CF standard names, on (valid_time, latitude, longitude) of one point
    tests/data/partitions/partitions_synthetic.csv       the partitions CSV (format: partitions)
    tests/data/partitions/torsethaugen_hs_tp_synthetic.csv   a scatter table in Hs-Tp

Each file says it is synthetic (a global attribute, a comment line). The partitions'
periods: the CSV gives Tp; the NetCDF gives ERA5's mean period Te = Tm-10 of the same
JONSWAP (gamma 3.3) partitions, so that both describe one sea.

    python scripts/make_partitions_example.py
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import xarray as xr

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "tests" / "data" / "partitions"
GAMMA = 3.3
NOTE = ("SYNTHETIC: made-up wind-sea and swell partitions written by scripts/make_partitions_example.py "
        "for tests and examples; not a measurement, not a hindcast")


def series(n=168, seed=32):
    rng = np.random.default_rng(seed)
    t = np.arange(n)
    day = 2 * np.pi * t / 24.0
    week = 2 * np.pi * t / n
    hs_w = np.round(1.0 + 0.6 * np.sin(day) + 0.3 * np.sin(week) + 0.05 * rng.standard_normal(n), 2)
    tp_w = np.round(6.0 + 1.2 * np.sin(day + 0.3) + 0.1 * rng.standard_normal(n), 2)
    dir_w = np.round(np.mod(60.0 + 25.0 * np.sin(week) + 5 * rng.standard_normal(n), 360.0), 1)
    hs_s = np.round(0.9 + 0.4 * np.sin(week + 1.0) + 0.03 * rng.standard_normal(n), 2)
    tp_s = np.round(14.0 + 2.0 * np.sin(week - 0.5) + 0.1 * rng.standard_normal(n), 2)
    dir_s = np.round(np.mod(100.0 + 10.0 * np.cos(week) + 2 * rng.standard_normal(n), 360.0), 1)
    times = pd.date_range("2021-03-01T00:00", periods=n, freq="h")
    return pd.DataFrame({"hs_wind": hs_w, "tp_wind": tp_w, "dir_wind": dir_w,
                         "hs_swell": hs_s, "tp_swell": tp_s, "dir_swell": dir_s}, index=times)


def write_csv(df, path):
    lines = [f"# {NOTE}", "time, hs_wind, tp_wind, dir_wind, hs_swell, tp_swell, dir_swell"]
    for t, r in df.iterrows():
        lines.append(f"{t:%Y-%m-%dT%H:%MZ}, " + ", ".join(f"{v:g}" for v in r.to_numpy()))
    path.write_text("\n".join(lines) + "\n")


def write_era5(df, path):
    from jls.sea.spectra import te_from_tp
    te = float(te_from_tp(1.0, GAMMA))
    e_w, e_s = df["hs_wind"] ** 2, df["hs_swell"] ** 2
    vec = e_w * np.exp(1j * np.radians(df["dir_wind"])) + e_s * np.exp(1j * np.radians(df["dir_swell"]))
    values = {
        "swh": np.sqrt(e_w + e_s), "pp1d": np.where(e_s >= e_w, df["tp_swell"], df["tp_wind"]),
        "mwp": (e_w * df["tp_wind"] + e_s * df["tp_swell"]) * te / (e_w + e_s),
        "mwd": np.mod(np.degrees(np.angle(vec)), 360.0),
        "shww": df["hs_wind"], "mpww": df["tp_wind"] * te, "mdww": df["dir_wind"],
        "shts": df["hs_swell"], "mpts": df["tp_swell"] * te, "mdts": df["dir_swell"],
    }
    meta = {
        "swh": ("Significant height of combined wind waves and swell", "m", "sea_surface_wave_significant_height"),
        "pp1d": ("Peak wave period", "s", "sea_surface_wave_period_at_variance_spectral_density_maximum"),
        "mwp": ("Mean wave period", "s",
                "sea_surface_wave_mean_period_from_variance_spectral_density_inverse_frequency_moment"),
        "mwd": ("Mean wave direction", "degree", "sea_surface_wave_from_direction"),
        "shww": ("Significant height of wind waves", "m", "sea_surface_wind_wave_significant_height"),
        "mpww": ("Mean period of wind waves", "s", None),
        "mdww": ("Mean direction of wind waves", "degree", "sea_surface_wind_wave_from_direction"),
        "shts": ("Significant height of total swell", "m", "sea_surface_swell_wave_significant_height"),
        "mpts": ("Mean period of total swell", "s", None),
        "mdts": ("Mean direction of total swell", "degree", "sea_surface_swell_wave_from_direction"),
    }
    ds = xr.Dataset(coords={"valid_time": df.index.values, "latitude": [28.9], "longitude": [-78.5]})
    for name, v in values.items():
        long_name, unit, std = meta[name]
        attrs = {"long_name": long_name, "units": unit, "GRIB_shortName": name}
        if std:
            attrs["standard_name"] = std
        ds[name] = (("valid_time", "latitude", "longitude"), np.asarray(v, float)[:, None, None], attrs)
    ds.attrs.update(Conventions="CF-1.7", title="SYNTHETIC ERA5-like wave partitions", comment=NOTE,
                    institution="none (synthetic)")
    ds.to_netcdf(path)


def write_table(path):
    """An Hs-Tp scatter table: a made-up joint distribution favouring long swell periods."""
    hs_edges = np.arange(0.0, 4.01, 0.5)
    tp_edges = np.arange(6.0, 20.01, 2.0)
    hs_c, tp_c = 0.5 * (hs_edges[1:] + hs_edges[:-1]), 0.5 * (tp_edges[1:] + tp_edges[:-1])
    counts = np.round(1000 * np.exp(-((hs_c[:, None] - 1.5) ** 2) / 0.8 - ((tp_c[None, :] - 12.0) ** 2) / 12.0))
    counts[hs_c[:, None] > 0.4 * tp_c[None, :] - 1.0] = 0           # no steep cells
    lines = [f"# {NOTE}", "# layout: matrix", "# hs_bins: edges", "# tz_bins: edges", "# values: counts",
             "# description: synthetic Hs-Tp table (the tz axis holds Tp: declare period: tp)",
             "hs\\tp," + ",".join(f"{a:.1f}-{b:.1f}" for a, b in zip(tp_edges[:-1], tp_edges[1:]))]
    for k, (a, b) in enumerate(zip(hs_edges[:-1], hs_edges[1:])):
        lines.append(f"{a:.1f}-{b:.1f}," + ",".join(f"{int(v)}" for v in counts[k]))
    path.write_text("\n".join(lines) + "\n")


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    df = series()
    write_csv(df, OUT / "partitions_synthetic.csv")
    write_era5(df, OUT / "era5_partitions_synthetic.nc")
    write_table(OUT / "torsethaugen_hs_tp_synthetic.csv")
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main()
