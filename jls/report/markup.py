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
    return _formatted(x, f",.{nd}f", unit)


def signed(x, nd=2, unit="") -> str:
    """A change with its sign ('+1.25', '-0.40'); one that rounds to zero unsigned
    ('0.00'), an en dash when missing."""
    return _formatted(x, f"+,.{nd}f", unit)


def _formatted(x, spec: str, unit: str) -> str:
    """``x`` in format ``spec`` with thin-space thousands, a value that rounds to zero
    without a sign, the unit after a non-breaking space; an en dash when missing."""
    try:
        x = float(x)
    except (TypeError, ValueError):
        return "–"
    if not math.isfinite(x):
        return "–"
    s = _unsigned_zero(format(x, spec)).replace(",", "\u2009")
    return f"{s}\u00a0{unit}" if unit else s


def _unsigned_zero(s: str) -> str:
    """'-0.00' -> '0.00': a value that rounds to zero has no sign."""
    return s[1:] if s[:1] in "+-" and not any(ch in "123456789" for ch in s) else s


def plural(n: int, word: str, words: str | None = None) -> str:
    """'1 leg', '2 legs' (``words``: an irregular plural)."""
    return f"{n} {word if n == 1 else (words or word + 's')}"


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
          size="8.5pt", caption_raw=False, n_columns=None, label=None) -> str:
    """A data table figure (template's ``datatable``). Rows hold cells made by
    :func:`cell` or plain strings (escaped here); ``n_columns`` when header cells span;
    ``label``: a Typst label (``tab-...``) other text refers to with :func:`ref`."""
    n = n_columns or len(header)
    cols = columns or f"({', '.join(['auto'] * n)})"
    if align is None:
        align = "(" + ", ".join(["left"] + ["right"] * (n - 1)) + ")"
    head = ", ".join(h if isinstance(h, Cell) else cell(h) for h in header)
    body = ",\n  ".join(", ".join(c if isinstance(c, Cell) else cell(c) for c in r) for r in rows)
    cap = caption if caption_raw else t(caption)
    return (f"#datatable(caption: [{cap}], size: {size}, columns: {cols}, align: {align},\n"
            f"  header: ({head},),\n  {body}{',' if body else ''}\n)" + (f" <{label}>" if label else "") + "\n")


def figure(filename: str, caption: str, width="100%", caption_raw=False, label=None) -> str:
    cap = caption if caption_raw else t(caption)
    return (f'#figure(image("{filename}", width: {width}), caption: [{cap}])'
            + (f" <{label}>" if label else "") + "\n")


def ref(label: str, word: str | None) -> str:
    """A reference to a labelled heading, table or figure, numbered by Typst when the
    document compiles ('section 13', 'table 1'; ``word`` None: the number alone): numbers
    are never written by hand, and a reference to a label that does not exist stops the
    compilation. Written as markup (``@label[word]``), not as code, so that a ';' after
    it stays in the text."""
    return f"@{label}[{t(word) if word else ''}]"


def bullets(items: list[str]) -> str:
    """A bullet list; items are markup."""
    return "\n".join(f"- {it}" for it in items) + "\n"
