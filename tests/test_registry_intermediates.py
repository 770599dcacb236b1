"""Intermediates that hold a registered quantity say what the registry says of it.

The RAO dataset, the hinge and fairlead transfers, a leg's scatter table and the tugger's
frequency-domain loads are not datasets jls writes, so they are not in the registry
(jls/schemas/datasets.yaml); each builds its own attributes (the RAO file format spells
units as m/m, rad/s). Where one holds a quantity a registered dataset also holds, its
hand-written units and long name must be the registry's (the unit in either spelling),
and every name with attributes it shares with that dataset is either that quantity or
listed below as another one.
"""

import numpy as np
import pytest

from jls.io import registry
from jls.sea.scatter import scatter_dataset
from jls.tugger.loads import frequency_domain_loads
from jls.tugger.setting import Tugger
from jls.vessel.rao import make_rao_dataset
from jls.vessel.transfer import fairlead_motion, hinge_excitation, point_motion

COMPARED = ("units", "long_name", "flag_meanings")


def unit(text: str) -> str:
    """A unit in UDUNITS spelling: 'm/s per m' -> 'm s-1 m-1', 'rad/s' -> 'rad s-1'."""
    out = []
    tokens = str(text).split()
    for i, tok in enumerate(tokens):
        if tok == "per":
            continue
        if i and tokens[i - 1] == "per":
            out.append(f"{tok}-1")
            continue
        head, *tail = tok.split("/")
        out += [head] + [f"{t}-1" for t in tail]
    return " ".join("degree" if t == "deg" else t for t in out)


def rao():
    omega = np.array([0.2, 0.4, 0.6])
    values = np.ones((omega.size, 2, 6), complex)
    return make_rao_dataset(omega, np.radians([0.0, 90.0]), values, source="synthetic",
                            source_format="test")


def tugger_loads():
    omega = np.linspace(0.1, 2.0, 50)
    sway = np.ones((1, omega.size), complex)
    return frequency_domain_loads(omega, sway, 0.5 * sway[0], [Tugger("reference", 1000.0)],
                                  tz=[8.0], hs=[1.0])


def scatter():
    return scatter_dataset(np.ones((2, 2, 2)), hs_lower=[0.0, 1.0], hs_upper=[1.0, 2.0],
                           tz_lower=[4.0, 5.0], tz_upper=[5.0, 6.0], direction=[0.0, 180.0])


def variables(obj):
    """name -> attrs of a Dataset's variables and coordinates, or of a DataArray and its
    coordinates (the DataArray under its own name)."""
    out = {name: dict(v.attrs) for name, v in obj.coords.items()}
    if hasattr(obj, "data_vars"):
        out.update({name: dict(v.attrs) for name, v in obj.data_vars.items()})
    else:
        out[obj.name] = dict(obj.attrs)
    return out


#: intermediate: (builder, the registered dataset it feeds, {its name: the registry's name
#: of the same quantity}, {a name it shares with that dataset: the other quantity it is})
INTERMEDIATES = {
    "RAO dataset": (rao, "vessel_motion",
                    {"omega": "omega", "rao": "rao", "dof": "vessel_dof", "dof_units": "vessel_dof_units"}, {}),
    "hinge excitation": (lambda: hinge_excitation(rao()), "vessel_motion",
                         {"omega": "omega", "qb": "hinge", "dof_b": "dof"}, {}),
    "fairlead motion": (lambda: fairlead_motion(rao()), "vessel_motion",
                        {"omega": "omega", "fairlead_motion": "fairlead", "axis": "axis"}, {}),
    "point motion": (lambda: point_motion(rao(), (1.0, 0.0, 0.0)), "vessel_motion",
                     {"omega": "omega", "axis": "axis"}, {}),
    "scatter table": (scatter, "sea_states",
                      {v: v for v in ("hs", "tz", "hs_lower", "hs_upper", "tz_lower", "tz_upper", "steep")},
                      {"probability": "the table's own, joint over direction where it has one; "
                                      "sea_states' is marginal over headings"}),
    "tugger loads": (tugger_loads, "response", {"omega": "omega", "tz": "tz"}, {}),
}


def registry_attrs(dataset: str) -> dict:
    entry = registry.layout(dataset)
    return {**entry["coordinates"], **entry["variables"]}


@pytest.mark.parametrize("name", list(INTERMEDIATES))
def test_shared_quantities_carry_the_registry_attributes(name):
    build, dataset, same, _ = INTERMEDIATES[name]
    attrs, spec = variables(build()), registry_attrs(dataset)
    for var, reg in same.items():
        assert var in attrs, (name, var)
        for key in COMPARED:
            if key in attrs[var] and key in spec[reg]:
                got, want = attrs[var][key], spec[reg][key]
                if key == "units":
                    got, want = unit(got), unit(want)
                assert got == want, (name, var, key)


@pytest.mark.parametrize("name", list(INTERMEDIATES))
def test_every_shared_name_is_accounted_for(name):
    build, dataset, same, other = INTERMEDIATES[name]
    written = {var for var, attrs in variables(build()).items() if attrs}
    shared = written & set(registry_attrs(dataset))
    assert shared <= set(same) | set(other), (name, sorted(shared - set(same) - set(other)))


def test_unit_spellings():
    assert unit("m/m") == "m m-1" and unit("rad/s") == "rad s-1"
    assert unit("m/s per m") == "m s-1 m-1" and unit("deg") == "degree" and unit("kN") == "kN"
