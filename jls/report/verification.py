"""The report chapter "Verification against a nonlinear reference" (chapter 4 of the
study on the rigging the report recommends) and the sentence page 1 carries about it.

Reads the context's ``verification`` (the verification cell datasets, layout
``verification_cell`` of the registry, :mod:`jls.stages.verification_cell`; a cell's
attributes ``roles`` and ``reasons`` say why it was chosen when the pipeline knows) and
the digest's ``best`` (the recommendation), ``baseline`` and ``no_tugger``; its figure,
when planned (:func:`figure_plan`), from ``figs``.

* :func:`verification` - the chapter: per verified cell the ROM over the reference of
  the relative-sway sigma and MPM and the verdict (within the tolerance or not,
  conservative or not), per verified combination the sway free decay and the harmonic
  transfer function of both models, and the periods of both models including the modes
  the ROM does not carry (surge, pitch);
* :func:`page_one_sentence` - whether the recommendation was confirmed and by how much
  the ROM over- or under-predicts there, or that it is unverified and why.
"""

from __future__ import annotations

import matplotlib
import numpy as np

from jls.report.markup import figure, num, t, table
from jls.report.style import STYLE, Task, new_figure, save
from jls.report.verification_study import study_section, wires_text

MAX_TRACE_CELLS = 4
REFERENCE_DOFS = ("surge", "sway", "heave", "roll", "pitch", "yaw")
NOT_IN_ROM = ("surge", "pitch")
FIGURE = "verification_traces"


# -- what the chapter shows ---------------------------------------------------------------
def verified(ds) -> bool:
    return bool(ds["verified"]) and str(ds.attrs.get("status", "")) == "verified"


def combo(ds) -> tuple:
    return (str(ds.attrs["candidate"]), str(ds.attrs["tugger"]))


def role(cx, ds) -> str:
    """'recommendation', 'baseline' (both, joined) or the cell's own roles."""
    roles = []
    if combo(ds) == tuple(cx.dg.best):
        roles.append("recommendation")
    if combo(ds) == (cx.dg.baseline, cx.dg.no_tugger):
        roles.append("baseline")
    return ", ".join(roles) or str(ds.attrs.get("roles", "")) or "configured"


def ordered(cx) -> list:
    """The cells, the recommendation's first, then the baseline's, then the others."""
    def key(ds):
        r = role(cx, ds)
        return (0 if "recommendation" in r else 1 if "baseline" in r else 2, str(ds.attrs["cell"]))
    return sorted(cx.verification, key=key)


def percent_off(ratio: float, what="the MPM") -> str:
    """'over-predicts the MPM by 1.2 %' / 'under-predicts ...' of a ROM / reference ratio."""
    d = 100.0 * (float(ratio) - 1.0)
    return f"{'over' if d >= 0 else 'under'}-predicts {what} by {num(abs(d), 1)} %"


def comparable(ds) -> bool:
    """The cell ran on a reference damped as the ROM (its verdict is not "not comparable")."""
    return verified(ds) and str(ds.attrs.get("verdict", "")) != "not comparable"


def verdict_text(ds) -> str:
    """The verdict of one cell in words."""
    if not verified(ds):
        return f"not verified: {ds.attrs.get('reason', '')}"
    if not comparable(ds):
        return f"not comparable: {ds.attrs.get('verdict_reason', '')}"
    tol = num(100 * float(ds["tolerance"]), 0)
    within = "within" if bool(ds["within_tolerance"]) else "outside"
    cons = "conservative" if bool(ds["conservative"]) else "not conservative"
    out = f"{within} the {tol} % tolerance, {cons}: the ROM {percent_off(ds['mpm_ratio'])}"
    if not bool(ds["within_tolerance"]) and not bool(ds["conservative"]):
        out += "; the workability there may be overstated"
    return out


def _cell_label(ds) -> str:
    return (f"{ds.attrs['candidate']} / {ds.attrs['tugger']}, {float(ds.attrs['heading_deg']):g}°, "
            f"Hs {float(ds.attrs['hs_m']):g} m, Tz {float(ds.attrs['tz_s']):g} s")


def _per_combination(cells) -> list:
    """The first verified cell of each (candidate, tugger): decay, transfer function and
    periods depend on the combination, not on the sea state."""
    seen, out = set(), []
    for ds in cells:
        if verified(ds) and combo(ds) not in seen:
            seen.add(combo(ds))
            out.append(ds)
    return out


# -- page 1 ---------------------------------------------------------------------------------
def page_one_sentence(cx) -> str:
    """Page 1's sentence on the recommendation's verification (Typst markup)."""
    best = tuple(cx.dg.best)
    name = t(f"{best[0]} rigging, tugger {best[1]}")
    mine = [ds for ds in cx.verification if combo(ds) == best]
    ran = [ds for ds in mine if verified(ds)]
    done = [ds for ds in ran if comparable(ds)]
    if ran and not done:
        return (f"*The recommendation ({name}) is unverified*: in none of its cells was the "
                f"nonlinear reference damped as the ROM ({t(ran[0].attrs.get('verdict_reason', ''))}).")
    if not mine:
        return (f"*The recommendation ({name}) is unverified*: no verification cell of it was run "
                "against the nonlinear reference (`verification.enabled` is false, or the "
                "recommendation is not among `verification.combinations`).")
    if not done:
        return (f"*The recommendation ({name}) is unverified*: the nonlinear reference could not "
                f"run ({t(mine[0].attrs.get('reason', ''))}).")
    worst = min(done, key=lambda ds: float(ds["mpm_ratio"]))
    ratios = [float(ds["mpm_ratio"]) for ds in done]
    tol = float(worst["tolerance"])
    span = (f"MPM ratio {num(min(ratios), 3)}" if len(done) == 1 else
            f"MPM ratios {num(min(ratios), 3)}-{num(max(ratios), 3)}")
    where = (f"in {len(done)} verified cell{'s' if len(done) > 1 else ''} ({span}, ROM over the "
             "6-DOF reference)")
    failing = [ds for ds in done if not bool(ds["within_tolerance"]) and not bool(ds["conservative"])]
    if failing:
        return (f"*The recommendation ({name}) is not confirmed* {where}: at {t(_cell_label(worst))} "
                f"the ROM {t(percent_off(worst['mpm_ratio'], 'the relative-sway MPM'))}, beyond the "
                f"{num(100 * tol, 0)} % tolerance, so its workability there may be overstated.")
    if all(bool(ds["conservative"]) for ds in done):
        ahead = f"so it is conservative there ({num(100 * tol, 0)} % tolerance)"
    else:
        ahead = f"within the {num(100 * tol, 0)} % tolerance"
    return (f"*The recommendation ({name}) is confirmed* against the nonlinear reference {where}: "
            f"at worst the ROM {t(percent_off(worst['mpm_ratio'], 'the relative-sway MPM'))}, "
            f"{ahead}.")


# -- the chapter --------------------------------------------------------------------------
def chapter(cx) -> str:
    """The chapter's markup (see :mod:`jls.report.chapters`)."""
    return verification(cx)


def verification(cx) -> str:
    out = ["= Verification against a nonlinear reference\n"]
    work = getattr(cx, "work", None)
    refused = str(work.attrs.get("verification_refused_legs", "")) if work is not None else ""
    if refused:                       # legs whose own sea the reference cannot run
        out.append(f"*Legs left out of the verification*: {t(refused)}.\n")
    cells = ordered(cx)
    if not cells:
        out.append("No cell was verified against the nonlinear reference (`verification.enabled` "
                   "is false, or no combination was chosen): nothing in this report has been "
                   "checked against an independent model, and the recommendation is unverified.\n")
        return "\n".join(out)
    done = [ds for ds in cells if verified(ds)]
    if not done:
        reason = cells[0].attrs.get("reason", "")
        out.append(f"#warning[*The nonlinear reference could not run*: {t(reason)}. None of the "
                   f"{len(cells)} chosen cells was verified, so nothing in this report has been "
                   "checked against an independent model and the recommendation is unverified.]\n")
        out.append(table("Chosen verification cells (not run).", ["cell", "role", "reason chosen"],
                         [[_cell_label(ds), role(cx, ds), str(ds.attrs.get("reasons", "")) or "–"]
                          for ds in cells]))
        return "\n".join(out)
    out.append(_method(done[0], [float(ds.attrs.get("transient_s", np.nan)) for ds in done],
                       [float(ds.attrs.get("reference_start_s", np.nan)) for ds in done]))
    out.append(page_one_sentence(cx) + "\n")
    out.append(_ratio_table(cx, cells))
    if FIGURE in cx.figs:
        out.append(figure(cx.figs[FIGURE], "Relative sway of the ROM and the reference over a window "
                          "from the middle of each record, identical vessel motion.", width="95%"))
    out.append(_decay_table(cx, _per_combination(done)))
    out.append(_damping_table(_per_combination(done)))
    out.append(_period_table(_per_combination(done)))
    out.append(_notes(done))
    wires = [w for w in getattr(cx, "verification_wires", []) if "reason" not in w.attrs]
    if wires:
        out.append(wires_text(wires))
    study = getattr(cx, "verification_study", None)
    if study is not None:
        out.append(study_section(study))
    return "\n".join(out)


def _damping_table(combos) -> str:
    """The reference damped as stated: per combination and reference mode the target
    ratio (the ROM's), the ratio a free decay along the mode measured, and the mode's
    share of the sway variance on the cell's record."""
    rows = []
    for ds in combos:
        if "damping_ratio_achieved" not in ds:
            continue
        tgt, ach = ds["damping_ratio_target"].values, ds["damping_ratio_achieved"].values
        share = ds["variance_share"].values if "variance_share" in ds else np.full(tgt.shape, np.nan)
        for j, dof in enumerate(map(str, ds["dominant_dof"].values)):
            rows.append([f"{ds.attrs['candidate']} / {ds.attrs['tugger']}", dof, num(100 * tgt[j], 3),
                         num(100 * ach[j], 3), num(100 * (ach[j] / tgt[j] - 1), 1),
                         "–" if not np.isfinite(share[j]) else num(100 * share[j], 1)])
    if not rows:
        return ""
    return table("The reference damped as the ROM: per mode of the reference the damping ratio its "
                 "dashpots are solved for (the ROM's ratio of the mode of the same dominant DOF; "
                 "surge the sway ratio, pitch the ROM's Rayleigh law), the ratio a small free decay "
                 "along the mode measures in MoorDyn (tugger lines held at their pretension), the "
                 "difference, and the mode's share of the jacket's sway variance on the cell's record. "
                 "A cell whose reference misses any target by more than 2 % is not comparable, "
                 "whatever its ratios.",
                 ["combination", "mode", "ζ target [%]", "ζ achieved [%]", "off [%]", "sway variance [%]"],
                 rows)


def page_one_what_was_verified(cx) -> str:
    """One short sentence for page 1: which cells, how close, what kind of check, and where
    the model's range ends (Typst markup; empty when nothing ran)."""
    done = [ds for ds in cx.verification if comparable(ds)]
    if not done:
        return ""
    ratios = [float(ds["mpm_ratio"]) for ds in done]
    n_ok = sum(str(ds.attrs.get("verdict", "")) == "verified" for ds in done)
    s = (f"Verified against an independent 6-DOF nonlinear model (same mass, stiffness and damping, "
         f"the wires' geometry exact): {n_ok} of {len(cx.verification)} cells within "
         f"{num(100 * float(done[0]['tolerance']), 0)} % (ROM over reference MPM "
         f"{num(min(ratios), 3)}-{num(max(ratios), 3)})")
    study = getattr(cx, "verification_study", None)
    if study is not None and np.isfinite(float(study.attrs.get("linear_range_hs_leaves_m", np.nan))):
        s += (f"; the geometric nonlinearity alone takes it outside from a relative-sway MPM of about "
              f"{num(float(study.attrs['linear_range_mpm_inside_m']), 0)} m")
    return s + "."


def _method(ds, transients, starts=()) -> str:
    a = ds.attrs
    lo, hi = min(transients), max(transients)
    start = (f"{num(lo, 0)} s" if abs(hi - lo) < 0.5 else f"{num(lo, 0)}-{num(hi, 0)} s")
    settle, note = [s for s in starts if np.isfinite(s)], ""
    if settle:                    # the reference started in the ROM's state (docs/verification.md)
        s0, s1 = min(settle), max(settle)
        span = f"{num(s0, 0)} s" if abs(s1 - s0) < 0.5 else f"{num(s0, 0)}-{num(s1, 0)} s"
        note = (f" The ROM starts from rest; the reference starts {span} before the statistics in the "
                "ROM's state at that instant (its position and velocity), so that only its own "
                "nonlinear difference from the ROM is left to settle.")
    return (
        "The ROM (the 4-DOF linear plant model every other chapter uses) is checked against an "
        f"independent 6-DOF nonlinear model of the same rigging: {t(a.get('reference', ''))}. "
        f"Damping: {t(a.get('damping', ''))}. Each cell drives both models with the same vessel "
        f"motion in one irregular sea state: a record of {num(float(a['duration_s']) / 60, 0)} min "
        f"after a start-up transient of {start} (five time constants of the ROM's slowest mode; "
        f"the study's records were 3 h, a longer record is `verification.duration_s`), RK4 at "
        f"{num(1000 * float(a['dt_s']), 0)} ms.{note} The relative-sway sigma and MPM of the ROM over "
        "the reference's is the ratio below: above 1 the ROM is conservative (it over-predicts), "
        f"and a cell is within tolerance when both ratios are within {num(100 * float(ds['tolerance']), 0)} % "
        "of 1, on a reference whose every mode has its target damping ratio within 2 % (else the "
        "cell is not comparable). Cells are chosen per verified combination: the live cells of the "
        "route nearest its workability boundary (relative-sway utilisation nearest 1), its design "
        "corner (the workable cell of the highest utilisation), the largest workable sea state on "
        "the heaviest leg, and a configured design sea state when enabled.\n")


def _ratio_table(cx, cells) -> str:
    rows = []
    for ds in cells:
        ok = verified(ds)

        def v(name, model=None, nd=3, ok=ok, ds=ds):
            if not ok:
                return "–"
            x = ds[name].sel(response="relative_sway") if name == "sigma" else ds[name]
            return num(float(x.sel(model=model) if model else x), nd)
        rows.append([_cell_label(ds), role(cx, ds), v("sigma", "rom"), v("sigma", "reference"),
                     v("sigma_ratio"), v("mpm", "rom", 2), v("mpm", "reference", 2), v("mpm_ratio"),
                     v("r", nd=4), verdict_text(ds)])
    return table("Verified cells: relative-sway sigma and 3-h MPM [m] of the ROM and the reference "
                 "on the same record, their ratio (ROM over reference), the correlation r of the "
                 "two records, and the verdict.",
                 ["cell (rigging / tugger, heading, sea state)", "role", "σ ROM", "σ ref.", "σ ratio",
                  "MPM ROM", "MPM ref.", "MPM ratio", "r", "verdict"], rows, size="7.5pt",
                 columns="(2fr, 1.3fr, auto, auto, auto, auto, auto, auto, auto, 2.6fr)",
                 align="(left, left, right, right, right, right, right, right, right, left)")


def _decay_table(cx, combos) -> str:
    periods = sorted({float(p) for ds in combos if "harmonic_gain" in ds for p in ds["period"].values})
    header = ["combination", "decay T ROM [s]", "T ref. [s]", "ζ ROM [%]", "ζ ref. [%]", "fit R²"]
    header += [f"gain ratio {p:g} s" for p in periods]
    rows = []
    for ds in combos:
        tp, z = ds["decay_period"], ds["decay_damping_ratio"]
        row = [f"{ds.attrs['candidate']} / {ds.attrs['tugger']}", num(float(tp.sel(model="rom")), 3),
               num(float(tp.sel(model="reference")), 3), num(100 * float(z.sel(model="rom")), 3),
               num(100 * float(z.sel(model="reference")), 3),
               num(float(ds["decay_fit_r2"].sel(model="reference")), 5)]
        for p in periods:
            if "harmonic_gain" in ds and p in ds["period"].values:
                g = ds["harmonic_gain"].sel(period=p).isel(amplitude=0)
                row.append(num(float(g.sel(model="rom") / g.sel(model="reference")), 3))
            else:
                row.append("–")
        rows.append(row)
    amp = next((float(ds["amplitude"].values[0]) for ds in combos if "harmonic_gain" in ds), None)
    harm = (f" Harmonic tests: steady-state |y - y_b| / |y_b| of the ROM over the reference's "
            f"under a hinge sway of {amp:g} m amplitude at each period."
            if amp is not None else " No harmonic test was configured (`verification.harmonic_periods_s`).")
    return table(f"Sway free decay of both models from a {float(combos[0].attrs['release_m']):g} m "
                 "release on a still vessel (undamped period and damping ratio by log decrement "
                 f"over successive peaks; R² of the reference's fit).{harm}", header, rows)


def _period_table(combos) -> str:
    rows = []
    for ds in combos:
        rom = dict(zip(map(str, ds["rom_dominant_dof"].values), ds["natural_period_rom"].values))
        ref = dict(zip(map(str, ds["dominant_dof"].values), ds["natural_period_reference"].values))
        dec = dict(zip(map(str, ds["dominant_dof"].values), ds["period_decay_reference"].values))
        for dof in REFERENCE_DOFS:
            r_rom = rom.get(dof)
            rows.append([f"{ds.attrs['candidate']} / {ds.attrs['tugger']}", dof,
                         "not carried" if r_rom is None else num(float(r_rom), 3),
                         num(float(ref.get(dof, np.nan)), 3), num(float(dec.get(dof, np.nan)), 3),
                         "–" if r_rom is None else num(float(r_rom) / float(ref.get(dof, np.nan)), 4)])
    return table("Natural periods [s] of the ROM and the reference (its linearisation, and small "
                 "free decays along each mode shape in MoorDyn), by the mode's dominant DOF. The "
                 f"ROM carries sway, heave, roll and yaw only: {', '.join(NOT_IN_ROM)} are modes of "
                 "the reference alone.",
                 ["combination", "mode", "ROM", "reference", "reference (decay)", "ROM / ref."], rows)


def _notes(done) -> str:
    worst_t = max(float(np.max(np.abs(ds["tension_static"].sel(model="rom")
                                      / ds["tension_static"].sel(model="reference") - 1))) for ds in done)
    slack = max(float(ds["slack_fraction"]) for ds in done)
    r2 = min(float(ds["r2"]) for ds in done)
    text = (f"Static wire tensions of the two models agree within {num(100 * worst_t, 2)} %; the "
            f"lowest R² of the ROM's relative sway against the reference's is {num(r2, 4)}; "
            + ("no hoist wire went slack in the reference." if slack == 0 else
               f"hoist wires were slack {num(100 * slack, 2)} % of the time at most in the reference."))
    lim = [float(ds["tugger_limit_fraction"]) for ds in done if "tugger_limit_fraction" in ds]
    if lim:
        text += f" The reference's tugger lines were at a winch limit {num(100 * max(lim), 2)} % of the time at most."
    return text + "\n"


# -- figure ---------------------------------------------------------------------------------
def trace_cells(cx) -> list:
    return [ds for ds in ordered(cx) if verified(ds) and ds.sizes.get("trace_time", 0)][:MAX_TRACE_CELLS]


def figure_plan(cx) -> list:
    """The chapter's figure (:class:`jls.report.style.Task`), when a cell has a trace."""
    return [Task(FIGURE, lambda d: traces(cx, d), 1.0 + 0.5 * len(trace_cells(cx)))] if trace_cells(cx) else []


def traces(cx, out_dir):
    """Relative sway of the ROM (black) and the reference (red) in the shown cells."""
    cells = trace_cells(cx)
    with matplotlib.rc_context(STYLE):
        fig = new_figure(1.7 * len(cells))
        axes = np.atleast_1d(fig.subplots(len(cells), 1, squeeze=False)[:, 0])
        for ax, ds in zip(axes, cells):
            time = ds["trace_time"].values
            for model, colour, lw in (("reference", "tab:red", 1.4), ("rom", "black", 0.7)):
                ax.plot(time, ds["trace_relative_sway"].sel(model=model).values, color=colour,
                        lw=lw, label="6-DOF reference" if model == "reference" else "ROM")
            ax.set_ylabel("relative sway [m]")
            ax.set_title(f"{_cell_label(ds)}: MPM ratio {float(ds['mpm_ratio']):.3f}")
        axes[-1].set_xlabel("time in the record [s]")
        axes[0].legend(ncol=2, loc="upper right")
        return save(fig, out_dir, FIGURE)


__all__ = ["chapter", "verification", "page_one_sentence", "page_one_what_was_verified", "study_section",
           "wires_text",
           "figure_plan", "traces", "verdict_text", "comparable"]
