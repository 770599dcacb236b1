"""Write tests/data/metocean/41010h2019part.txt: an NDBC standard meteorological file of
the 99 records of the committed NDBC 41010 spectra (tests/data/spectra/ndbc_41010_2019/),
WVHT, DPD, APD and MWD computed from the spectra with jls's integration rule
(jls.sea.measured.integrated_parameters; MWD the energy-weighted mean direction of the
Fourier reconstruction, jls.sea.records.mean_direction). The other columns are NDBC's
missing-value codes: the spectra do not give them.

Usage: python scripts/make_ndbc_stdmet_fixture.py [--out FILE]
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
import pandas as pd

from jls.sea.measured import integrated_parameters, read_spectra
from jls.sea.records import mean_direction

ROOT = Path(__file__).resolve().parents[1]
SPECTRA = ROOT / "tests" / "data" / "spectra" / "ndbc_41010_2019" / "41010w2019part.txt.gz"
OUT = ROOT / "tests" / "data" / "metocean" / "41010h2019part.txt"
HEADER = ("#YY  MM DD hh mm WDIR WSPD GST  WVHT   DPD   APD MWD   PRES  ATMP  WTMP  DEWP  VIS  TIDE\n"
          "#yr  mo dy hr mn degT m/s  m/s     m   sec   sec degT   hPa  degC  degC  degC   mi    ft\n")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", type=Path, default=OUT)
    args = ap.parse_args(argv)
    efth = read_spectra(SPECTRA, "ndbc")
    ip = integrated_parameters(efth)
    mwd = mean_direction(efth)
    rows = []
    for k, t in enumerate(pd.DatetimeIndex(efth["time"].values)):
        rows.append(f"{t:%Y %m %d %H %M} 999 99.0 99.0 {float(ip['hs'][k]):5.2f} {float(ip['tp'][k]):5.2f} "
                    f"{float(ip['tm02'][k]):5.2f} {int(np.round(mwd[k])) % 360:3d} 9999.0 999.0 999.0 "
                    "999.0 99.0 99.00\n")
    args.out.write_text(HEADER + "".join(rows))
    print(f"wrote {args.out} ({len(rows)} records)")


if __name__ == "__main__":
    main()
