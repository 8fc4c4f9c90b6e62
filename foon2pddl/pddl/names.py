"""PDDL identifiers and comments from arbitrary labels.

`sanitize` maps any text to a valid PDDL name `[a-z][a-z0-9_-]*` (readable, not
unique); `NameTable` makes names unique within one namespace and keeps the
mapping both ways, so a plan's action names map back 1:1; `comment` makes text
safe inside a `;` comment (nothing can end the comment early). Everything is
deterministic: the same calls in the same order give the same names.
"""

from __future__ import annotations

import hashlib
import re
import unicodedata

#: Words a PDDL reader treats specially (requirements-independent), and names our
#: encodings use themselves; a label sanitized to one of these gets a `_` suffix.
RESERVED: frozenset[str] = frozenset(
    {
        "define", "domain", "problem", "requirements", "types", "constants", "predicates", "functions",
        "action", "parameters", "precondition", "effect", "objects", "init", "goal", "metric",
        "and", "or", "not", "imply", "exists", "forall", "when", "either", "object", "number",
        "increase", "decrease", "assign", "scale-up", "scale-down", "minimize", "maximize",
        "total-cost", "total-time", "at", "over", "start", "end", "all", "preference",
        "always", "sometime", "within", "at-most-once", "sometime-after", "sometime-before",
        "always-within", "hold-during", "hold-after", "derived", "durative-action", "duration",
        "condition", "constraints", "length", "serial", "parallel",
    }
)

#: Longest base name kept before a collision suffix (labels with ingredient lists get long).
MAX_LENGTH = 80

#: Hex digits of the full label's digest that a truncated name ends with.
DIGEST_LENGTH = 8

_SEPARATORS = re.compile(r"[_-]{2,}")
_VALID = re.compile(r"[a-z][a-z0-9_-]*\Z")


_NOT_NAME_CHAR = re.compile(r"[^a-z0-9-]")


def _ascii_chars(text: str) -> str:
    """Lower-case ASCII letters/digits kept, `-` kept, anything else `_`; non-ASCII letters spelled `uXXXX`."""
    if text.isascii():
        return _NOT_NAME_CHAR.sub("_", text.lower())
    out: list[str] = []
    for ch in unicodedata.normalize("NFKD", text):
        if unicodedata.combining(ch):
            continue
        if ch.isascii():
            low = ch.lower()
            out.append(low if ("a" <= low <= "z" or "0" <= low <= "9" or low == "-") else "_")
        elif ch.isalnum():
            out.append(f"_u{ord(ch):04x}_")
        else:
            out.append("_")
    return "".join(out)


def sanitize(label: str, max_length: int = MAX_LENGTH) -> str:
    """A valid, readable PDDL name for `label` (`[a-z][a-z0-9_-]*`, never a reserved word); not unique.

    A name longer than `max_length` is cut and ends with `__` and a digest of the whole label (SHA-256,
    `DIGEST_LENGTH` hex digits), so long labels that share a prefix get different, order-independent names.
    """
    name = _SEPARATORS.sub(lambda m: "-" if "-" in m.group() else "_", _ascii_chars(label)).strip("_-")
    if not name:
        name = "x"
    elif not name[0].isalpha():
        name = "x_" + name
    if len(name) > max_length:
        digest = hashlib.sha256(label.encode("utf-8", "surrogatepass")).hexdigest()[:DIGEST_LENGTH]
        name = name[: max(1, max_length - DIGEST_LENGTH - 2)].rstrip("_-") + "__" + digest
    if name in RESERVED:
        name += "_"
    return name


def is_valid_name(name: str) -> bool:
    """Whether `name` is an identifier `sanitize` could produce (valid PDDL, lower case, not reserved)."""
    return bool(_VALID.match(name)) and name not in RESERVED


class NameTable:
    """Collision-free PDDL names for labels in one namespace, with the mapping kept.

    `name(key, label)` returns the same name for the same key every time; a new
    key whose sanitized label is taken gets the first free `-2`, `-3`, ... suffix
    (a truncated label's name carries its digest, so only short labels that
    sanitize alike, or a digest collision, get one).
    `key` defaults to the label; give another (hashable) key when different
    things can share a label (an object label and a state label, say).
    """

    def __init__(self, reserved: frozenset[str] | set[str] = frozenset()) -> None:
        self._names: dict[object, str] = {}
        self._labels: dict[str, str] = {}
        self._taken: set[str] = set(reserved)

    def name(self, label: str, key: object = None) -> str:
        """The unique name of `key` (default: `label`), allocated from `label` on first use."""
        key = label if key is None else key
        found = self._names.get(key)
        if found is not None:
            return found
        base = sanitize(label)
        name, n = base, 1
        while name in self._taken:
            n += 1
            name = f"{base}-{n}"
        self._taken.add(name)
        self._names[key] = name
        self._labels[name] = label
        return name

    def reserve(self, name: str, label: str = "") -> str:
        """Claim an exact, valid name (for an encoding's own predicates); error if taken."""
        if not _VALID.match(name):
            raise ValueError(f"not a valid PDDL name: {name!r}")
        if name in self._taken:
            raise ValueError(f"name already taken: {name!r}")
        self._taken.add(name)
        self._labels[name] = label or name
        return name

    def __contains__(self, key: object) -> bool:
        return key in self._names

    def __len__(self) -> int:
        return len(self._names)

    @property
    def labels(self) -> dict[str, str]:
        """PDDL name -> original label, for every name handed out."""
        return dict(self._labels)


# Everything a reader may treat as a line break (str.splitlines' set) plus other control characters.
_UNSAFE_IN_COMMENT = re.compile(r"[\x00-\x08\x0a-\x1f\x7f\x85\u2028\u2029]")


def comment(text: str) -> str:
    """`text` made safe for one `;` comment line: one line, printable ASCII only (others as `<U+XXXX>`)."""
    text = _UNSAFE_IN_COMMENT.sub(" ", text)
    if text.isascii():
        return text
    return "".join(ch if ch.isascii() else f"<U+{ord(ch):04X}>" for ch in text)
