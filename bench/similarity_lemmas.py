"""Draw a batch of substitution pairs over WordNet lemmas no rule was designed on (splits `lemmas`, `lemmas2`,
`lemmas3`, `lemmas4`, `lemmas5`, `lemmas6`, `lemmas7`, `lemmas8`, `lemmas9`).

`python -m bench.similarity_lemmas [--shared DIR] [--split S] BLIND KEY` writes BLIND (the
pairs in a seeded shuffle with an empty `label` column) and KEY (each pair's split and
source), as `similarity_sample` does. The labels are WordNet 3.0 noun lemmas drawn at
random (the split's seed, `SEEDS`): `FOOD` synsets and `TOOLS` synsets under roots fixed
before the first draw (the kinds of objects FOON recipes use), each synset named by its
first lower-case lemma (`apple_pie` -> `apple pie`), skipping labels of the reference
vocabulary (the shared subgraphs and the example), of the search inputs (the `outside`
split) and of `similarity_pairs.tsv` as it was when the split was drawn (every split but
this one and the ones drawn after it) and of the earlier batches' draws: `lemmas2` skips every
label `lemmas` drew, `lemmas3` every label `lemmas` and `lemmas2` drew, `lemmas4` every label the three
earlier batches drew (and so on). From `lemmas5` on the tool roots are joined by `MORE_TOOLS`
(`tool_roots`): `lemmas4` found only 14 unused lemmas under `TOOLS`, and FOON recipes also use
containers (jars, bottles, cans, baskets, trays, drinking glasses), kitchen knives, strainers, tongs,
openers, boards, wraps, towels and the refrigerator, which `TOOLS` does not reach; the earlier
batches keep `TOOLS` alone, so they draw as they were drawn. From `lemmas6` on `KITCHEN_TOOLS` joins
them too (kitchen objects FOON uses that no earlier root reaches: shakers, mills, presses, the sink), and
`N_TOOLS_MORE` tool lemmas are drawn instead of `N_TOOLS`. From `lemmas9` on `MORE_FOOD` joins the food roots and
`KITCHEN_OBJECTS` the tool roots (`food_roots`, `tool_roots`: `lemmas8` found only 4 tool lemmas left), with
`N_FOOD_MORE` food lemmas and up to `ACCEPTED_OBJECTS` pairs. The pairs: a seeded
sample of `ACCEPTED` (`ACCEPTED_MORE` from `lemmas5` on, `ACCEPTED_KITCHEN` from `lemmas6` on) pairs among those of a drawn label with a drawn or reference label that the paper's rule or the cook mode
accepts (>= 0.89), plus `RANDOM` seeded pairs from the rest (`random`).
The sources name the modes at the commit the batch was drawn on; rerun there to reproduce it.
"""

from __future__ import annotations

import random
from pathlib import Path

from foon2pddl.generalize.cook import reference_vocabulary
from foon2pddl.generalize.expand import DEFAULT_THRESHOLD
from foon2pddl.generalize.modes import make_similarity
from foon2pddl.model.foon import normalize_label

from .harness import run_main
from .similarity import read_pairs, search_labels
from .similarity_sample import main as sample_main

N_FOOD, N_TOOLS, ACCEPTED, RANDOM = 80, 40, 170, 30
#: The batches in the order they were drawn, with their seeds (`lemmas` at 8697b53, `lemmas2` at 213d3ab,
#: `lemmas3` at f864136, `lemmas4` at 5ececf4, `lemmas5` at 7edb3f9, `lemmas6` at e121a45, `lemmas7` at a65fb7b,
#: `lemmas8` at 03d5418; `lemmas7` and `lemmas8` keep `lemmas6`'s roots and sizes: `lemmas8` found only 4 tool
#: lemmas left under them, so a later batch draws food alone unless roots are added; `lemmas9` at 0d4a503,
#: with `MORE_FOOD` and `KITCHEN_OBJECTS`).
SEEDS = {"lemmas": 42, "lemmas2": 43, "lemmas3": 44, "lemmas4": 45, "lemmas5": 46, "lemmas6": 47, "lemmas7": 48,
         "lemmas8": 49, "lemmas9": 50}
#: `lemmas5` on: more sampled pairs (each earlier batch had about 18 good pairs of 200, so wide intervals).
ACCEPTED_MORE, MORE_FROM = 270, "lemmas5"
FOOD = ("edible_fruit.n.01", "vegetable.n.01", "herb.n.02", "spice.n.02", "cheese.n.01", "meat.n.01",
        "seafood.n.01", "bread.n.01", "sauce.n.01", "condiment.n.01", "dish.n.02", "baked_goods.n.01",
        "dairy_product.n.01", "vegetable_oil.n.01", "sweetening.n.01", "edible_nut.n.01", "pasta.n.02",
        "beverage.n.01")
TOOLS = ("kitchen_utensil.n.01", "tableware.n.01", "kitchen_appliance.n.01", "cutlery.n.02")
#: Fixed before the `lemmas5` draw: roots of FOON's tools and containers that `TOOLS` does not reach,
#: each mostly kitchen objects. Left out as mostly not kitchen objects: container, vessel (baths, tanks,
#: cesspools), box, bag, receptacle, bucket, mold, edge tool and knife (chisels, planes, axes, weapons,
#: scalpels: the kitchen knives are listed one by one), home appliance and white goods (irons, washers,
#: dryers: the refrigerator and dishwasher are listed), utensil (ceramic materials), brush, rack,
#: thermometer, scale, timer, board, wrapping and foil. Crockery, glassware, kitchenware and cookware
#: are under `TOOLS` already.
MORE_TOOLS = ("jar.n.01", "bottle.n.01", "can.n.01", "basket.n.01", "tray.n.01", "glass.n.02",
              "drinking_vessel.n.01", "pitcher.n.02", "mortar.n.03", "lid.n.02", "strainer.n.01", "ladle.n.01",
              "tongs.n.01", "skewer.n.01", "peeler.n.03", "bottle_opener.n.01", "can_opener.n.01",
              "nutcracker.n.01", "pestle.n.03", "funnel.n.02", "chopping_board.n.01", "bread_knife.n.01",
              "butcher_knife.n.01", "carving_knife.n.01", "cleaver.n.01", "parer.n.02", "slicer.n.03",
              "plastic_wrap.n.01", "aluminum_foil.n.01", "paper_towel.n.01", "dishtowel.n.01", "potholder.n.01",
              "napkin.n.01", "apron.n.01", "toothpick.n.01", "refrigerator.n.01", "dishwasher.n.01")


#: Fixed before the `lemmas6` draw (`lemmas5` left 88 unused tool lemmas, many not kitchen objects: ink, pill
#: and specimen bottles, inkstands): roots of the kitchen objects FOON's labels name that no earlier root
#: reaches (shaker, sink, faucet, measuring cup, garlic press, pepper mill, scraper, dropper, carton, plastic
#: bag) and a few kindred ones, each mostly kitchen objects. Left out as mostly not kitchen objects: mill
#: (windmills, treadmills), press (bench and punch presses), scissors (pruning shears, snuffers), bag, box,
#: bucket, brush, scale and table. With them, `N_TOOLS_MORE` tool lemmas and up to `ACCEPTED_KITCHEN` pairs
#: (each earlier batch had at most about 40 good pairs: a bigger batch narrows the intervals).
KITCHEN_TOOLS = ("shaker.n.03", "sink.n.01", "faucet.n.01", "measure.n.09", "garlic_press.n.01",
                 "cheese_press.n.01", "pepper_mill.n.01", "coffee_mill.n.01", "spicemill.n.01",
                 "meat_grinder.n.01", "scraper.n.01", "dropper.n.01", "carton.n.02", "plastic_bag.n.01")
KITCHEN_FROM, N_TOOLS_MORE, ACCEPTED_KITCHEN = "lemmas6", 50, 300

#: Fixed before the `lemmas9` draw (`lemmas8` found 4 unused tool lemmas and held 13 good pairs of 189): food
#: roots `FOOD` does not reach, each mostly food a FOON recipe could use (food fish, grains, flours, breakfast
#: cereals, edible fats, flavorers such as extracts and seed spices, courses: desserts and appetizers, sweets:
#: candies, jams and jellies, chocolate, gelatin dishes, yeast, cornstarch, edible seeds, juices; unused lemmas
#: at the base, before the draw: 26, 18, 16, 4, 7, 31, 64, 82, 13, 5, 5, 1, 6, 3, overlapping; 281 in all,
#: beside 872 under `FOOD`). Left out: foodstuff (the parent of most food roots: it would swamp the pool), fat (myelin, polyunsaturated fat),
#: leavening, thickener and mix (WordNet files them under abstractions or materials), starches (paddy).
MORE_FOOD = ("fish.n.02", "grain.n.02", "flour.n.01", "breakfast_food.n.01", "edible_fat.n.01", "flavorer.n.01",
             "course.n.07", "sweet.n.03", "chocolate.n.02", "gelatin.n.02", "yeast.n.01", "cornstarch.n.01",
             "edible_seed.n.01", "juice.n.01")
#: Fixed before the `lemmas9` draw: kitchen objects the tool roots do not reach, each one synset (a root with
#: kitchen hyponyms has none left unused): the trash bin, counters and tables, racks, table linen, filters and
#: cloths, burners and grills, thermometers and timers, bins and boxes for food, cleaning things, bags for
#: groceries (42 unused lemmas at the base, none left under the earlier roots: the draw takes them all, a
#: population, not a sample). With them, `N_FOOD_MORE` food lemmas (80 before) and up to `ACCEPTED_OBJECTS`
#: accepted pairs (300 before), for more good pairs per batch. Left out as mostly not kitchen objects (counted at the base): bag (54 unused: pockets, purses, sleeping bags), box (42:
#: coffins, safes, mailboxes), brush (12: toothbrushes, paintbrushes), bucket, basin and tub (bathtubs, fonts),
#: knife and scissors (scalpels, pocketknives, pruning shears), barrel and keg (casks, powder kegs), dispenser
#: (inhalers), rack (coatracks, ski racks), table (desks, altars), thermometer (clinical and laboratory kinds),
#: timer (parking meters), scale (laboratory balances), mitten (not an oven glove).
KITCHEN_OBJECTS = ("ashcan.n.01", "countertop.n.01", "kitchen_table.n.01", "drainboard.n.01", "dish_rack.n.01",
                   "plate_rack.n.01", "toastrack.n.01", "table_linen.n.01", "tea_cozy.n.01", "coaster.n.03",
                   "drinking_straw.n.01", "coffee_filter.n.01", "filter_paper.n.01", "cheesecloth.n.01",
                   "wax_paper.n.01", "burner.n.02", "gas_ring.n.01", "barbecue.n.03", "hibachi.n.01",
                   "candy_thermometer.n.01", "meat_thermometer.n.01", "oven_thermometer.n.01", "egg_timer.n.01",
                   "wine_bucket.n.01", "flour_bin.n.01", "breadbox.n.01", "canister.n.02", "trivet.n.01",
                   "dishrag.n.01", "sponge.n.01", "bottlebrush.n.01", "scrub_brush.n.01", "dishpan.n.01",
                   "soap_dispenser.n.01", "cereal_box.n.01", "grocery_bag.n.01", "doggie_bag.n.01")
OBJECTS_FROM, N_FOOD_MORE, ACCEPTED_OBJECTS = "lemmas9", 120, 360


def _since(split: str, first: str) -> bool:
    return list(SEEDS).index(split) >= list(SEEDS).index(first)


def food_roots(split: str) -> tuple[str, ...]:
    """`FOOD`, joined by `MORE_FOOD` from `lemmas9` on (the earlier batches draw as they were drawn)."""
    return FOOD + (MORE_FOOD if _since(split, OBJECTS_FROM) else ())


def tool_roots(split: str) -> tuple[str, ...]:
    """`TOOLS`, joined by `MORE_TOOLS` from `lemmas5` on, `KITCHEN_TOOLS` from `lemmas6` on and `KITCHEN_OBJECTS`
    from `lemmas9` on (the earlier batches draw as they were drawn)."""
    return (TOOLS + (MORE_TOOLS if _since(split, MORE_FROM) else ())
            + (KITCHEN_TOOLS if _since(split, KITCHEN_FROM) else ())
            + (KITCHEN_OBJECTS if _since(split, OBJECTS_FROM) else ()))


def sizes(split: str) -> tuple[int, int, int]:
    """(food lemmas, tool lemmas, accepted pairs at most) drawn for `split`."""
    if _since(split, OBJECTS_FROM):
        return N_FOOD_MORE, N_TOOLS_MORE, ACCEPTED_OBJECTS
    if _since(split, KITCHEN_FROM):
        return N_FOOD, N_TOOLS_MORE, ACCEPTED_KITCHEN
    return N_FOOD, N_TOOLS, ACCEPTED_MORE if _since(split, MORE_FROM) else ACCEPTED


def _pool(reader, roots: tuple[str, ...]) -> list[str]:
    out: set[str] = set()
    for root in roots:
        s = reader.synset(root)
        out.update(x.name() for x in [s, *s.closure(lambda y: y.hyponyms())])
    return sorted(out)


def _name(reader, synset: str) -> str:
    lemmas = [x.name() for x in reader.synset(synset).lemmas() if x.name().islower()]
    return normalize_label(lemmas[0].replace("_", " ")) if lemmas else ""


def draws(reader, shared: Path, upto: str = "lemmas") -> dict[str, list[str]]:
    """The labels drawn for each batch from the first to `upto` (module doc), in draw order: each batch
    skips the labels every earlier batch drew, so they are drawn once each, in order."""
    splits = list(SEEDS)[:list(SEEDS).index(upto) + 1]
    base = set(reference_vocabulary()) | set(search_labels(shared))
    pairs = read_pairs()
    pools: dict[tuple[str, ...], list[str]] = {}
    out: dict[str, list[str]] = {}
    for split in splits:
        later = list(SEEDS)[list(SEEDS).index(split):]
        seen = base | {x for p in pairs if p.split not in later for x in (p.a, p.b)}  # the file as it was drawn on
        seen |= {x for labels in out.values() for x in labels}  # and every label an earlier batch drew
        rng = random.Random(SEEDS[split])
        drawn: list[str] = []
        n_food, n_tools, _ = sizes(split)
        for roots, n in ((food_roots(split), n_food), (tool_roots(split), n_tools)):
            if roots not in pools:
                pools[roots] = _pool(reader, roots)
            pool = list(pools[roots])
            rng.shuffle(pool)
            got = 0
            for synset in pool:
                label = _name(reader, synset)
                if label and label not in seen and label not in drawn:
                    drawn.append(label)
                    got += 1
                    if got == n:
                        break
        out[split] = drawn
    return out


def draw_labels(reader, shared: Path, split: str = "lemmas") -> list[str]:
    """The labels drawn for `split` (module doc), in draw order."""
    return draws(reader, shared, split)[split]


def candidates(shared: Path, split: str = "lemmas") -> list[tuple[str, str, str, str]]:
    """(label_a, label_b, split, source) of the batch `split` (module doc)."""
    paper = make_similarity("paper")
    drawn = draw_labels(paper.reader, shared, split)
    cook = make_similarity("cook", reader=paper.reader)
    others = sorted(set(reference_vocabulary()) | set(drawn))
    accepted, rest = [], []
    for a in drawn:
        for b in others:
            if b == a or (b in drawn and b < a):
                continue
            pair = tuple(sorted((a, b)))
            modes = [m for m, sim in (("paper", paper), ("cook", cook)) if sim(a, b) >= DEFAULT_THRESHOLD]
            (accepted if modes else rest).append((*pair, split, "+".join(modes) or "random"))
    rng = random.Random(SEEDS[split])
    picked = rng.sample(sorted(accepted), min(sizes(split)[2], len(accepted)))
    print(f"{len(drawn)} labels drawn; {len(accepted)} pairs accepted by either mode, {len(picked)} sampled")
    return picked + rng.sample(sorted(rest), RANDOM)


def main() -> None:
    sample_main("python -m bench.similarity_lemmas", __doc__, candidates, SEEDS)


if __name__ == "__main__":
    run_main(main)
