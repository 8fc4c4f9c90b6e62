"""A task tree's steps in a cook's words (`recipe`, the default output of `retrieve` and `plan`): what moves,
from where, into what, with which tool, and what the step makes, read from the unit's FOON nodes.

A place FOON names by a shorter or longer word than the object's label (`egg mixture (in [pan])` where the
unit's object is the `cooking pan`: `places.head_of`) is that object, so the pan is said once, as the place,
never as a tool.
"""

from __future__ import annotations

from collections.abc import Collection, Iterable

from ..model.foon import FunctionalUnit, ObjectNode, State
from ..model.pairing import transfer, unit_roles
from ..model.places import contents, head_of, named_holder
from ..model.words import prose_list

#: State labels that, naming another input (`_holder`), say where a step happens.
PLACE_WORDS = ("on", "in", "inside", "into", "onto", "under", "over", "above", "below")

#: How a recipe says where an object goes, per place state.
_INTO = {"in": "into", "inside": "into", "into": "into", "on": "onto", "onto": "onto", "under": "under",
         "over": "over", "above": "above", "below": "below"}
#: How a recipe says where a step happens, per place state (`cut ..., on the cutting board`, `mix ..., in the bowl`).
_AT = {"in": "in", "inside": "in", "into": "in", "on": "on", "onto": "on"}

#: A unit's place names read as its objects' labels (`aliases`): `pan` -> `cooking pan`.
Aliases = dict[str, str]


def aliases(unit: FunctionalUnit) -> Aliases:
    """The place names of `unit` that no object of it has as label, each read as the one input label it names by
    the head-noun rule (`egg mixture (in [pan])` beside a `cooking pan`: `places.head_of`); a name two input
    labels could be is left as written. O(nodes x inputs)."""
    labels = {n.label for n in (*unit.inputs, *unit.outputs)}
    out: Aliases = {}
    for n in (*unit.inputs, *unit.outputs):
        for s in n.states:
            if (h := _holder(s)) and h not in labels:
                found = {i.label for i in unit.inputs if head_of(h, i.label)}
                if len(found) == 1:
                    out[h] = found.pop()
    return out


def _holder(state: State) -> str:
    """The object a place state names, or "": `model.places.named_holder` for a place word (`on [pizza pan]`, and
    `pizza sauce (on {pizza dough})`, 0082's cheese pizza: FOON writes a spread's place in braces too)."""
    return named_holder(state) if state.label in PLACE_WORDS else ""


def _place(node: ObjectNode, named: Aliases | None = None) -> tuple[str, str] | None:
    """(place word, holder) of the node's first place state (`_holder`), or None; the holder as `named` reads it."""
    found = next(((s.label, h) for s in node.states if (h := _holder(s))), None)
    return (found[0], named.get(found[1], found[1])) if found and named else found


def _said_at(unit: FunctionalUnit, named: Aliases) -> dict[str, int]:
    """Holder label -> how many place states of the unit's nodes say `on` it, less those saying `in` it (as `_AT`
    reads each place word)."""
    out: dict[str, int] = {}
    for n in (*unit.inputs, *unit.outputs):
        for s in n.states:
            if (h := _holder(s)) and (word := _AT.get(s.label)):
                h = named.get(h, h)
                out[h] = out.get(h, 0) + (1 if word == "on" else -1)
    return out


def surfaces(units: Iterable[FunctionalUnit]) -> frozenset[str]:
    """The labels the units' nodes put things `on` more often than `in` (`on {pizza dough}`, `on [plate]`), each
    unit's place names read through its `aliases`: where a step whose own nodes do not say it puts a thing
    (`_onto`). O(nodes)."""
    total: dict[str, int] = {}
    for u in units:
        for h, k in _said_at(u, aliases(u)).items():
            total[h] = total.get(h, 0) + k
    return frozenset(h for h, k in total.items() if k > 0)


def _onto(unit: FunctionalUnit, label: str, named: Aliases, on: frozenset[str]) -> tuple[str, str]:
    """(`on` or `in`, label): how a thing FOON names only in `label`'s list goes there. The unit's own nodes
    decide when they say `on` it more often than `in`, or the reverse (0042's pour onto the plate its tomato is
    `on`); else the recipe's `surfaces` `on` (0085's sour cream spread on the pizza dough, which later steps put
    the onion `on`); else `in`."""
    k = _said_at(unit, named).get(label, 0)
    return ("on" if k > 0 or (k == 0 and label in on) else "in"), label


def _lister(unit: FunctionalUnit, thing: str, *, of: str | None = None, but: ObjectNode | None = None,
            away: Collection[str] = (), not_on: Aliases | None = None) -> ObjectNode | None:
    """Where `thing` is, as FOON's lists say: the first input whose contents list it, of label `of` when given,
    not the node `but`, of no label in `away`, and with `not_on` (the unit's aliases) not itself in or on `thing`
    (0017's tray the bread is on); None when none. O(inputs x states)."""
    return next((j for j in unit.inputs if thing in contents(j) and (of is None or j.label == of) and j is not but
                 and j.label not in away and not (not_on is not None and thing in _holders(j, not_on))), None)


def _holders(node: ObjectNode, named: Aliases) -> set[str]:
    """Every object the node's place states name (`_holder`, as `named` reads them)."""
    return {named.get(h, h) for s in node.states if (h := _holder(s))}


def _unplaced(node: ObjectNode) -> str:
    """The node in words without its place state (`lime juice`, `lime (whole)`)."""
    states = [s.describe() for s in node.states if not _holder(s)]
    return node.label + (f" ({', '.join(states)})" if states else "")


def _without_contents(node: ObjectNode, contents: set[str]) -> str:
    """The node in words without an ingredient set listing only `contents` (said already)."""
    states = [s.describe() for s in node.states if not (s.ingredients and set(s.ingredients) <= contents)]
    return node.label + (f" ({', '.join(states)})" if states else "")


def _becomes(unit: FunctionalUnit, new: dict[str, ObjectNode]) -> dict[str, ObjectNode]:
    """Label -> the input that becomes its new output (`model.pairing.unit_roles`): of two bowls, the one whose
    contents the new bowl keeps, not the last one listed."""
    return {r.label: r.before for r in unit_roles(unit)
            if r.before is not None and r.after is not None and new.get(r.label) == r.after}


def _filled(unit: FunctionalUnit, new: dict[str, ObjectNode], before: dict[str, ObjectNode],
            moved: set[str], named: Aliases, on: frozenset[str]) -> list[tuple[ObjectNode, tuple[str, str] | None, tuple[str, str]]]:
    """(input, its place, (`in` or `on`: `_onto`, container)) for each input that a container's new node newly lists while the
    unit gives it no node of its own (0001's `pour*`: the cream and the sugar only in the mixing bowl's list);
    not an input already in it, or beside it in one holder (stirred in the pot where both are), unless another
    container of its label lists it (the salt sprinkled from one bowl into the other). An input two
    containers newly list goes into the one inside another of them (0071's cream into the pudding in the tray),
    else into the first: each input is said once."""
    into: dict[ObjectNode, list[str]] = {}
    for label, container in new.items():
        if label not in before:
            continue
        added = contents(container) - contents(before[label])
        for i in unit.inputs:
            place = _place(i, named)
            elsewhere = _lister(unit, i.label, of=label, but=before[label]) is not None
            if (i.label in added and i.label not in new and i.label not in moved
                    and ((place or ("", ""))[1] != label or elsewhere)
                    and not (place and place == _place(before[label], named))):
                into.setdefault(i, []).append(label)
    out = []
    for i, labels in into.items():
        inner = [c for c in labels if (_place(new[c], named) or ("", ""))[1] in labels]
        out.append((i, _place(i, named), _onto(unit, (inner or labels)[0], named, on)))
    return out


def _source(unit: FunctionalUnit, moved: ObjectNode, label: str, into: ObjectNode | None) -> str:
    """The container `moved` leaves, said so a cook tells it from `into`: with its state when both have one label
    (`from the bowl (contains {salt}) into the bowl (contains {egg white and yolk})`), else by its label."""
    if into is None or into.label != label:
        return label
    found = _lister(unit, moved.label, of=label, but=into)
    return found.describe() if found is not None else label


def _listed_only(unit: FunctionalUnit, new: dict[str, ObjectNode], before: dict[str, ObjectNode],
                 said: set[str], named: Aliases, on: frozenset[str]
                 ) -> list[tuple[ObjectNode, tuple[str, str], tuple[str, str]]]:
    """(what, (`in`, from), (`in` or `on`: `_onto`, into)) for a thing FOON names only in containers' lists: a container's new node
    newly lists it, no node of the unit has its label or one word for it (`rice` beside `white rice`), and another
    input lists it that does not hold the container (0085's `scoop`: the bottle (contains {sour cream}) and the
    scraper (clean) -> scraper (contains {sour cream}): `scoop sour cream from the bottle into the scraper
    (clean)`; not the pan's oil and onion that FOON lists again in the mixture cooked in it). The thing is a node
    of its label alone. O(containers x inputs x labels)."""
    labels = {n.label for n in (*unit.inputs, *unit.outputs)} | said
    out = []
    for label, container in new.items():
        around = _holders(container, named) | (_holders(before[label], named) if label in before else set())
        for thing in sorted(contents(container) - contents(before[label]) if label in before else ()):
            source = _lister(unit, thing, away=around | {label})
            if source is not None and not any(t == thing or head_of(thing, t) for t in labels):
                out.append((ObjectNode(thing), ("in", source.label), _onto(unit, label, named, on)))
    return out


def _carrier(unit: FunctionalUnit, moved: ObjectNode, src: tuple[str, str] | None, dst: tuple[str, str],
             moving: set[str], named: Aliases) -> tuple[str, str] | None:
    """Where `moved` is when the step begins, if not where its own node says: the first other input that lists it.
    FOON updates the holder a step fills (0082's scoop: `serving spoon (contains {pizza sauce})`) and leaves the
    filled thing's own node as it was (`pizza sauce (in [bowl])`), so the next step pours the sauce from the
    spoon. Not its own holder, nor what it goes into or what holds that (0053's baking tray lists the sauce poured
    onto the tortilla in it), nor a thing the step moves or one on `moved` (0017's bread `on [baking tray]` that
    lists the tray). Holders are read through the unit's `named` aliases, as every place in the step's words (a
    tortilla `on [tray]` beside the `baking tray` that lists the sauce: the tray holds where it goes). None when no
    other input lists it. O(inputs x states)."""
    into = next((i for i in unit.inputs if i.label == dst[1]), None)
    away = {dst[1], *moving, *(src[1:] if src else ()), *(_holders(into, named) if into is not None else ())}
    found = _lister(unit, moved.label, away=away, not_on=named)
    return ("in", found.label) if found is not None else None


def _listed(what: list[tuple[str, str, bool]]) -> str:
    """Things moved to one place, each with where it comes from (`from the bowl`), the source said once for a run
    of things from one holder (`onion (sliced) and bacon (chopped) from the cutting board`). (words, source, one):
    `one` when the source is surely one object (`_one_source`). Two bowls, each of one thing, stay two, and so do
    things `in [bottle]` with no bottle node (the greek salad's olive oil and vinegar, each in its own)."""
    runs: list[tuple[list[str], str, bool]] = []
    for words, source, one in what:
        if runs and one and runs[-1][2] and source and runs[-1][1] == source:
            runs[-1][0].append(words)
        else:
            runs.append(([words], source, one))
    said = [prose_list(words) + source for words, source, _ in runs]
    return prose_list(said)


def _one_source(unit: FunctionalUnit, src: tuple[str, str] | None) -> bool:
    """Whether the place `src` (relation, holder label) a thing moves from is surely one object, so that things
    moved from it are said to come from it once (`_listed`): the unit's only input of that label, or, with none, a
    surface the thing is on (a cutting board, a plate). O(inputs)."""
    if src is None:
        return False
    kin = sum(j.label == src[1] for j in unit.inputs)
    return kin == 1 or (kin == 0 and src[0] in ("on", "onto"))


def _between(unit: FunctionalUnit) -> tuple[list[ObjectNode], ObjectNode, ObjectNode] | None:
    """(what moves, from which container, into which) when two inputs of one container label trade contents
    (`model.pairing.transfer` over the unit's roles, which say which input becomes which output). None otherwise."""
    roles = unit_roles(unit)
    found = transfer([(r.before, r.after) for r in roles])
    if found is None:
        return None
    src, dst, moved = found
    return [i for i in unit.inputs if i.label in moved], roles[src].before, roles[dst].before


def _changed(unit: FunctionalUnit, new: dict[str, ObjectNode], by_label: dict[str, ObjectNode],
             named: Aliases) -> tuple[list[ObjectNode], ObjectNode | None]:
    """What a step that moves nothing works on, and the container it goes into (or None).

    The inputs that change, but not a tool the step only leaves dirty (`soiled`: the knife of `cut lemon (whole),
    with the knife (clean)`), nor the container of what the step makes (`making lime juice in the juicer`), nor
    the holder of another input that changes (the stove under the heated pan, the pan holding the omelette it
    cooks: they are places); when only that container changes, the inputs the step uses up that become what it
    makes (`egg` -> `egg white and yolk`) go into it (`crack egg (uncracked) into the bowl (empty)`); when no
    input changes, the inputs used up in that container are what the step works (`mix egg mixture ..., with the
    whisk, in the cooking pan, making omelette ...`)."""
    receivers = {p[1] for o in new.values() if o.label not in by_label and (p := _place(o, named))}
    changing = [i for i in unit.inputs if i.label in new]
    changed = [i for i in changing if i.label not in receivers and not soiled(i, new.get(i.label))]
    if not changed:
        out_labels = {o.label for o in unit.outputs}
        made = [o.label for o in new.values() if o.label not in by_label]
        into = next((i for i in changing if i.label in receivers), None)
        used_up = [i for i in unit.inputs if i.label not in out_labels and (
            _place(i) is None and any(m.startswith(i.label + " ") for m in made) if into is not None
            else bool(_holders(i, named) & receivers))]  # nothing changes: what is in the container made into
        if used_up:
            return used_up, into
        changed = [i for i in changing if not soiled(i, new.get(i.label))] or changing
    if not changed:  # FOON says nothing changes (a unit copying its input): every input, as written
        return list(unit.inputs), None
    if len(changed) > 1:  # what holds a changed input, or holds its holder (the microwave round the bowl), is a place
        inputs = {i.label: i for i in unit.inputs}
        inside, todo = set(), [h for i in changed for h in _holders(i, named)]
        while todo:
            if (h := todo.pop()) not in inside:
                inside.add(h)
                todo += _holders(inputs[h], named) if h in inputs else []
        changed = [i for i in changed if i.label not in inside] or changed
    return changed, None


def soiled(node: ObjectNode, after: ObjectNode | None) -> bool:
    """Whether a step only makes `node` dirty, leaving it `after` (`knife (clean)` -> `knife (dirty)`): a tool it
    uses, not what it works on, when something else changes too (here and in `pddl.relational_replay`'s words)."""
    if after is None:
        return False
    before_states, after_states = {s.label for s in node.states}, {s.label for s in after.states}
    return "dirty" in after_states and before_states ^ after_states <= {"clean", "dirty"}


def _ordered_places(places: list[ObjectNode], subjects: list[ObjectNode], named: Aliases) -> list[ObjectNode]:
    """The places, innermost first: those the step's subjects are in or on, then what holds those, and so on
    (`in the cooking pan, on the stove`); any left in input order."""
    out: list[ObjectNode] = []
    frontier = subjects
    while frontier:
        frontier = [p for p in places if p not in out and any(p.label in _holders(n, named) for n in frontier)]
        out += frontier
    return out + [p for p in places if p not in out]


def recipe_text(unit: FunctionalUnit, on: frozenset[str] = frozenset()) -> str:
    """A step in a cook's words: what moves, from where, into what, with which tool, and what it makes.

    `pour sugar (granulated) into the pitcher (contains {lime juice})`, where `step_text` lists the
    pitcher first as if it were poured. An input moves when its output of the same label is in a
    place state (`in [pitcher]`) other than its own; the containers named so, and the contents of
    moved objects, are not tools. Without a move: what changes (`_changed`; a tool it only leaves dirty is a
    tool: `cut lemon (whole), with the knife (clean), ...`), then the tools and the places,
    each said once with its own word (`cut lime (whole), with the knife, on the cutting board`; `mix ..., in the
    bowl`). Labels no input has are what the step makes. A place name is read as the unit's object it names
    (`aliases`). A thing named only in a container's list goes `into` or `onto` it as `_onto` reads the unit and
    `on`, the labels the recipe puts things on (`surfaces` of its units). O(n^2) in the unit's n nodes.
    """
    named = aliases(unit)
    new = {o.label: o for o in unit.outputs if o not in unit.inputs}
    by_label = {i.label: i for i in unit.inputs}
    before = {**by_label, **_becomes(unit, new)}
    moves = [(i, _place(i, named), _place(new[i.label], named)) for i in unit.inputs
             if i.label in new and _place(new[i.label], named) not in (None, _place(i, named))]
    moves += _filled(unit, new, before, {i.label for i, _, _ in moves}, named, on)
    moves += _listed_only(unit, new, before, {i.label for i, _, _ in moves}, named, on)
    moving = {i.label for i, _, _ in moves}
    said = moving | {p[1] for _, a, b in moves for p in (a, b) if p}  # the stale holder too
    moves = [(i, _carrier(unit, i, src, dst, moving, named) or src, dst) for i, src, dst in moves]
    said |= {src[1] for _, src, _ in moves if src}
    between = None if moves else _between(unit)
    changed: list[ObjectNode] = []
    into = None
    if between:  # two containers of one label: `pour lettuce from the bowl (...) into the bowl (...)`
        what, src, dst = between
        text = (f"{unit.motion.label} " + ", ".join(_unplaced(i) for i in what)
                + f" from the {src.describe()} into the {dst.describe()}")
        said = {src.label} | {i.label for i in what}
    elif moves:
        parts: list[tuple[list[tuple[str, str, bool]], str]] = []  # (what moves from where, into what): `_listed`
        for i, src, dst in moves:
            where = before.get(dst[1])
            source = f" from the {_source(unit, i, src[1], where)}" if src else ""
            one = _one_source(unit, src)
            to = f"{_INTO.get(dst[0], dst[0])} the {where.describe() if where else dst[1]}"
            if parts and parts[-1][1] == to:
                parts[-1][0].append((_unplaced(i), source, one))
            else:
                parts.append(([(_unplaced(i), source, one)], to))
        text = f"{unit.motion.label} " + "; ".join(f"{_listed(what)} {to}" for what, to in parts)
    else:
        changed, into = _changed(unit, new, by_label, named)
        said = {i.label for i in changed} | ({into.label} if into is not None else set())
    holders = {i.label for i, _, _ in moves} | said
    rest = [i for i in unit.inputs if i.label not in said and not (_holders(i, named) & holders)]
    places = [i for i in rest if any(i.label in _holders(n, named) for n in unit.inputs)]
    used = [i for i in rest if i not in places and _worked_in(unit, i, new)]
    tools = [i for i in rest if i not in places and i not in used]
    if not moves and not between:  # a place said once: `cut lime (whole), with the knife, on the cutting board`
        at = {p.label for p in places}
        text = f"{unit.motion.label} " + ", ".join(_unplaced(i) if (_place(i, named) or ("", ""))[1] in at
                                                   else i.describe() for i in changed)
        if into is not None:  # by the word of what is made there: `crack egg ... onto the pizza dough`
            word = next((_INTO.get(p[0], p[0]) for o in new.values()
                         if o.label not in by_label and (p := _place(o, named)) and p[1] == into.label), "into")
            text += f" {word} the {into.describe()}"
    if used:  # `spread toast, using up the butter (softened), with the knife`: the butter is no tool
        text += ", using up the " + ", ".join(i.describe() for i in used)
    if tools:
        text += ", with the " + ", ".join(t.describe() for t in tools)
    for word, group in _by_word(_ordered_places(places, changed or [i for i, _, _ in moves], named), unit, named):
        text += f", {word} the " + ", ".join(_without_contents(p, holders) for p in group)
    made = [o for label, o in sorted(new.items()) if label not in by_label]
    if made:
        text += ", making " + ", ".join(_unplaced(o) + (f" {p[0]} the {p[1]}" if (p := _place(o, named)) else "")
                                        for o in made)
    return text


def _worked_in(unit: FunctionalUnit, node: ObjectNode, new: dict[str, ObjectNode]) -> bool:
    """Whether the step uses `node` up into what it changes: no output keeps its label, and a state an output
    gains begins with it (`butter (softened)` spread on `toast (buttered)`). A tool FOON's unit leaves out of
    its outputs (the public data often does: `knife (clean)`) names no new state, so it stays a tool."""
    if any(o.label == node.label for o in unit.outputs):
        return False
    gained = {s.label for o in new.values() for s in o.states} - {s.label for i in unit.inputs for s in i.states}
    return any(word.startswith(node.label) for state in gained for word in (state, *state.split()))


def _by_word(places: list[ObjectNode], unit: FunctionalUnit, named: Aliases) -> list[tuple[str, list[ObjectNode]]]:
    """The places in runs of one word (`on`, `in`, ...: how the unit's nodes stand in or on each), in order."""
    runs: list[tuple[str, list[ObjectNode]]] = []
    for p in places:
        word = next((w for n in unit.inputs if (w := _place(n, named)) and w[1] == p.label), ("on", ""))[0]
        word = _AT.get(word, word)
        if runs and runs[-1][0] == word and not any(p.label in _holders(q, named) for q in runs[-1][1]):
            runs[-1][1].append(p)
        else:
            runs.append((word, [p]))
    return runs
