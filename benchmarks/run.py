"""Every speed figure of jls as one table: figure, target, measured, ratio.

    python benchmarks/run.py                  # every benchmark
    python benchmarks/run.py solver plant     # some of them (names below)

A benchmark is a script ``benchmarks/bench_<name>.py`` with a function ``rows()`` that
returns rows (figure, target, measured, ratio) -- :class:`rows.Row`, or plain 4-tuples
with ``ratio >= 1`` meaning the target is met (target / measured for a time or memory
limit, measured / target for a rate). Every such script is found and run: adding a
benchmark is adding the script. Each runs in its own process (one core's figures are
not disturbed by another benchmark's threads or imports).
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
ORDER = ("solver", "plant", "pipeline", "fanout")       # the rest follow by name
CHILD = ("import json, sys; sys.path.insert(0, {here!r}); import bench_{name} as b; "
         "print('@@ROWS@@' + json.dumps([list(r) for r in b.rows()]))")


def available() -> list[str]:
    names = [p.stem.removeprefix("bench_") for p in sorted(HERE.glob("bench_*.py"))
             if "def rows(" in p.read_text()]
    return [n for n in ORDER if n in names] + [n for n in names if n not in ORDER]


def run(name: str) -> list[tuple]:
    r = subprocess.run([sys.executable, "-c", CHILD.format(here=str(HERE), name=name)],
                       capture_output=True, text=True, cwd=HERE.parent)
    for line in r.stdout.splitlines():
        if line.startswith("@@ROWS@@"):
            return [tuple(row) for row in json.loads(line[len("@@ROWS@@"):])]
    return [(f"{name}: failed ({(r.stderr.strip().splitlines() or ['no output'])[-1]})",
             "", "", float("nan"))]


def table(rows) -> str:
    head = ("figure", "target", "measured", "ratio")
    text = [(str(f), str(t), str(m), "" if r != r else f"{r:.2f}") for f, t, m, r in rows]
    width = [max(len(x[i]) for x in text + [head]) for i in range(4)]
    line = lambda cells: "  ".join(c.ljust(w) if i == 0 else c.rjust(w)  # noqa: E731
                                   for i, (c, w) in enumerate(zip(cells, width)))
    out = [line(head), line(["-" * w for w in width])] + [line(x) for x in text]
    return "\n".join(out)


def main(argv=None) -> int:
    names = available()
    wanted = (argv if argv is not None else sys.argv[1:]) or names
    unknown = [n for n in wanted if n not in names]
    if unknown:
        print(f"unknown benchmark(s) {unknown}; available: {names}", file=sys.stderr)
        return 2
    rows = []
    for name in wanted:
        rows += run(name)
        print(table(rows).splitlines()[-1], file=sys.stderr, flush=True)
    print(table(rows))
    missed = [r for r in rows if not (r[3] >= 1.0)]
    print(f"\n{len(rows) - len(missed)} of {len(rows)} figures meet their target "
          "(ratio >= 1: target / measured for a limit, measured / target for a rate)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
