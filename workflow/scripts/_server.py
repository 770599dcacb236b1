"""The job server: workflow jobs on this machine start from one process that has imported
numpy, scipy, xarray, numba, matplotlib and jls once, instead of each importing them.

A workflow job is a short process whose imports cost 0.6-1.3 s of CPU (xarray and pandas
0.45 s, numba 0.4 s, scipy, Snakemake's job object, MoorDyn in a verification cell),
often more than its work. For a run on this machine the Snakefile starts the server
(``start``) before the first job and stops it after the last. A job's script, as
Snakemake starts it, hands itself over at its first line (``_job`` calls
:func:`hand_over`): it sends the server its script, working directory, environment and
standard streams; the server forks a child, already imported, that runs the script as
Python would have, with the job's streams, directory and environment; the job's process
waits, passes its signals on to the child, and ends with the child's exit status. What a
job computes does not depend on which process runs it (the tests run jobs both ways).

Where there is no server (a cluster job, a script run by hand, a server not yet ready or
gone, a system other than Linux) the job runs in its own process, as before.
``JLS_JOB_SERVER=off`` in the environment turns the server off for a run (a job's CPU
time and memory in Snakemake's benchmark files are then its own process's; with the
server they count only the waiting process, the wall time stays right).

Standard library only, until the server imports what its children share.
"""

from __future__ import annotations

import json
import os
import signal
import socket
import struct
import sys
import traceback

#: environment variable naming the server's socket (set for the jobs by ``start``)
SOCKET_VAR = "JLS_JOB_SERVER"
#: set in the server and its children, so that a child's script does not hand over again
CHILD_VAR = "JLS_JOB_CHILD"
#: how long a job waits for the server to take it before it runs in its own process [s]
#: (the server takes a job between two of its imports, each well under a second)
START_TIMEOUT_S = 20.0
#: for tests and debugging: a file each child appends its process id and script to
TRACE_VAR = "JLS_JOB_SERVER_TRACE"
#: imported by the server before it takes a job: what every job imports
CORE = (
    "snakemake.io", "snakemake.iocontainers", "snakemake.logging", "snakemake.shell",
    "numpy", "pandas", "xarray", "netCDF4", "jls.io.netcdf", "jls.io.provenance",
    "jls.config.dataset_hash",
)


def _send(sock, data: bytes):
    sock.sendall(struct.pack("!I", len(data)) + data)


def _recv_exact(sock, n):
    buf = b""
    while len(buf) < n:
        chunk = sock.recv(n - len(buf))
        if not chunk:
            raise EOFError
        buf += chunk
    return buf


def _recv(sock) -> bytes:
    (n,) = struct.unpack("!I", _recv_exact(sock, 4))
    return _recv_exact(sock, n)


# -- the job's side ------------------------------------------------------------------------

def hand_over() -> None:
    """Run this job's script in a child of the server and end with its exit status; return
    (and let the script run here) when there is no server to take it."""
    path = os.environ.get(SOCKET_VAR)
    if not path or path == "off" or os.environ.get(CHILD_VAR):
        return
    sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    try:
        sock.connect(path)
    except OSError:
        sock.close()
        return
    request = {"argv": sys.argv, "cwd": os.getcwd(), "env": dict(os.environ)}
    for stream in (sys.stdout, sys.stderr):
        stream.flush()
    try:
        sock.settimeout(START_TIMEOUT_S)
        socket.send_fds(sock, [b"j"], [0, 1, 2])
        _send(sock, json.dumps(request).encode())
        child = int(_recv(sock))
        _send(sock, b"go")          # the child runs the script only after this
        sock.settimeout(None)
    except (OSError, EOFError, ValueError):
        sock.close()
        return                      # the server did not take it: run here
    passed = []

    def pass_on(sig, _frame):
        passed.append(sig)
        try:
            os.kill(child, sig)
        except ProcessLookupError:
            pass

    for sig in (signal.SIGTERM, signal.SIGINT, signal.SIGHUP, signal.SIGQUIT):
        signal.signal(sig, pass_on)
    try:
        status = int(_recv(sock))
    except (OSError, EOFError, ValueError):
        if passed:                   # ended by the signal passed on, as a process would be
            os._exit(128 + passed[0])
        print(f"jls job server: the job's process {child} ended without an exit status "
              "(killed, or it crashed)", file=sys.stderr)
        status = 1
    os._exit(status)


# -- the server's side ---------------------------------------------------------------------

def _exit_status(exc: SystemExit) -> int:
    """The exit status Python gives a SystemExit (a message goes to stderr, status 1)."""
    code = exc.code
    if code is None:
        return 0
    if isinstance(code, int):
        return code
    print(code, file=sys.stderr)
    return 1


def _run_child(conn) -> int:
    """In the forked child: take the job's streams, directory and environment, run its
    script as ``python script`` would, and return its exit status."""
    _, fds, _, _ = socket.recv_fds(conn, 1, 3)
    request = json.loads(_recv(conn))
    for target, fd in enumerate(fds):
        os.dup2(fd, target)
        os.close(fd)
    os.chdir(request["cwd"])
    os.environ.clear()
    os.environ.update(request["env"])
    os.environ[CHILD_VAR] = "1"
    sys.argv = list(request["argv"])
    sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
    for sig in (signal.SIGTERM, signal.SIGINT, signal.SIGHUP, signal.SIGQUIT, signal.SIGCHLD):
        signal.signal(sig, signal.SIG_DFL)
    signal.signal(signal.SIGINT, signal.default_int_handler)
    _send(conn, str(os.getpid()).encode())
    if _recv(conn) != b"go":        # the job gave up waiting and runs in its own process
        raise EOFError
    if os.environ.get(TRACE_VAR):
        with open(os.environ[TRACE_VAR], "a") as trace:
            trace.write(f"{os.getpid()} {sys.argv[0]}\n")
    blas = os.environ.get("OPENBLAS_NUM_THREADS") or os.environ.get("OMP_NUM_THREADS")
    if blas and blas.isdigit():     # the job's threads, as its own process would have read
        from threadpoolctl import threadpool_limits
        threadpool_limits(limits=int(blas))
    import atexit
    import runpy
    try:
        runpy.run_path(sys.argv[0], run_name="__main__")
        status = 0
    except SystemExit as exc:
        status = _exit_status(exc)
    except BaseException:
        traceback.print_exc()
        status = 1
    atexit._run_exitfuncs()         # as the interpreter would at its exit
    return status


def _preloads():
    """The rest of what the children share, one step at a time, taken between jobs: scipy,
    numba with its compiler readied, every module of jls (matplotlib and the report among
    them) and MoorDyn where installed. A module that fails to import is left to the job
    that needs it, which then fails as it would have without the server."""
    import importlib
    import pkgutil

    import jls
    for name in ("scipy.linalg", "scipy.optimize", "scipy.signal", "scipy.interpolate",
                 "scipy.stats", "threadpoolctl", "numba"):
        yield importlib.import_module(name)
    # numba readies its compiler's registries once a process, at the first compiled call
    # (0.45 s of a job that loads a cached kernel): done here, for every child.
    import numba
    yield numba.njit(lambda x: x + 1)(1)
    for info in pkgutil.walk_packages(jls.__path__, "jls.", onerror=lambda _name: None):
        try:
            yield importlib.import_module(info.name)
        except Exception as exc:
            print(f"jls job server: {info.name} not preloaded: {exc}", file=sys.stderr)
    try:
        yield importlib.import_module("moordyn")
    except ImportError:
        pass


def _check_parent(parent):
    """End the server once the Snakemake process has ended (a run that stopped at its
    parse, or was killed), removing its socket and, where :func:`start` made them, its
    log and folder (only those: nothing else is ever deleted)."""
    if os.getppid() != parent:
        path, folder = _SOCKET_PATH
        if folder:
            _remove(folder)
        else:
            _unlink(path)
        os._exit(0)


def _unlink(path):
    try:
        os.unlink(path)
    except OSError:
        pass


def _remove(folder):
    """Remove start()'s folder: its known files, then the folder if that left it empty."""
    for name in (LOG, SOCKET, PID):
        _unlink(os.path.join(folder, name))
    try:
        os.rmdir(folder)
    except OSError:
        pass


def _remove_stale(tmp):
    """Remove the folders of servers that were killed without a chance to tidy up (a
    SIGKILL to Snakemake's process group): those whose server's process has ended."""
    import glob
    for folder in glob.glob(os.path.join(tmp, PREFIX + "*")):
        try:
            with open(os.path.join(folder, PID)) as fh:
                os.kill(int(fh.read()), 0)
        except ProcessLookupError:
            _remove(folder)
        except (OSError, ValueError):
            pass                     # being made by another run, or not ours to judge


#: the socket and, where start() made it, the folder holding it and the server's log
_SOCKET_PATH = ["", ""]
#: start()'s folder (in the temporary directory) and the server's log, socket and process
#: id in it
PREFIX, LOG, SOCKET, PID = "jls-jobs-", "log", "socket", "pid"


def _stop(*_):
    raise SystemExit(0)


def serve(path, parent, folder="") -> None:
    """Import what every job needs, then fork a child per job until ``parent`` (the
    Snakemake process) ends or the server is told to stop (SIGTERM); between jobs, import
    the rest (:func:`_preloads`), so that the first jobs need not wait for it."""
    import importlib
    _SOCKET_PATH[:] = [path, folder]
    os.environ[CHILD_VAR] = "1"
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    signal.signal(signal.SIGTERM, _stop)
    signal.signal(signal.SIGINT, signal.SIG_IGN)     # Ctrl-C reaches the jobs themselves
    importlib.import_module("_job")     # its collector setting, for every child
    for name in CORE:
        _check_parent(parent)
        importlib.import_module(name)
    listener = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    listener.bind(path)
    listener.listen(64)
    preloads = _preloads()
    try:
        while True:
            _check_parent(parent)
            listener.settimeout(0 if preloads else 0.5)
            try:
                conn, _ = listener.accept()
            except (BlockingIOError, TimeoutError, InterruptedError):
                conn = None
                if preloads is not None and next(preloads, StopIteration) is StopIteration:
                    preloads = None
            if conn is not None:
                _fork_job(listener, conn)
            while True:                  # reap finished children
                try:
                    pid, _ = os.waitpid(-1, os.WNOHANG)
                except ChildProcessError:
                    break
                if pid == 0:
                    break
    finally:
        listener.close()
        _unlink(path)
        # Snakemake has waited for every job: reap their children, so that their resource
        # use (the peak memory of the largest, RUSAGE_CHILDREN) reaches the server's parent
        while True:
            try:
                os.waitpid(-1, 0)
            except ChildProcessError:
                break


def _fork_job(listener, conn):
    """Fork a child that runs the job on ``conn`` and ends with its status."""
    conn.setblocking(True)
    if os.fork() != 0:
        conn.close()
        return
    listener.close()
    status = 1
    try:
        status = _run_child(conn)
    finally:
        for stream in (sys.stdout, sys.stderr):
            try:
                stream.flush()
            except Exception:
                pass
        try:
            _send(conn, str(status).encode())
        except OSError:
            pass
        os._exit(status)


#: command-line options of a Snakemake run that executes no job
NO_JOBS = {
    "-n", "--dry-run", "--dryrun", "--lint", "-S", "--summary", "-D", "--detailed-summary",
    "-l", "--list", "--list-rules", "--lt", "--list-target-rules", "--dag", "--d3dag",
    "--rulegraph", "--filegraph", "--unlock", "--cleanup-metadata", "--cm", "--lc",
    "--list-changes", "--li", "--list-input-changes", "--lp", "--list-params-changes",
    "--list-code-changes", "--delete-all-output", "--delete-temp-output", "--archive",
    "--report", "-t", "--touch", "--containerize", "--export-cwl", "--print-compilation",
    "--generate-unit-tests", "--conda-create-envs-only", "-h", "--help", "--version", "-v",
}


def runs_jobs(argv) -> bool:
    """Whether a Snakemake command line may execute jobs (none of :data:`NO_JOBS`, also
    among combined short options such as ``-np``)."""
    for arg in argv[1:]:
        name = arg.split("=", 1)[0]
        if name in NO_JOBS:
            return False
        if arg.startswith("-") and not arg.startswith("--") and arg[1:].isalpha():
            if any(f"-{c}" in NO_JOBS for c in arg[1:]):
                return False
    return True


def start():
    """Start the server; returns its process, or None where the environment turns it off.
    Jobs started after this call find it once it is ready (before that, they run in their
    own processes)."""
    import subprocess
    import tempfile
    # Linux only: forking a process that has loaded numpy's BLAS and matplotlib is not
    # safe on macOS (Python's multiprocessing spawns there), and Windows has no fork.
    if os.environ.get(SOCKET_VAR) == "off" or not sys.platform.startswith("linux"):
        return None
    _remove_stale(tempfile.gettempdir())
    folder = tempfile.mkdtemp(prefix=PREFIX)
    path = os.path.join(folder, SOCKET)
    with open(os.path.join(folder, LOG), "w") as log:
        proc = subprocess.Popen([sys.executable, os.path.abspath(__file__), path,
                                 str(os.getpid()), folder], stdin=subprocess.DEVNULL,
                                stdout=log, stderr=subprocess.STDOUT)
    with open(os.path.join(folder, PID), "w") as fh:
        fh.write(str(proc.pid))
    os.environ[SOCKET_VAR] = path
    proc.folder = folder
    return proc


def stop(proc) -> None:
    """Stop the server (the jobs it started have ended: Snakemake waited for them); what
    it wrote (a module it could not preload) goes to stderr."""
    if proc is None:
        return
    os.environ.pop(SOCKET_VAR, None)
    proc.terminate()
    try:
        proc.wait(timeout=5)
    except Exception:
        proc.kill()
    log = os.path.join(proc.folder, LOG)
    if os.path.exists(log) and os.path.getsize(log):
        with open(log) as f:
            sys.stderr.write(f.read())
    _remove(proc.folder)


if __name__ == "__main__":
    serve(sys.argv[1], int(sys.argv[2]), *sys.argv[3:4])
