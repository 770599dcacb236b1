"""The job server (workflow/scripts/_server.py): a job's script handed over to a forked,
already imported child runs as ``python script`` would have, with the job's directory,
environment, streams, exit status and signals; without a server it runs in its own
process. That the workflow's datasets are the same bits either way is
tests/test_determinism.py's."""

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SCRIPTS = ROOT / "workflow" / "scripts"
sys.path.insert(0, str(SCRIPTS))
import _server  # noqa: E402

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"),
                                reason="the job server runs on Linux only")

JOB = f"""
import sys
sys.path.insert(0, {str(SCRIPTS)!r})
import _job  # noqa: F401
import os, time
print("pid", os.getpid(), "parent", os.getppid(), "cwd", os.getcwd(),
      "value", os.environ.get("JOB_VALUE"), "argv", sys.argv[1:], flush=True)
print("to stderr", file=sys.stderr)
action = sys.argv[1]
if action == "exit":
    sys.exit(int(sys.argv[2]))
if action == "message":
    raise SystemExit("jls step: input error: a named reason")
if action == "raise":
    raise ValueError("a failure")
if action == "sleep":
    open(sys.argv[2], "w").write(str(os.getpid()))
    time.sleep(60)
"""


@pytest.fixture(scope="module")
def server(tmp_path_factory):
    folder = tmp_path_factory.mktemp("server")
    path = str(folder / "socket")
    proc = subprocess.Popen([sys.executable, str(SCRIPTS / "_server.py"), path, str(os.getpid())],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    deadline = time.monotonic() + 60
    while not os.path.exists(path):
        assert proc.poll() is None, proc.stdout.read()
        assert time.monotonic() < deadline, "the server did not start in 60 s"
        time.sleep(0.05)
    yield path, proc
    proc.terminate()
    proc.wait(timeout=10)
    assert not os.path.exists(path), "the server left its socket"


def run_job(tmp_path, socket_path, *args, **kw):
    script = tmp_path / "job.py"
    script.write_text(JOB)
    env = {**os.environ, "JOB_VALUE": "42"}
    if socket_path is not None:
        env[_server.SOCKET_VAR] = socket_path
    return subprocess.run([sys.executable, str(script), *args], cwd=tmp_path, env=env,
                          capture_output=True, text=True, timeout=120, **kw)


def fields(stdout):
    words = stdout.split()
    return {k: words[words.index(k) + 1] for k in ("pid", "parent", "cwd", "value")}


def test_a_job_runs_in_a_child_of_the_server_with_its_directory_environment_and_streams(
        tmp_path, server):
    path, proc = server
    r = run_job(tmp_path, path, "exit", "0")
    assert r.returncode == 0, r.stderr
    f = fields(r.stdout)
    assert int(f["parent"]) == proc.pid                  # forked by the server
    assert f["cwd"] == str(tmp_path) and f["value"] == "42"
    assert "['exit', '0']" in r.stdout
    assert "to stderr" in r.stderr


@pytest.mark.parametrize("where", ["no-such-socket", "off"])
def test_without_a_server_the_job_runs_in_its_own_process(tmp_path, where):
    script = tmp_path / "job.py"
    script.write_text(JOB)
    value = str(tmp_path / where) if where != "off" else "off"
    proc = subprocess.Popen([sys.executable, str(script), "exit", "0"], cwd=tmp_path,
                            env={**os.environ, _server.SOCKET_VAR: value, "JOB_VALUE": "42"},
                            stdout=subprocess.PIPE, text=True)
    out, _ = proc.communicate(timeout=120)
    assert proc.returncode == 0
    assert int(fields(out)["pid"]) == proc.pid and fields(out)["value"] == "42"


@pytest.mark.parametrize("args, status, stderr", [
    (("exit", "3"), 3, "to stderr"),
    (("message",), 1, "jls step: input error: a named reason"),
    (("raise",), 1, "ValueError: a failure"),
])
def test_the_exit_status_and_error_are_those_python_gives(tmp_path, server, args, status,
                                                          stderr):
    path, _ = server
    served = run_job(tmp_path, path, *args)
    alone = run_job(tmp_path, None, *args)
    assert served.returncode == alone.returncode == status
    assert stderr in served.stderr and stderr in alone.stderr
    if args[0] == "raise":
        assert "Traceback" in served.stderr


def test_a_signal_to_the_job_ends_its_child(tmp_path, server):
    path, _ = server
    script = tmp_path / "job.py"
    script.write_text(JOB)
    marker = tmp_path / "child.pid"
    job = subprocess.Popen([sys.executable, str(script), "sleep", str(marker)], cwd=tmp_path,
                           env={**os.environ, _server.SOCKET_VAR: path},
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    deadline = time.monotonic() + 60
    while not (marker.exists() and marker.read_text()):
        assert time.monotonic() < deadline and job.poll() is None
        time.sleep(0.05)
    child = int(marker.read_text())
    assert child != job.pid
    job.send_signal(signal.SIGTERM)
    assert job.wait(timeout=30) != 0
    deadline = time.monotonic() + 30
    while _alive(child):
        assert time.monotonic() < deadline, "the child outlived its job"
        time.sleep(0.05)


def _alive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    return Path(f"/proc/{pid}/stat").exists() and " Z " not in Path(f"/proc/{pid}/stat").read_text()


def test_the_server_ends_and_removes_its_folder_when_snakemake_ends(tmp_path):
    # A stand-in for the Snakemake process: starts the server and ends at once.
    code = (f"import sys; sys.path.insert(0, {str(SCRIPTS)!r}); import _server; "
            "p = _server.start(); print(p.folder, p.pid)")
    env = {k: v for k, v in os.environ.items() if k != _server.SOCKET_VAR}
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True,
                         text=True, timeout=60, check=True).stdout.split()
    folder, pid = Path(out[0]), int(out[1])
    deadline = time.monotonic() + 60
    while folder.exists() or _alive(pid):
        assert time.monotonic() < deadline, "the server outlived its Snakemake process"
        time.sleep(0.1)


@pytest.mark.parametrize("argv, runs", [
    (["snakemake", "--cores", "2"], True),
    (["snakemake", "-c2", "reports/default.pdf"], True),
    (["snakemake", "--cores=2", "--configfile", "x.yaml"], True),
    (["snakemake", "-n"], False),
    (["snakemake", "--cores", "2", "-np"], False),
    (["snakemake", "--dry-run"], False),
    (["snakemake", "--lint"], False),
    (["snakemake", "--summary"], False),
    (["snakemake", "--unlock"], False),
])
def test_a_command_line_that_runs_no_job_starts_no_server(argv, runs):
    assert _server.runs_jobs(argv) is runs


def test_a_server_whose_snakemake_ended_removes_its_socket_and_nothing_else(tmp_path):
    keep = tmp_path / "keep.txt"
    keep.write_text("not the server's")
    path = tmp_path / "socket"
    # A stand-in for the Snakemake process: starts the server by hand, waits until it
    # takes jobs, and ends.
    code = (f"import subprocess, sys, os, time; p = subprocess.Popen([sys.executable, "
            f"{str(SCRIPTS / '_server.py')!r}, {str(path)!r}, str(os.getpid())])\n"
            f"while not os.path.exists({str(path)!r}): time.sleep(0.05)\n"
            "print(p.pid)")
    pid = int(subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                             timeout=60, check=True).stdout)
    deadline = time.monotonic() + 60
    while _alive(pid):
        assert time.monotonic() < deadline, "the server outlived its Snakemake process"
        time.sleep(0.1)
    assert keep.read_text() == "not the server's" and not path.exists()


def test_a_job_that_gave_up_waiting_is_not_run_by_the_server_too(tmp_path, server):
    # The job's side of the hand-over, stopped before its go-ahead: as a job that waited
    # longer than START_TIMEOUT_S and then ran in its own process.
    import json
    import socket
    path, _ = server
    marker = tmp_path / "ran.txt"
    script = tmp_path / "job.py"
    script.write_text(f"open({str(marker)!r}, 'w').write('ran')\n")
    sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    sock.connect(path)
    socket.send_fds(sock, [b"j"], [0, 1, 2])
    _server._send(sock, json.dumps({"argv": [str(script)], "cwd": str(tmp_path),
                                    "env": dict(os.environ)}).encode())
    child = int(_server._recv(sock))
    sock.close()
    deadline = time.monotonic() + 30
    while _alive(child):
        assert time.monotonic() < deadline, "the child outlived its job's connection"
        time.sleep(0.05)
    assert not marker.exists()
    # and a job handed over in full still runs
    r = run_job(tmp_path, path, "exit", "0")
    assert r.returncode == 0 and "value 42" in r.stdout


def test_the_folders_of_killed_servers_are_removed_at_the_next_start_and_no_other(tmp_path):
    dead = subprocess.Popen([sys.executable, "-c", "pass"])
    dead.wait()
    folders = {}
    for name, pid in (("killed", dead.pid), ("running", os.getpid()), ("starting", None)):
        folder = tmp_path / f"{_server.PREFIX}{name}"
        folder.mkdir()
        (folder / _server.LOG).write_text("")
        (folder / _server.SOCKET).write_text("")
        if pid is not None:
            (folder / _server.PID).write_text(str(pid))
        folders[name] = folder
    (folders["running"] / "other.txt").write_text("kept")
    _server._remove_stale(str(tmp_path))
    assert not folders["killed"].exists()
    assert (folders["running"] / _server.SOCKET).exists()
    assert (folders["starting"] / _server.SOCKET).exists()
