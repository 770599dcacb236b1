"""The report's chapter "Inputs and provenance": the software and configuration, the
vessel data and its conventions, the input files with their checksums, the datasets read
and whether each was made with this report's configuration, the wave statistics' sources
and the Python packages."""

from __future__ import annotations

import numpy as np

from jls.report import control
from jls.report.context import Context, heading, representative
from jls.report.markup import cell, mono, num, path, t, table


def chapter(cx: Context) -> str:
    p, v, dg = cx.prov, cx.vessel, cx.dg
    omega = v["omega"].values
    rows = [
        ["route", t(dg.route)], ["jls version", t(p.get("jls_version", "?"))],
        ["configuration SHA-256", mono(p.get("config_sha256", "?"))],
        ["source commit", mono(p["git_commit"]) if p.get("git_commit", control.NOT_GIT) != control.NOT_GIT
         else t(control.NOT_GIT)],
        ["created", t(p.get("created", "?"))], ["Python", t(p.get("python", "?"))],
        ["vessel data source", path(p.get("vessel_source") or v.attrs.get("vessel_source", "not stated"))],
        ["vessel description", t(p.get("vessel_description") or v.attrs.get("vessel_description", "not stated"))],
        ["RAO range", t(f"omega {omega.min():.3f}-{omega.max():.3f} rad/s (periods "
                        f"{2 * np.pi / omega.max():.1f}-{2 * np.pi / omega.min():.1f} s), "
                        f"headings {', '.join(f'{h:g}' for h in v['heading'].values)} deg")],
        ["RAO extrapolation", t(v.attrs.get("extrapolation", "not stated"))],
        ["phase convention", t(v.attrs.get("phase_convention", "not stated"))],
        ["heading convention", t(v.attrs.get("heading_convention", "not stated"))],
        ["wave spectrum", t(f"{cx.resp.attrs.get('spectrum', 'not stated')}, gamma "
                            f"{cx.resp.attrs.get('gamma', '?')}")],
        ["steepness rule", t(cx.sea.attrs.get("steepness_rule", cx.work.attrs.get("steepness_rule", "not stated")))
         + f" ({cx.sec('sea_states')} says what it does)"],
    ]
    out = [heading("provenance", "Inputs and provenance"),
           table("Provenance of this assessment.", ["item", "value"],
                 [[cell(a), cell(b, raw=True)] for a, b in rows],
                 columns="(auto, 1fr)", align="(left, left)")]
    desc = p.get("vessel_description") or v.attrs.get("vessel_description", "")
    if representative(desc):
        out.append("#note[*Vessel data are representative, not the vessel's own.* The RAOs belong "
                   "to a hull of the same class computed or supplied for this tool; the vessel's "
                   "own response may differ, most of all near the roll resonance, which drives "
                   "the hinge sway.]\n")
    else:
        out.append("#note[The vessel description does not say that the RAOs are representative; "
                   "they are taken to be the vessel's own data. Check the source above.]\n")
    inputs = p.get("inputs", {}) or {}
    # The checksum goes on its own line under the path: a column of its own would take
    # 64 monospace characters of the width and leave too little for the path.
    rows = [[cell(t(name, wrap=True), raw=True),
             cell(f"{path(d.get('path', ''))} \\ {mono(d.get('sha256', ''))}", raw=True)]
            for name, d in inputs.items()]
    out.append(table("Input files (path, and SHA-256 checksum below it).",
                     ["input", "path and SHA-256"], rows, columns="(22%, 1fr)", align="left",
                     size="7.5pt"))
    rows = []
    per = p.get("config_sha256_datasets") if isinstance(p.get("config_sha256_datasets"), dict) else {}
    extra = [(name, ds) for name, ds in (("screening", cx.screening), ("weather_windows", cx.windows),
                                         ("tugger_studies", cx.studies), ("voyage", cx.voyage))
             if ds is not None]
    for name, ds in (("sea_states", cx.sea), ("vessel_motion", v), ("plant", cx.plant),
                     ("response", cx.resp), ("workability", cx.work), *extra):
        sha = str(ds.attrs.get("config_sha256", ""))
        if name in dg.same_config:
            flag = dg.same_config[name]
        else:
            flag = None if not (sha and per.get(name)) else sha == str(per[name])
        same = {None: "–", True: "yes", False: "NO"}[flag]
        rows.append([cell(name), cell(t(ds.attrs.get("created_by", "–")), raw=True),
                     cell(t(ds.attrs.get("jls_version", "–")), raw=True),
                     cell(mono(sha[:12]) if sha else "–", raw=True), same])
    out.append(table("The datasets read: the rule that wrote each, its jls version and "
                     f"configuration hash, and whether that hash equals the report's hash of "
                     f"{dg.hash_basis}.",
                     ["dataset", "written by", "jls", "config SHA-256", "same config"], rows,
                     align="(left, left, left, left, center)"))
    src = [[t(leg), path(cx.sea.attrs.get(f"source_{leg}", "not stated")),
            num(cx.sea["record_total"].sel(leg=leg), 0) if "record_total" in cx.sea else "–"]
           for leg in cx.legs]
    out.append(table("Wave statistics of each leg: source file and the sum of its raw values "
                     "(records or probabilities).", ["leg", "source", "raw total"],
                     [[cell(a, raw=True), cell(b, raw=True), c] for a, b, c in src],
                     align="(left, left, right)"))
    pk = list((p.get("packages") or {}).items())
    per_row = 4
    rows = []
    for i in range(0, len(pk), per_row):
        chunk = pk[i:i + per_row] + [("", "")] * (per_row - len(pk[i:i + per_row]))
        rows.append([x for name, ver in chunk for x in (cell(name), cell(ver))])
    out.append(table("Python packages.", ["package", "version"] * per_row, rows,
                     align="(" + ", ".join(["left"] * 2 * per_row) + ")", size="7.5pt"))
    return "\n".join(out)


__all__ = ["chapter"]
