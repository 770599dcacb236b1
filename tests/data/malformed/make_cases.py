"""Writes the malformed-input case files of tests/test_malformed_inputs.py.

Run from the repository root: python tests/data/malformed/make_cases.py
Each file is a small valid input with one fault; the test names the fault it expects.
"""

from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
VALID_CONFIG = (HERE.parents[2] / "config" / "config.yaml").read_text()


def wamit_rows(periods=(20.0, 10.0, 5.0), headings=(90.0, 180.0), rot_scale=1.0):
    rows = []
    for t in periods:
        for b in headings:
            for mode in range(1, 7):
                amp = (1.0 if mode <= 3 else 0.02 * rot_scale) * (1 + 0.1 * mode) / (1 + 5.0 / t)
                ph = 10.0 * mode - 30.0
                z = amp * np.exp(1j * np.radians(ph))
                rows.append(f"{t:.4E} {b:.4E} {mode:d} {amp:.6E} {ph:.6E} {z.real:.6E} {z.imag:.6E}")
    return rows


def csv_rows(freqs=(0.3, 0.6, 1.2), col="omega_rad_s", rot_scale=1.0):
    dofs = ("surge", "sway", "heave", "roll", "pitch", "yaw")
    out = [f"{col},wave_direction_deg,dof,amplitude,phase_deg"]
    for w in freqs:
        for b in (90, 180):
            for i, d in enumerate(dofs):
                amp = (0.8 if i < 3 else 0.03 * rot_scale) / (1 + w)
                out.append(f"{w},{b},{d},{amp:.6f},{10 * i}")
    return out


def physical_csv(heave=1.0, rotations=1.0, radians=False, header=""):
    """A CSV RAO of a hull in waves of 6-40 s: heave tending to 1 and the rotations to the
    wave slope w^2/g at long periods, phases spread over +-170 deg (or the same phases in
    radians in the phase_deg column)."""
    dofs = ("surge", "sway", "heave", "roll", "pitch", "yaw")
    out = [header + "period_s,wave_direction_deg,dof,amplitude,phase_deg"] if header else [
        "period_s,wave_direction_deg,dof,amplitude,phase_deg"]
    for n, t in enumerate((40.0, 20.0, 10.0, 6.0)):
        w = 2 * np.pi / t
        k, low = w * w / 9.81, 1.0 / (1.0 + (w / 0.8) ** 4)
        for b in (90, 180):
            amps = {"surge": 0.9 * low * (b == 180), "sway": 0.9 * low * (b == 90),
                    "heave": heave / (1.0 + (w / 1.0) ** 4), "roll": rotations * k * low * (b == 90),
                    "pitch": rotations * k * low * (b == 180), "yaw": 0.1 * rotations * k * low}
            for i, d in enumerate(dofs):
                ph = ((37 * (i + 1) * (n + 2) + b) % 340) - 170.0
                out.append(f"{t},{b},{d},{amps[d]:.8g},{np.radians(ph) if radians else ph:.6g}")
    return "\n".join(out) + "\n"


def files():
    f = {}
    # --- configuration files (YAML level) ---
    f["config_duplicate_key.yaml"] = VALID_CONFIG.replace("  m_kin_t: 7719", "  m_kin_t: 7719\n  m_kin_t: 7700")
    f["config_latin1.yaml"] = VALID_CONFIG.replace("# jls configuration", "# jls configuration caf\xe9").encode("latin-1")
    f["config_empty.yaml"] = b""
    f["config_comments_only.yaml"] = "# nothing here\n# at all\n"
    f["config_list.yaml"] = "- jacket\n- rigging\n"
    f["config_scalar.yaml"] = "just a sentence\n"
    f["config_tab.yaml"] = VALID_CONFIG.replace("  m_grav_t: 7650", "\tm_grav_t: 7650")
    f["config_syntax.yaml"] = VALID_CONFIG.replace("  z_p_m: 22.41", "  z_p_m: [22.41")
    f["config_yte.yaml"] = "__use_yte__: true\n" + VALID_CONFIG
    f["config_alias_bomb.yaml"] = "\n".join(
        ['a: &a ["x","x","x","x","x","x","x","x","x"]']
        + [f"{c}: &{c} [{', '.join(['*' + p] * 9)}]" for p, c in zip("abcdefgh", "bcdefghi")]) + "\n"
    f["config_nested_duplicate.yaml"] = VALID_CONFIG.replace("    splash_clearance_m: 5", "    splash_clearance_m: 5\n    splash_clearance_m: 50")
    # --- plant matrices ---
    a1 = (HERE.parent / "appendix_a1_plant.yaml").read_text()
    f["plant_duplicate_key.yaml"] = a1.replace("zeta: 0.0098", "zeta: 0.0098\nzeta: 0.02")
    f["plant_latin1.yaml"] = ("# d\xe9mo\n" + a1).encode("latin-1")
    f["plant_empty.yaml"] = b""
    f["plant_list.yaml"] = "- [1, 2]\n"
    f["plant_missing_K.yaml"] = "M: [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]\nKb: [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]\n"
    eye = "[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]"
    f["plant_3x3.yaml"] = f"M: {eye}\nK: [[1,0,0],[0,1,0],[0,0,1]]\nKb: {eye}\n"
    f["plant_text.yaml"] = f"M: {eye}\nK: [[1,0,0,0],[0,one,0,0],[0,0,1,0],[0,0,0,1]]\nKb: {eye}\n"
    f["plant_nan.yaml"] = f"M: {eye}\nK: [[1,0,0,0],[0,.nan,0,0],[0,0,1,0],[0,0,0,1]]\nKb: {eye}\n"
    f["plant_asymmetric.yaml"] = f"M: {eye}\nK: [[1,0.5,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]\nKb: {eye}\n"
    f["plant_negative_mass.yaml"] = f"M: [[-1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]\nK: {eye}\nKb: {eye}\n"
    f["plant_unknown_key.yaml"] = a1 + "Cc: 1\n"
    f["plant_zeta_and_C.yaml"] = a1 + f"C: {eye}\n"
    f["plant_zeta_range.yaml"] = a1.replace("zeta: 0.0098", "zeta: 0.98")
    f["plant_tab.yaml"] = a1.replace("zeta: 0.0098", "M2:\n\t- 1")
    f["plant_duplicate.json"] = '{"M": 1, "M": 2}'
    f["plant_invalid.json"] = '{"M": [1, 2,}'
    f["plant_unstable.yaml"] = f"M: {eye}\nK: [[-1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]\nKb: {eye}\n"
    # --- scatter tables ---
    head = "# layout: matrix\n# hs_bins: edges\n# tz_bins: edges\n# values: counts\n"
    good = head + "hs\\tz,5.0-6.0,6.0-7.0\n0.0-1.0,20,10\n1.0-2.0,10,8\n"
    f["scatter_zero_bytes.csv"] = b""
    f["scatter_comments_only.csv"] = "# nothing\n"
    f["scatter_semicolons.csv"] = good.replace(",", ";")
    f["scatter_tabs.csv"] = good.replace(",", "\t")
    f["scatter_latin1.csv"] = ("# note: mesur\xe9\n" + good).encode("latin-1")
    f["scatter_hs_cm.csv"] = head + "hs\\tz,5.0-6.0,6.0-7.0\n0.0-100.0,20,10\n100.0-200.0,10,8\n"
    f["scatter_tz_hz.csv"] = head + "hs\\tz,0.1-0.2,0.2-0.3\n0.0-1.0,20,10\n1.0-2.0,10,8\n"
    f["scatter_swapped.csv"] = head + "hs\\tz,1.0-2.0,2.0-3.0\n5.0-6.0,20,10\n6.0-7.0,10,8\n"
    f["scatter_tz_tenths.csv"] = head + "hs\\tz,50.0-60.0,60.0-70.0\n0.0-1.0,20,10\n1.0-2.0,10,8\n"
    f["scatter_no_rows.csv"] = head
    f["scatter_header_only_row.csv"] = head + "hs\\tz,5.0-6.0,6.0-7.0\n"
    # --- hindcasts ---
    hhead = "time (YYYY-MM-DD-HH); significant wave height (m); zero-up-crossing period (s)\n"
    f["hindcast_empty.txt"] = b""
    f["hindcast_latin1.txt"] = ("# mesur\xe9\n" + hhead + "2000-01-01-00; 0.40; 4.20\n").encode("latin-1")
    f["hindcast_commas.txt"] = hhead.replace(";", ",") + "2000-01-01-00, 0.40, 4.20\n"
    f["hindcast_outside.txt"] = hhead + "2000-01-01-00; 0.40; 4.20\n2000-01-01-01; 9.00; 8.20\n"
    f["hindcast_ok.txt"] = hhead + "2000-01-01-00; 0.40; 4.20\n2000-01-01-01; 1.40; 6.20\n"
    f["hindcast_swapped.txt"] = hhead + "2000-01-01-00; 6.40; 1.20\n2000-01-01-01; 7.40; 1.40\n"
    # --- RAO files ---
    rows = wamit_rows()
    f["rao_ok.4"] = "\n".join(rows) + "\n"
    f["rao_truncated.4"] = "\n".join(rows[:-8]) + "\n"
    f["rao_missing_dof.4"] = "\n".join(r for r in rows if r.split()[2] != "5") + "\n"
    f["rao_six_columns.4"] = "\n".join(rows[:3] + [" ".join(rows[3].split()[:6])] + rows[4:]) + "\n"
    f["rao_text.4"] = "\n".join(rows[:3] + [rows[3].replace(rows[3].split()[3], "abc", 1)] + rows[4:]) + "\n"
    bad = rows[5].split()
    bad[5] = "9.0E+00"
    f["rao_reim_mismatch.4"] = "\n".join(rows[:5] + [" ".join(bad)] + rows[6:]) + "\n"
    bad = rows[2].split()
    bad[2] = "7"
    f["rao_mode7.4"] = "\n".join(rows[:2] + [" ".join(bad)] + rows[3:]) + "\n"
    f["rao_duplicate_row.4"] = "\n".join(rows + [rows[0]]) + "\n"
    f["rao_degrees.4"] = "\n".join(wamit_rows(rot_scale=57.3 * 20)) + "\n"
    f["rao_periods_as_omega.4"] = "\n".join(wamit_rows(periods=(0.02, 0.01, 0.005))) + "\n"
    f["rao_negative_period.4"] = "\n".join(rows[:1] + [rows[1].replace("2.0000E+01", "-2.0000E+01", 1)] + rows[2:]) + "\n"
    f["rao_empty.4"] = b""
    f["rao_latin1.4"] = ("\xe9\n" + "\n".join(rows)).encode("latin-1")
    f["rao_ok.csv"] = "\n".join(csv_rows()) + "\n"
    f["rao_deg_undeclared.csv"] = "\n".join(csv_rows(rot_scale=57.3 * 10)) + "\n"
    f["rao_deg_declared.csv"] = "# rotation_units: deg/m\n" + "\n".join(csv_rows(rot_scale=57.3)) + "\n"
    f["rao_bad_rotation_units.csv"] = "# rotation_units: grad/m\n" + "\n".join(csv_rows()) + "\n"
    f["rao_periods_in_omega.csv"] = "\n".join(csv_rows(freqs=(5.0, 10.0, 20.0))) + "\n"
    f["rao_hz.csv"] = "\n".join(csv_rows(freqs=(0.001, 0.05, 0.2))) + "\n"
    r = csv_rows()
    f["rao_csv_truncated.csv"] = "\n".join(r[:-4]) + "\n"
    f["rao_csv_unknown_dof.csv"] = "\n".join(r[:3] + [r[3].replace("heave", "heav")] + r[4:]) + "\n"
    f["rao_csv_missing_column.csv"] = "\n".join([r[0].replace(",dof", "")] + [",".join(x.split(",")[:2] + x.split(",")[3:]) for x in r[1:]]) + "\n"
    f["rao_csv_both_freq.csv"] = "\n".join(["period_s," + r[0]] + ["1," + x for x in r[1:]]) + "\n"
    f["rao_csv_negative_amp.csv"] = "\n".join(r[:2] + [r[2].replace(",0.", ",-0.", 1)] + r[3:]) + "\n"
    f["rao_csv_ragged.csv"] = "\n".join(r[:2] + [r[2] + ",7"] + r[3:]) + "\n"
    f["rao_csv_duplicate.csv"] = "\n".join(r + [r[1]]) + "\n"
    f["rao_csv_empty.csv"] = "# only a comment\n"
    f["rao_not_netcdf.nc"] = b"this is not a NetCDF file\n"
    f["rao_unknown_suffix.txt"] = "\n".join(rows) + "\n"
    # --- values YAML 1.1 (Snakemake) and YAML 1.2 read differently; keys that are not text ---
    f["config_sexagesimal.yaml"] = VALID_CONFIG.replace("        duration_h: 50\n", "        duration_h: 50:00\n")
    f["config_route_no.yaml"] = VALID_CONFIG.replace("routes:\n  default:", "routes:\n  NO:")
    f["config_route_number.yaml"] = VALID_CONFIG.replace("routes:\n  default:", "routes:\n  2024:")
    f["config_yes.yaml"] = VALID_CONFIG.replace("  enabled: true", "  enabled: yes")
    f["config_octal.yaml"] = VALID_CONFIG.replace("  seed: 1\n", "  seed: 017\n")
    f["config_underscore.yaml"] = VALID_CONFIG.replace("  m_grav_t: 7650 ", "  m_grav_t: 7_650")
    f["config_date.yaml"] = VALID_CONFIG + "document: {revision: 2026-01-05}\n"
    # --- scatter-table metadata: corner labels, declared bins, stated totals, header keys ---
    body = "0.0-1.0,20,10\n1.0-2.0,10,8\n"
    f["scatter_corner_tp.csv"] = head + "hs\\tp,5.0-6.0,6.0-7.0\n" + body
    f["scatter_corner_transposed.csv"] = head + "Tz [s] / Hs [m],5.0-6.0,6.0-7.0\n" + body
    f["scatter_declared_centres.csv"] = good.replace("# hs_bins: edges", "# hs_bins: centres")
    f["scatter_declared_edges.csv"] = head + "hs\\tz,5.5,6.5\n0.0-1.0,20,10\n1.0-2.0,10,8\n"
    f["scatter_records_mismatch.csv"] = good.replace("# values: counts", "# values: counts\n# records: 64")
    f["scatter_span_mismatch.csv"] = good.replace("# values: counts", "# values: counts\n# records: 48\n"
                                                  "# first_record: 2000-01-01 00:00 UTC\n"
                                                  "# last_record: 2000-01-03 23:00 UTC\n# missing_hours: 2")
    f["scatter_hs_feet.csv"] = good.replace("# values: counts", "# values: counts\n# hs_units: ft")
    f["scatter_period_tp.csv"] = good.replace("# values: counts", "# values: counts\n# period: tp")
    f["scatter_scale_key.csv"] = good.replace("# values: counts", "# values: counts\n# hs_scale_factor: 0.01")
    # --- hindcast column names ---
    f["hindcast_peak_period.txt"] = hhead.replace("zero-up-crossing period (s)", "peak period Tp (s)") + \
        "2000-01-01-00; 0.40; 4.20\n2000-01-01-01; 1.40; 6.20\n"
    f["hindcast_feet.txt"] = hhead.replace("significant wave height (m)", "significant wave height (ft)") + \
        "2000-01-01-00; 1.40; 4.20\n2000-01-01-01; 4.40; 6.20\n"
    # --- RAO metadata and magnitudes (a hull in 6-40 s waves) ---
    f["rao_physical.csv"] = physical_csv()
    f["rao_phase_radians.csv"] = physical_csv(radians=True)
    f["rao_phase_radians_declared.csv"] = "# phase_units: rad\n" + physical_csv(radians=True)
    f["rao_heading_convention.csv"] = "# heading_convention: coming from\n" + physical_csv()
    f["rao_reference_declared.csv"] = "# reference_point_m: 0, 0, -5\n" + physical_csv()
    f["rao_heave_cm.csv"] = physical_csv(heave=100.0)
    f["rao_rotations_x10.csv"] = physical_csv(rotations=10.0)
    f["rao_rotations_per_length.csv"] = physical_csv(rotations=1 / 20.0)
    return f


def main():
    for name, content in files().items():
        path = HERE / name
        if isinstance(content, bytes):
            path.write_bytes(content)
        else:
            path.write_text(content, encoding="utf-8")


if __name__ == "__main__":
    main()
