"""How the category index was bootstrapped from WordNet hypernyms (once; the shipped file was then corrected
by hand). To extend an index to new labels use `foon2pddl categories --extend` (`extend.py`).

Each category below names WordNet "anchor" synsets; an object label joins every
category one of whose anchors is among the hypernyms of one of its kitchen
senses (`senses.resolve`, head-noun fallback included). The output is a draft:
WordNet puts the banana plant among herbs and a spoon among containers, and
knows nothing of `X mixture`, so the shipped `generalize/data/categories.json`
is this draft corrected by hand (and later refined: coarse categories split).
"""

from __future__ import annotations

#: (name, parent, description, anchor synsets), in the index's order (parents first).
SPEC: tuple[tuple[str, str | None, str, tuple[str, ...]], ...] = (
    # produce
    ("fruits", None, "edible fruits", ("edible_fruit.n.01",)),
    ("citrus fruits", "fruits", "lemons, limes, oranges", ("citrus.n.01", "citrus.n.02")),
    ("berries", "fruits", "small pulpy fruits", ("berry.n.01",)),
    ("melons", "fruits", "gourd-family fruits", ("melon.n.01",)),
    ("tropical fruits", "fruits", "mango, pineapple, banana, avocado", ()),
    ("pome and stone fruits", "fruits", "apples, pears, cherries, olives", ("apple.n.01", "drupe.n.01")),
    ("vegetables", None, "edible plants and their parts", ("vegetable.n.01",)),
    ("leafy vegetables", "vegetables", "salad leaves and greens", ("greens.n.01", "salad_green.n.01")),
    ("root vegetables", "vegetables", "roots and tubers", ("root_vegetable.n.01",)),
    ("alliums", "vegetables", "onions, garlic, chives", ("onion.n.03", "alliaceous_plant.n.01", "garlic.n.02")),
    ("peppers", "vegetables", "sweet and hot capsicum fruits", ("pepper.n.04", "capsicum.n.01")),
    ("legumes", "vegetables", "beans, peas, lentils", ("legume.n.03", "bean.n.01", "legume.n.01")),
    ("brassicas", "vegetables", "cabbage family", ("cruciferous_vegetable.n.01",)),
    ("mushrooms", "vegetables", "edible fungi", ("mushroom.n.05",)),
    ("fruit vegetables", "vegetables", "tomatoes, cucumbers, squash, corn", ("solanaceous_vegetable.n.01",)),
    # seasoning
    ("seasonings", None, "added for flavour", ("flavorer.n.01",)),
    ("herbs", "seasonings", "fresh or dried culinary herbs", ("herb.n.02",)),
    ("spices", "seasonings", "ground or whole spices", ("spice.n.02",)),
    ("salts", "seasonings", "table, sea and flavoured salts", ("salt.n.02",)),
    ("seasoning blends", "seasonings", "mixed seasonings", ()),
    ("extracts and zests", "seasonings", "vanilla and lemon extract, citrus zest", ("peel.n.02",)),
    ("condiments", None, "table condiments", ("condiment.n.01",)),
    ("sauces", None, "savoury and sweet sauces", ("sauce.n.01",)),
    ("dressings", "sauces", "salad dressings", ("dressing.n.01",)),
    ("spreads", None, "butters and spreads for bread", ("spread.n.05",)),
    # animal products
    ("dairy", None, "milk products", ("dairy_product.n.01", "milk.n.01")),
    ("cheeses", "dairy", "cheeses", ("cheese.n.01",)),
    ("creams", "dairy", "creams", ("cream.n.02",)),
    ("eggs", None, "eggs and their parts", ("egg.n.02",)),
    ("meats", None, "meat", ("meat.n.01",)),
    ("poultry", "meats", "chicken, turkey", ("poultry.n.02",)),
    ("beef and pork", "meats", "beef and pork cuts", ("beef.n.02", "pork.n.01")),
    ("ground meats", "meats", "minced meat", ("hamburger.n.01",)),
    ("sausages and cured meats", "meats", "bacon, ham, sausages", ("sausage.n.01", "bacon.n.01", "ham.n.01")),
    ("seafood", None, "fish and shellfish", ("seafood.n.01", "fish.n.02")),
    # staples
    ("grains", None, "rice and cereal grains", ("grain.n.02", "rice.n.01")),
    ("flours and starches", None, "flour, meal, starch", ("flour.n.01", "meal.n.03", "starch.n.01")),
    ("leavening agents", None, "baking powder, baking soda, yeast", ("leaven.n.01",)),
    ("pasta and noodles", None, "dried and fresh pasta", ("pasta.n.02", "noodle.n.01")),
    ("breads", None, "breads and flatbreads", ("bread.n.01",)),
    ("nuts and seeds", None, "edible nuts and seeds", ("edible_nut.n.01", "edible_seed.n.01")),
    ("fats and oils", None, "cooking fats", ("fat.n.01",)),
    ("cooking oils", "fats and oils", "vegetable oils", ("vegetable_oil.n.01",)),
    ("sweeteners", None, "sugars and syrups", ("sweetening.n.01",)),
    ("sugars", "sweeteners", "granulated sugars", ("sugar.n.01",)),
    ("syrups", "sweeteners", "syrups and honey", ("syrup.n.01",)),
    ("chocolate and cocoa", None, "chocolate and cocoa products", ("chocolate.n.02", "cocoa.n.01")),
    ("confectionery", None, "candy and sweets", ("candy.n.01",)),
    # drinks and liquids
    ("beverages", None, "drinks", ("beverage.n.01",)),
    ("juices", "beverages", "fruit and vegetable juices", ("juice.n.01",)),
    ("coffee and tea", "beverages", "coffee and tea", ("coffee.n.01", "tea.n.01")),
    ("alcoholic drinks", "beverages", "wine, beer, spirits, cocktails", ("alcohol.n.01",)),
    ("water and ice", None, "water and ice", ("water.n.06", "ice.n.01")),
    ("stocks and broths", None, "stocks and broths", ("broth.n.01",)),
    # prepared foods
    ("soups", None, "soups", ("soup.n.01",)),
    ("salads", None, "salads", ("salad.n.01",)),
    ("sandwiches", None, "sandwiches and wraps", ("sandwich.n.01",)),
    ("doughs and batters", None, "uncooked doughs and batters", ("dough.n.01", "batter.n.02")),
    ("mixtures", None, "intermediate mixtures of ingredients", ("concoction.n.01", "mix.n.01")),
    ("baked goods", None, "baked sweets and pastries", ("baked_goods.n.01",)),
    ("cakes and muffins", "baked goods", "cakes, muffins, brownies", ("cake.n.03", "muffin.n.01")),
    ("cookies", "baked goods", "cookies and biscuits", ("cookie.n.01",)),
    ("desserts", None, "desserts", ("dessert.n.01",)),
    ("puddings and custards", "desserts", "puddings and custards", ("pudding.n.01", "pudding.n.03", "custard.n.01")),
    ("prepared dishes", None, "cooked dishes", ("dish.n.02",)),
    ("egg dishes", "prepared dishes", "omelettes, frittatas, scrambled eggs", ("omelet.n.01", "scrambled_eggs.n.01")),
    ("pizzas", "prepared dishes", "pizzas", ("pizza.n.01",)),
    ("dumplings", "prepared dishes", "dumplings", ("dumpling.n.01",)),
    ("fried potatoes", "prepared dishes", "fries and hash browns", ("french_fries.n.01", "home_fries.n.01")),
    # equipment
    ("containers", None, "anything that holds food", ("container.n.01",)),
    ("open containers", "containers", "vessels open at the top", ()),
    ("bowls", "open containers", "bowls", ("bowl.n.01", "bowl.n.03")),
    ("plates and trays", "open containers", "plates, dishes and trays", ("plate.n.04", "dish.n.01", "tray.n.01")),
    ("drinking vessels", "open containers", "cups, mugs, glasses", ("drinking_vessel.n.01", "glass.n.02", "cup.n.01")),
    ("measuring cups", "open containers", "measuring cups", ("measuring_cup.n.01",)),
    ("storage containers", "containers", "closable containers: bottles, jars, boxes, bags", (
        "bottle.n.01", "jar.n.01", "box.n.01", "bag.n.01", "carton.n.02", "can.n.01", "packet.n.01")),
    ("pitchers and jugs", "containers", "pouring vessels", ("pitcher.n.02", "jug.n.01", "teapot.n.01")),
    ("cookware", None, "pots and pans", ("cooking_utensil.n.01",)),
    ("pots", "cookware", "pots, saucepans, kettles", ("pot.n.01", "saucepan.n.01", "kettle.n.01")),
    ("pans", "cookware", "frying pans, skillets, griddles", ("pan.n.01", "frying_pan.n.01", "griddle.n.01")),
    ("bakeware", "cookware", "baking sheets, muffin and pizza pans", ("cookie_sheet.n.01",)),
    ("cutlery", None, "knives, forks, spoons for the table", ("cutlery.n.02",)),
    ("spoons", "cutlery", "spoons", ("spoon.n.01",)),
    ("forks and chopsticks", "cutlery", "forks and chopsticks", ("fork.n.01", "chopstick.n.01")),
    ("cutting tools", None, "knives, scissors, cutters, peelers", ("knife.n.01", "scissors.n.01", "cutter.n.06")),
    ("kitchen utensils", None, "hand tools for preparing food", ("kitchen_utensil.n.01",)),
    ("mixing tools", "kitchen utensils", "whisks and beaters", ("whisk.n.01", "beater.n.02")),
    ("spatulas and turners", "kitchen utensils", "spatulas, turners, scrapers", ("spatula.n.01", "spatula.n.02",
                                                                                "turner.n.08")),
    ("serving utensils", "kitchen utensils", "ladles, tongs, scoops", ("ladle.n.01", "tongs.n.01", "scoop.n.06")),
    ("strainers", "kitchen utensils", "strainers and colanders", ("strainer.n.01",)),
    ("pressing and grating tools", "kitchen utensils", "graters, mashers, presses, mills, juicers", (
        "grater.n.01", "masher.n.02", "mill.n.04", "pestle.n.03")),
    ("kitchen appliances", None, "powered kitchen appliances", ("kitchen_appliance.n.01", "home_appliance.n.01")),
    ("heating appliances", "kitchen appliances", "stoves, ovens, microwaves, toasters, grills", (
        "stove.n.01", "oven.n.01", "microwave.n.02", "toaster.n.02", "grill.n.02")),
    ("blending appliances", "kitchen appliances", "blenders, mixers, food processors", (
        "blender.n.01", "mixer.n.04", "food_processor.n.01")),
    ("refrigerators", "kitchen appliances", "fridges", ("refrigerator.n.01",)),
    ("appliance parts", None, "jars, bowls and lids of appliances", ()),
    ("lids and covers", None, "lids and covers", ("lid.n.02",)),
    ("wraps and liners", None, "foil, plastic wrap, parchment paper", ("foil.n.01", "wrapping.n.01", "paper.n.01")),
    ("cutting boards", None, "cutting boards", ("chopping_board.n.01",)),
    ("kitchen fixtures", None, "sinks, faucets, tables, bins", ("faucet.n.01", "sink.n.01", "table.n.02",
                                                                 "ashcan.n.01")),
)


def bootstrap(labels: list[str]) -> dict:
    """The draft index: {"categories": {name: {"parent", "description", "members"}}}."""
    from .similarity import LabelSimilarity

    sim = LabelSimilarity()
    wn = sim.reader
    anchors: dict[str, list[str]] = {}
    for name, _, _, names in SPEC:
        for a in names:
            wn.synset(a)  # fails loudly on a misspelt anchor
            anchors.setdefault(a, []).append(name)
    members: dict[str, set[str]] = {name: set() for name, *_ in SPEC}
    for label in labels:
        for sense in sim.resolution(label).senses:
            s = wn.synset(sense)
            for h in [s, *s.closure(lambda x: x.hypernyms() + x.instance_hypernyms())]:
                for cat in anchors.get(h.name(), ()):
                    members[cat].add(label)
    return {"categories": {name: {"parent": parent, "description": desc, "members": sorted(members[name])}
                           for name, parent, desc, _ in SPEC}}
