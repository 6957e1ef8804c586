"""Questions as people type them, held out (benchmarks/heldout_questions*.txt,
each written by a writer who had not seen the vocabulary, annotated
afterwards; a set's `# blind:` line records its one measurement before
any change made for it, and the reader may have been changed for its
failures since), per file and pooled: of the questions the
vocabulary can express, the share read as meant (the scene, and the
expectations asked or wanted where the reader hears them); the misreads (a
question answered as another scene, or one the vocabulary cannot express
answered at all); the silent drops (a word of a question answered neither
read, said back, shown as ignored nor a word of its frame); and the
refusals, each one line. Last, the first measurements of the sets that
record one (`# blind:`), pooled: the reader as each set first met it.

Against an older reader (one without `read_question`), the scene alone is
compared and silent drops are not counted: it does not say what it read.
"""
from __future__ import annotations

import re
from pathlib import Path

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning import reading
from pantarhei.bridge.reasoning.dropped import dropped_words


def question_files() -> list[Path]:
    """The held-out question files, each written and annotated apart."""
    return sorted(Path(__file__).parent.glob("heldout_questions*.txt"),
                  key=lambda p: int(m.group(1)) if (m := re.search(r"_(\d+)\.txt$", p.name)) else 1)


def annotated(path: Path) -> list[tuple[str, dict[str, str] | None]]:
    """(question, what it should be read as: "scene", "asked", "goals"; None: cannot be said)."""
    out = []
    for line in path.read_text(encoding="utf-8").splitlines():
        if not line.strip() or line.startswith("#"):
            continue
        question, meant = line.split("\t")
        out.append((question, None if meant == "cannot" else
                    dict(part.strip().split("=", 1) for part in meant.split(";"))))
    return out


def is_annotated(path: Path) -> bool:
    """Whether the questions of a held-out file carry what they should be
    read as: a set is committed as written, before it is annotated, and
    is measured only once annotated."""
    lines = [line for line in path.read_text(encoding="utf-8").splitlines()
             if line.strip() and not line.startswith("#")]
    return bool(lines) and all("\t" in line for line in lines)


def _names(text: str) -> list[str]:
    return sorted(n for n in text.split(",") if n)


def measure(path: Path) -> dict:
    full = hasattr(reading, "read_question")
    counts = {"questions": 0, "expressible": 0, "read as meant": 0, "refused though expressible": 0,
              "misread": 0, "silent drops": 0 if full else None, "refused in one line": 0,
              "refused": 0, "asked heard wrong": 0 if full else None}
    wrong: list[str] = []
    for question, meant in annotated(path):
        counts["questions"] += 1
        counts["expressible"] += meant is not None
        try:
            heard = reading.read_question(question) if full else None
            scene = list(heard.scene) if full else reading.understand(question)
        except UserError as e:
            counts["refused"] += 1
            counts["refused in one line"] += "\n" not in str(e)
            if meant is not None:
                counts["refused though expressible"] += 1
                wrong.append(f"refused (expressible): {question}  -- {e}")
            continue
        lost = dropped_words(question, heard) if full else []
        if lost:
            counts["silent drops"] += 1
            wrong.append(f"dropped {lost}: {question}")
        if meant is None:
            counts["misread"] += 1
            wrong.append(f"answered (cannot be said) as {scene}: {question}")
            continue
        if sorted(scene) not in [_names(s) for s in meant["scene"].split("|")]:
            counts["misread"] += 1
            wrong.append(f"misread as {scene} (meant {meant['scene']}): {question}")
            continue
        ok = True
        if full:
            for key in ("asked", "goals"):
                said = sorted(getattr(heard, key))
                if meant.get(key, "") != "-" and said != _names(meant.get(key, "")):
                    ok = False
                    wrong.append(f"{key} {said} (meant {meant.get(key, '')}): {question}")
        counts["read as meant"] += ok
        counts["asked heard wrong"] = (counts["asked heard wrong"] or 0) + (not ok) if full else None
    return {**counts, "wrong": wrong}


def pooled(measures: list[dict]) -> dict:
    """The counts of several files' measures added up (a count not kept stays None)."""
    keys = [k for k in measures[0] if k != "wrong"]
    return {k: None if measures[0][k] is None else sum(m[k] for m in measures) for k in keys}


def blind(path: Path) -> str | None:
    """What the file's header says its first measurement found, before the
    reader was changed for it (`# blind: ...`, continued on the next
    header line), or None."""
    lines = path.read_text(encoding="utf-8").splitlines()
    for i, line in enumerate(lines):
        if line.startswith("# blind: "):
            more = lines[i + 1][2:] if i + 1 < len(lines) and lines[i + 1].startswith("# ") else ""
            return f"{line[len('# blind: '):]} {more}".strip()
    return None


def main() -> None:
    measures, firsts = [], []
    for path in question_files():
        if not is_annotated(path):
            print(f"held-out questions {path.name}: written, not annotated yet (left out)")
            continue
        measures.append(measure(path))
        firsts.append(blind(path))
        report(f"held-out questions typed by a writer who had not seen the vocabulary "
               f"({path.name})", measures[-1], firsts[-1])
    if len(measures) > 1:
        report("all held-out questions, pooled", {**pooled(measures), "wrong": []})
    firsts = [f for f in firsts if f]
    if firsts:
        counts = [tuple(map(int, re.match(r"(\d+) of (\d+) read as meant, (\d+) misread, (\d+) silent", f).groups()))
                  for f in firsts]
        read, of, misread, dropped = (sum(c[k] for c in counts) for k in range(4))
        print(f"first measurements, blind, of the {len(firsts)} sets that record one: {read} of {of} read as meant "
              f"({100 * read / of:.0f}%), {misread} misread, {dropped} silent drops")


def report(title: str, m: dict, first: str | None = None) -> None:
    """Print one measure's figures under `title`, what the first
    measurement found (`first`, where the file says), then what it got
    wrong."""
    share = m["read as meant"] / m["expressible"] if m["expressible"] else 0.0
    print(f"{title}: {m['questions']}, {m['expressible']} expressible")
    print(f"  read as meant:               {m['read as meant']} of {m['expressible']} "
          f"({100 * share:.0f}%; target at least 90%)")
    print(f"  refused though expressible:  {m['refused though expressible']}")
    print(f"  asked or wanted heard wrong: {m['asked heard wrong']}")
    print(f"  misread (target 0):          {m['misread']}")
    print(f"  silent drops (target 0):     {m['silent drops']}")
    print(f"  refusals in one line:        {m['refused in one line']} of {m['refused']}")
    if first:
        print(f"  first measured blind:        {first}")
    for line in m["wrong"]:
        print(f"    {line}")


if __name__ == "__main__":
    main()
