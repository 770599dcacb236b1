"""Frequency-domain statistics of sea states of one or more directional wave systems, for
every candidate, tugger setting and relative motion at once.

**Superposition.** The relative motions are linear in the excitation x(omega, beta) =
(qb_sway, qb_heave, qb_roll, qb_yaw, y_f): the hinge RAO and the fairlead sway at the
relative heading beta. So for every candidate c and tugger t there is a T(omega) (4 x 5)
with H(omega, beta) = T(omega) x(omega, beta), and the variance of a response r over a
directional sea S(omega, theta) is::

    m_n = int omega^n T_r Q(omega) T_r^H domega,   Q(omega) = sum_theta S(omega, theta) dtheta x x^H

Q is the 5 x 5 cross-spectral matrix of the excitation, the same for every candidate. It
is summed over every direction of every wave system of the sea state (each direction met
at ``beta = (course - theta + 180) mod 360``), with x x^H interpolated linearly between the
RAO headings: the linear interpolation of |H|^2 in heading that
:mod:`jls.response.directional` applies to measured spectra (:func:`heading_weights`).
Q is Hermitian and non-negative, Q = sum_k lambda_k v_k v_k^H, so the response is that to
at most five *equivalent excitations* sqrt(lambda_k) v_k, solved by the one compiled solver
(:func:`jls.response.solver.relative_power`) as if they were headings; a long-crested
system has rank 1 and costs one heading. The moments are then the trapezoid sums of |H|^2
on the solver's frequency grid, exactly as :func:`jls.response.moments.unit_moments` sums
them for a long-crested JONSWAP (to round-off, the same numbers).

Energy outside the RAO range is taken as no motion; the fraction of each sea state's
energy there is returned and checked against the configuration's stated zero-motion bands
(:mod:`jls.response.coverage`: more than 0.1 % unexplained is an error).

Statistics: sigma = sqrt(m0), Tz of the response 2 pi sqrt(m0/m2), MPM over the exposure
(:func:`jls.response.statistics.from_moments`), per criterion ``relative_sway_m``,
``relative_heave_m``, ``relative_roll_deg``, ``relative_yaw_deg``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import xarray as xr

from jls.errors import InputError
from jls.names import CRITERIA, RESPONSES
from jls.response.coverage import ENERGY_OUTSIDE_LIMIT, FIELD, zero_bands
from jls.response.directional import heading_weights
from jls.response.moments import Excitation, excitation
from jls.response.solver import relative_power
from jls.response.statistics import FIXED_CYCLES_STUDY, from_moments, trapezoid_weights
from jls.sea.headings import relative_heading
from jls.sea.sea_state import DIRECTIONS, SeaState, single_sea_state
from jls.threads import single_threaded_blas

__all__ = ["CRITERION_OF", "SeaStateTransfer", "sea_state_transfer", "cross_spectra",
           "equivalent_excitations", "heading_products", "group_products", "hold_powers", "sea_state_moments", "sea_state_statistics", "energy_outside"]

#: criterion key of each response (the motion criteria of :data:`jls.names.CRITERIA`)
CRITERION_OF = {resp: key for key, (resp, _) in CRITERIA.items() if resp in RESPONSES}
BLOCK = 64            # candidates per solver call (bounded memory)
STATES = 8            # sea states per solver call
RANK_TOL = 1e-13      # equivalent excitations below this share of the largest are empty
#: Sea states per RAO heading from which the moments come from the response power at the
#: RAO headings (n_h solves a candidate and tugger, whatever the number of sea states)
#: instead of each sea state's equivalent excitations (up to 5 solves a sea state):
#: :func:`heading_moments` when n_states >= n_h / HEADING_STATES.
HEADING_STATES = 5
HEADING_BLOCK = 8     # candidates per block of heading powers (bounded memory)
HEADING_GROUP = 64    # sea states per matrix product


@dataclass(frozen=True)
class SeaStateTransfer:
    """What every sea state shares: the plant of every candidate (``plant``: M, K, Kb, C,
    names), the excitation per RAO heading on the solver's grid (``exc``), the tugger
    settings {name: c [kN s/m]}, whether the RAO headings cover 0-180 only (mirrored), and
    the configuration's ``outside_policy`` (vessel.outside_rao_range)."""

    plant: xr.Dataset
    exc: Excitation
    tuggers: dict
    symmetric: bool
    outside_policy: object = None

    @property
    def candidates(self):
        return [str(c) for c in self.plant["candidate"].values]


def sea_state_transfer(plant: xr.Dataset, motion: xr.Dataset, tuggers: dict, omega_step: float,
                       outside_policy=None) -> SeaStateTransfer:
    """The :class:`SeaStateTransfer` of a plant and the vessel motion at its headings
    (ideally the RAO's headings over the whole circle, :func:`jls.sea.headings.rao_grid`)."""
    heads = np.mod(motion["heading"].values.astype(float), 360.0)
    exc = excitation(plant, motion, heads, omega_step)
    zero_bands(outside_policy)                     # a malformed policy fails here
    return SeaStateTransfer(plant, exc, dict(tuggers), bool(heads.max() <= 180.0 + 1e-9), outside_policy)


def _states(sea_states):
    if isinstance(sea_states, SeaState):
        return [sea_states]
    return [s if isinstance(s, SeaState) else single_sea_state(s) for s in sea_states]


def _heading_spectra(tr: SeaStateTransfer, state: SeaState, course: float, n_dirs: int):
    """A (n_h, n_w): the spectrum [m^2 s/rad] met at each RAO heading, summed over the
    systems and their directions with the heading interpolation weights."""
    heads, omega = tr.exc.headings, tr.exc.omega
    A = np.zeros((heads.size, omega.size))
    for sys in state.systems:
        dirs, w = sys.directions(n_dirs)
        beta = relative_heading(course, dirs)
        i0, i1, w1 = heading_weights(heads, beta, tr.symmetric)
        hw = np.zeros(heads.size)
        np.add.at(hw, i0, w * (1 - w1))
        np.add.at(hw, i1, w * w1)
        A += hw[:, None] * sys.spectrum(omega)[None, :]
    return A


def cross_spectra(tr: SeaStateTransfer, sea_states, vessel_heading_deg, n_dirs=DIRECTIONS, part=None) -> np.ndarray:
    """Q (n_states, n_w, 5, 5) complex: the cross-spectral matrix of the excitation (module
    docstring) of each sea state met by the vessel on ``vessel_heading_deg`` [deg true]
    (one for all, or one per sea state). ``part``: "positive" or "negative" for the matrices
    of the positive and the negative densities apart (a measured directional spectrum
    reconstructed from Fourier coefficients can be negative in places; Q is their difference)."""
    states = _states(sea_states)
    course = np.broadcast_to(np.asarray(vessel_heading_deg, float), (len(states),))
    X = np.concatenate([tr.exc.qb, tr.exc.fairlead_sway[..., None]], axis=-1)     # (n_h, n_w, 5)
    out = np.empty((len(states), tr.exc.omega.size, 5, 5), complex)
    for k, (s, c) in enumerate(zip(states, course)):
        A = _heading_spectra(tr, s, float(c), n_dirs)
        if part == "positive":
            A = np.maximum(A, 0.0)
        elif part == "negative":
            A = np.maximum(-A, 0.0)
        out[k] = np.einsum("hw,hwi,hwj->wij", A, X, X.conj(), optimize=True)
    return out


def equivalent_excitations(Q):
    """(qb (n_s, K, n_w, 4), yf (n_s, K, n_w)): the K <= 5 excitations sqrt(lambda_k) v_k
    whose responses' |H|^2 sum to T Q T^H (empty ones left out: K is the largest rank)."""
    Q = 0.5 * (Q + np.conj(np.swapaxes(Q, -1, -2)))          # Hermitian to round-off
    lam, V = np.linalg.eigh(Q)                                # ascending
    lam = np.clip(lam, 0.0, None)
    peak = lam.max() if lam.size else 0.0
    used = lam.max(axis=(0, 1)) > RANK_TOL * peak if peak > 0 else np.zeros(5, bool)
    keep = np.flatnonzero(used)
    if keep.size == 0:
        keep = np.array([4])
    x = V[..., keep] * np.sqrt(lam[..., None, keep])          # (n_s, n_w, 5, K)
    x = np.moveaxis(x, -1, 1)                                 # (n_s, K, n_w, 5)
    return np.ascontiguousarray(x[..., :4]), np.ascontiguousarray(x[..., 4])


def energy_outside(tr: SeaStateTransfer, sea_states, source=None) -> np.ndarray:
    """Fraction of each sea state's energy outside the solver's frequency range (taken as
    no motion); InputError when more than 0.1 % of it lies outside the stated bands too."""
    omega = tr.exc.omega
    lo, hi = float(omega[0]), float(omega[-1])
    below, above = zero_bands(tr.outside_policy, source)
    out = []
    for s in _states(sea_states):
        total = sum(x.m0() for x in s.systems)
        if total <= 0:
            out.append(0.0)
            continue
        low = np.linspace(0.0, lo, 4001)
        e_low = float(np.trapezoid(s.spectrum(low), low))
        e_in = float(np.trapezoid(s.spectrum(omega), omega))
        e_high = max(total - e_low - e_in, 0.0)
        outside = (e_low + e_high) / total
        explained = (e_low if below >= lo else 0.0) + (e_high if np.isfinite(above) and above <= hi else 0.0)
        if outside - explained / total > ENERGY_OUTSIDE_LIMIT:
            raise InputError(f"the sea state ({s.describe()}) has {100 * outside:.2f} % of its energy "
                             f"outside the RAO range [{lo:.3f}, {hi:.3f}] rad/s and the stated "
                             "zero-motion bands; extend the RAOs or state the band where the vessel "
                             "does not move", file=source, field=FIELD, value=round(100 * outside, 3))
        out.append(outside)
    return np.asarray(out)


def heading_products(tr: SeaStateTransfer, states, course, n_dirs=DIRECTIONS):
    """(groups, An) of :func:`heading_moments`: the slices of sea states of each matrix
    product and, per group, the (n_h n_w, g) matrices of A_h(omega) times the weights of m0
    and m2. Any linear response with |H|^2 known per RAO heading (the tip, the wire
    tensions: :mod:`jls.response.sea_state_tip_tension`) takes its moments from the same."""
    omega = tr.exc.omega
    n_s = len(states)
    tw = trapezoid_weights(omega)
    groups = [slice(a, min(a + HEADING_GROUP, n_s)) for a in range(0, n_s, HEADING_GROUP)]
    return groups, [group_products(tr, states[g], course[g], n_dirs, tw) for g in groups]


def group_products(tr: SeaStateTransfer, states, course, n_dirs=DIRECTIONS, tw=None):
    """[A_h(omega) times the weights of m0, of m2] ((n_h n_w, g) each) of one group of sea
    states (:func:`heading_products`)."""
    omega = tr.exc.omega
    tw = trapezoid_weights(omega) if tw is None else tw
    A = np.stack([_heading_spectra(tr, st, float(c), n_dirs) for st, c in zip(states, course)])
    return [np.ascontiguousarray((A * (tw * omega**q)).reshape(A.shape[0], -1).T) for q in (0, 2)]


def hold_powers(tr: SeaStateTransfer, n_states: int, products) -> bool:
    """Whether the response powers of every candidate are held and each group of sea states'
    products formed on the fly (more sea states than candidates and no products given:
    memory in candidates, not in sea states)."""
    return products is None and n_states > tr.plant.sizes["candidate"]


def heading_moments(tr: SeaStateTransfer, states, course, *, n_dirs=DIRECTIONS, threads=None, products=None):
    """m0, m2 as :func:`sea_state_moments`, for many sea states at once.

    Q = sum_h A_h x_h x_h^H (the spectrum met at each RAO heading h, :func:`cross_spectra`),
    so T Q T^H = sum_h A_h |T x_h|^2: the response power at the RAO headings, solved once
    per candidate and tugger (n_h solves, whatever the number of sea states), weighted by
    each sea state's A_h(omega) and the trapezoid weights: one matrix product per block of
    candidates and group of sea states. The same numbers as the equivalent excitations, to
    round-off; cheaper from about n_h / 5 sea states on (:data:`HEADING_STATES`).
    ``products``: :func:`heading_products` of the same sea states, formed once by a caller
    that needs them for other responses too. Without them and with more sea states than
    candidates (:func:`hold_powers`), the powers of every candidate are held and each group
    of :data:`HEADING_GROUP` sea states' products is formed, used and dropped: memory
    linear in candidates (n_c n_t 4 n_h n_w), not in sea states (2 n_h n_w each)."""
    omega = tr.exc.omega
    n_w, n_s, n_h = omega.size, len(states), tr.exc.headings.size
    p = tr.plant
    M, K, Kb, C = (p[k].values for k in ("M", "K", "Kb", "C"))
    c_t = [float(v) for v in tr.tuggers.values()]
    n_c, n_t = M.shape[0], len(c_t)
    m = np.zeros((2, n_s, n_c, n_t, 4))
    if hold_powers(tr, n_s, products):        # the candidates' powers held, the states' products not
        rows = []
        for b in range(0, n_c, HEADING_BLOCK):
            sl = slice(b, min(b + HEADING_BLOCK, n_c))
            P = relative_power(M[sl], K[sl], Kb[sl], C[sl], omega, tr.exc.qb, tr.exc.fairlead_sway, c_t,
                               threads=threads)
            rows.append((sl, P.shape[0], np.ascontiguousarray(P.transpose(0, 1, 3, 2, 4)).reshape(-1, n_h * n_w)))
        tw = trapezoid_weights(omega)
        for a in range(0, n_s, HEADING_GROUP):
            g = slice(a, min(a + HEADING_GROUP, n_s))
            an = group_products(tr, states[g], course[g], n_dirs, tw)
            with single_threaded_blas():
                for sl, nb, r in rows:
                    for q in (0, 1):
                        m[q, g, sl] = (r @ an[q]).reshape(nb, n_t, 4, -1).transpose(3, 0, 1, 2)
        return m[0], m[1]
    # per group of sea states, (n_h n_w, g) of A_h(omega) times the weights of m0 and m2
    groups, An = heading_products(tr, states, course, n_dirs) if products is None else products
    for b in range(0, n_c, HEADING_BLOCK):
        sl = slice(b, min(b + HEADING_BLOCK, n_c))
        P = relative_power(M[sl], K[sl], Kb[sl], C[sl], omega, tr.exc.qb, tr.exc.fairlead_sway, c_t,
                           threads=threads)                                    # (nb, t, n_h, 4, n_w)
        rows = np.ascontiguousarray(P.transpose(0, 1, 3, 2, 4)).reshape(-1, n_h * n_w)
        with single_threaded_blas():           # the same bits whatever the threads (and no spinning)
            for g, an in zip(groups, An):
                for q in (0, 1):
                    m[q, g, sl] = (rows @ an[q]).reshape(P.shape[0], n_t, 4, -1).transpose(3, 0, 1, 2)
    return m[0], m[1]


def sea_state_moments(tr: SeaStateTransfer, sea_states, vessel_heading_deg, *, n_dirs=DIRECTIONS,
                      threads=None, products=None):
    """m0, m2 (n_states, n_candidates, n_tuggers, 4 responses) [m^2, degree^2; /s^2] of each
    sea state (a :class:`jls.sea.sea_state.SeaState`, or a list of systems) met on
    ``vessel_heading_deg`` [deg true] (one, or one per sea state). Linear in candidates and
    sea states; candidates in blocks of :data:`BLOCK`, sea states in groups of :data:`STATES`.
    ``products``: :func:`heading_products` of these sea states when the caller has them."""
    states = _states(sea_states)
    course = np.broadcast_to(np.asarray(vessel_heading_deg, float), (len(states),))
    if products is not None or len(states) * HEADING_STATES >= tr.exc.headings.size:
        return heading_moments(tr, states, course, n_dirs=n_dirs, threads=threads, products=products)
    p = tr.plant
    M, K, Kb, C = (p[k].values for k in ("M", "K", "Kb", "C"))
    c_t = [float(v) for v in tr.tuggers.values()]
    omega = tr.exc.omega
    tw = trapezoid_weights(omega)
    W = np.stack([tw, tw * omega**2], axis=1)                       # (n_w, 2)
    n_c, n_t, n_s = M.shape[0], len(c_t), len(states)
    m = np.zeros((n_s, n_c, n_t, 4, 2))
    for a in range(0, n_s, STATES):
        grp = slice(a, min(a + STATES, n_s))
        Q = cross_spectra(tr, states[grp], course[grp], n_dirs, part="positive")
        Qn = cross_spectra(tr, states[grp], course[grp], n_dirs, part="negative")
        negative = bool(np.any(Qn != 0))
        if negative:                                                # positive part, then negative
            Q = np.concatenate([Q, Qn])
        qb, yf = equivalent_excitations(Q)                          # (g, K, n_w, 4), (g, K, n_w)
        g, k = qb.shape[:2]
        qb, yf = qb.reshape(g * k, omega.size, 4), yf.reshape(g * k, omega.size)
        for b in range(0, n_c, BLOCK):
            s = slice(b, min(b + BLOCK, n_c))
            P = relative_power(M[s], K[s], Kb[s], C[s], omega, qb, yf, c_t, threads=threads)
            mom = np.moveaxis((P @ W).reshape(P.shape[0], n_t, g, k, 4, 2).sum(axis=3), 2, 0)
            m[grp, s] = mom[:g // 2] - mom[g // 2:] if negative else mom
    return m[..., 0], m[..., 1]


def sea_state_statistics(tr: SeaStateTransfer, sea_states, vessel_heading_deg, *, exposure_h=3.0,
                         cycles="response", n_dirs=DIRECTIONS, threads=None, source=None,
                         products=None) -> xr.Dataset:
    """Statistics of each sea state for every candidate and tugger (module docstring):
    ``sigma``, ``tz_response``, ``n_cycles``, ``mpm``, ``m0``, ``m2`` over (sea_state,
    candidate, tugger, criterion) with the criteria ``relative_sway_m`` ... ``relative_yaw_deg``,
    and ``energy_outside`` (sea_state). ``cycles``: "response" (N = exposure / Tz of the
    response) or "fixed" (the study's N = 1000), as ``assessment.mpm_cycles``; ``products``:
    :func:`heading_products` of these sea states, formed once by a caller that shares them."""
    if cycles not in ("response", "fixed"):
        raise InputError("cycles must be 'response' or 'fixed'", field="assessment.mpm_cycles", value=cycles)
    states = _states(sea_states)
    outside = energy_outside(tr, states, source)
    m0, m2 = sea_state_moments(tr, states, vessel_heading_deg, n_dirs=n_dirs, threads=threads, products=products)
    st = from_moments(m0, m2, float(exposure_h) * 3600.0, "response" if cycles == "response" else FIXED_CYCLES_STUDY)
    dims = ("sea_state", "candidate", "tugger", "criterion")
    ds = xr.Dataset({k: (dims, v) for k, v in {**st, "m0": m0, "m2": m2}.items()},
                    coords={"sea_state": np.arange(len(states)), "candidate": tr.candidates,
                            "tugger": list(tr.tuggers), "criterion": [CRITERION_OF[r] for r in RESPONSES],
                            "response": ("criterion", list(RESPONSES))})
    ds["energy_outside"] = ("sea_state", outside)
    ds["vessel_heading_deg"] = ("sea_state", np.broadcast_to(np.asarray(vessel_heading_deg, float),
                                                             (len(states),)).copy())
    ds["description"] = ("sea_state", [s.describe() for s in states])
    ds.attrs.update(exposure_h=float(exposure_h), mpm_cycles=cycles, directions_per_system=int(n_dirs),
                    method="cross-spectral matrix of the excitation over every direction of every "
                           "system (jls.response.sea_state)")
    return ds

