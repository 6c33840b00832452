"""Every citation resolves inside the repository: no file of the project points
at a document a clone does not carry (a numbered section of an outside
contract, a path beside the repository, a numbered issue of a tracker), and
every relative link of a Markdown page names a file that exists.

The source documents are cited by the names docs/SOURCES.md gives them ("the
report", "seed 002"), and what they say is in the project's own pages. CI's
script (.ci/) is the one file allowed to know what lies beside the clone.
"""
from __future__ import annotations

import re
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[3]

# Written in pieces so that this file does not match itself.
OUTSIDE = re.compile(
    r"\bSPEC(?: sections?)? ?[0-9]"       # a section of the outside contract
    r"|\.\./shared|\bshared/seed[s]"    # the folder beside the clone
    r"|\b[Ii]ssues? (?:#)?[0-9]"        # a tracker's issue (a journal's is "No. N")
)
LINK = re.compile(r"\]\(([^)\s]+)\)")


SKIP = {".git", ".venv", "build", "out", "__pycache__", ".pytest_cache", ".hypothesis"}


def _tracked() -> list[Path]:
    """The files of the repository as a clone has them (git's list; outside a
    git checkout, the tree without what builds and runs leave behind)."""
    proc = subprocess.run(["git", "ls-files", "-z"], cwd=ROOT, capture_output=True)
    if proc.returncode == 0:
        return [ROOT / name for name in proc.stdout.decode().split("\0") if name]
    return sorted(p for p in ROOT.rglob("*") if p.is_file()
                  and not SKIP.intersection(p.relative_to(ROOT).parts))


def _text(path: Path) -> str | None:
    try:
        return path.read_text(encoding="utf-8")
    except (UnicodeDecodeError, FileNotFoundError, IsADirectoryError):
        return None  # pictures, tape images


def test_no_file_cites_what_a_clone_does_not_carry():
    found = []
    for path in _tracked():
        rel = path.relative_to(ROOT)
        if rel.parts[0] == ".ci":
            continue
        text = _text(path)
        if text is None:
            continue
        for n, line in enumerate(text.splitlines(), 1):
            m = OUTSIDE.search(line)
            if m:
                found.append(f"{rel}:{n}: {m.group(0)!r} in {line.strip()[:80]!r}")
    assert not found, "citations outside the repository:\n" + "\n".join(found)


def _slug(heading: str) -> str:
    """A heading's anchor as GitHub makes it."""
    return re.sub(r"[^\w\- ]", "", heading.strip().lower()).replace(" ", "-")


@pytest.mark.parametrize("page", sorted(
    str(p.relative_to(ROOT)) for p in _tracked() if p.suffix == ".md"))
def test_relative_links_of_a_page_resolve(page):
    """A relative link names a file of the repository, and its #anchor, if
    any, a heading of that page (CARDS.md#numbers; #numbers on the page)."""
    path = ROOT / page
    broken = []
    for target in LINK.findall(path.read_text(encoding="utf-8")):
        if re.match(r"[a-z]+:", target):
            continue  # a web address, a mail address
        name, sep, anchor = target.partition("#")
        dest = path.parent / name if name else path
        if not dest.exists():
            broken.append(target)
        elif sep and dest.suffix == ".md":
            heads = {_slug(line.lstrip("#")) for line in
                     dest.read_text(encoding="utf-8").splitlines() if line.startswith("#")}
            if anchor not in heads:
                broken.append(target)
    assert not broken, f"{page}: links to nothing: {broken}"


def test_the_checker_catches_each_kind_of_outside_citation():
    """The pattern is not vacuous: each kind it forbids is caught, and the
    project's own way of citing passes."""
    spec, shared = "SP" + "EC", "sha" + "red"   # in pieces: this file must pass itself
    for bad in (f"see {spec} section 7", f"{spec} 6: travel", f"{spec} sections 2-4", f"../{shared}/{spec}.md",
                f"{shared}/seeds/001_x.txt", "(iss" "ue 5)", "iss" "ues 2 and 3"):
        assert OUTSIDE.search(bad), bad
    for good in ("the report, Table I", "seed 002, Table 5", "Acta Optica, No. 3",
                 "docs/RECONSTRUCTION.md", "specification"):
        assert not OUTSIDE.search(good), good


PATH_IN_CODE = re.compile(r"`([A-Za-z0-9_.-]+(?:/[A-Za-z0-9_.-]+)+/?)`")
MADE_BY_RUNS = ("out/", "build/", ".venv/", "damaged/")


@pytest.mark.parametrize("page", sorted(
    str(p.relative_to(ROOT)) for p in _tracked() if p.suffix == ".md"))
def test_paths_a_page_names_exist(page):
    """A path written as code (`harness/verify.py`, `examples/report/`) names a
    file or folder of the repository (or one a run makes: out/, build/)."""
    path = ROOT / page
    missing = []
    for name in PATH_IN_CODE.findall(path.read_text(encoding="utf-8")):
        if name.startswith(MADE_BY_RUNS) or name.isupper():
            continue  # made by a run; a listing's upper-case DOCS/CARDS.MD
        if not (ROOT / name).exists() and not (path.parent / name).exists():
            missing.append(name)
    assert not missing, f"{page} names paths that do not exist: {missing}"


# A section cited by its title after its page: docs/PERFORMANCE.md, "The
# tour"; (RECONSTRUCTION.md, "Odd sizes"); [CARDS.md](CARDS.md) ("Packages"
# and "Columns not read"), in prose or in a comment of any language.
SECTION = re.compile(r'((?:docs/|legacy/)?[A-Za-z0-9_-]+\.md)\)?(?:,| \(|:)\s*["“]([^"”]{2,100})["”]'
                     r'((?:\s*(?:,|and|, and)\s*["“][^"”]{2,100}["”])*)')
COMMENT = re.compile(r"^\s*(?:[!#*>]+|C(?=\s)|//)\s?")


def _flat(text: str) -> str:
    """The text as one line, each line's comment marker taken off, so that a
    title broken over two comment lines reads whole."""
    return " ".join(" ".join(COMMENT.sub("", line) for line in text.splitlines()).split())


def _plain(text: str) -> str:
    return " ".join(re.sub(r"[*`]", "", text).split()).lower()


def cited_sections(path: Path, text: str, pages: dict[str, str]) -> list[tuple[str, str]]:
    """(page, title) for each section ``text`` (the file ``path``) cites by
    title, of a page in ``pages`` (repository path to its text)."""
    out = []
    for m in SECTION.finditer(_flat(text)):
        page = next((c for c in (m.group(1), str((path.parent / m.group(1)).relative_to(ROOT)),
                                 "docs/" + Path(m.group(1)).name) if c in pages), None)
        if page is not None:
            titles = [m.group(2)] + re.findall(r'["“]([^"”]+)["”]', m.group(3))
            out += [(page, title) for title in titles]
    return out


def test_every_section_cited_by_title_is_in_its_page():
    """A title after a page's name (docs/ROBUSTNESS.md, "em703") stands in
    that page as written: a heading, a paragraph's bold title or a rule's
    first words renamed without its citations would leave them pointing
    nowhere."""
    pages = {str(p.relative_to(ROOT)): p.read_text(encoding="utf-8")
             for p in _tracked() if p.suffix == ".md"}
    plain = {page: _plain(_flat(text)) for page, text in pages.items()}
    cited, missing = 0, []
    for path in _tracked():
        text = _text(path)
        if text is None or path.relative_to(ROOT).parts[0] == ".ci" or path == Path(__file__):
            continue                   # this file's citations are the pattern's examples
        for page, title in cited_sections(path, text, pages):
            cited += 1
            if _plain(title) not in plain[page]:
                missing.append(f"{path.relative_to(ROOT)}: {page}, {title!r}")
    assert cited >= 25, cited          # the pattern still finds the project's citations
    assert not missing, "sections cited that their pages do not have:\n" + "\n".join(missing)


def test_the_section_pattern_reads_each_way_of_citing():
    pages = {"docs/PERFORMANCE.md": "", "docs/CARDS.md": "", "docs/RECONSTRUCTION.md": ""}
    here = ROOT / "harness" / "x.py"
    for text, want in [
        ('see docs/PERFORMANCE.md, "The tour" below', [("docs/PERFORMANCE.md", "The tour")]),
        ('(RECONSTRUCTION.md, "Odd sizes")', [("docs/RECONSTRUCTION.md", "Odd sizes")]),
        ('"""No silent misreads (docs/CARDS.md, "Packages" and "Columns not read").',
         [("docs/CARDS.md", "Packages"), ("docs/CARDS.md", "Columns not read")]),
        ('! the kicks (docs/PERFORMANCE.md, "Where TENZOR\n! spends its time")',
         [("docs/PERFORMANCE.md", "Where TENZOR spends its time")]),
        ('C     SEE DOCS/PERFORMANCE.MD', []),
    ]:
        assert cited_sections(here, text, pages) == want, text
