"""The pre-transit report of ``jls forecast``: one or two pages that answer go or no-go
for each option on a forecast, with the forecast's wave systems and each option's hourly
utilisation against time (the go window shaded, the governing criterion named) and the
basis (alpha and its source, contingency, the forecast's file and issue time).

Every number printed is read from the answer (:func:`jls.stages.forecast.answer`) the
JSON output holds, so the two always agree.
"""

from __future__ import annotations

import shutil
import tempfile
from importlib import resources
from pathlib import Path

import numpy as np
import pandas as pd

from jls.io.atomic import write_atomically
from jls.report.markup import cell, figure, t, table
from jls.report.style import STYLE, new_figure, save

__all__ = ["write_pdf", "source"]

MAX_LINES = 8          # options drawn in the utilisation plot (the rest are in the table)


def _times(ds):
    return pd.DatetimeIndex(ds["time"].values)


def _draw_systems(ds, out_dir):
    import matplotlib
    with matplotlib.rc_context(STYLE):
        fig = new_figure(2.6)
        ax1, ax2 = fig.subplots(2, 1, sharex=True)
        x = _times(ds)
        spectra = ds.attrs["forecast_format"] == "spectra"
        if spectra:                      # a measured spectrum: its total Hs, and Tp of its largest bin
            j = np.argmax(ds["hs"].values, axis=1)
            ax2.plot(x, ds["tp"].values[np.arange(len(x)), j], label="Tp of the largest direction bin")
        for j, kind in enumerate([] if spectra else ds["system"].values.tolist()):
            hs = np.where(ds["hs"].values[:, j] > 0, ds["hs"].values[:, j], np.nan)
            ax1.plot(x, hs, label=f"{kind}: Hs")
            ax2.plot(x, np.where(np.isfinite(hs), ds["tp"].values[:, j], np.nan), label=f"{kind}: Tp")
        ax1.plot(x, ds["hs_total"].values, color="black", lw=0.8, label="total Hs")
        ax1.set_ylabel("Hs [m]")
        ax2.set_ylabel("Tp [s]")
        ax1.legend(ncol=3, loc="upper left")
        ax2.legend(ncol=2, loc="upper left")
        return save(fig, out_dir, "forecast_systems")


def _drawn_options(out):
    rows = [(c, tg, o) for c, per in out["options"].items() for tg, o in per.items()]
    rows.sort(key=lambda r: (not r[2]["go"], -(r[2]["margin"] if r[2]["margin"] is not None else -9)))
    return rows[:MAX_LINES]


def _draw_utilisation(ds, out, out_dir):
    import matplotlib
    with matplotlib.rc_context(STYLE):
        fig = new_figure(3.0)
        ax = fig.subplots()
        x = _times(ds)
        start = int(ds.attrs["start_index"])
        need = int(ds.attrs["window_h"])
        ax.axvspan(x[start], x[min(start + need, len(x) - 1)], color="0.85", zorder=0,
                   label="leg and contingency from the planned start")
        for c, tg, o in _drawn_options(out):
            u = [h["utilisation"] if h["utilisation"] is not None else np.nan for h in o["hourly"]]
            ax.plot(x, u, label=f"{c} / {tg}" + (" (go)" if o["go"] else ""))
        ax.axhline(1.0, color="tab:red", lw=1.0, label="forecast limit (utilisation 1)")
        ax.set_ylabel("utilisation / alpha")
        ax.set_ylim(bottom=0)
        fig.legend(ncol=3, loc="outside lower center")
        return save(fig, out_dir, "forecast_utilisation")


def source(ds, out, figures: dict) -> str:
    """Typst source of the pre-transit report."""
    a = out
    any_go = any(o["go"] for per in a["options"].values() for o in per.values())
    head = ("GO: the leg may start at the planned time with the options marked go."
            if any_go else "NO-GO: no option keeps the whole leg inside the forecast limits from the planned start.")
    if any_go and a["criteria_not_evaluated"]:
        head = ("GO on the criteria evaluated here, for the options marked go; "
                + ", ".join(a["criteria_not_evaluated"]) + " not evaluated: check before sailing.")
    lines = [
        '#import "template.typ": *',
        f'#show: report.with(title: [{t("Pre-transit forecast check, route " + a["route"] + ", leg " + a["leg"])}], '
        f'subtitle: [{t("Forecast issued " + a["issued"] + " · planned start " + a["start"])}], '
        f'footer-left: [{t("jls forecast · " + Path(a["forecast"]["file"]).name)}])',
        "",
        f"*{t(head)}*",
        "",
        t(f"The leg lasts {a['duration_h']:g} h with {a['contingency_h']:g} h of contingency "
          f"({a['contingency_source']}): every one of its {a['window_h']} hours must stay inside the forecast "
          f"limits. Alpha: {a['alpha_source']}. Heading: {a['heading_basis']}. Options: {a['options_from']}. Each hour's utilisation is the "
          f"largest over the criteria of its {a['exposure_h']:g}-h MPM over the limit (the tip clearance and the "
          "wire tension as the workability defines them), divided by alpha."),
        "",
    ]
    if a["criteria_not_evaluated"]:
        lines += [f"*{t('Not evaluated by this check: ' + ', '.join(a['criteria_not_evaluated']) + '. Check them separately before sailing.')}*", ""]
    rows = []
    for c, per in a["options"].items():
        for tg, o in per.items():
            g = o["governing"]
            rows.append([c, tg, cell("GO" if o["go"] else "NO-GO", bold=True),
                         o["first_start"] or "none in the forecast",
                         f"{g['criterion']} at {g['hour']}" if g else "–",
                         f"{100 * o['margin']:.0f} %" if o["margin"] is not None else "–",
                         o["reason"] or "–"])
    lines.append(table("Go or no-go per option from the planned start; first start from which the whole leg "
                       "stays inside; the governing criterion and hour of the window from the planned start, "
                       "and its margin (1 - utilisation).",
                       ["candidate", "tugger", "answer", "first start", "governing", "margin", "why not"], rows,
                       size="7.5pt"))
    lines.append(figure(figures["systems"], "The forecast's wave systems: Hs and Tp per hour."))
    lines.append(figure(figures["utilisation"], "Utilisation per hour (over alpha) of the options (up to "
                        f"{MAX_LINES}, those that go first); the shaded band is the leg and its contingency "
                        "from the planned start."))
    lines.append(t(f"Forecast file {a['forecast']['file']} ({a['forecast']['format']}, sha256 "
                   f"{a['forecast']['sha256'][:16]}); criteria and limits: "
                   + ", ".join(f"{k} {v:g}" for k, v in a["criteria"].items()) + "."))
    return "\n".join(lines) + "\n"


def write_pdf(ds, out, pdf_path) -> Path:
    """Draw the figures, write and compile the Typst source; the PDF replaces
    ``pdf_path`` atomically."""
    from jls.report.document import compile_pdf
    pdf_path = Path(pdf_path)
    with tempfile.TemporaryDirectory() as tmp:
        d = Path(tmp)
        shutil.copy(resources.files("jls.report").joinpath("template.typ"), d / "template.typ")
        figs = {"systems": _draw_systems(ds, d).name, "utilisation": _draw_utilisation(ds, out, d).name}
        (d / "forecast.typ").write_text(source(ds, out, figs), encoding="utf-8")
        write_atomically(pdf_path, lambda tmp_pdf: compile_pdf(d / "forecast.typ", Path(tmp_pdf)),
                         suffix=".pdf")
    return pdf_path
