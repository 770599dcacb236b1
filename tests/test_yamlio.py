"""The one YAML loader: what it accepts as well as what it refuses."""

import pytest

from jls.errors import InputError
from jls.io import yamlio


def test_engineering_floats_and_ordinary_yaml():
    data = yamlio.loads("a: 4.55e6\nb: 4.55e+6\nc: 1e-3\nd: 12\ne: [1, 2.5]\nf: .inf\n")
    assert data == {"a": 4.55e6, "b": 4.55e6, "c": 1e-3, "d": 12, "e": [1, 2.5],
                    "f": float("inf")}
    assert isinstance(data["a"], float) and isinstance(data["d"], int)


def test_small_anchors_and_merge_keys_are_fine():
    text = ("base: &b {x: 1, y: 2}\n"
            "leg: {<<: *b, y: 3}\n"            # a merge key overridden: not a duplicate
            "list: [*b, *b]\n")
    data = yamlio.loads(text)
    assert data["leg"] == {"x": 1, "y": 3} and data["list"] == [{"x": 1, "y": 2}] * 2


def test_alias_expansion_is_bounded_not_the_anchor_count():
    # 4 levels of 10 aliases: 11 110 nodes expanded, under the bound.
    levels = ['a: &a [0, 0, 0, 0, 0, 0, 0, 0, 0, 0]']
    for prev, name in zip("abc", "bcd"):
        levels.append(f"{name}: &{name} [{', '.join(['*' + prev] * 10)}]")
    assert len(yamlio.loads("\n".join(levels))["d"]) == 10
    # Two more levels pass the bound.
    for prev, name in zip("de", "ef"):
        levels.append(f"{name}: &{name} [{', '.join(['*' + prev] * 10)}]")
    with pytest.raises(InputError, match="alias bomb"):
        yamlio.loads("\n".join(levels), source="bomb.yaml")


def test_byte_order_mark_and_comments_in_a_utf8_file(tmp_path):
    path = tmp_path / "c.yaml"
    path.write_bytes("\ufeff# déjà vu\nname: café\n".encode("utf-8"))
    assert yamlio.load(path) == {"name": "café"}


@pytest.mark.parametrize("text, match", [
    ("a: 1\na: 2\n", r"c\.yaml: line 2: key given twice \(first on line 1\).*'a'"),
    ("x:\n  - {k: 1, k: 2}\n", "key given twice"),
    ("a:\n\tb: 1\n", "line 2: tab character"),
    ("a: [1, 2\n", "not valid YAML"),
    ("", "empty file"),
    ("# only\n\n", "empty file"),
    ("[1, 2]\n", "top level must be a mapping"),
])
def test_refused(text, match):
    with pytest.raises(InputError, match=match):
        yamlio.loads(text, source="c.yaml")


def test_yte_refused_only_when_asked():
    text = "__use_yte__: true\na: 1\n"
    assert yamlio.loads(text)["a"] == 1
    with pytest.raises(InputError, match="YTE"):
        yamlio.loads(text, refuse_yte=True)
    assert yamlio.loads("- 1\n", mapping=False) == [1]
