"""The lift system outside the hull (docs/inputs.md, class c): vessel.hull states the
hull's extent, and a fairlead, anchor, padeye or tip point inside it is refused with the
two numbers that contradict; without vessel.hull the check is not made and a warning says
so. The shipped configuration states the hull and passes."""

import copy
from pathlib import Path

import pytest

from jls.config.hull_checks import NOT_CHECKED, check_hull, hull_box, inside
from jls.config.loader import load_yaml
from jls.config.workflow_inputs import check_config_files, config_warnings
from jls.errors import InputError

ROOT = Path(__file__).resolve().parents[1]
BASE = load_yaml(ROOT / "config" / "config.yaml")


def _merged(overlay: dict) -> dict:
    from jls.config.workflow_inputs import merge
    cfg = copy.deepcopy(BASE)
    merge(cfg, copy.deepcopy(overlay))
    return cfg


def _refused(overlay: dict) -> str:
    cfg = _merged(overlay)
    with pytest.raises(InputError) as exc:
        check_config_files(cfg, [("config/config.yaml", copy.deepcopy(BASE)), ("my.yaml", overlay)])
    text = str(exc.value)
    assert "\n" not in text
    return text


def test_the_shipped_hull_is_clear_of_the_lift_system():
    cfg = check_config_files(copy.deepcopy(BASE), [("config/config.yaml", copy.deepcopy(BASE))])
    assert check_hull(cfg) == []
    box = hull_box(cfg["vessel"])
    # 382 m hull, transom 167.706 m aft of the RAO reference point; deck 30 - 14 = 16 m up
    assert box["x"] == pytest.approx((-167.706, 214.294))
    assert box["z"] == (-14.0, 16.0) and box["y"] == (-62.0, 62.0)
    # the hinge 47.56 m aft of the transom: the jacket hangs outboard
    assert cfg["vessel"]["hinge_m"][0] < box["x"][0] - 47.5


def test_inside_is_strict():
    box = {"x": (0.0, 10.0), "y": (-5.0, 5.0), "z": (-2.0, 3.0)}
    assert inside(box, 5.0, 0.0, 0.0)
    assert not inside(box, 5.0, 0.0, 3.0)           # on the deck: outside
    assert not inside(box, 5.0, 5.0, 0.0)           # on the side shell
    assert not inside(box, -0.1, 0.0, 0.0) and not inside(box, 5.0, 0.0, 3.1)


#: A hull under the hinge with its main deck 44 - 14 = 30 m above the water, and a jacket
#: whose tip is 20 m below its padeyes: the tip stands 119.46 - 60.091 - 20 = 39.37 m
#: above the water, clear of the deck; the fairleads 100 m below the hinge are at 19.46 m.
UNDER_HINGE = {"vessel": {"hull": {"length_m": 300, "breadth_m": 124, "depth_m": 44,
                                   "draught_m": 14, "aft_end_x_m": -280},
                          "fairlead_drop_m": 100},
               "rigging": {"limits": {"padeye_to_tip_m": 20}}}


def test_tugger_fairleads_inside_the_hull():
    text = _refused(UNDER_HINGE)
    assert text.startswith("my.yaml: vessel.fairlead_drop_m:")
    assert "port tugger fairlead" in text and "19.46 m above the waterline" in text
    assert "main deck is 30.00 m above the waterline" in text
    assert "x -280.00 to 20.00 m" in text and "+-62.00 m" in text and "(got 100)" in text


def test_fairleads_on_deck_or_outboard_are_accepted():
    # on the deck: 119.46 - 89.46 = 30 m above the water
    on_deck = copy.deepcopy(UNDER_HINGE)
    on_deck["vessel"]["fairlead_drop_m"] = 89.46
    cfg = check_config_files(_merged(on_deck), [("my.yaml", on_deck)])
    assert NOT_CHECKED not in config_warnings(cfg) and check_hull(cfg) == []
    # a 70 m breadth puts them (37.5 m either side of a hinge 1 m to port) outboard
    outboard = copy.deepcopy(UNDER_HINGE)
    outboard["vessel"]["hull"]["breadth_m"] = 70
    check_config_files(_merged(outboard), [("my.yaml", outboard)])
    # and one fairlead 0.1 m inside the side shell is refused: the starboard one at y = -36.5
    outboard["vessel"]["hull"]["breadth_m"] = 73.2
    text = _refused(outboard)
    assert "starboard tugger fairlead" in text and "at x = -215.26 m, y = -36.50 m" in text
    assert "y within +-36.60 m" in text


def test_padeyes_inside_the_hull():
    # the deck raised to 70 m: the padeyes (119.46 - 60.091 = 59.37 m up) are under it
    overlay = copy.deepcopy(UNDER_HINGE)
    overlay["vessel"]["hull"]["depth_m"] = 84
    overlay["vessel"]["fairlead_drop_m"] = 40
    text = _refused(overlay)
    # the drop is set in config/config.yaml; the hull (my.yaml) is named in the text
    assert text.startswith("config/config.yaml: rigging.h_drop_m:") and "the padeye of wire" in text
    assert "59.37 m above the waterline" in text and "main deck is 70.00 m" in text
    assert "(got 60.091)" in text


def test_jacket_tip_inside_the_hull_named_with_its_key():
    # tip points given: the transom at x = -210 m reaches 5.26 m past the hinge; deck 16 m up
    overlay = {"vessel": {"hull": {"length_m": 382, "breadth_m": 124, "depth_m": 30,
                                   "draught_m": 14, "aft_end_x_m": -205.0}},
               "assessment": {"tip_clearance": {"tip_offsets_m": [[-15, 20], [15, 20]]}}}
    text = _refused(overlay)
    # padeyes at x -215.263 + 16.97 = -198.3 m, 119.46 - 60.091 - 22.41 + 22.41 = 59.37 m up:
    # above the deck; the tip 48 m lower, 11.37 m up, at x -200.26 m: inside
    assert text.startswith("my.yaml: assessment.tip_clearance.tip_offsets_m[1]:")
    assert "11.37 m above the waterline" in text and "main deck is 16.00 m" in text
    assert "(got [15, 20])" in text


def test_stated_jacket_envelope_reaching_into_the_hull():
    overlay = {"jacket": {"envelope_half_m": [45, 40]}}
    # x -215.263 +- 45 reaches -170.26 m, the transom is at -167.706 m: clear
    check_config_files(_merged(overlay), [("my.yaml", overlay)])
    cfg = _merged({"jacket": {"envelope_half_m": [50, 40]}})
    with pytest.raises(InputError) as exc:
        check_config_files(cfg, [("my.yaml", cfg)])
    text = str(exc.value)
    assert text.startswith("my.yaml: rigging.h_drop_m:") and "reaches into the hull" in text
    assert "x -265.26 to -165.26 m" in text and "x -167.71 to 214.29 m" in text


def test_deck_below_the_waterline():
    overlay = {"vessel": {"hull": {"length_m": 382, "breadth_m": 124, "depth_m": 12,
                                   "draught_m": 14, "aft_end_x_m": -167.706}}}
    text = _refused(overlay)
    assert text.startswith("my.yaml: vessel.hull.depth_m:") and "draught of 14 m" in text
    assert "(got 12)" in text


def test_without_a_hull_the_check_is_not_made_and_said_so(tmp_path, monkeypatch):
    cfg = copy.deepcopy(BASE)
    del cfg["vessel"]["hull"]
    cfg = check_config_files(cfg, [("config/config.yaml", cfg)])
    assert NOT_CHECKED in config_warnings(cfg)
    # jls check prints it
    import shutil

    from jls.cli import main
    monkeypatch.chdir(tmp_path)
    shutil.copytree(ROOT / "config", tmp_path / "config")
    text = (tmp_path / "config" / "config.yaml").read_text()
    line = next(ln for ln in text.splitlines() if ln.strip().startswith("hull:"))
    (tmp_path / "config" / "config.yaml").write_text(text.replace(line + "\n", ""))
    from contextlib import redirect_stdout
    from io import StringIO
    out = StringIO()
    with redirect_stdout(out):
        assert main(["check"]) == 0
    assert "jls: warning: vessel.hull is not given" in out.getvalue()


def test_a_hull_is_not_inherited_by_another_vessel():
    """config/examples/own_vessel.yaml gives another RAO file without a hull: the shipped
    hull (which would hold its jacket, at x = 100 m) is not carried over; the check is
    not made and said so. Its own hull given beside the RAO file is checked."""
    own = load_yaml(ROOT / "config" / "examples" / "own_vessel.yaml")
    cfg = check_config_files(_merged(own), [("config/config.yaml", copy.deepcopy(BASE)),
                                            ("own_vessel.yaml", own)])
    assert "hull" not in cfg["vessel"] and NOT_CHECKED in config_warnings(cfg)
    own = copy.deepcopy(own)
    own["vessel"]["hull"] = {"length_m": 246, "breadth_m": 46, "depth_m": 25, "draught_m": 16,
                             "aft_end_x_m": -123}
    # the candidate 'deeper' (drop 65.71 m) puts the tip 5.75 m up, below the deck at 9 m
    with pytest.raises(InputError, match=r"^config/config.yaml: candidates\[0\].drop_height_m: the jacket "
                       r"tip point .* 5.75 m above the waterline lies inside the hull: the hull's main "
                       r"deck is 9.00 m above"):
        check_config_files(_merged(own), [("config/config.yaml", copy.deepcopy(BASE)),
                                          ("own_vessel.yaml", own)])


def test_the_commands_do_not_carry_a_hull_over_to_another_vessel():
    """jls's commands load the configuration files themselves (jls.config.loader.load):
    the same rule as the workflow."""
    from jls.config.loader import load
    cfg = load(ROOT / "config" / "config.yaml", ROOT / "config" / "examples" / "own_vessel.yaml")
    assert "hull" not in cfg["vessel"]
    assert "hull" in load(ROOT / "config" / "config.yaml")["vessel"]
