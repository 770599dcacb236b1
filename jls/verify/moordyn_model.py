"""The reference written as a MoorDyn-C 2.x input and run as a quiet, file-less session.

MoorDyn works in SI units: the file is written in kg, N, m, s (converted from jls's
t, kN here and nowhere else). MoorDyn prints to the terminal and writes output files
beside its input: the input is written to a temporary directory that is removed when
the session closes, every output is disabled (``disableOutput``, ``disableOutTime``)
and the terminal output of creating the system is discarded at the file-descriptor
level. The time scheme is RK4 (the default RK2 gains energy on undamped modes) and the
initial-condition solve is skipped (``Init_NoIC``): the body starts at the pose jls
solved (:func:`jls.verify.statics.solve_pose`). With one segment per line no line has a
node of its own, and the coupled points' positions handed to the initialisation only
seed MoorDyn's catenary guess of the inner nodes, which a one-segment line discards
(each step sets the coupled points from the record): the initialisation then takes each
coupled point straight above its line's body end, where MoorDyn skips the catenary
(whose Newton iteration on a taut wire of a tiny weight runs its 2 x 10^5 iterations
and fails, about 9 ms a wire, 37 ms per session). Option names MoorDyn does not know are
ignored by it, so only names read by MoorDyn 2.7's option parser are written (water
density is ``rho``, water depth ``WtrDpth``).

Objects, in the order MoorDyn numbers them (from 1):

* points: 4 padeyes on the body; 4 lift-beam tips (coupled); with a tugger 2 fairleads
  (coupled) and 2 attachments on the body; the weight correction at the CoG (a body
  point with a constant force, (M_kin - M_grav) g upward); per dashpot a body point
  (carrying its line's weight on it upward) and a fixed point
  :data:`jls.verify.damping.FAR_M` away;
* lines: 4 hoist wires (A at the tip, B at the padeye); 2 tugger lines (A at the
  fairlead); the dashpots (A at the fixed point).

The coupled degrees of freedom are the tips' positions (12) then the fairleads' (6).
"""

from __future__ import annotations

import contextlib
import os
import shutil
import sys
import tempfile

import numpy as np

from jls.verify.statics import pose_matrix, rotation

KG, N = 1000.0, 1000.0          # t -> kg, kN -> N
#: Smallest line mass per length written [kg/m]: a massless line gives MoorDyn a zero
#: time step; this one adds 1e-9 of the jacket's mass.
MIN_LINE_MASS_KG_PER_M = 1e-3
#: Unstretched length of a tugger line [m]: short, so that its EA (set each step to
#: give the commanded tension) makes a soft spring within the step.
TUGGER_L0_M = 0.1
#: Water depth written [m]: deep enough that no line node or point reaches MoorDyn's
#: seabed (a dashpot's line of action may pass 100 m and more below the jacket's CoG,
#: whose body point is then below the water line; its seabed contact pushed the jacket).
WATER_DEPTH_M = 10000.0
#: Diameter of a dashpot line [m]: no buoyancy worth the name where it is under water.
DASHPOT_DIAMETER_M = 1e-6


class ReferenceUnavailable(RuntimeError):
    """MoorDyn cannot be imported: the nonlinear reference cannot run."""


def import_moordyn():
    """The moordyn module, or :class:`ReferenceUnavailable` saying why."""
    try:
        import moordyn
        return moordyn
    except Exception as exc:  # noqa: BLE001 - ImportError, or a broken binary wheel
        raise ReferenceUnavailable(
            "the nonlinear reference needs MoorDyn (pip install moordyn, MoorDyn-C 2.x): "
            f"it cannot be imported ({type(exc).__name__}: {exc}); nothing was verified") from None


def available() -> tuple[bool, str]:
    """(True, version) when MoorDyn imports, else (False, the reason)."""
    try:
        import_moordyn()
    except ReferenceUnavailable as exc:
        return False, str(exc)
    from importlib.metadata import PackageNotFoundError, version
    try:
        return True, version("moordyn")
    except PackageNotFoundError:
        return True, "unknown"


def _fmt(v) -> str:
    return f"{float(v):.12e}"


def tugger_ea(tension_kN, length_m) -> float:
    """EA [N] of a tugger line of stretched length ``length_m`` carrying ``tension_kN``."""
    return tension_kN * N * TUGGER_L0_M / max(length_m - TUGGER_L0_M, 1e-6)


def internal_step(ref, dt=0.02) -> float:
    """MoorDyn's own step dtM [s]: the coupling step ``dt``, or with wires of several
    segments a tenth of the axial period of one segment's node (an explicit scheme on a
    steel wire's nodes needs it: 50 kg/m gives about 1 ms), MoorDyn then sub-stepping
    each coupling step."""
    if ref.segments <= 1:
        return float(dt)
    seg = ref.L0 / ref.segments
    m_node = ref.wire_mass_per_length * seg                     # t
    k_seg = ref.k * ref.segments                                # kN/m
    period = 2 * np.pi * np.sqrt(m_node / k_seg)
    n = int(np.ceil(dt / (0.1 * float(period.min()))))
    return float(dt) / max(n, 1)


def input_text(ref, pose=None, dt=0.02) -> str:
    """The MoorDyn input of the reference with the body at ``pose`` (default: static)."""
    pose = ref.pose if pose is None else np.asarray(pose, float)
    types, points, lines = [], [], []

    def point(kind, r, force=None):
        extra = "" if force is None else " ".join(_fmt(f) for f in force) + " "
        points.append(f"{len(points) + 1} {kind} {_fmt(r[0])} {_fmt(r[1])} {_fmt(r[2])} 0 0 {extra}0 0")
        return len(points)

    def line_type(name, mass_t_per_m, ea_kN, ba_kN_s, diameter_m=0.01):
        # a negative BA is minus a damping ratio (MoorDyn's convention): not converted
        m = max(mass_t_per_m * KG, MIN_LINE_MASS_KG_PER_M)
        ba_kN_s = ba_kN_s if ba_kN_s >= 0 else ba_kN_s / N
        types.append(f"{name} {diameter_m:g} {_fmt(m)} {_fmt(ea_kN * N)} {_fmt(ba_kN_s * N)} 0 0 0 0 0")
        return name

    def line(kind, a, b, L0, segs=1):
        lines.append(f"{len(lines) + 1} {kind} {a} {b} {_fmt(L0)} {segs} -")

    pad = [point("Body1", p) for p in ref.padeyes]
    tips = [point("Coupled", t) for t in ref.tips_rest]
    for i in range(4):
        name = line_type(f"wire{i + 1}", ref.wire_mass_per_length, ref.k[i] * ref.L0[i],
                         ref.wire_axial_damping if ref.segments > 1 else 0.0)
        line(name, tips[i], pad[i], ref.L0[i], ref.segments)
    if ref.tugger is not None:
        fl = [point("Coupled", f) for f in ref.fairleads_rest]
        att = [point("Body1", a) for a in ref.attachments]
        cog, R = pose[:3], rotation(*pose[3:])
        for j in range(2):
            length = np.linalg.norm(ref.fairleads_rest[j] - (cog + R @ ref.attachments[j]))
            name = line_type(f"tugger{j + 1}", 0.0, tugger_ea(ref.tugger.pretension, length) / N, 0.0)
            line(name, fl[j], att[j], TUGGER_L0_M)
    dp = ref.dashpots
    cog0, R0 = pose[:3], rotation(*pose[3:])
    L0_dash = 1.5 * dp.far_m
    # dashpots at one body point share it; each point carries upward the half of its
    # dashpot lines' weight that MoorDyn puts on their body end (a few kg each, but far
    # from the CoG their moment would tilt the jacket by 1e-7 rad)
    keys = [tuple(float(v) for v in b) for b, c in zip(dp.points, dp.c_line) if c > 0.0]
    lift = 0.5 * MIN_LINE_MASS_KG_PER_M * L0_dash * ref.g          # N per dashpot line
    count = {k: keys.count(k) for k in keys}
    origin = (0.0, 0.0, 0.0)
    cog_pt = point("Body1", origin, force=(0.0, 0.0, (ref.m_kin - ref.m_grav) * ref.g * N
                                            + count.get(origin, 0) * lift))
    shared = {origin: cog_pt}
    for n, (b, d, c) in enumerate(zip(dp.points, dp.directions, dp.c_line)):
        if c <= 0.0:
            continue
        key = tuple(float(v) for v in b)
        if key not in shared:
            shared[key] = point("Body1", b, force=(0.0, 0.0, count[key] * lift))
        body_pt = shared[key]
        far = point("Fixed", cog0 + R0 @ b + dp.far_m * d)
        name = line_type(f"dashpot{n + 1}", 0.0, 1e-3, c * L0_dash, DASHPOT_DIAMETER_M)
        line(name, far, body_pt, L0_dash)
    ang = np.degrees(pose[3:])
    body = (f"1 free {_fmt(pose[0])} {_fmt(pose[1])} {_fmt(pose[2])} {_fmt(ang[0])} {_fmt(ang[1])} "
            f"{_fmt(ang[2])} {_fmt(ref.m_kin * KG)} 0 "
            + "|".join(_fmt(i * KG) for i in ref.inertia) + " 0 0 0")
    return "\n".join([
        "jls nonlinear reference: jacket on four hoist wires in air (generated by jls.verify)",
        "---------------------- LINE TYPES -----------------------------------",
        "Name Diam MassDen EA BA EI Cd Ca CdAx CaAx",
        "(-) (m) (kg/m) (N) (N-s) (N-m^2) (-) (-) (-) (-)", *types,
        "---------------------- BODIES -----------------------------------",
        "ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca*",
        "(#) (-) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)", body,
        "---------------------- POINTS -----------------------------------",
        "ID Attachment X Y Z Mass Volume [FX FY FZ] CdA Ca",
        "(#) (-) (m) (m) (m) (kg) (m^3) [(N)] (m^2) (-)", *points,
        "---------------------- LINES -----------------------------------",
        "ID LineType AttachA AttachB UnstrLen NumSegs Outputs",
        "(#) (name) (#) (#) (m) (-) (-)", *lines,
        "---------------------- OPTIONS -----------------------------------",
        f"{internal_step(ref, dt):.10g} dtM", "RK4 tScheme", f"{ref.g:.10g} g", "1025 rho",
        f"{WATER_DEPTH_M:g} WtrDpth", "0 writeLog", "1 disableOutput", "1 disableOutTime",
        "--------------------- need this line ------------------------------", ""])


@contextlib.contextmanager
def _quiet_stdout():
    """Discard what C code prints to file descriptor 1 (MoorDyn's banner)."""
    sys.stdout.flush()
    saved = os.dup(1)
    try:
        with open(os.devnull, "w") as null:
            os.dup2(null.fileno(), 1)
            yield
    finally:
        os.dup2(saved, 1)
        os.close(saved)


def _init_positions(ref, pose, x0) -> list:
    """The coupled points' positions for MoorDyn's initialisation (module docstring):
    ``x0`` with one segment per line, each point moved horizontally to straight above
    (or below) its line's body end at ``pose``; ``x0`` itself with more segments."""
    if ref.segments != 1:
        return x0
    cog, R = pose_matrix(ref.pose if pose is None else pose)
    ends = ref.padeyes if ref.tugger is None else np.concatenate([ref.padeyes, ref.attachments])
    p = np.array(x0, float).reshape(-1, 3)
    p[:, :2] = (cog + np.asarray(ends, float) @ R.T)[:, :2]
    return p.ravel().tolist()


class Session:
    """One MoorDyn system of the reference, started at ``pose`` (static by default).

    Use as a context manager; ``tips0`` (4, 3) and ``fairleads0`` (2, 3) are the
    coupled points' positions at t = 0 (default: at rest). Attributes: ``md`` (the
    moordyn module), ``system``, ``body``, ``wires`` (4 lines), ``tugger_lines``.
    """

    def __init__(self, ref, pose=None, dt=0.02, tips0=None, fairleads0=None):
        self.md = import_moordyn()
        self.ref, self.dt = ref, float(dt)
        self.dir = tempfile.mkdtemp(prefix="jls-moordyn-")
        path = os.path.join(self.dir, "reference.txt")
        with open(path, "w") as fh:
            fh.write(input_text(ref, pose, dt))
        md = self.md
        try:
            with _quiet_stdout():
                self.system = md.Create(path)
                md.SetVerbosity(self.system, md.LEVEL_NONE)
                x = [ref.tips_rest if tips0 is None else tips0]
                if ref.tugger is not None:
                    x.append(ref.fairleads_rest if fairleads0 is None else fairleads0)
                x0 = np.concatenate([np.ravel(a) for a in x]).tolist()
                err = md.Init_NoIC(self.system, _init_positions(ref, pose, x0), [0.0] * len(x0))
        except Exception:
            shutil.rmtree(self.dir, ignore_errors=True)
            raise
        if err != 0:
            self.close()
            raise RuntimeError(f"MoorDyn could not initialise the reference (error {err})")
        self.body = md.GetBody(self.system, 1)
        self.wires = [md.GetLine(self.system, i + 1) for i in range(4)]
        self.tugger_lines = ([md.GetLine(self.system, 5 + j) for j in range(2)]
                             if ref.tugger is not None else [])
        self.n_coupled = len(x0)

    def close(self):
        if getattr(self, "system", None) is not None:
            with _quiet_stdout():
                self.md.Close(self.system)
            self.system = None
        shutil.rmtree(self.dir, ignore_errors=True)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False


__all__ = ["Session", "input_text", "internal_step", "available", "import_moordyn", "ReferenceUnavailable",
           "tugger_ea", "TUGGER_L0_M", "MIN_LINE_MASS_KG_PER_M"]
