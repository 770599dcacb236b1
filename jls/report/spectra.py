"""Chapter "Wave spectra": which spectrum each leg was assessed with and where it came
from (sea_states.nc attributes ``leg_kind_<leg>``, ``period_conversion_<leg>``,
``source_<leg>``), and, for the legs given by measured spectra, how the relative sway
integrated directly over them compares with the single JONSWAP on the same (Hs, Tz)
(``measured_response.nc``, :mod:`jls.stages.measured_response`): the probability-weighted
ratio of relative-sway sigma, per option, as the dataset holds it."""

from __future__ import annotations

from jls.report.context import Context, combo_text, heading
from jls.report.markup import cell, figure, num, t, table
from jls.report.style import Task

KINDS = {
    "scatter": "scatter table of Hs-Tz cells",
    "hindcast": "hourly hindcast (Hs, Tz), binned",
    "metocean": "hourly integrated parameters, binned",
    "spectra": "hourly measured spectra: workability judged hour by hour, cells binned on Hs and Tm02",
}


def used_spectrum(cx: Context, leg: str) -> str:
    """What the assessment of ``leg`` used, in words."""
    a = cx.sea.attrs
    gamma = float(cx.resp.attrs.get("gamma", 3.3))
    kind = str(a.get(f"leg_kind_{leg}", "scatter"))
    text = f"JONSWAP, gamma {gamma:g}, Tp from Tz (DNV-RP-C205), on each cell"
    conv = str(a.get(f"period_conversion_{leg}", ""))
    if kind == "metocean" and conv:
        text += f"; the file's period: {conv}"
    if kind == "spectra":
        text += ("; Tz = Tm02 of each spectrum; in the workability, the weather windows and the route simulation "
                 "each hour's relative sway scaled by its measured-spectrum ratio (below)")
    model = sea_model_of(cx, leg)
    if model in SEA_MODEL_TEXT:
        text = (f"{SEA_MODEL_TEXT[model]}; cells binned as JONSWAP, gamma {gamma:g}, on "
                + ("Hs and the Tz of the sum of the partitions" if model == "partitions" else
                   "Hs and the Tz of the JONSWAP with the table's Tp")
                + "; in the workability" + (", the weather windows and the route simulation" if model == "partitions" else "")
                + " the relative sway scaled by the ratio (below)")
    return text


#: how a leg's declared sea model is integrated, in words (measured_response.nc)
SEA_MODEL_TEXT = {
    "partitions": "each hour's wind-sea and swell partitions, JONSWAP each, spread and met at their own "
                  "directions (spectrum: partitions)",
    "torsethaugen": "each cell's Torsethaugen wind sea and swell (DNV-RP-C205 3.5.7) at the table's Hs and Tp "
                    "(spectrum: torsethaugen)",
}


def sea_model_of(cx: Context, leg: str) -> str:
    """The sea model of a leg integrated directly (the prefix of its integration text in
    measured_response.nc), or "" for a JONSWAP leg."""
    m = cx.measured
    if m is None or str(leg) not in {str(x) for x in m["leg"].values}:
        return ""
    text = str(m.attrs.get(f"integration_{leg}", ""))
    head = text.split(":", 1)[0]
    return head if head in ("partitions", "torsethaugen", "measured") else "measured"


def cost_rows(cx: Context) -> list[list]:
    """Per leg integrated directly: its sea model and the ratio of its relative-sway sigma
    to a long-crested and to a short-crested JONSWAP on the same (Hs, Tz), probability-
    weighted, for the recommendation (dataset values, three decimals)."""
    m, best = cx.measured, cx.dg.best
    rows = []
    for leg in m["leg"].values:
        vals = []
        for v in ("sigma_ratio", "sigma_ratio_short_crested"):
            r = m[v].sel(leg=leg)
            opts = {(str(c), str(g)) for c in r["candidate"].values for g in r["tugger"].values}
            vals.append(num(float(r.sel(candidate=best[0], tugger=best[1])), 3) if best in opts else "–")
        rows.append([cell(t(str(leg)), raw=True), cell(t(sea_model_of(cx, str(leg))), raw=True), *vals])
    return rows


def workability_rows(cx: Context) -> list[list]:
    """Per spectra leg: the recommendation's leg workability judged hour by hour on the
    measured spectra (the assessment's) and over the binned JONSWAP cells, in percent as
    the dataset holds them."""
    w, best = cx.work, cx.dg.best
    rows = []
    for leg in cx.measured["leg"].values:
        at = dict(candidate=best[0], tugger=best[1], leg=leg)
        hourly, binned = (100 * float(w[v].sel(at)) for v in ("workability_leg", "workability_leg_binned"))
        rows.append([cell(t(str(leg)), raw=True), num(hourly, 1), num(binned, 1), num(hourly - binned, 1)])
    return rows


def ratio_rows(cx: Context) -> list[list]:
    """Per spectra leg: hours, integration, the ratio of the report's recommendation and
    the range over every option (dataset values, three decimals)."""
    m = cx.measured
    best = cx.dg.best
    rows = []
    for leg in m["leg"].values:
        r = m["sigma_ratio"].sel(leg=leg)
        opts = {(str(c), str(g)) for c in r["candidate"].values for g in r["tugger"].values}
        shown = num(float(r.sel(candidate=best[0], tugger=best[1])), 3) if best in opts else "–"
        rows.append([cell(t(str(leg)), raw=True), str(int(m["hours"].sel(leg=leg))),
                     cell(t(str(m.attrs.get(f"integration_{leg}", ""))), raw=True), shown,
                     f"{num(float(r.min()), 3)} – {num(float(r.max()), 3)}"])
    return rows


def leg_models(cx: Context) -> dict:
    """{leg: its sea model}: "jonswap" or the declared one of a leg integrated directly."""
    return {str(leg): sea_model_of(cx, leg) or "jonswap" for leg in cx.legs}


def figure_plan(cx: Context) -> list[Task]:
    from jls.report.spectra_figure import NAME, sea_transfer
    models = leg_models(cx)
    return [Task(NAME, lambda d: sea_transfer(cx, models, d), 1.0 + 0.5 * len(models))]


def _figure(cx: Context) -> str:
    from jls.report.spectra_figure import NAME, TOP_CELLS
    if NAME not in cx.figs:
        return ""
    return figure(cx.figs[NAME], "Where the energy meets the resonance: per leg, its typical wave "
                  "spectra S (solid; a leg of partitions or measured spectra: the probability-weighted mean "
                  f"of its hours; a JONSWAP or Torsethaugen leg: its {TOP_CELLS} most probable cells, each "
                  "with its share of the leg) against the relative-sway transfer function |H| per unit wave "
                  f"amplitude (dashed, right axis) of the recommendation ({t(combo_text(cx.dg.best))}) at the "
                  "leg's most probable heading; dotted: its sway period. From the sea-state, response, plant "
                  "and measured-response datasets.", width="95%")


def chapter(cx: Context) -> str:
    out = [heading("spectra", "Wave spectra")]
    a = cx.sea.attrs
    rows = [[cell(t(leg), raw=True), cell(t(KINDS.get(str(a.get(f"leg_kind_{leg}", "scatter")), "")), raw=True),
             cell(t(str(a.get(f"source_{leg}", ""))), raw=True), cell(t(used_spectrum(cx, leg)), raw=True)]
            for leg in cx.legs]
    out.append("Every scatter cell of the assessment (cells, limiting Hs, long-term voyage "
               "extremes) is a single-peak JONSWAP built from its Hs and Tz; the time-domain cells of a "
               "leg whose sea is its own (partitions, measured spectra, a Torsethaugen table) run on a "
               "multi-directional record of that leg's sea in the cell, the others on that JONSWAP. "
               + (t(str(cx.work.attrs["hourly_rule"])) + " " if "hourly_rule" in cx.work.attrs else "")
               + "The table says what each leg's statistics were built from.\n")
    out.append(table("Wave statistics of each leg: the kind of record, its file and the "
                     "spectrum the assessment used.", ["leg", "record", "file", "spectrum used"],
                     rows, align="(left, left, left, left)"))
    out.append(_figure(cx))
    m = cx.measured
    if m is None:
        out.append("No leg of this route is given by measured spectra, so the single-JONSWAP "
                   "simplification is not compared with the sea as measured here.\n")
        return "\n".join(out)
    out.append(
        "For each leg given by measured spectra, the relative sway of every hour was also "
        "integrated directly over the measured spectrum, each direction bin met at its own "
        "relative heading on the leg's course (spreading and any swell included, no "
        "parametric fit), and beside it over the JONSWAP with the hour's Hs and Tz = Tm02 met at "
        "the heading of the hour's mean direction. The ratio is the sum over the leg's hours of "
        "the measured-spectrum sigma over the same sum for the JONSWAP (each hour equally "
        "probable): above 1, the single JONSWAP understates the sway the measured seas drive. "
        f"Shown: the recommendation ({t(combo_text(cx.dg.best))}) and the range over all "
        "rigging and tugger options (the measured-response dataset).\n")
    out.append(table("Relative-sway sigma over the measured spectra against a single JONSWAP on "
                     "the same (Hs, Tz), per spectra leg.",
                     ["leg", "hours", "integration", "ratio, recommendation", "ratio, all options"],
                     ratio_rows(cx), align="(left, right, left, right, right)"))
    if "sigma_ratio_short_crested" in m:
        out.append("What each leg's sea model costs: the relative-sway sigma of its sea (measured "
                   "spectra, partitions or Torsethaugen systems) over that of a long-crested JONSWAP "
                   "and of a short-crested JONSWAP (spread as sea.spreading.wind about the hour's mean "
                   "direction) on the same (Hs, Tz), summed over the leg's hours or weighted by its "
                   f"cells' probability, for the recommendation ({t(combo_text(cx.dg.best))}; "
                   "measured_response.nc: sigma_ratio, sigma_ratio_short_crested).\n")
        out.append(table("Relative-sway sigma of each leg's sea model against a JONSWAP on the same "
                         "(Hs, Tz), long-crested and short-crested.",
                         ["leg", "sea model", "ratio, long-crested", "ratio, short-crested"],
                         cost_rows(cx), align="(left, left, right, right)"))
    out.append(own_sea_text(cx))
    if "workability_leg_binned" in cx.work:
        out.append(table("Leg workability of the recommendation, hour by hour on the measured "
                         "spectra (the assessment's) against the binned JONSWAP cells [%] "
                         "(the workability dataset).",
                         ["leg", "hourly, measured", "binned, JONSWAP", "difference [pp]"],
                         workability_rows(cx), align="(left, right, right, right)"))
    return "\n".join(out)


def own_sea_text(cx: Context) -> str:
    """Which stages judge the hours of these legs on their own sea and which do not."""
    from jls.assessment.hourly import OWN_SEA_NOT_USED
    m = cx.measured
    legs = t(", ".join(str(leg) for leg in m["leg"].values))
    if "utilisation" not in m:
        return ("The weather windows, the route simulation and voyage extremes and the departure "
                f"simulation of leg(s) {legs} {t(OWN_SEA_NOT_USED)}.\n")
    crit = t(", ".join(str(c) for c in m["criterion"].values))
    v = cx.voyage
    note = "" if v is None else str(v.attrs.get("own_sea_not_used", ""))
    scatter = v is not None and "own_sea_level_ratio" in v
    stats = ("its level there its utilisation times the limit, its up-crossing period its own sea's "
             "(measured_response.nc tz_response_own) and its sigma the one whose MPM at that period is the level"
             if "tz_response_own" in m else
             "its level there its utilisation times the limit, its sigma moved by the same factor, its "
             "up-crossings at the response period of the JONSWAP on its (Hs, Tz)")
    return (f"Each recorded hour of leg(s) {legs} is judged on its own directional sea for every "
            f"criterion ({crit}; measured_response.nc utilisation, the functions of jls response and "
            "jls forecast) in "
            "the workability, the weather windows, the route simulation's voyage maxima, the "
            "departure simulation and the long-term voyage extreme of the recorded hours as cells "
            f"(the hindcast variables of voyage.nc; {stats})"
            + ("; the long-term voyage extreme of the scatter cells takes each record (an hour, or a "
               "table's cell) at each heading with its probability and its own sea's sigma and period in place "
               "of the leg's binned JONSWAP cells (voyage_level; voyage_level_jonswap is the same voyage on "
               "every leg's binned JONSWAP)" if scatter else "")
            + ". Not on it: "
            + ("" if scatter else "the long-term voyage extreme of the scatter cells (the hours binned on "
               "(Hs, Tz): JONSWAP seas), ")
            + "the winch limits, uncertainty bands and time-domain cells of the leg's binned JONSWAP cells"
            + (f"; {t(note)} (attribute own_sea_not_used of voyage.nc)" if note else "") + ".\n")


def own_sea_level_ratio(cx: Context) -> float | None:
    """The recommendation's relative-sway voyage level (median) with the own-sea legs'
    records over that with every leg's binned JONSWAP (``voyage.nc`` ``own_sea_level_ratio``),
    None where the dataset has none."""
    from jls.names import SWAY_M
    v, best = cx.voyage, cx.dg.best
    if v is None or "own_sea_level_ratio" not in v or SWAY_M not in v["criterion"].values \
            or best[0] not in v["candidate"].values or best[1] not in v["tugger"].values:
        return None
    return float(v["own_sea_level_ratio"].sel(candidate=best[0], tugger=best[1], criterion=SWAY_M)
                 .sel(non_exceedance=0.5, method="nearest"))


def page_one_warning(cx: Context) -> str:
    """Page 1's warning where the measured seas drive more sway than the single JONSWAP:
    a spectra leg's workability, weather windows, route and departure simulations judge
    every criterion on each hour's own sea (``measured_response.nc`` ``utilisation``), and so
    does the long-term voyage extreme of its recorded hours as cells (``hindcast_*`` of
    ``voyage.nc``, a route of hourly legs), but the long-term voyage extreme of its scatter
    cells takes the legs' own-sea records as well, and the warning gives the voyage-level
    ratio of the recommendation (own sea over binned JONSWAP, ``own_sea_level_ratio``:
    :func:`_scatter_sentence`), not the sigma ratio, which can overstate or reverse it (its
    time-domain cells run on its own sea, :mod:`jls.timedomain.cell_sea`). Empty without
    spectra legs or where every sigma ratio (the recommendation's, at two decimals) is at most 1."""
    m = cx.measured
    if m is None:
        return ""
    best = cx.dg.best
    high = []
    for leg in m["leg"].values:
        r = m["sigma_ratio"].sel(leg=leg)
        opts = {(str(c), str(g)) for c in r["candidate"].values for g in r["tugger"].values}
        value = float(r.sel(candidate=best[0], tugger=best[1])) if best in opts else float(r.max())
        if round(value, 2) > 1.0:
            high.append(f"{leg} {num(value, 2)} x")
    if not high:
        return ""
    hours_own = "utilisation" in m and cx.voyage is not None and "hindcast_voyage_level" in cx.voyage
    return (f"#warning[*Sea model:* on the legs given by measured spectra, partitions or Torsethaugen systems "
            f"the relative sway exceeds a single JONSWAP's on the same (Hs, Tz): {t('; '.join(high))}, "
            f"{combo_text(best)}; {cx.sec('spectra')}. " + (
                "Their workability, weather windows, route and departure simulations judge every criterion "
                "on each hour's own sea" if "utilisation" in m else
                "Their workability, weather windows and route simulation include the sway hour by hour")
            + (" (as does the long-term voyage extreme of their recorded hours)" if hours_own else "")
            + "; their time-domain cells run on their own sea; " + _scatter_sentence(cx) + "]\n")


def _scatter_sentence(cx: Context) -> str:
    """Page 1: what the long-term voyage extreme of the scatter cells makes of the own seas:
    the voyage-level ratio (``own_sea_level_ratio``, the recommendation's median relative
    sway), not the sigma ratio, which can overstate or reverse it."""
    r = own_sea_level_ratio(cx)
    note = "" if cx.voyage is None else str(cx.voyage.attrs.get("own_sea_not_used", ""))
    if r is None:
        return ("the long-term voyage extremes of their scatter cells are JONSWAP seas on the binned (Hs, Tz) "
                "(the sigma ratio above is not the ratio of their voyage levels).")
    side = "above" if round(r, 2) > 1.0 else "below" if round(r, 2) < 1.0 else "equal to"
    return (f"the long-term voyage extreme of their scatter cells takes their own seas: the recommendation's "
            f"median voyage level of the relative sway is {num(r, 2)} x that of JONSWAP seas on the binned "
            f"(Hs, Tz) ({side} it; voyage.nc own_sea_level_ratio)"
            + (f"; not on their own seas: {t(note)}." if note else "."))


__all__ = ["chapter", "figure_plan", "leg_models", "used_spectrum", "ratio_rows", "workability_rows", "page_one_warning", "own_sea_level_ratio", "cost_rows",
           "sea_model_of", "SEA_MODEL_TEXT"]
