"""The commands README.md and docs/*.md show: one reading of the pages for the docs tests and benchmarks.

Three forms are read, in page order:
- transcripts: a `$ foon2pddl ...` line in a fenced block, the lines under it its documented output
  (`; $ foon2pddl ...` opens a block of file excerpts: the command is read, its lines are not output);
- command lines: a line of a fenced block starting `foon2pddl ` (a `\\` continuation joined, a trailing
  `# comment` kept: the shell drops it);
- inline commands: a `` `foon2pddl ...` `` span of prose with options or arguments (`` `foon2pddl plan` ``
  names the command).
A synopsis (`[--option ...]`, an upper-case placeholder such as `G`, `FILE|-`, `PATHS`) is no command.
Every reader of a page's fenced blocks, here and in tests/, reads them through `blocks` (and `joined`, `prose`).
"""

from __future__ import annotations

import re
import shlex
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PAGES = (ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md")))

#: A placeholder word of a synopsis: `G`, `FILE|-`, `PATHS`, `HEAD` in `tcp://HEAD:8786`.
_PLACEHOLDER = re.compile(r"(?:^|[/:=])[A-Z][A-Z|\-]*(?:$|[:/=])|^\[|^\.\.\.$")
_INLINE = re.compile(r"`(foon2pddl [^`]+)`")
#: Options whose value is a file the command writes (so it need not exist beforehand).
_OUTPUTS = {"-o", "--output", "--plot", "--graphml", "--plan-file", "--report"}


@dataclass(frozen=True)
class Block:
    """A fenced block of a page: its info string (`python`; "" for none), the line number of its first line (the
    one under the opening fence), its lines."""

    lang: str
    start: int
    lines: tuple[str, ...]


def blocks(text: str) -> list[Block]:
    """The page's fenced blocks, in order: a line starting with ``` opens one and the next such line closes it (an
    unclosed one runs to the page's end). O(lines)."""
    out: list[Block] = []
    open_at: tuple[str, int] | None = None
    lines = text.splitlines()
    for number, line in enumerate(lines, start=1):
        if not line.startswith("```"):
            continue
        if open_at is None:
            open_at = (line[3:].strip(), number + 1)
        else:
            out.append(Block(open_at[0], open_at[1], tuple(lines[open_at[1] - 1:number - 1])))
            open_at = None
    if open_at is not None:
        out.append(Block(open_at[0], open_at[1], tuple(lines[open_at[1] - 1:])))
    return out


def joined(block: Block) -> Iterator[tuple[int, int, str]]:
    """(first line number, last line number, text) of each line of `block`, a `\\` continuation joined to the next
    line (stripped, one space between); a continuation the block ends in is dropped."""
    pending, first = "", 0
    for number, line in enumerate(block.lines, start=block.start):
        first = first if pending else number
        line = (pending + " " + line.strip()) if pending else line
        if line.endswith("\\"):
            pending = line[:-1].rstrip()
            continue
        pending = ""
        yield first, number, line


def prose(text: str) -> str:
    """The page with its fenced blocks, fences included, blanked (each character a space, line breaks kept): what
    is outside them, at its own offsets."""
    lines = text.splitlines(keepends=True)
    for b in blocks(text):
        for k in range(b.start - 2, min(b.start - 1 + len(b.lines) + 1, len(lines))):
            lines[k] = "".join(c if c == "\n" else " " for c in lines[k])
    return "".join(lines)


@dataclass(frozen=True)
class DocCommand:
    """One documented command: where it is shown and its shell text."""

    page: str  # README.md, docs/x.md
    line: int
    text: str  # the shell command line, `foon2pddl` first
    form: str  # transcript | block | inline

    @property
    def where(self) -> str:
        return f"{self.page}:{self.line}"


def transcripts(text: str) -> list[tuple[str, list[str]]]:
    """(command, documented output lines) for every `$ foon2pddl` line in fenced blocks whose command
    reads only the checkout (the embedded example and the shipped test corpus, not `../`)."""
    out: list[tuple[str, list[str]]] = []
    for block in blocks(text):
        transcript = False
        for line in block.lines:
            if line.startswith("$ foon2pddl "):
                command = line[len("$ foon2pddl "):]
                transcript = "../" not in command
                if transcript:
                    out.append((command, []))
            elif transcript and line:
                out[-1][1].append(line)
    return out


def _shown(text: str) -> Iterator[tuple[int, str, str]]:
    """(line number, command text, form) of every command a page shows, synopses included, in line order (a
    command over `\\` continuations at its last line)."""
    shown: list[tuple[int, str, str]] = []
    for number, line in enumerate(prose(text).splitlines(), start=1):
        for m in _INLINE.finditer(line):
            if " " in m.group(1).strip()[len("foon2pddl "):]:  # `foon2pddl plan` names the command
                shown.append((number, m.group(1), "inline"))
    for block in blocks(text):
        for number, line in enumerate(block.lines, start=block.start):
            for prompt in ("$ ", "; $ "):
                if line.startswith(prompt + "foon2pddl "):
                    shown.append((number, line[len(prompt):], "transcript"))
        shown += [(last, line, "block") for _, last, line in joined(block) if line.startswith("foon2pddl ")]
    yield from sorted(shown, key=lambda s: s[0])


def is_synopsis(command: str) -> bool:
    """Whether `command` is a synopsis (placeholders, optional parts) rather than a command to run."""
    try:
        words = shlex.split(command, comments=True)
    except ValueError:
        return True
    return any(_PLACEHOLDER.search(w) for w in words if not w.startswith("-") or w.startswith("[-"))


def missing_inputs(command: str, root: Path = ROOT) -> list[str]:
    """The files `command` reads that `root` does not hold (the reader's own files: `my_recipes/`)."""
    words = shlex.split(command, comments=True)
    out = []
    for before, word in zip(["", *words], words, strict=False):
        if before in _OUTPUTS or word.startswith("-"):
            continue
        path = word.split()[0] if " " in word else word  # a --planner-cmd: its program
        if ("/" in path or re.search(r"\.(json|pddl|txt|foon)$", path)) and not (root / path).exists():
            out.append(path)
    return out


def documented_commands(pages: tuple[Path, ...] = PAGES) -> list[DocCommand]:
    """Every runnable command the pages show, once each (where first shown), in page order."""
    seen: dict[str, DocCommand] = {}
    for page in pages:
        for number, text, form in _shown(page.read_text()):
            text = text.strip()
            if text not in seen and not is_synopsis(text):
                seen[text] = DocCommand(str(page.relative_to(ROOT)), number, text, form)
    return list(seen.values())


#: A code span of prose (it may run over a line break, not a paragraph's end).
_SPAN = re.compile(r"`((?:[^`\n]|\n(?![ \t]*\n))+)`")
#: The commands whose `--goal` a page may show; any other first word is no command (`--goal X` alone).
_GOAL_COMMANDS = ("retrieve", "compile", "plan")


@dataclass(frozen=True)
class GoalExample:
    """One `--goal` value a page shows, with the command (and its arguments) it is shown in."""

    page: str
    line: int
    command: str  # retrieve | compile | plan; `retrieve` for a bare `--goal X` (the embedded example network)
    args: tuple[str, ...]  # the command's arguments as shown (`--goal X` among them)
    goal: str

    @property
    def where(self) -> str:
        return f"{self.page}:{self.line}"


def _goal_texts(text: str) -> Iterator[tuple[int, str]]:
    """(line number, text) of every code span of prose and every fenced-block line (`\\` continuations
    joined) that shows `--goal`, and of every goal in a table row's first code span under `## Goals`."""
    for block in blocks(text):
        for start, _, line in joined(block):
            line = line.removeprefix("; ").removeprefix("$ ")
            if "--goal " in line:
                yield start, line
    outside = prose(text)  # a fence's backticks open no span
    goals_table = re.search(r"^## Goals\n(.*?)^#", outside, re.M | re.S)
    for m in _SPAN.finditer(outside):
        number = text.count("\n", 0, m.start()) + 1
        span = " ".join(m.group(1).split())
        if re.search(r"--goal ", span):
            yield number, span
        elif goals_table and goals_table.start(1) <= m.start() < goals_table.end(1) and \
                text[text.rfind("\n", 0, m.start()) + 1:m.start()] == "| ":
            yield number, "--goal " + shlex.quote(span)  # a row of the goal syntax table


def goal_examples(pages: tuple[Path, ...] = PAGES) -> list[GoalExample]:
    """Every `--goal` value the pages show (fenced blocks, prose code spans, format.md's goal table), with the
    command it is shown in; a placeholder value (`--goal G`, `--goal TEXT`) is no example."""
    out: list[GoalExample] = []
    for page in pages:
        for number, shown in _goal_texts(page.read_text()):
            if is_synopsis(shown):
                continue
            words = shlex.split(shown, comments=True)
            words = words[1:] if words[:1] == ["foon2pddl"] else words
            command = words[0] if words[:1] and words[0] in _GOAL_COMMANDS else "retrieve"
            args = tuple(words[1:] if words[:1] == [command] else words[words.index("--goal"):])
            for before, word in zip(args, args[1:], strict=False):
                if before == "--goal" and not _PLACEHOLDER.search(word):
                    out.append(GoalExample(str(page.relative_to(ROOT)), number, command, args, word))
    return out
