"""The one table writer: every table fgdwa prints or writes (experiment reports,
benchmark summaries, replays, IR-SIM runs) is a Table, as aligned text or Markdown."""

from __future__ import annotations

from typing import Sequence


class Table:
    """Rows under headers, with an optional title: ``text()`` aligned for a terminal (the
    first column to the left, the rest to the right), ``markdown()`` for a page."""

    def __init__(self, headers: Sequence[str], rows: Sequence[Sequence], title: str = ""):
        self.title = title
        self.headers = [str(h) for h in headers]
        self.rows = [[str(c) for c in row] for row in rows]

    def text(self) -> str:
        widths = [max(len(h), *(len(r[i]) for r in self.rows)) if self.rows else len(h)
                  for i, h in enumerate(self.headers)]
        line = lambda cells: "  ".join(c.ljust(w) if i == 0 else c.rjust(w)  # noqa: E731
                                       for i, (c, w) in enumerate(zip(cells, widths)))
        out = [self.title] if self.title else []
        out += [line(self.headers), line(["-" * w for w in widths])]
        out += [line(r) for r in self.rows]
        return "\n".join(out)

    def markdown(self) -> str:
        esc = lambda c: c.replace("|", "\\|")  # noqa: E731
        out = [f"**{self.title}**", ""] if self.title else []
        out.append("| " + " | ".join(esc(h) for h in self.headers) + " |")
        numeric = [i > 0 and all(_numeric(r[i]) for r in self.rows) for i in range(len(self.headers))]
        out.append("|" + "|".join("---:" if n else "---" for n in numeric) + "|")
        out += ["| " + " | ".join(esc(c) for c in r) + " |" for r in self.rows]
        return "\n".join(out)


def _numeric(cell: str) -> bool:
    try:
        float(cell.split(" ")[0])
        return True
    except ValueError:
        return cell in ("-", "")
