"""The verification's identification tools and the ROM driven by a user's records:
log decrement on a known decay, a response record made by the ROM itself, malformed
records, the command line, and what happens without MoorDyn."""

import json
import sys

import numpy as np
import pytest

from jls.cli import main
from jls.config.builders import plant_from_config
from jls.config.loader import load
from jls.errors import InputError
from jls.verify import (
    compare,
    highpass,
    log_decrement,
    read_motion_record,
    read_response_record,
    reference_available,
    rom,
    rom_from_record,
)
from jls.verify.excitation import Excitation

LEVER = (-215.263, 1.0, 99.998)


@pytest.fixture(scope="module")
def plant():
    return plant_from_config(load("config/config.yaml"))


@pytest.mark.parametrize("period, zeta", [(15.44, 0.0098), (3.5, 0.05), (19.2, 0.002)])
def test_log_decrement_recovers_a_known_decay(period, zeta):
    # a damped mode sampled at 0.02 s with a small, faster second mode riding on it
    wn = 2 * np.pi / period
    wd = wn * np.sqrt(1 - zeta ** 2)
    t = np.arange(0.0, 12 * period, 0.02)
    y = 0.6 * np.exp(-zeta * wn * t) * np.cos(wd * t) + 0.002 * np.exp(-0.2 * t) * np.cos(7.3 * t)
    fit = log_decrement(t, y)
    assert fit.period_undamped == pytest.approx(period, rel=0.01)
    assert fit.zeta == pytest.approx(zeta, rel=0.01)
    assert fit.r2 > 0.999 and fit.n_peaks >= 10


def test_compare_identity_and_scaling():
    y = np.sin(np.linspace(0, 50, 2001))
    assert compare(y, y) == {"r": pytest.approx(1.0), "r2": 1.0, "rms_error": 0.0,
                             "rms_error_relative": 0.0, "sigma_ratio": 1.0}
    c = compare(1.1 * y, y)
    assert c["r"] == pytest.approx(1.0) and c["sigma_ratio"] == pytest.approx(1.1)
    assert c["r2"] == pytest.approx(1 - 0.01, rel=1e-3)


def _vessel_csv(path, t, roll_deg, sway_m):
    with open(path, "w") as fh:
        fh.write("# measured transit, rotations in degrees\ntime_s,roll_deg,sway_m\n")
        for a, b, c in zip(t, roll_deg, sway_m):
            fh.write(f"{a:.3f},{b:.9g},{c:.9g}\n")


def test_a_response_record_made_by_the_rom_gives_r_1(plant, tmp_path):
    dt = 0.1
    t = np.arange(0.0, 2500.0, dt)
    roll = 0.6 * np.sin(2 * np.pi * t / 9.0) + 0.25 * np.sin(2 * np.pi * t / 12.3 + 1.0)
    sway = 0.1 * np.sin(t / 3.0)
    _vessel_csv(tmp_path / "motion.csv", t, roll, sway)
    rec = read_motion_record(tmp_path / "motion.csv")
    assert rec.kind == "vessel" and not rec.resampled
    # the ROM's own relative sway from the same (filtered) record, written as a response
    exc = Excitation("vessel", highpass(rec.data, dt), dt)
    qb, _ = exc.rom_input(LEVER)
    rel = rom.relative(rom.simulate(plant, dt, qb), qb)
    with open(tmp_path / "response.csv", "w") as fh:
        fh.write("time_s,relative_sway_m\n")
        fh.writelines(f"{a:.3f},{b:.17g}\n" for a, b in zip(t, rel[:, 0]))
    resp = read_response_record(tmp_path / "response.csv")
    out = rom_from_record(plant, rec, resp, vessel_lever_m=LEVER, filter_response=False)
    c = out["against_response"]["relative_sway"]["comparison"]
    assert c["r"] == pytest.approx(1.0, abs=1e-12) and c["r2"] == pytest.approx(1.0, abs=1e-12)
    assert out["compared_s"][0] >= out["transient_s"]
    # filtered like the motion (the default) it stays the same signal
    out = rom_from_record(plant, rec, resp, vessel_lever_m=LEVER)
    assert out["against_response"]["relative_sway"]["comparison"]["r"] > 0.99


def test_uneven_sampling_is_resampled_and_said(tmp_path):
    t = np.cumsum(np.r_[0.0, np.full(50, 0.1), np.full(50, 0.11)])
    _vessel_csv(tmp_path / "m.csv", t, np.sin(t), np.zeros_like(t))
    rec = read_motion_record(tmp_path / "m.csv")
    assert rec.resampled and np.allclose(np.diff(rec.time), rec.dt)


BAD = {
    "non_monotonic": ("time_s,roll_deg\n" + "".join(f"{i},0.1\n" for i in range(12)) + "5,0.2\n",
                      ["time_s", "line 14", "5"]),
    "nan": ("time_s,roll_deg\n" + "".join(f"{i},0.1\n" for i in range(12)) + "12,nan\n",
            ["roll_deg", "line 14", "nan"]),
    "unknown_column": ("time_s,rol_deg\n" + "".join(f"{i},0.1\n" for i in range(12)),
                       ["rol_deg", "unknown column"]),
    "mixed_kinds": ("time_s,roll_deg,y_b_m\n" + "".join(f"{i},0.1,0\n" for i in range(12)),
                    ["y_b_m"]),
    "text": ("time_s,roll_deg\n" + "".join(f"{i},0.1\n" for i in range(12)) + "12,abc\n",
             ["roll_deg", "abc"]),
}


@pytest.mark.parametrize("case", sorted(BAD))
def test_malformed_records_stop_with_a_named_error(case, tmp_path):
    text, words = BAD[case]
    path = tmp_path / f"{case}.csv"
    path.write_text(text)
    with pytest.raises(InputError) as err:
        read_motion_record(path)
    msg = str(err.value)
    assert str(path) in msg
    for w in words:
        assert w in msg


def test_malformed_response_record_is_named(tmp_path):
    path = tmp_path / "resp.csv"
    path.write_text("time_s,relative_swy_m\n" + "".join(f"{i},0\n" for i in range(12)))
    with pytest.raises(InputError, match="relative_swy_m"):
        read_response_record(path)


def test_cli_malformed_record_writes_nothing(tmp_path, capsys, monkeypatch):
    import shutil
    from pathlib import Path
    root = Path(__file__).resolve().parents[1]
    shutil.copytree(root / "config", tmp_path / "config")
    monkeypatch.chdir(tmp_path)
    (tmp_path / "bad.csv").write_text(BAD["nan"][0])
    before = sorted(p.name for p in tmp_path.rglob("*"))
    assert main(["verify", "--record", "bad.csv", "--json"]) == 2
    out = capsys.readouterr()
    assert out.out == "" and "bad.csv" in out.err and "roll_deg" in out.err
    assert sorted(p.name for p in tmp_path.rglob("*")) == before


def test_cli_record_json(plant, tmp_path, capsys):
    t = np.arange(0.0, 1800.0, 0.2)
    _vessel_csv(tmp_path / "m.csv", t, 0.5 * np.sin(2 * np.pi * t / 9.0), np.zeros_like(t))
    assert main(["verify", "--record", str(tmp_path / "m.csv"), "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["kind"] == "vessel" and out["rom"]["sigma"] > 0 and out["highpass_hz"] == 0.02


@pytest.mark.skipif(not reference_available()[0], reason="MoorDyn cannot be imported")
def test_cli_verify_one_case_json(capsys):
    assert main(["verify", "--duration-h", "0.1", "--transient-s", "200", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["sigma_ratio"] == pytest.approx(1.0, abs=0.02) and out["r"] > 0.999
    assert set(out["natural_period_reference_s"]) == {"surge", "sway", "heave", "roll", "pitch", "yaw"}
    assert max(abs(x - 1) for x in out["tension_static_ratio"]) < 1e-3


def test_without_moordyn_the_library_says_so(monkeypatch, plant, capsys):
    monkeypatch.setitem(sys.modules, "moordyn", None)          # import moordyn now fails
    ok, why = reference_available()
    assert not ok and "MoorDyn" in why and "pip install moordyn" in why
    from jls.verify import ReferenceUnavailable, build_reference, run, still
    ref = build_reference(plant)                               # statics need no MoorDyn
    with pytest.raises(ReferenceUnavailable, match="nothing was verified"):
        run(ref, still(0.02, 1.0))
    assert main(["verify", "--duration-h", "0.1", "--json"]) == 2
    assert "MoorDyn" in capsys.readouterr().err
