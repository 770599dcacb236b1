"""Fixtures several test files share: the shipped configuration, validated, and its
rigging (each built once per test module, as the files built them)."""

from pathlib import Path

import pytest

from jls.config.builders import rigging_from_config
from jls.config.loader import load

CONFIG = Path(__file__).resolve().parents[1] / "config" / "config.yaml"


@pytest.fixture(scope="module")
def cfg():
    """The shipped configuration (config/config.yaml), loaded and validated."""
    return load(CONFIG)


@pytest.fixture(scope="module")
def rig(cfg):
    """The shipped rigging (:func:`jls.config.builders.rigging_from_config`)."""
    return rigging_from_config(cfg)
