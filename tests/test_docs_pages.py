"""What README and the docs pages say about themselves and about the files a newcomer writes from them holds
(issue 24's newcomer passes): README lists every page, and json-schema.md's fields are the reader's and the
shipped JSON Schema's."""

from __future__ import annotations

import json
import re
import shlex

import pytest
from click.testing import CliRunner
from conftest import ROOT

from bench.doc_commands import blocks, prose
from foon2pddl.cli import main
from foon2pddl.io.jsonio import parse_json

SCHEMA_PAGE = ROOT / "docs" / "json-schema.md"


def _optional_in_schema() -> set[str]:
    schema = json.loads((ROOT / "docs" / "foon.schema.json").read_text())
    parts = [schema, *schema["$defs"].values()]
    return {key for part in parts for key in part.get("properties", {}) if key not in part.get("required", ())}


def test_json_schema_md_lists_every_field_that_may_be_left_out():
    """json-schema.md said "Only `motion_flag`, ... and `expanded_from` may be left out" where the reader and the
    schema also take a document without `level`, a unit without `sources` and a source without `line` (each with
    the default the page's tables give)."""
    sentence = re.search(r"Only (.*?) may be left out", SCHEMA_PAGE.read_text(), re.S).group(1)
    said = set(re.findall(r"`(\w+)`", sentence))
    assert said == _optional_in_schema()


def test_a_document_without_the_optional_fields_reads_with_their_defaults():
    """The oracle for the list: a unit with no `sources`, a source with no `line`, a document with no `level`."""
    node = {"label": "onion", "states": []}
    doc = {"format": "foon2pddl.foon", "version": 1, "units": [
        {"inputs": [node], "motion": {"label": "chop"}, "outputs": [{"label": "onion", "states": [
            {"label": "chopped"}]}]},
        {"inputs": [node], "motion": {"label": "peel"}, "outputs": [node], "sources": [{"path": "r.txt"}]}]}
    foon = parse_json(json.dumps(doc), "doc.json")
    assert foon.level == 3 and foon.units[0].sources == () and foon.units[1].sources[0].line == 0


def test_readme_lists_every_docs_page():
    """README's `## Documentation` list left out docs/extending.md (registries: a planner, a network kind, an
    encoding, a retrieval method), so a newcomer reading README never found it."""
    readme = (ROOT / "README.md").read_text()
    listed = readme.split("## Documentation", 1)[1].split("\n## ", 1)[0]
    pages = sorted(p.name for p in (ROOT / "docs").glob("*.md"))
    assert [p for p in pages if f"(docs/{p})" not in listed] == []


def test_retrieval_md_steps_example_is_a_line_steps_prints():
    """retrieval.md's `steps` example read `3. chop onion (on [cutting board], whole) with knife on cutting board ->
    onion (chopped, on [cutting board])`: no tree prints it (the onion is peeled first, and the board it is on is
    `cutting board (contains {onion})`). The page names the command its example comes from; the line is that
    command's."""
    text = " ".join((ROOT / "docs" / "retrieval.md").read_text().split())
    m = re.search(r"- `steps`: the same tree and numbering as FOON nodes \(`foon2pddl (retrieve [^`]*)`\): `([^`]*)`",
                  text)
    assert m, "retrieval.md's `steps` bullet names no command and example"
    result = CliRunner().invoke(main, shlex.split(m.group(1)))
    assert result.exit_code == 0, result.output
    assert m.group(2) in result.stdout.splitlines()


def test_skills_md_names_every_field_of_the_skill_plans_json():
    """skills.md's `--format json` list left out `domain`, `macro_steps` and `decomposed`, and each step's `skills`
    and `seconds`: a robot executive's author reading it did not know they were there. Every key of the document,
    of a step and of a skill is named in that bullet."""
    page = " ".join((ROOT / "docs" / "skills.md").read_text().split())
    bullet = re.search(r"- `--format json`: (.*?); - `-o DIR`", page).group(1)
    named = set(re.findall(r"`(\w+)`", bullet))
    result = CliRunner().invoke(main, ["plan", "--goal", "whipped cream", "--skills", "--format", "json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    shown = set(data) | set(data["steps"][0]) | set(data["skills"][0]) | set(data["replay"])
    assert sorted(shown - named) == []


@pytest.mark.parametrize("encoding", ["relational", "instances", "tree"])
def test_planning_md_names_every_field_of_plans_json(encoding):
    """planning.md listed `plan --format json`'s fields without the `relational` and `instances` keys those
    encodings add (docs/pddl.md has them, planning.md's list looked complete)."""
    page = " ".join((ROOT / "docs" / "planning.md").read_text().split())
    paragraph = re.search(r"With `--format json` everything is one JSON document(.*?)A batch", page).group(1)
    named = set(re.findall(r"`(\w+)`", paragraph))
    result = CliRunner().invoke(main, ["plan", "--goal", "whipped cream", "--encoding", encoding, "--format", "json"])
    assert result.exit_code == 0, result.output
    assert sorted(set(json.loads(result.stdout)) - named) == []


def test_readme_says_which_extras_make_install_installs():
    """README said `make install` installs the package "with every extra"; it installs three of the four
    (pyproject's `interop`, the other unified-planning engines, is not among them, as README's own table says).
    The extras README names are the Makefile's, and every other extra is named as left out."""
    readme = " ".join((ROOT / "README.md").read_text().split())
    installed = set(re.search(r"pip install [-\w ]*?-e '\.\[([\w,]+)\]'", (ROOT / "Makefile").read_text()).group(1)
                    .split(","))
    pyproject = (ROOT / "pyproject.toml").read_text()
    table = pyproject.split("[project.optional-dependencies]")[1].split("\n[", 1)[0]
    extras = set(re.findall(r"^([\w-]+) = \[", table, re.M))
    sentence = re.search(r"`make install` creates `\.venv/` and installs the package (.*?)\):", readme).group(1)
    assert "every extra" not in sentence
    assert f"'.[{','.join(sorted(installed, key=sentence.find))}]'" in sentence
    assert extras - installed == {"interop"}  # the test reads the table it means to
    assert all(f"`{extra}`" in sentence for extra in extras - installed)


def test_the_test_corpus_readme_names_every_entry():
    """README says `tests/data/README.md` says what each file is; it left out `scene/` (the scene kitchens
    docs/scene.md plans with)."""
    corpus = ROOT / "tests" / "data"
    text = (corpus / "README.md").read_text()
    entries = sorted(p.name + ("/" if p.is_dir() else "") for p in corpus.iterdir()
                     if p.name not in ("README.md", ".gitattributes"))
    assert [e for e in entries if f"`{e}`" not in text] == []


def test_format_md_counts_the_search_kitchens_one_sided_containers():
    """format.md said 318 of the 590 `x in [c]` items of the search inputs' kitchen.json have no matching
    `c contains {x}` item; the file has 618 such items (each a distinct node), 333 of them unmatched."""
    text = " ".join((ROOT / "docs" / "format.md").read_text().split())
    m = re.search(r"\(([\d,]+) of the ([\d,]+) `x in \[c\]` items of the search inputs' `kitchen.json`", text)
    items = json.loads((ROOT / "tests" / "data" / "foon-search-inputs" / "kitchen.json").read_text())
    listed = {(item["label"], x) for item in items for x in item.get("ingredients") or ()}
    placed = [item for item in items if item.get("container")]
    unmatched = [item for item in placed if (item["container"], item["label"]) not in listed]
    assert (int(m.group(1).replace(",", "")), int(m.group(2).replace(",", ""))) == (len(unmatched), len(placed))


def _registry_entries():
    from foon2pddl.generalize.network import NetworkKind
    from foon2pddl.pddl.registry import Encoding
    from foon2pddl.planners.registry import Planner
    from foon2pddl.retrieval.methods import Method

    return [(Planner, "A planner"), (NetworkKind, "A network kind"), (Encoding, "An encoding"),
            (Method, "A retrieval method")]


@pytest.mark.parametrize(("entry", "section"), _registry_entries(), ids=lambda x: getattr(x, "__name__", x))
def test_extending_md_names_every_field_of_each_registry_entry(entry, section):
    """extending.md's table gave `Encoding(name, encode, description, ..., replay, view, holders)` and its section
    named neither `complete` nor `kitchen_init`, fields the dataclass has: the table row lists every field in
    order, and the entry's section says what each one (but its name and description) is for."""
    import dataclasses

    page = (ROOT / "docs" / "extending.md").read_text()
    fields = [f.name for f in dataclasses.fields(entry)]
    row = next(line for line in page.splitlines() if line.startswith("| ") and f"`{entry.__name__}(" in line)
    listed = re.search(rf"`{entry.__name__}\((.*?)\)`", row).group(1)
    assert [f.strip() for f in listed.split(",")] == fields
    body = page.split(f"## {section}\n", 1)[1].split("\n## ", 1)[0]
    said = set(re.findall(r"`(\w+)", body))
    assert [f for f in fields if f not in said and f not in ("name", "description")] == []


def test_readme_names_the_example_kitchens_file():
    """README said every command without PATHS uses "the embedded example network (`foon2pddl/data/example/`, ...)
    and its kitchen": the kitchen is not in that directory and no page named its file, so a newcomer who wanted to
    change it (a kitchen without a board, without the lime) looked for it in vain (stop 49's third newcomer pass).
    README names the file the commands read."""
    from foon2pddl.io.inputs import example_path

    readme = " ".join((ROOT / "README.md").read_text().split())
    kitchen = example_path("example_kitchen.txt").resolve().relative_to(ROOT.resolve())
    assert f"`{kitchen}`" in readme


def test_planning_md_says_what_its_planner_cmd_examples_need():
    """planning.md showed two `--planner-cmd` commands "so both of these work"; the second, run as written, exits 2
    with `no executable './my-downward/fast-downward.py'`: the page did not say it needs a Fast Downward checkout
    there. Every relative executable a shown command needs and the repository lacks is named in the prose."""
    text = (ROOT / "docs" / "planning.md").read_text()
    said_at = text[:text.index("so both of these work")].count("\n") + 1
    block = next(b for b in blocks(text) if b.start > said_at)  # the block the sentence introduces
    commands = [words[words.index("--planner-cmd") + 1] for words in map(shlex.split, block.lines)
                if "--planner-cmd" in words]
    needed = {shlex.split(c)[0] for c in commands}
    needed = {w for w in needed if w.startswith("./") and not (ROOT / w).exists()}
    assert needed, commands  # the block read is the one with the `--planner-cmd` commands
    assert [w for w in needed if f"`{w.rsplit('/', 1)[0]}`" not in prose(text)] == []


def test_readme_layout_names_each_packages_own_files():
    """README's Layout said, inside `pddl/`'s parenthesis, "jinja2 templates in `templates/`": a newcomer looked for
    `foon2pddl/pddl/templates/`, which does not exist (the templates, of the PDDL text and of the experiment
    report, are `foon2pddl/templates/`; stop 50's newcomer pass). Every file or directory a package's parenthesis
    names in backticks is in that package."""
    layout = (ROOT / "README.md").read_text().split("## Layout", 1)[1].split("\n## ", 1)[0]
    misplaced = []
    for m in re.finditer(r"`([a-z_]+)/` \(", layout):
        depth, end = 1, m.end()
        while depth:
            depth += {"(": 1, ")": -1}.get(layout[end], 0)
            end += 1
        base = ROOT / "foon2pddl" / m.group(1)
        base = base if base.is_dir() else ROOT / m.group(1)
        named = re.findall(r"`([a-z_]+(?:\.py|/))`", layout[m.end():end])
        misplaced += [f"{m.group(1)}/{n}" for n in named if not (base / n.rstrip("/")).exists()]
    assert misplaced == []


def test_readme_says_bench_silence_runs_each_command_with_every_cache_it_measures():
    """README's Layout said `python -m bench.silence` runs every documented command "each from an empty cache"
    (nc53a's pass); it runs each twice, from an empty cache and again with the cache that run left, and reports
    the longer silence of the two (its output names both: `[empty cache, ...; empty 1.1 s ..., warm 1.0 s ...]`)."""
    from bench.silence import CACHES

    readme = " ".join((ROOT / "README.md").read_text().split())
    said = readme.split("`python -m bench.silence`", 1)[1].split(")", 1)[0]
    assert CACHES == ("empty", "warm")
    assert "from an empty cache" in said and "again with the cache" in said, said
