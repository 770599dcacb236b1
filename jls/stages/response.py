"""Unit-Hs response dataset: statistics per candidate, tugger, heading and Tz, and the
transfer functions of the candidates the report shows (docs/reference/outputs.md,
``response.nc`` and ``operability.nc``).

The vessel RAOs are interpolated (amplitude and phase) onto one frequency grid refined
around the lightly damped modes of every candidate (:func:`jls.response.solver.frequency_grid`,
bounded in size whatever the number of candidates), transferred to the hinge and the
fairleads, and driven through the plant of every candidate. Candidates are processed in
blocks of ``BLOCK`` (bounded memory); spectral moments of each sea state can be kept in
a :class:`jls.io.sea_state_cache.SeaStateCache` so that only sea states not seen before are
evaluated. The grid never leaves the RAO's frequency range: the energy of each sea state
outside it is measured, and more than 0.1 % is an error unless the configuration states
that the vessel is still there.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.io import registry
from jls.response.coverage import check_coverage
from jls.response.moments import excitation, shown_transfer, statistics_dataset, unit_moments
from jls.response.tip import NOT_COMPUTED, TipSettings, tip_response
from jls.response.wire_loads import has_geometry, tension_response
from jls.tugger.loads import add_tugger_loads


def response_dataset(plant: xr.Dataset, motion: xr.Dataset, tz, headings_deg, tuggers: dict,
                     *, gamma=3.3, exposure_h=3.0, cycles="response", omega_step=0.002,
                     outside_policy="error", source=None, shown=("baseline",), cache=None,
                     threads=None, moments=None, tensions=True, tugger_loads=True,
                     tip: TipSettings | None = None, g=9.81) -> xr.Dataset:
    """Unit-Hs statistics of every candidate and transfer functions of ``shown``.

    plant, motion: datasets of docs/reference/outputs.md (complex merged); tz: Tz values [s];
    headings_deg: headings to evaluate; tuggers: name -> damping slope [kN s/m];
    cycles: "response" or "fixed" (N = 1000, as the study); cache: sea-state cache directory;
    moments: (m0, m2) of every candidate on the sorted ``tz`` already computed (by chunks,
    :func:`unit_moments`), else computed here.
    tensions: add the wire-tension statistics (:mod:`jls.response.wire_loads`) when the plant
    carries the wire geometry: True for every candidate, a list of candidate names for
    those only (NaN for the others), False for none.
    tugger_loads: add the tugger loads per candidate, tugger, heading and Tz
    (:func:`jls.tugger.loads.add_tugger_loads`; computed here also when the moments come
    from chunks).
    tip: the tip-clearance settings (:class:`jls.response.tip.TipSettings`): add the
    statistics of the jacket tip's motion relative to the wave surface (``tip_*``,
    ``wave_*``; :func:`jls.response.tip.tip_response`, every candidate; needs the
    geometric plant); None: not computed. g [m/s^2]: the waves' dispersion.
    The number of sea states evaluated (not read from the cache) is in attrs
    ``sea_states_evaluated`` of the returned dataset (not written to files).
    """
    tz = np.asarray(sorted(set(float(t) for t in tz)))
    lo, hi = float(motion["omega"].min()), float(motion["omega"].max())
    frac = check_coverage(lo, hi, tz, gamma, outside_policy, source)
    exc = excitation(plant, motion, headings_deg, omega_step)
    if moments is None:
        m0, m2, evaluated = unit_moments(plant, exc, tz, [float(tuggers[n]) for n in tuggers],
                                         gamma, cache=cache, threads=threads)
    else:
        (m0, m2), evaluated = moments, 0
    ds = statistics_dataset(m0, m2, candidates=plant["candidate"].values.tolist(), tuggers=tuggers,
                            headings=exc.headings, tz=tz, gamma=gamma, exposure_h=exposure_h,
                            cycles=cycles, energy_outside_fraction=frac, outside_policy=outside_policy)
    if tensions is not False and has_geometry(plant):
        ds = ds.merge(tension_response(plant, exc, tz, tuggers, gamma=gamma, exposure_h=exposure_h,
                                       cycles=cycles, threads=threads,
                                       candidates=None if tensions is True else tensions),
                      combine_attrs="override")
        registry.annotate(ds, "response")
    if tugger_loads:
        add_tugger_loads(ds, plant, exc, tuggers, gamma=gamma, exposure_h=exposure_h,
                         cycles=cycles, threads=threads)
    ds.attrs.update(tip_crest=NOT_COMPUTED, tip_clearance=NOT_COMPUTED)
    if tip is not None:
        ds = ds.merge(tip_response(plant, exc, motion.attrs["hinge_m"][:2], tz, tuggers, tip,
                                   gamma=gamma, exposure_h=exposure_h, cycles=cycles, g=g,
                                   threads=threads), combine_attrs="override")
        ds.attrs.update(tip_crest=tip.crest, tip_clearance=tip.describe())
        registry.annotate(ds, "response")
    if shown:
        ds["transfer"] = shown_transfer(plant, exc, shown, tuggers, threads)
        registry.annotate(ds, "response")
    ds.attrs["sea_states_evaluated"] = evaluated
    return ds
