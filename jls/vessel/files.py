"""RAO files: which reader a file needs (by declared format or suffix), and reading it
into the jls layout (:mod:`jls.vessel.rao`) with its plausibility checks."""

from __future__ import annotations

from pathlib import Path

import xarray as xr

from jls.errors import InputError
from jls.io.files import MB, regular_file
from jls.io.netcdf import ENGINE
from jls.vessel.rao import check_rao, first_line, read_rao_netcdf


def load_rao(path, format: str | None = None, **kwargs) -> xr.Dataset:
    """Read any supported RAO file into the jls layout.

    ``format`` is one of "wamit4" (alias "wamit"), "capytaine", "jls" (alias
    "netcdf"), "csv", "orcaflex" (an OrcaFlex vessel type, YAML text), "aqwa_lis" (an
    AQWA-LINE listing); by default it is inferred from the suffix: ``.4`` WAMIT, ``.csv``
    CSV, ``.yml``/``.yaml`` OrcaFlex, ``.lis`` AQWA, ``.nc`` either a jls file (variable
    ``rao`` with dim ``dof``) or a Capytaine RAO file.
    Extra keyword arguments go to the reader.
    """
    path = Path(path)
    fmt = rao_format(path, format)
    if fmt == "wamit4":
        from jls.vessel.wamit import read_wamit4
        ds = read_wamit4(path, **kwargs)
    elif fmt == "csv":
        from jls.vessel.csv_io import read_rao_csv
        ds = read_rao_csv(path, **kwargs)
    elif fmt == "capytaine":
        from jls.vessel.capytaine_io import read_capytaine_nc
        ds = read_capytaine_nc(path, **kwargs)
    elif fmt == "jls":
        ds = read_rao_netcdf(path)
    elif fmt == "orcaflex":
        from jls.vessel.orcaflex import read_orcaflex_vessel_type
        ds = read_orcaflex_vessel_type(path, **kwargs)
    elif fmt == "aqwa_lis":
        from jls.vessel.aqwa import read_aqwa_lis
        ds = read_aqwa_lis(path, **kwargs)
    else:
        raise InputError("unknown RAO format (wamit4, capytaine, jls, csv, orcaflex, aqwa_lis)",
                         file=path,
                         field="format", value=format)
    check_rao(ds, file=path)
    return ds


MAX_RAO_BYTES = 2048 * MB          # a NetCDF of 37 headings x 500 frequencies is ~2 MB


def rao_format(path, format: str | None = None) -> str:
    """The reader a file needs: ``format`` (aliases allowed) or inferred from the file."""
    path = Path(path)
    if not path.exists():
        raise InputError("RAO file not found", file=path, field="path", value=str(path))
    regular_file(path, "RAO file", MAX_RAO_BYTES, field="path")     # not a pipe or device
    if format:
        return _FORMAT_ALIASES.get(str(format).lower().strip(), str(format).lower())
    return _format_from_suffix(path)


_FORMAT_ALIASES = {"wamit": "wamit4", ".4": "wamit4", "4": "wamit4", "netcdf": "jls",
                   "nc": "jls", "capytaine_nc": "capytaine", ".csv": "csv",
                   "aqwa": "aqwa_lis", "lis": "aqwa_lis", "yml": "orcaflex", "yaml": "orcaflex"}


def _format_from_suffix(path: Path) -> str:
    suffix = path.suffix.lower()
    if suffix == ".4":
        return "wamit4"
    if suffix == ".csv":
        return "csv"
    if suffix in (".yml", ".yaml"):
        return "orcaflex"
    if suffix == ".lis":
        return "aqwa_lis"
    if suffix in (".nc", ".nc4", ".netcdf"):
        try:
            with xr.open_dataset(path, engine=ENGINE) as raw:
                is_jls = "rao" in raw and "dof" in raw["rao"].dims
        except (OSError, ValueError) as exc:
            raise InputError(f"cannot read NetCDF file: {first_line(exc)}", file=path) from None
        return "jls" if is_jls else "capytaine"
    raise InputError("cannot infer the RAO format from the suffix (.4, .csv, .nc, .yml, .lis); "
                     "pass format=", file=path, field="format", value=path.suffix)


