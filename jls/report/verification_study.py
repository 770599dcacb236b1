"""The verification chapter's sections on what the cells alone do not show: the wires as
wires (the one-segment reference against wires of several segments with their mass and
axial damping, :mod:`jls.verify.wires`) and the study's own comparison beside the
project's (its table 4.4, what the reference can and cannot see, the linear range
measured; :mod:`jls.verify.study`). Used by :mod:`jls.report.verification`."""

from __future__ import annotations

import numpy as np

from jls.report.markup import num, t, table


def wires_text(wires) -> str:
    """The wires as wires: per check the multi-segment reference against the one-segment
    one on the same record, the static tensions against the ROM's, and the wall times."""
    rows = [[t(str(w.attrs["cell"]).replace("__", " ")), f"{int(w.attrs['segments'])}",
             num(float(w.attrs["wire_mass_t_per_m"]), 3), num(float(w["sigma_ratio_segments"]), 4),
             num(float(w["r_segments"]), 5), num(100 * float(w["tension_ratio_max"]), 3),
             f"{num(float(w['wall_time_segments']), 1)} / {num(float(w['wall_time_one_segment']), 2)}"]
            for w in wires]
    ok = all(bool(w["within_tolerance"]) for w in wires)
    tol = num(100 * float(wires[0].attrs["tolerance"]), 0)
    verdict = (f"The one-segment reference of the cells above stands as the fast default: the wires as "
               f"wires agree with it within the {tol} % tolerance in every check."
               if ok else
               f"*The one-segment reference does not stand*: in at least one check the wires as wires "
               f"differ from it by more than the {tol} % tolerance, so the cells above rest on a "
               "reference that leaves out what matters.")
    return (table(f"The wires as wires: each hoist wire of several segments with its own mass and axial "
                  f"damping (a segment's axial damping ratio {num(float(wires[0].attrs['axial_damping_ratio']), 2)}) "
                  f"against the one-segment reference, same record ({num(float(wires[0].attrs['duration_s']), 0)} s "
                  "after the start-up); static padeye tensions held still in MoorDyn against the ROM's; "
                  "wall time of the two references on the record.",
                  ["cell", "segments", "mass [t/m]", "σ ratio", "r", "static T off [%]",
                   "wall time [s] (segments / one)"], rows)
            + verdict + "\n")


def study_section(study) -> str:
    """The study's table 4.4 beside the project's ROM against its reference at the same sea
    states with the study's plant, what the reference can and cannot see, and the linear
    range measured."""
    from jls.verify.study import SEES
    a = study.attrs
    rows = []
    for i, name in enumerate(map(str, study["sea_state"].values)):
        def f(v, nd=3):
            v = float(v)
            return num(v, nd) if np.isfinite(v) else "–"
        err = float(study["study_error"].values[i])
        ratio = float(study["sigma_ratio"].values[i])
        rows.append([name, f(study["hs"].values[i], 2), f(study["tz"].values[i], 2),
                     f(study["study_sigma_rom"].values[i]), f(study["study_sigma_full"].values[i]),
                     f"{100 * err:+.1f} %", f(study["sigma_rom"].values[i]), f(study["sigma_reference"].values[i]),
                     "–" if not np.isfinite(ratio) else f"{100 * (ratio - 1):+.1f} %"])
    out = [table(f"The study's comparison (the study's table 4.4: relative-sway RMS of its ROM and of the full "
                 f"nonlinear OrcaFlex model, beam seas, equal component counts) beside this project's ROM "
                 f"against its 6-DOF reference on one record per sea state with the study's plant "
                 f"({t(str(a['candidate']))} rigging, no tugger; "
                 f"{num(float(a['duration_s']) / 60, 0)} min after the start-up).",
                 ["sea state", "Hs [m]", "Tz [s]", "study ROM σ [m]", "OrcaFlex σ [m]", "study error",
                  "ROM σ [m]", "reference σ [m]", "ROM / reference"], rows, size="8pt")]
    if "reason" in a:
        out.append(f"The project's columns are empty: the reference could not run ({t(str(a['reason']))}).\n")
        return "\n".join(out)
    out.append(
        f"*What the reference can and cannot see.* It shares with the ROM {SEES['shares']}; it adds "
        f"{SEES['adds']}; it lacks {SEES['lacks']}. Inside the study's design cell (V1, V2) both "
        "comparisons agree within a few per cent. At V4 and S1 the study's ROM over-predicts "
        "OrcaFlex by 16.8 % and 33.4 %; the geometric nonlinearity, which the reference does see, "
        f"gives {t(_pct(study, 'V4'))} and {t(_pct(study, 'S1'))} here. The rest of the study's "
        "difference comes from what the reference lacks (drag growing with the swing, the block "
        "connection system), and this verification cannot confirm the ROM there.\n")
    hs_in, hs_out = float(a["linear_range_hs_inside_m"]), float(a["linear_range_hs_leaves_m"])
    tol = num(100 * float(a["tolerance"]), 0)
    if np.isfinite(hs_out):
        out.append(f"*The linear range, measured.* Stepping Hs up at Tz {num(float(a['linear_range_tz_s']), 1)} s "
                   f"(S1's, beam seas) on the study's plant, the ROM over the reference's relative-sway MPM "
                   f"leaves the {tol} % tolerance at Hs {num(hs_out, 2)} m; it is inside up to Hs "
                   f"{num(hs_in, 2)} m, where the reference's MPM is {num(float(a['linear_range_mpm_inside_m']), 1)} m. "
                   "The assumptions chapter's linear-range flag (twice the sway limit) is the study's, "
                   "which includes the effects this reference lacks.\n")
    else:
        out.append(f"*The linear range, measured.* Stepping Hs up at Tz {num(float(a['linear_range_tz_s']), 1)} s "
                   f"the ratio stayed within the {tol} % tolerance up to Hs {num(float(study['step_hs'].values[-1]), 2)} m.\n")
    return "\n".join(out)


def _pct(study, name) -> str:
    r = float(study["sigma_ratio"].sel(sea_state=name))
    return f"{100 * (r - 1):+.1f} %" if np.isfinite(r) else "–"


__all__ = ["wires_text", "study_section"]
