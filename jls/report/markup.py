"""Typst markup from Python values: escaped text, numbers, tables and figures.

Every piece of text that comes from data (names, paths, descriptions) passes through
:func:`t`, which escapes Typst's markup characters, so a file name with ``_`` or ``#``
prints as written and can never inject markup.
"""

from __future__ import annotations

import math

_SPECIAL = set("\\#*_$@<>[]`~=-+/'\"")


def t(value, wrap=False) -> str:
    """Plain text as Typst markup (markup characters escaped, newlines as spaces).

    ``wrap`` adds break opportunities (zero-width spaces) after ``_``, ``=`` and ``/`` so
    that long identifiers and paths can wrap inside a table column.
    """
    out = []
    for ch in str(value):
        if ch in "\r\n\t":
            out.append(" ")
        elif ch in _SPECIAL:
            out.append("\\" + ch)
        elif ord(ch) < 32:
            continue
        else:
            out.append(ch)
        if wrap and ch in "_=/":
            out.append("\u200b")
    return "".join(out)


def mono(value) -> str:
    """Monospaced text (checksums, paths) as a Typst raw element."""
    s = str(value).replace("\\", "\\\\").replace('"', '\\"')
    s = "".join(ch for ch in s if ord(ch) >= 32)
    return f'#raw("{s}")'


def path(value) -> str:
    """A file path as text that never hyphenates and may break after each '/'."""
    return f"#text(hyphenate: false)[{t(value, wrap=True)}]"


def num(x, nd=2, unit="") -> str:
    """A number with ``nd`` decimals, an en dash when missing."""
    try:
        x = float(x)
    except (TypeError, ValueError):
        return "–"
    if not math.isfinite(x):
        return "–"
    s = f"{x:,.{nd}f}".replace(",", "\u2009")
    return f"{s}\u00a0{unit}" if unit else s


def sci(x, nd=3) -> str:
    try:
        x = float(x)
    except (TypeError, ValueError):
        return "–"
    return "–" if not math.isfinite(x) else f"{x:.{nd}e}"


class Cell(str):
    """Markup of one finished table cell (plain strings in a table are escaped)."""


def cell(content: str, *, bold=False, raw=False, colspan=1, fill=None, align=None) -> Cell:
    """A table cell; ``content`` is text unless ``raw`` (already markup)."""
    body = content if raw else t(content, wrap=True)
    if bold:
        body = f"*{body}*" if body.strip() else body
    if colspan == 1 and fill is None and align is None:
        return Cell(f"[{body}]")
    args = [f"colspan: {colspan}"] if colspan != 1 else []
    if fill:
        args.append(f"fill: {fill}")
    if align:
        args.append(f"align: {align}")
    return Cell(f"table.cell({', '.join(args)})[{body}]")


def table(caption: str, header: list, rows: list[list], *, columns=None, align=None,
          size="8.5pt", caption_raw=False, n_columns=None) -> str:
    """A data table figure (template's ``datatable``). Rows hold cells made by
    :func:`cell` or plain strings (escaped here); ``n_columns`` when header cells span."""
    n = n_columns or len(header)
    cols = columns or f"({', '.join(['auto'] * n)})"
    if align is None:
        align = "(" + ", ".join(["left"] + ["right"] * (n - 1)) + ")"
    head = ", ".join(h if isinstance(h, Cell) else cell(h) for h in header)
    body = ",\n  ".join(", ".join(c if isinstance(c, Cell) else cell(c) for c in r) for r in rows)
    cap = caption if caption_raw else t(caption)
    return (f"#datatable(caption: [{cap}], size: {size}, columns: {cols}, align: {align},\n"
            f"  header: ({head},),\n  {body}{',' if body else ''}\n)\n")


def figure(filename: str, caption: str, width="100%", caption_raw=False) -> str:
    cap = caption if caption_raw else t(caption)
    return f'#figure(image("{filename}", width: {width}), caption: [{cap}])\n'


def bullets(items: list[str]) -> str:
    """A bullet list; items are markup."""
    return "\n".join(f"- {it}" for it in items) + "\n"
