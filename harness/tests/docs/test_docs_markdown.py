"""Every Markdown page renders as it is written: a code fence is a line of
its own (a closing fence with text after it does not close, and every fence
after it in the page is off by one, code shown as prose and prose as code),
and every table starts with its header and the line of dashes under it (a
blank line inside a table cuts off the rows after it, which then show as
raw `| ... |` text)."""
from __future__ import annotations

import re

import pytest

from harness.tests.docs.test_docs_citations import ROOT, _tracked

OPENING = re.compile(r"^ *```[\w+-]*$")    # a fence, with its language if any
CLOSING = re.compile(r"^ *```$")
RULE = re.compile(r"^\|(?: *:?-+:? *\|)+$")  # the dashes under a table's header


def problems(text: str) -> list[str]:
    """What would not render as written, a line each: its number and why."""
    found, fenced, table = [], 0, []
    lines = text.splitlines()

    def end_table() -> None:
        if table and (len(table) < 2 or not RULE.match(lines[table[1] - 1])
                      or RULE.match(lines[table[0] - 1])):
            found.append(f"{table[0]}: a table without its header and the line of "
                         "dashes under it (a blank line cut it off?)")
        table.clear()

    for n, line in enumerate(lines, start=1):
        if fenced:
            if CLOSING.match(line):
                fenced = 0
            elif line.lstrip().startswith("```"):
                found.append(f"{n}: text after a closing fence (the fence does not close)")
            continue
        if line.lstrip().startswith("```"):
            end_table()
            if not OPENING.match(line):
                found.append(f"{n}: text after an opening fence's language")
            fenced = n
        elif line.startswith("|"):
            table.append(n)
        else:
            end_table()
    end_table()
    if fenced:
        found.append(f"{fenced}: a fence that never closes")
    return found


@pytest.mark.parametrize("page", sorted(
    str(p.relative_to(ROOT)) for p in _tracked() if p.suffix == ".md"))
def test_a_page_renders_as_written(page):
    found = problems((ROOT / page).read_text(encoding="utf-8"))
    assert not found, f"{page}:\n" + "\n".join(found)


def test_the_check_finds_each_fault():
    """Each fault is found where it is, and a good page passes."""
    good = "# T\n\n```sh\nmake\n```\n\n| a | b |\n|---|--:|\n| 1 | 2 |\n\ntext\n"
    assert problems(good) == []
    assert problems("```\ncode\n``` more\ntext\n```\n") == [
        "3: text after a closing fence (the fence does not close)"]
    assert problems("```sh make\n```\n") == ["1: text after an opening fence's language"]
    assert problems("```\ncode\n") == ["1: a fence that never closes"]
    assert problems("| a | b |\n|---|---|\n| 1 | 2 |\n\n| 3 | 4 |\n") == [
        "5: a table without its header and the line of dashes under it (a blank line "
        "cut it off?)"]
    assert problems("| a | b |\n") != []
    assert problems("|---|---|\n|---|---|\n") != []
