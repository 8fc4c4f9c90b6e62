"""WordNet through NLTK's reader: an installed NLTK corpus, or Debian's WordNet 3.0 files.

Search order: NLTK's data roots (what `python -m nltk.downloader wordnet` installs),
then a corpus assembled earlier in the user cache, then Debian's `wordnet-base` +
`wordnet-sense-index` files in /usr/share/wordnet, which are copied once into
`<cache>/nltk_data/corpora/wordnet/` (NLTK refuses files outside its data roots,
so links would not do) together with the standard `lexnames` table that Debian
does not ship. Locating the corpus and reading its version does not import NLTK
(importing it costs over a second), so a cached similarity matrix loads fast.
"""

from __future__ import annotations

import importlib.util
import os
import re
import shutil
import sys
import tempfile
import zipfile
from functools import lru_cache
from pathlib import Path

from ..errors import FoonInputError, MissingDependencyError, require
from ..model.bulk import full_gc_paused
from .cache import cache_dir

DEBIAN_DIR = Path("/usr/share/wordnet")

#: The files NLTK's WordNetCorpusReader opens (its `_FILES`), `lexnames` excepted.
CORPUS_FILES = (
    "cntlist.rev", "index.sense",
    "index.adj", "index.adv", "index.noun", "index.verb",
    "data.adj", "data.adv", "data.noun", "data.verb",
    "adj.exc", "adv.exc", "noun.exc", "verb.exc",
)

#: WordNet's lexicographer files by number (the `lexnames` file of every WordNet 3.0
#: distribution): number, name, syntactic category (1 noun, 2 verb, 3 adjective, 4 adverb).
LEXNAMES: tuple[tuple[str, int], ...] = (
    ("adj.all", 3), ("adj.pert", 3), ("adv.all", 4),
    ("noun.Tops", 1), ("noun.act", 1), ("noun.animal", 1), ("noun.artifact", 1),
    ("noun.attribute", 1), ("noun.body", 1), ("noun.cognition", 1), ("noun.communication", 1),
    ("noun.event", 1), ("noun.feeling", 1), ("noun.food", 1), ("noun.group", 1),
    ("noun.location", 1), ("noun.motive", 1), ("noun.object", 1), ("noun.person", 1),
    ("noun.phenomenon", 1), ("noun.plant", 1), ("noun.possession", 1), ("noun.process", 1),
    ("noun.quantity", 1), ("noun.relation", 1), ("noun.shape", 1), ("noun.state", 1),
    ("noun.substance", 1), ("noun.time", 1),
    ("verb.body", 2), ("verb.change", 2), ("verb.cognition", 2), ("verb.communication", 2),
    ("verb.competition", 2), ("verb.consumption", 2), ("verb.contact", 2), ("verb.creation", 2),
    ("verb.emotion", 2), ("verb.motion", 2), ("verb.perception", 2), ("verb.possession", 2),
    ("verb.social", 2), ("verb.stative", 2), ("verb.weather", 2),
    ("adj.ppl", 3),
)

INSTALL_HINT = (
    "install Debian's WordNet 3.0 files "
    "(apt-get install wordnet-base wordnet-sense-index) or NLTK's corpus (python -m nltk.downloader wordnet)"
)

_VERSION = re.compile(r"Word[nN]et (\d+\+?|\d+\.\d+) Copyright")


def lexnames_text() -> str:
    """The `lexnames` file: `NN<TAB>name<TAB>category` per line, numbered 00-44."""
    return "".join(f"{i:02d}\t{name}\t{cat}\n" for i, (name, cat) in enumerate(LEXNAMES))


def nltk_data_roots() -> list[Path]:
    """NLTK's default data roots on Unix (`nltk.data.path` as NLTK computes it), without importing NLTK."""
    roots = [Path(d).expanduser() for d in os.environ.get("NLTK_DATA", "").split(os.pathsep) if d]
    if "APPENGINE_RUNTIME" not in os.environ and os.path.expanduser("~/") != "~/":
        roots.append(Path(os.path.expanduser("~/nltk_data")))
    roots += [Path(sys.prefix, "nltk_data"), Path(sys.prefix, "share", "nltk_data"),
              Path(sys.prefix, "lib", "nltk_data"), Path("/usr/share/nltk_data"),
              Path("/usr/local/share/nltk_data"), Path("/usr/lib/nltk_data"), Path("/usr/local/lib/nltk_data")]
    return roots


def assembled_root(cache: Path | None = None) -> Path:
    """The NLTK data root inside the cache that holds an assembled `corpora/wordnet`."""
    return (cache or cache_dir()) / "nltk_data"


def _complete(corpus: Path) -> bool:
    return corpus.is_dir() and all((corpus / f).is_file() for f in (*CORPUS_FILES, "lexnames"))


def assemble(debian_dir: Path, root: Path) -> Path:
    """Copy Debian's WordNet files and a `lexnames` table into `root/corpora/wordnet` (atomically)."""
    target = root / "corpora" / "wordnet"
    if _complete(target):
        return target
    target.parent.mkdir(parents=True, exist_ok=True)
    staging = Path(tempfile.mkdtemp(prefix=".wordnet-", dir=target.parent))
    try:
        for name in CORPUS_FILES:
            shutil.copyfile(debian_dir / name, staging / name)
        (staging / "lexnames").write_text(lexnames_text(), encoding="utf-8")
        try:
            os.rename(staging, target)  # another process may have won the race: keep its copy
        except OSError:
            if not _complete(target):
                raise
    finally:
        shutil.rmtree(staging, ignore_errors=True)
    return target


def locate(
    debian_dir: Path = DEBIAN_DIR, cache: Path | None = None, nltk_roots: list[Path] | None = None
) -> tuple[Path, Path]:
    """(data root, corpus dir or zip) of the WordNet to use, assembling Debian's files if needed.

    Raises MissingDependencyError naming both install routes when no WordNet is found.
    """
    for root in nltk_data_roots() if nltk_roots is None else nltk_roots:
        corpus = root / "corpora" / "wordnet"
        if (corpus / "lexnames").is_file():
            return root, corpus
        if (root / "corpora" / "wordnet.zip").is_file():
            return root, root / "corpora" / "wordnet.zip"
    root = assembled_root(cache)
    if _complete(root / "corpora" / "wordnet"):
        return root, root / "corpora" / "wordnet"
    if all((debian_dir / f).is_file() for f in CORPUS_FILES):
        try:
            return root, assemble(debian_dir, root)
        except OSError as exc:
            raise FoonInputError(str(root), 0, f"cannot assemble WordNet from {debian_dir}: {exc}") from None
    raise MissingDependencyError("WordNet not found", INSTALL_HINT)


#: What reading a damaged corpus raises in NLTK or on the values it returns (a truncated data file gives
#: None synsets, a truncated index StopIteration, a bad `lexnames` ValueError, a bad zip BadZipFile).
_DAMAGE = (OSError, ValueError, LookupError, StopIteration, EOFError, AttributeError, TypeError, zipfile.BadZipFile)
#: WordNet's parts of speech and their file suffixes.
_POS = (("n", "noun"), ("v", "verb"), ("a", "adj"), ("r", "adv"))


def damaged(corpus: Path, exc: BaseException) -> FoonInputError:
    """The error for a corpus that cannot be read: what failed and how to reinstall it."""
    detail = str(exc).strip().splitlines()
    what = f"{type(exc).__name__}: {detail[0][:200]}" if detail and detail[0].strip("*") else type(exc).__name__
    return FoonInputError(str(corpus), 0, f"damaged WordNet corpus ({what}); reinstall it: {INSTALL_HINT}")


def check_corpus(wn) -> None:
    """Fail on a corpus damaged where opening does not look: each data file must hold the synset at the
    largest offset its index names (a truncated or replaced data file does not). One pass over the
    lemma index (linear in its size, tens of milliseconds) and one synset read per part of speech."""
    offsets = getattr(wn, "_lemma_pos_offset_map", None)
    if not isinstance(offsets, dict):
        return
    for pos, name in _POS:
        last = max((o for by_pos in offsets.values() for o in by_pos.get(pos, ())), default=None)
        if last is not None and wn.synset_from_pos_and_offset(pos, last) is None:
            raise EOFError(f"data.{name} lacks the synset at offset {last} that index.{name} names")


def corpus_version(corpus: Path) -> str:
    """WordNet version from the copyright header of `data.adj` (as NLTK's `get_version` reads it);
    FoonInputError when the corpus cannot be read."""
    try:
        return _corpus_version(corpus)
    except (OSError, zipfile.BadZipFile, KeyError) as exc:
        raise damaged(corpus, exc) from None


def _corpus_version(corpus: Path) -> str:
    if corpus.suffix == ".zip":
        with zipfile.ZipFile(corpus) as zf:
            name = next((n for n in zf.namelist() if n.endswith("/data.adj")), None)
            head = zf.read(name)[:4096].decode("utf-8", "replace") if name else ""
    else:
        with open(corpus / "data.adj", encoding="utf-8", errors="replace") as fh:
            head = fh.read(4096)
    m = _VERSION.search(head)
    return m.group(1) if m else "unknown"


def check_available() -> None:
    """Raise MissingDependencyError unless WordNet can be opened: a corpus (`locate`) and NLTK to read it.
    Imports nothing (NLTK costs over a second): for checks before long work."""
    locate()
    try:
        found = importlib.util.find_spec("nltk") is not None
    except (ImportError, ValueError):
        found = False
    if not found:
        raise MissingDependencyError("WordNet similarity (FOON-EXP, categories) needs nltk", "pip install 'foon2pddl[gen]'")


@lru_cache(maxsize=1)
def version() -> str:
    """Version of the WordNet `reader()` opens (e.g. "3.0"), read without importing NLTK."""
    return corpus_version(locate()[1])


@lru_cache(maxsize=1)
def reader():
    """NLTK's WordNetCorpusReader over the located corpus (no multilingual data); FoonInputError naming
    the corpus when it is damaged (`check_corpus`), never NLTK's own exception."""
    import warnings

    nltk_data = require("nltk.data", "gen", "WordNet similarity (FOON-EXP, categories)")
    WordNetCorpusReader = require("nltk.corpus.reader.wordnet", "gen", "WordNet").WordNetCorpusReader

    root, corpus = locate()
    if str(root) not in [str(p) for p in nltk_data.path]:
        nltk_data.path.append(str(root))  # authorizes the root in NLTK's path sandbox
    class Reader(WordNetCorpusReader):
        def map_wn(self, version="wordnet"):
            # NLTK maps the synsets of WordNet 3.0 onto the loaded WordNet for its multilingual
            # data, by parsing index.sense twice: more than half of opening, and useless here
            # (no multilingual data is loaded, and the map is the identity for WordNet 3.0).
            return None

    try:
        pointer = nltk_data.find("corpora/wordnet")
        # NLTK's maps are millions of long-lived objects: full collections rescanned them while they grew, each
        # holding the interpreter lock for up to 0.8 s (load 10), so the step's line beat late (2.5 s gaps)
        with warnings.catch_warnings(), full_gc_paused():
            warnings.simplefilter("ignore")  # "multilingual functions are not available"
            wn = Reader(pointer, None)
            check_corpus(wn)
    except _DAMAGE as exc:
        raise damaged(corpus, exc) from None
    return wn
