; foon2pddl, encoding ocp, level 3: 92 of 101 units after relevance pruning
; goal: scrambled eggs (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain foon-ocp-0f102b38)
  (:requirements :strips)
  (:constants
    air
    avocado
    baking_powder
    banana
    basil
    black_olive
    black_pepper
    bottle
    bowl
    bread
    butter
    carton
    cilantro
    cinnamon
    cucumber
    custard
    cutting_board
    egg
    egg_mixture
    electric_mixer
    feta_cheese
    flour
    fork
    french_toast
    fruit_salad
    frying_pan
    greek_salad
    guacamole
    heavy_cream
    honey
    immersion_blender
    jar
    juicer
    knife
    ladle
    lime
    lime_juice
    maple_syrup
    milk
    mixing_bowl
    olive_oil
    onion
    oregano
    pancake
    pancake_batter
    plate
    pot
    red_wine_vinegar
    salad_tongs
    salt
    scrambled_eggs
    spatula
    spoon
    stove
    strawberry
    sugar
    table
    tomato
    tomato_soup
    vanilla_extract
    vegetable_broth
    whipped_cream
    whisk
    wooden_spoon
  )
  (:predicates
    (in ?h ?x)  ; in ?h is ?x (?x is in ?h; air: ?h is empty)
    (on ?h ?x)  ; on ?h is ?x (?x is on ?h)
    (under ?x ?h)  ; under ?x is ?h (?x is on or in ?h)
    (is-chopped ?o)  ; ?o is chopped
    (is-ground ?o)  ; ?o is ground
    (is-sliced ?o)  ; ?o is sliced
    (is-whole ?o)  ; ?o is whole
  )

  (:action pour_heavy_cream_9
    ; unit 9: pour from 02-whipped_cream.foon:3, 09-fruit_salad.foon:164
    ; pour: mixing bowl (empty), heavy cream (in [carton]) -> mixing bowl (contains {heavy cream}), heavy cream (in [mixing bowl])
    :parameters ()
    :precondition (and
      (in mixing_bowl air)
      (under mixing_bowl table)
      (on table mixing_bowl)
      (in carton heavy_cream)
      (under heavy_cream carton)
    )
    :effect (and
      (in mixing_bowl heavy_cream)
      (under heavy_cream mixing_bowl)
      (in carton heavy_cream)
      (under mixing_bowl table)
      (on table mixing_bowl)
      (not (in mixing_bowl air))
    )
  )

  (:action pour_sugar_10
    ; unit 10: pour from 02-whipped_cream.foon:13, 09-fruit_salad.foon:174
    ; pour: mixing bowl (contains {heavy cream}), sugar (granulated) -> mixing bowl (contains {heavy cream, sugar}), sugar (in [mixing bowl])
    :parameters ()
    :precondition (and
      (under mixing_bowl table)
      (on table mixing_bowl)
      (under sugar table)
      (on table sugar)
    )
    :effect (and
      (in mixing_bowl sugar)
      (under sugar mixing_bowl)
      (under mixing_bowl table)
      (on table mixing_bowl)
    )
  )

  (:action attach_11
    ; unit 11: attach from 02-whipped_cream.foon:23
    ; attach: mixing bowl (contains {heavy cream, sugar}), electric mixer (off) -> mixing bowl (attached to [electric mixer], contains {heavy cream, sugar}), electric mixer (off, with [mixing bowl])
    :parameters ()
    :precondition (and
      (under mixing_bowl table)
      (on table mixing_bowl)
      (under electric_mixer table)
      (on table electric_mixer)
    )
    :effect (and
      (under mixing_bowl table)
      (on table mixing_bowl)
      (under electric_mixer table)
      (on table electric_mixer)
    )
  )

  (:action turn_on_12
    ; unit 12: turn on from 02-whipped_cream.foon:35
    ; turn on: electric mixer (off, with [mixing bowl]) -> electric mixer (on, with [mixing bowl])
    :parameters ()
    :precondition (and
      (under electric_mixer table)
      (on table electric_mixer)
    )
    :effect (and
      (under electric_mixer table)
      (on table electric_mixer)
    )
  )

  (:action mix_ingredients_13
    ; unit 13: mix from 02-whipped_cream.foon:43
    ; mix: electric mixer (on, with [mixing bowl]), mixing bowl (attached to [electric mixer], contains {heavy cream, sugar}), heavy cream (in [mixing bowl]), sugar (in [mixing bowl]) -> electric mixer (on, with [mixing bowl]), mixing bowl (at...
    :parameters ()
    :precondition (and
      (under electric_mixer table)
      (on table electric_mixer)
      (under mixing_bowl table)
      (on table mixing_bowl)
      (in mixing_bowl heavy_cream)
      (under heavy_cream mixing_bowl)
      (in mixing_bowl sugar)
      (under sugar mixing_bowl)
    )
    :effect (and
      (in mixing_bowl whipped_cream)
      (under whipped_cream mixing_bowl)
      (under heavy_cream mixing_bowl)
      (under sugar mixing_bowl)
      (under electric_mixer table)
      (on table electric_mixer)
      (under mixing_bowl table)
      (on table mixing_bowl)
    )
  )

  (:action turn_off_14
    ; unit 14: turn off from 02-whipped_cream.foon:64
    ; turn off: electric mixer (on, with [mixing bowl]) -> electric mixer (off, with [mixing bowl])
    :parameters ()
    :precondition (and
      (under electric_mixer table)
      (on table electric_mixer)
    )
    :effect (and
      (under electric_mixer table)
      (on table electric_mixer)
    )
  )

  (:action detach_15
    ; unit 15: detach from 02-whipped_cream.foon:72
    ; detach: electric mixer (off, with [mixing bowl]), mixing bowl (attached to [electric mixer], contains {whipped cream}) -> electric mixer (off), mixing bowl (contains {whipped cream})
    :parameters ()
    :precondition (and
      (under electric_mixer table)
      (on table electric_mixer)
      (under mixing_bowl table)
      (on table mixing_bowl)
    )
    :effect (and
      (under electric_mixer table)
      (on table electric_mixer)
      (under mixing_bowl table)
      (on table mixing_bowl)
    )
  )

  (:action scoop_bowl_16
    ; unit 16: scoop from 02-whipped_cream.foon:84
    ; scoop: mixing bowl (contains {whipped cream}), whipped cream (in [mixing bowl], whipped), spatula, bowl (empty) -> bowl (contains {whipped cream}), whipped cream (in [bowl], whipped), spatula
    :parameters ()
    :precondition (and
      (under mixing_bowl table)
      (on table mixing_bowl)
      (in mixing_bowl whipped_cream)
      (under whipped_cream mixing_bowl)
      (under spatula table)
      (on table spatula)
      (in bowl air)
      (under bowl table)
      (on table bowl)
    )
    :effect (and
      (in bowl whipped_cream)
      (under whipped_cream bowl)
      (under mixing_bowl table)
      (on table mixing_bowl)
      (in mixing_bowl whipped_cream)
      (under spatula table)
      (on table spatula)
      (under bowl table)
      (on table bowl)
      (not (in bowl air))
    )
  )

  (:action crack_17
    ; unit 17: crack from 03-scrambled_eggs.foon:3, 05-french_toast.foon:3
    ; crack: bowl (empty), egg (whole) -> bowl (contains {egg}), egg (cracked, in [bowl])
    :parameters ()
    :precondition (and
      (in bowl air)
      (under bowl table)
      (on table bowl)
      (is-whole egg)
      (under egg table)
      (on table egg)
    )
    :effect (and
      (in bowl egg)
      (under egg bowl)
      (is-whole egg)
      (under bowl table)
      (on table bowl)
      (not (in bowl air))
    )
  )

  (:action beat_18
    ; unit 18: beat from 03-scrambled_eggs.foon:14
    ; beat: egg (cracked, in [bowl]), whisk -> egg (beaten, in [bowl]), whisk
    :parameters ()
    :precondition (and
      (in bowl egg)
      (under egg bowl)
      (under whisk table)
      (on table whisk)
    )
    :effect (and
      (in bowl egg)
      (under egg bowl)
      (under whisk table)
      (on table whisk)
    )
  )

  (:action pour_milk_19
    ; unit 19: pour from 03-scrambled_eggs.foon:24, 05-french_toast.foon:24
    ; pour: bowl (contains {egg}), egg (beaten, in [bowl]), milk (in [carton]) -> bowl (contains {egg, milk}), milk (in [bowl])
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (in bowl egg)
      (under egg bowl)
      (in carton milk)
      (under milk carton)
    )
    :effect (and
      (in bowl milk)
      (under milk bowl)
      (under egg bowl)
      (in carton milk)
      (under bowl table)
      (on table bowl)
    )
  )

  (:action sprinkle_salt_20
    ; unit 20: sprinkle from 03-scrambled_eggs.foon:37
    ; sprinkle: bowl (contains {egg, milk}), salt (granulated), black pepper (ground) -> bowl (contains {black pepper, egg, milk, salt}), salt (in [bowl]), black pepper (in [bowl])
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (under salt table)
      (on table salt)
      (is-ground black_pepper)
      (under black_pepper table)
      (on table black_pepper)
    )
    :effect (and
      (in bowl salt)
      (under salt bowl)
      (in bowl black_pepper)
      (under black_pepper bowl)
      (is-ground black_pepper)
      (under bowl table)
      (on table bowl)
    )
  )

  (:action mix_ingredients_21
    ; unit 21: mix from 03-scrambled_eggs.foon:51
    ; mix: bowl (contains {black pepper, egg, milk, salt}), egg (beaten, in [bowl]), milk (in [bowl]), salt (in [bowl]), black pepper (in [bowl]), whisk -> bowl (contains {egg mixture}), egg mixture (contains {black pepper, egg, milk, salt}, i...
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (in bowl egg)
      (under egg bowl)
      (in bowl milk)
      (under milk bowl)
      (in bowl salt)
      (under salt bowl)
      (in bowl black_pepper)
      (under black_pepper bowl)
      (under whisk table)
      (on table whisk)
    )
    :effect (and
      (in bowl egg_mixture)
      (under egg_mixture bowl)
      (under egg bowl)
      (under milk bowl)
      (under salt bowl)
      (under black_pepper bowl)
      (under bowl table)
      (on table bowl)
      (under whisk table)
      (on table whisk)
    )
  )

  (:action pick-and-place_frying_pan_22
    ; unit 22: pick-and-place from 03-scrambled_eggs.foon:71, 04-pancakes.foon:76, 05-french_toast.foon:83
    ; pick-and-place: frying pan (empty), stove (off) -> frying pan (empty, on [stove])
    :parameters ()
    :precondition (and
      (in frying_pan air)
      (under frying_pan table)
      (on table frying_pan)
      (under stove table)
      (on table stove)
    )
    :effect (and
      (on stove frying_pan)
      (under frying_pan stove)
      (on table frying_pan)
      (under stove table)
      (on table stove)
      (in frying_pan air)
    )
  )

  (:action turn_on_23
    ; unit 23: turn on from 03-scrambled_eggs.foon:80, 04-pancakes.foon:85, 05-french_toast.foon:92, +1 more
    ; turn on: stove (off) -> stove (on)
    :parameters ()
    :precondition (and
      (under stove table)
      (on table stove)
    )
    :effect (and
      (under stove table)
      (on table stove)
    )
  )

  (:action pick-and-place_butter_24
    ; unit 24: pick-and-place from 03-scrambled_eggs.foon:86, 04-pancakes.foon:91, 05-french_toast.foon:98
    ; pick-and-place: frying pan (empty, on [stove]), butter (solid) -> frying pan (contains {butter}, on [stove]), butter (in [frying pan], solid)
    :parameters ()
    :precondition (and
      (in frying_pan air)
      (on stove frying_pan)
      (under frying_pan stove)
      (under butter table)
      (on table butter)
    )
    :effect (and
      (in frying_pan butter)
      (under butter frying_pan)
      (on table butter)
      (on stove frying_pan)
      (under frying_pan stove)
      (not (in frying_pan air))
    )
  )

  (:action melt_25
    ; unit 25: melt from 03-scrambled_eggs.foon:99, 04-pancakes.foon:104, 05-french_toast.foon:111
    ; melt: stove (on), butter (in [frying pan], solid) -> butter (in [frying pan], melted)
    :parameters ()
    :precondition (and
      (under stove table)
      (on table stove)
      (in frying_pan butter)
      (under butter frying_pan)
    )
    :effect (and
      (under stove table)
      (on table stove)
      (in frying_pan butter)
      (under butter frying_pan)
    )
  )

  (:action pour_26
    ; unit 26: pour from 03-scrambled_eggs.foon:109
    ; pour: bowl (contains {egg mixture}), egg mixture (contains {black pepper, egg, milk, salt}, in [bowl]), frying pan (contains {butter}, on [stove]), butter (in [frying pan], melted) -> frying pan (contains {butter, egg mixture}, on [stove...
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (in bowl egg_mixture)
      (under egg_mixture bowl)
      (on stove frying_pan)
      (under frying_pan stove)
      (in frying_pan butter)
      (under butter frying_pan)
    )
    :effect (and
      (in frying_pan egg_mixture)
      (under egg_mixture frying_pan)
      (under bowl table)
      (on table bowl)
      (in bowl egg_mixture)
      (under butter frying_pan)
      (on stove frying_pan)
      (under frying_pan stove)
    )
  )

  (:action stir_ingredients_27
    ; unit 27: stir from 03-scrambled_eggs.foon:128
    ; stir: stove (on), frying pan (contains {butter, egg mixture}, on [stove]), egg mixture (contains {black pepper, egg, milk, salt}, in [frying pan]), spatula -> frying pan (contains {scrambled eggs}, on [stove]), scrambled eggs (cooked, in...
    :parameters ()
    :precondition (and
      (under stove table)
      (on table stove)
      (on stove frying_pan)
      (under frying_pan stove)
      (in frying_pan egg_mixture)
      (under egg_mixture frying_pan)
      (under spatula table)
      (on table spatula)
    )
    :effect (and
      (in frying_pan scrambled_eggs)
      (under scrambled_eggs frying_pan)
      (under stove table)
      (under egg_mixture frying_pan)
      (on stove frying_pan)
      (under frying_pan stove)
      (under spatula table)
      (on table spatula)
    )
  )

  (:action scoop_plate_28
    ; unit 28: scoop from 03-scrambled_eggs.foon:146
    ; scoop: frying pan (contains {scrambled eggs}, on [stove]), scrambled eggs (cooked, in [frying pan]), spatula, plate (empty) -> plate (contains {scrambled eggs}), scrambled eggs (cooked, on [plate]), spatula
    :parameters ()
    :precondition (and
      (on stove frying_pan)
      (under frying_pan stove)
      (in frying_pan scrambled_eggs)
      (under scrambled_eggs frying_pan)
      (under spatula table)
      (on table spatula)
      (on plate air)
      (under plate table)
      (on table plate)
    )
    :effect (and
      (on plate scrambled_eggs)
      (under scrambled_eggs plate)
      (on stove frying_pan)
      (under frying_pan stove)
      (in frying_pan scrambled_eggs)
      (under spatula table)
      (on table spatula)
      (under plate table)
      (on table plate)
      (not (on plate air))
    )
  )

  (:action pour_flour_29
    ; unit 29: pour from 04-pancakes.foon:3
    ; pour: mixing bowl (empty), flour (powder) -> mixing bowl (contains {flour}), flour (in [mixing bowl])
    :parameters ()
    :precondition (and
      (in mixing_bowl air)
      (under mixing_bowl table)
      (on table mixing_bowl)
      (under flour table)
      (on table flour)
    )
    :effect (and
      (in mixing_bowl flour)
      (under flour mixing_bowl)
      (under mixing_bowl table)
      (on table mixing_bowl)
      (not (in mixing_bowl air))
    )
  )

  (:action pour_baking_powder_30
    ; unit 30: pour* from 04-pancakes.foon:13
    ; pour: mixing bowl (contains {flour}), baking powder (powder), sugar (granulated), salt (granulated) -> mixing bowl (contains {baking powder, flour, salt, sugar}), baking powder (in [mixing bowl]), sugar (in [mixing bowl]), salt (in [mixi...
    :parameters ()
    :precondition (and
      (under mixing_bowl table)
      (on table mixing_bowl)
      (under baking_powder table)
      (on table baking_powder)
      (under sugar table)
      (on table sugar)
      (under salt table)
      (on table salt)
    )
    :effect (and
      (in mixing_bowl baking_powder)
      (under baking_powder mixing_bowl)
      (in mixing_bowl sugar)
      (under sugar mixing_bowl)
      (in mixing_bowl salt)
      (under salt mixing_bowl)
      (under mixing_bowl table)
      (on table mixing_bowl)
    )
  )

  (:action crack_31
    ; unit 31: crack from 04-pancakes.foon:31
    ; crack: mixing bowl (contains {baking powder, flour, salt, sugar}), egg (whole) -> mixing bowl (contains {baking powder, egg, flour, salt, sugar}), egg (cracked, in [mixing bowl])
    :parameters ()
    :precondition (and
      (under mixing_bowl table)
      (on table mixing_bowl)
      (is-whole egg)
      (under egg table)
      (on table egg)
    )
    :effect (and
      (in mixing_bowl egg)
      (under egg mixing_bowl)
      (is-whole egg)
      (under mixing_bowl table)
      (on table mixing_bowl)
    )
  )

  (:action pour_milk_32
    ; unit 32: pour from 04-pancakes.foon:42
    ; pour: mixing bowl (contains {baking powder, egg, flour, salt, sugar}), milk (in [carton]) -> mixing bowl (contains {baking powder, egg, flour, milk, salt, sugar}), milk (in [mixing bowl])
    :parameters ()
    :precondition (and
      (under mixing_bowl table)
      (on table mixing_bowl)
      (in carton milk)
      (under milk carton)
    )
    :effect (and
      (in mixing_bowl milk)
      (under milk mixing_bowl)
      (in carton milk)
      (under mixing_bowl table)
      (on table mixing_bowl)
    )
  )

  (:action whisk_33
    ; unit 33: whisk from 04-pancakes.foon:52
    ; whisk: mixing bowl (contains {baking powder, egg, flour, milk, salt, sugar}), flour (in [mixing bowl]), baking powder (in [mixing bowl]), sugar (in [mixing bowl]), salt (in [mixing bowl]), egg (cracked, in [mixing bowl]), milk (in [mixin...
    :parameters ()
    :precondition (and
      (under mixing_bowl table)
      (on table mixing_bowl)
      (in mixing_bowl flour)
      (under flour mixing_bowl)
      (in mixing_bowl baking_powder)
      (under baking_powder mixing_bowl)
      (in mixing_bowl sugar)
      (under sugar mixing_bowl)
      (in mixing_bowl salt)
      (under salt mixing_bowl)
      (in mixing_bowl egg)
      (under egg mixing_bowl)
      (in mixing_bowl milk)
      (under milk mixing_bowl)
      (under whisk table)
      (on table whisk)
    )
    :effect (and
      (in mixing_bowl pancake_batter)
      (under pancake_batter mixing_bowl)
      (under flour mixing_bowl)
      (under baking_powder mixing_bowl)
      (under sugar mixing_bowl)
      (under salt mixing_bowl)
      (under egg mixing_bowl)
      (under milk mixing_bowl)
      (under mixing_bowl table)
      (on table mixing_bowl)
      (under whisk table)
      (on table whisk)
    )
  )

  (:action pour_ladle_34
    ; unit 34: pour from 04-pancakes.foon:114
    ; pour: mixing bowl (contains {pancake batter}), pancake batter (contains {baking powder, egg, flour, milk, salt, sugar}, in [mixing bowl]), ladle, frying pan (contains {butter}, on [stove]), butter (in [frying pan], melted) -> frying pan ...
    :parameters ()
    :precondition (and
      (under mixing_bowl table)
      (on table mixing_bowl)
      (in mixing_bowl pancake_batter)
      (under pancake_batter mixing_bowl)
      (under ladle table)
      (on table ladle)
      (on stove frying_pan)
      (under frying_pan stove)
      (in frying_pan butter)
      (under butter frying_pan)
    )
    :effect (and
      (in frying_pan pancake_batter)
      (under pancake_batter frying_pan)
      (under mixing_bowl table)
      (in mixing_bowl pancake_batter)
      (under butter frying_pan)
      (on stove frying_pan)
      (under frying_pan stove)
      (under ladle table)
      (on table ladle)
    )
  )

  (:action cook_35
    ; unit 35: cook from 04-pancakes.foon:135
    ; cook: stove (on), frying pan (contains {butter, pancake batter}, on [stove]), pancake batter (contains {baking powder, egg, flour, milk, salt, sugar}, in [frying pan]) -> frying pan (contains {pancake}, on [stove]), pancake (half-cooked,...
    :parameters ()
    :precondition (and
      (under stove table)
      (on table stove)
      (on stove frying_pan)
      (under frying_pan stove)
      (in frying_pan pancake_batter)
      (under pancake_batter frying_pan)
    )
    :effect (and
      (in frying_pan pancake)
      (under pancake frying_pan)
      (under stove table)
      (on table stove)
      (under pancake_batter frying_pan)
      (on stove frying_pan)
      (under frying_pan stove)
    )
  )

  (:action flip_36
    ; unit 36: flip from 04-pancakes.foon:151
    ; flip: pancake (half-cooked, in [frying pan]), spatula -> pancake (cooked, in [frying pan]), spatula
    :parameters ()
    :precondition (and
      (in frying_pan pancake)
      (under pancake frying_pan)
      (under spatula table)
      (on table spatula)
    )
    :effect (and
      (in frying_pan pancake)
      (under pancake frying_pan)
      (under spatula table)
      (on table spatula)
    )
  )

  (:action pick-and-place_pancake_37
    ; unit 37: pick-and-place from 04-pancakes.foon:161
    ; pick-and-place: frying pan (contains {pancake}, on [stove]), pancake (cooked, in [frying pan]), spatula, plate (empty) -> plate (contains {pancake}), pancake (cooked, on [plate]), spatula
    :parameters ()
    :precondition (and
      (on stove frying_pan)
      (under frying_pan stove)
      (in frying_pan pancake)
      (under pancake frying_pan)
      (under spatula table)
      (on table spatula)
      (on plate air)
      (under plate table)
      (on table plate)
    )
    :effect (and
      (on plate pancake)
      (under pancake plate)
      (on stove frying_pan)
      (under frying_pan stove)
      (in frying_pan pancake)
      (under plate table)
      (on table plate)
      (under spatula table)
      (on table spatula)
      (not (on plate air))
    )
  )

  (:action pour_maple_syrup_38
    ; unit 38: pour from 04-pancakes.foon:178
    ; pour: plate (contains {pancake}), pancake (cooked, on [plate]), maple syrup (in [bottle]) -> plate (contains {maple syrup, pancake}), pancake (cooked, on [plate], topped {maple syrup}), maple syrup (on [pancake])
    :parameters ()
    :precondition (and
      (under plate table)
      (on table plate)
      (on plate pancake)
      (under pancake plate)
      (in bottle maple_syrup)
      (under maple_syrup bottle)
    )
    :effect (and
      (on pancake maple_syrup)
      (under maple_syrup pancake)
      (in bottle maple_syrup)
      (under plate table)
      (on table plate)
      (on plate pancake)
      (under pancake plate)
    )
  )

  (:action beat_39
    ; unit 39: beat from 05-french_toast.foon:14
    ; beat: egg (cracked, in [bowl]), fork -> egg (beaten, in [bowl]), fork
    :parameters ()
    :precondition (and
      (in bowl egg)
      (under egg bowl)
      (under fork table)
      (on table fork)
    )
    :effect (and
      (in bowl egg)
      (under egg bowl)
      (under fork table)
      (on table fork)
    )
  )

  (:action pour_cinnamon_40
    ; unit 40: pour* from 05-french_toast.foon:37
    ; pour: bowl (contains {egg, milk}), cinnamon (ground), vanilla extract (liquid) -> bowl (contains {cinnamon, egg, milk, vanilla extract}), cinnamon (in [bowl]), vanilla extract (in [bowl])
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (is-ground cinnamon)
      (under cinnamon table)
      (on table cinnamon)
      (under vanilla_extract table)
      (on table vanilla_extract)
    )
    :effect (and
      (in bowl cinnamon)
      (under cinnamon bowl)
      (in bowl vanilla_extract)
      (under vanilla_extract bowl)
      (is-ground cinnamon)
      (under bowl table)
      (on table bowl)
    )
  )

  (:action mix_ingredients_41
    ; unit 41: mix from 05-french_toast.foon:51
    ; mix: bowl (contains {cinnamon, egg, milk, vanilla extract}), egg (beaten, in [bowl]), milk (in [bowl]), cinnamon (in [bowl]), vanilla extract (in [bowl]), fork -> bowl (contains {custard}), custard (contains {cinnamon, egg, milk, vanilla...
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (in bowl egg)
      (under egg bowl)
      (in bowl milk)
      (under milk bowl)
      (in bowl cinnamon)
      (under cinnamon bowl)
      (in bowl vanilla_extract)
      (under vanilla_extract bowl)
      (under fork table)
      (on table fork)
    )
    :effect (and
      (in bowl custard)
      (under custard bowl)
      (under egg bowl)
      (under milk bowl)
      (under cinnamon bowl)
      (under vanilla_extract bowl)
      (under bowl table)
      (on table bowl)
      (under fork table)
      (on table fork)
    )
  )

  (:action dip_42
    ; unit 42: dip from 05-french_toast.foon:71
    ; dip: bowl (contains {custard}), custard (contains {cinnamon, egg, milk, vanilla extract}, in [bowl]), bread (sliced) -> bread (sliced, soaked {custard})
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (in bowl custard)
      (under custard bowl)
      (is-sliced bread)
      (under bread table)
      (on table bread)
    )
    :effect (and
      (under bowl table)
      (in bowl custard)
      (under custard bowl)
      (is-sliced bread)
      (under bread table)
      (on table bread)
    )
  )

  (:action pick-and-place_43
    ; unit 43: pick-and-place from 05-french_toast.foon:121
    ; pick-and-place: frying pan (contains {butter}, on [stove]), butter (in [frying pan], melted), bread (sliced, soaked {custard}) -> frying pan (contains {bread, butter}, on [stove]), bread (in [frying pan], sliced, soaked {custard})
    :parameters ()
    :precondition (and
      (on stove frying_pan)
      (under frying_pan stove)
      (in frying_pan butter)
      (under butter frying_pan)
      (is-sliced bread)
      (under bread table)
      (on table bread)
    )
    :effect (and
      (in frying_pan bread)
      (under bread frying_pan)
      (under butter frying_pan)
      (on table bread)
      (on stove frying_pan)
      (under frying_pan stove)
      (is-sliced bread)
    )
  )

  (:action fry_44
    ; unit 44: fry from 05-french_toast.foon:139
    ; fry: stove (on), frying pan (contains {bread, butter}, on [stove]), bread (in [frying pan], sliced, soaked {custard}), spatula -> frying pan (contains {french toast}, on [stove]), french toast (cooked, in [frying pan]), spatula
    :parameters ()
    :precondition (and
      (under stove table)
      (on table stove)
      (on stove frying_pan)
      (under frying_pan stove)
      (in frying_pan bread)
      (under bread frying_pan)
      (is-sliced bread)
      (under spatula table)
      (on table spatula)
    )
    :effect (and
      (in frying_pan french_toast)
      (under french_toast frying_pan)
      (under stove table)
      (under bread frying_pan)
      (is-sliced bread)
      (on stove frying_pan)
      (under frying_pan stove)
      (under spatula table)
      (on table spatula)
    )
  )

  (:action pick-and-place_french_toast_45
    ; unit 45: pick-and-place from 05-french_toast.foon:158
    ; pick-and-place: frying pan (contains {french toast}, on [stove]), french toast (cooked, in [frying pan]), spatula, plate (empty) -> plate (contains {french toast}), french toast (cooked, on [plate]), spatula
    :parameters ()
    :precondition (and
      (on stove frying_pan)
      (under frying_pan stove)
      (in frying_pan french_toast)
      (under french_toast frying_pan)
      (under spatula table)
      (on table spatula)
      (on plate air)
      (under plate table)
      (on table plate)
    )
    :effect (and
      (on plate french_toast)
      (under french_toast plate)
      (on stove frying_pan)
      (under frying_pan stove)
      (in frying_pan french_toast)
      (under plate table)
      (on table plate)
      (under spatula table)
      (on table spatula)
      (not (on plate air))
    )
  )

  (:action pour_maple_syrup_46
    ; unit 46: pour from 05-french_toast.foon:175
    ; pour: plate (contains {french toast}), french toast (cooked, on [plate]), maple syrup (in [bottle]) -> plate (contains {french toast, maple syrup}), french toast (cooked, on [plate], topped {maple syrup}), maple syrup (on [french toast])
    :parameters ()
    :precondition (and
      (under plate table)
      (on table plate)
      (on plate french_toast)
      (under french_toast plate)
      (in bottle maple_syrup)
      (under maple_syrup bottle)
    )
    :effect (and
      (on french_toast maple_syrup)
      (under maple_syrup french_toast)
      (in bottle maple_syrup)
      (under plate table)
      (on table plate)
      (on plate french_toast)
      (under french_toast plate)
    )
  )

  (:action pick-and-place_onion_47
    ; unit 47: pick-and-place from 06-tomato_soup.foon:3, 07-guacamole.foon:105, 08-greek_salad.foon:53
    ; pick-and-place: cutting board (empty), onion (whole) -> cutting board (contains {onion}), onion (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (on cutting_board air)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole onion)
      (under onion table)
      (on table onion)
    )
    :effect (and
      (on cutting_board onion)
      (under onion cutting_board)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole onion)
      (not (on cutting_board air))
    )
  )

  (:action peel_48
    ; unit 48: peel from 06-tomato_soup.foon:14, 07-guacamole.foon:116, 08-greek_salad.foon:64
    ; peel: cutting board (contains {onion}), onion (on [cutting board], whole), knife -> cutting board (contains {onion}), onion (on [cutting board], peeled), knife
    :parameters ()
    :precondition (and
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board onion)
      (under onion cutting_board)
      (is-whole onion)
      (under knife table)
      (on table knife)
    )
    :effect (and
      (is-whole onion)
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board onion)
      (under onion cutting_board)
      (under knife table)
      (on table knife)
    )
  )

  (:action chop_onion_49
    ; unit 49: chop from 06-tomato_soup.foon:28, 07-guacamole.foon:130
    ; chop: cutting board (contains {onion}), onion (on [cutting board], peeled), knife -> cutting board (contains {onion}), onion (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board onion)
      (under onion cutting_board)
      (under knife table)
      (on table knife)
    )
    :effect (and
      (is-chopped onion)
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board onion)
      (under onion cutting_board)
      (under knife table)
      (on table knife)
    )
  )

  (:action pick-and-place_tomato_50
    ; unit 50: pick-and-place from 06-tomato_soup.foon:42, 07-guacamole.foon:156, 08-greek_salad.foon:28
    ; pick-and-place: cutting board (empty), tomato (whole) -> cutting board (contains {tomato}), tomato (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (on cutting_board air)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole tomato)
      (under tomato table)
      (on table tomato)
    )
    :effect (and
      (on cutting_board tomato)
      (under tomato cutting_board)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole tomato)
      (not (on cutting_board air))
    )
  )

  (:action chop_tomato_51
    ; unit 51: chop from 06-tomato_soup.foon:53, 07-guacamole.foon:167, 08-greek_salad.foon:39
    ; chop: cutting board (contains {tomato}), tomato (on [cutting board], whole), knife -> cutting board (contains {tomato}), tomato (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board tomato)
      (under tomato cutting_board)
      (is-whole tomato)
      (under knife table)
      (on table knife)
    )
    :effect (and
      (is-chopped tomato)
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board tomato)
      (under tomato cutting_board)
      (under knife table)
      (on table knife)
      (not (is-whole tomato))
    )
  )

  (:action pick-and-place_pot_52
    ; unit 52: pick-and-place from 06-tomato_soup.foon:67
    ; pick-and-place: pot (empty), stove (off) -> pot (empty, on [stove])
    :parameters ()
    :precondition (and
      (in pot air)
      (under pot table)
      (on table pot)
      (under stove table)
      (on table stove)
    )
    :effect (and
      (on stove pot)
      (under pot stove)
      (on table pot)
      (under stove table)
      (on table stove)
      (in pot air)
    )
  )

  (:action pour_olive_oil_53
    ; unit 53: pour from 06-tomato_soup.foon:82
    ; pour: pot (empty, on [stove]), olive oil (in [bottle]) -> pot (contains {olive oil}, on [stove]), olive oil (in [pot])
    :parameters ()
    :precondition (and
      (in pot air)
      (on stove pot)
      (under pot stove)
      (in bottle olive_oil)
      (under olive_oil bottle)
    )
    :effect (and
      (in pot olive_oil)
      (under olive_oil pot)
      (in bottle olive_oil)
      (on stove pot)
      (under pot stove)
      (not (in pot air))
    )
  )

  (:action pick-and-place_onion_54
    ; unit 54: pick-and-place from 06-tomato_soup.foon:94
    ; pick-and-place: pot (contains {olive oil}, on [stove]), onion (chopped, on [cutting board]) -> pot (contains {olive oil, onion}, on [stove]), onion (chopped, in [pot])
    :parameters ()
    :precondition (and
      (on stove pot)
      (under pot stove)
      (is-chopped onion)
      (on cutting_board onion)
      (under onion cutting_board)
    )
    :effect (and
      (in pot onion)
      (under onion pot)
      (on cutting_board onion)
      (on stove pot)
      (under pot stove)
      (is-chopped onion)
    )
  )

  (:action saute_55
    ; unit 55: saute from 06-tomato_soup.foon:108
    ; saute: stove (on), olive oil (in [pot]), onion (chopped, in [pot]), wooden spoon -> onion (in [pot], sauteed), wooden spoon
    :parameters ()
    :precondition (and
      (under stove table)
      (on table stove)
      (in pot olive_oil)
      (under olive_oil pot)
      (is-chopped onion)
      (in pot onion)
      (under onion pot)
      (under wooden_spoon table)
      (on table wooden_spoon)
    )
    :effect (and
      (under stove table)
      (under olive_oil pot)
      (is-chopped onion)
      (in pot onion)
      (under onion pot)
      (under wooden_spoon table)
      (on table wooden_spoon)
    )
  )

  (:action pick-and-place_tomato_56
    ; unit 56: pick-and-place from 06-tomato_soup.foon:122
    ; pick-and-place: pot (contains {olive oil, onion}, on [stove]), onion (in [pot], sauteed), tomato (chopped, on [cutting board]) -> pot (contains {olive oil, onion, tomato}, on [stove]), tomato (chopped, in [pot])
    :parameters ()
    :precondition (and
      (on stove pot)
      (under pot stove)
      (in pot onion)
      (under onion pot)
      (is-chopped tomato)
      (on cutting_board tomato)
      (under tomato cutting_board)
    )
    :effect (and
      (in pot tomato)
      (under tomato pot)
      (under onion pot)
      (on cutting_board tomato)
      (on stove pot)
      (under pot stove)
      (is-chopped tomato)
    )
  )

  (:action pour_vegetable_broth_57
    ; unit 57: pour from 06-tomato_soup.foon:139
    ; pour: pot (contains {olive oil, onion, tomato}, on [stove]), vegetable broth (in [carton]) -> pot (contains {olive oil, onion, tomato, vegetable broth}, on [stove]), vegetable broth (in [pot])
    :parameters ()
    :precondition (and
      (on stove pot)
      (under pot stove)
      (in carton vegetable_broth)
      (under vegetable_broth carton)
    )
    :effect (and
      (in pot vegetable_broth)
      (under vegetable_broth pot)
      (in carton vegetable_broth)
      (on stove pot)
      (under pot stove)
    )
  )

  (:action simmer_58
    ; unit 58: simmer from 06-tomato_soup.foon:151
    ; simmer: stove (on), pot (contains {olive oil, onion, tomato, vegetable broth}, on [stove]), olive oil (in [pot]), onion (in [pot], sauteed), tomato (chopped, in [pot]), vegetable broth (in [pot]) -> pot (contains {tomato soup}, on [stove...
    :parameters ()
    :precondition (and
      (under stove table)
      (on table stove)
      (on stove pot)
      (under pot stove)
      (in pot olive_oil)
      (under olive_oil pot)
      (in pot onion)
      (under onion pot)
      (is-chopped tomato)
      (in pot tomato)
      (under tomato pot)
      (in pot vegetable_broth)
      (under vegetable_broth pot)
    )
    :effect (and
      (in pot tomato_soup)
      (under tomato_soup pot)
      (under stove table)
      (on table stove)
      (under olive_oil pot)
      (under onion pot)
      (is-chopped tomato)
      (under tomato pot)
      (under vegetable_broth pot)
      (on stove pot)
      (under pot stove)
    )
  )

  (:action turn_on_59
    ; unit 59: turn on from 06-tomato_soup.foon:174
    ; turn on: immersion blender (off) -> immersion blender (on)
    :parameters ()
    :precondition (and
      (under immersion_blender table)
      (on table immersion_blender)
    )
    :effect (and
      (under immersion_blender table)
      (on table immersion_blender)
    )
  )

  (:action blend_60
    ; unit 60: blend from 06-tomato_soup.foon:180
    ; blend: immersion blender (on), pot (contains {tomato soup}, on [stove]), tomato soup (chunky, in [pot]) -> tomato soup (in [pot], pureed), immersion blender (on)
    :parameters ()
    :precondition (and
      (under immersion_blender table)
      (on table immersion_blender)
      (on stove pot)
      (under pot stove)
      (in pot tomato_soup)
      (under tomato_soup pot)
    )
    :effect (and
      (on stove pot)
      (under pot stove)
      (in pot tomato_soup)
      (under tomato_soup pot)
      (under immersion_blender table)
      (on table immersion_blender)
    )
  )

  (:action scoop_bowl_61
    ; unit 61: scoop from 06-tomato_soup.foon:195
    ; scoop: pot (contains {tomato soup}, on [stove]), tomato soup (in [pot], pureed), ladle, bowl (empty) -> bowl (contains {tomato soup}), tomato soup (in [bowl], pureed), ladle
    :parameters ()
    :precondition (and
      (on stove pot)
      (under pot stove)
      (in pot tomato_soup)
      (under tomato_soup pot)
      (under ladle table)
      (on table ladle)
      (in bowl air)
      (under bowl table)
      (on table bowl)
    )
    :effect (and
      (in bowl tomato_soup)
      (under tomato_soup bowl)
      (on stove pot)
      (under pot stove)
      (in pot tomato_soup)
      (under ladle table)
      (on table ladle)
      (under bowl table)
      (on table bowl)
      (not (in bowl air))
    )
  )

  (:action sprinkle_basil_62
    ; unit 62: sprinkle from 06-tomato_soup.foon:212
    ; sprinkle: bowl (contains {tomato soup}), tomato soup (in [bowl], pureed), basil (fresh) -> bowl (contains {basil, tomato soup}), tomato soup (garnished {basil}, in [bowl], pureed), basil (on [tomato soup])
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (in bowl tomato_soup)
      (under tomato_soup bowl)
      (under basil table)
      (on table basil)
    )
    :effect (and
      (on tomato_soup basil)
      (under basil tomato_soup)
      (under bowl table)
      (on table bowl)
      (in bowl tomato_soup)
      (under tomato_soup bowl)
    )
  )

  (:action pick-and-place_avocado_63
    ; unit 63: pick-and-place from 07-guacamole.foon:3
    ; pick-and-place: cutting board (empty), avocado (whole) -> cutting board (contains {avocado}), avocado (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (on cutting_board air)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole avocado)
      (under avocado table)
      (on table avocado)
    )
    :effect (and
      (on cutting_board avocado)
      (under avocado cutting_board)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole avocado)
      (not (on cutting_board air))
    )
  )

  (:action cut_avocado_64
    ; unit 64: cut from 07-guacamole.foon:14
    ; cut: cutting board (contains {avocado}), avocado (on [cutting board], whole), knife -> cutting board (contains {avocado}), avocado (halved, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board avocado)
      (under avocado cutting_board)
      (is-whole avocado)
      (under knife table)
      (on table knife)
    )
    :effect (and
      (is-whole avocado)
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board avocado)
      (under avocado cutting_board)
      (under knife table)
      (on table knife)
    )
  )

  (:action scoop_avocado_65
    ; unit 65: scoop from 07-guacamole.foon:28
    ; scoop: avocado (halved, on [cutting board]), spoon, bowl (empty) -> bowl (contains {avocado}), avocado (in [bowl], scooped), spoon
    :parameters ()
    :precondition (and
      (on cutting_board avocado)
      (under avocado cutting_board)
      (under spoon table)
      (on table spoon)
      (in bowl air)
      (under bowl table)
      (on table bowl)
    )
    :effect (and
      (in bowl avocado)
      (under avocado bowl)
      (on cutting_board avocado)
      (under spoon table)
      (on table spoon)
      (under bowl table)
      (on table bowl)
      (not (in bowl air))
    )
  )

  (:action mash_66
    ; unit 66: mash from 07-guacamole.foon:42
    ; mash: avocado (in [bowl], scooped), fork -> avocado (in [bowl], mashed), fork
    :parameters ()
    :precondition (and
      (in bowl avocado)
      (under avocado bowl)
      (under fork table)
      (on table fork)
    )
    :effect (and
      (in bowl avocado)
      (under avocado bowl)
      (under fork table)
      (on table fork)
    )
  )

  (:action pick-and-place_lime_67
    ; unit 67: pick-and-place from 07-guacamole.foon:52, 09-fruit_salad.foon:83
    ; pick-and-place: cutting board (empty), lime (whole) -> cutting board (contains {lime}), lime (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (on cutting_board air)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole lime)
      (under lime table)
      (on table lime)
    )
    :effect (and
      (on cutting_board lime)
      (under lime cutting_board)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole lime)
      (not (on cutting_board air))
    )
  )

  (:action cut_lime_68
    ; unit 68: cut from 07-guacamole.foon:63, 09-fruit_salad.foon:94
    ; cut: cutting board (contains {lime}), lime (on [cutting board], whole), knife -> cutting board (contains {lime}), lime (halved, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board lime)
      (under lime cutting_board)
      (is-whole lime)
      (under knife table)
      (on table knife)
    )
    :effect (and
      (is-whole lime)
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board lime)
      (under lime cutting_board)
      (under knife table)
      (on table knife)
    )
  )

  (:action squeeze_69
    ; unit 69: squeeze from 07-guacamole.foon:77, 09-fruit_salad.foon:108
    ; squeeze: lime (halved, on [cutting board]), juicer (empty) -> lime (squeezed), juicer (contains {lime juice}), lime juice (in [juicer])
    :parameters ()
    :precondition (and
      (on cutting_board lime)
      (under lime cutting_board)
      (in juicer air)
      (under juicer table)
      (on table juicer)
    )
    :effect (and
      (under lime table)
      (on table lime)
      (in juicer lime_juice)
      (under lime_juice juicer)
      (on cutting_board lime)
      (under juicer table)
      (on table juicer)
      (not (in juicer air))
    )
  )

  (:action pour_lime_juice_70
    ; unit 70: pour from 07-guacamole.foon:90
    ; pour: juicer (contains {lime juice}), lime juice (in [juicer]), bowl (contains {avocado}), avocado (in [bowl], mashed) -> bowl (contains {avocado, lime juice}), lime juice (in [bowl])
    :parameters ()
    :precondition (and
      (under juicer table)
      (on table juicer)
      (in juicer lime_juice)
      (under lime_juice juicer)
      (under bowl table)
      (on table bowl)
      (in bowl avocado)
      (under avocado bowl)
    )
    :effect (and
      (in bowl lime_juice)
      (under lime_juice bowl)
      (under juicer table)
      (in juicer lime_juice)
      (under avocado bowl)
      (under bowl table)
      (on table bowl)
    )
  )

  (:action pick-and-place_onion_71
    ; unit 71: pick-and-place from 07-guacamole.foon:144
    ; pick-and-place: bowl (contains {avocado, lime juice}), onion (chopped, on [cutting board]) -> bowl (contains {avocado, lime juice, onion}), onion (chopped, in [bowl])
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (is-chopped onion)
      (on cutting_board onion)
      (under onion cutting_board)
    )
    :effect (and
      (in bowl onion)
      (under onion bowl)
      (on cutting_board onion)
      (under bowl table)
      (on table bowl)
      (is-chopped onion)
    )
  )

  (:action pick-and-place_tomato_72
    ; unit 72: pick-and-place from 07-guacamole.foon:181
    ; pick-and-place: bowl (contains {avocado, lime juice, onion}), tomato (chopped, on [cutting board]) -> bowl (contains {avocado, lime juice, onion, tomato}), tomato (chopped, in [bowl])
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (is-chopped tomato)
      (on cutting_board tomato)
      (under tomato cutting_board)
    )
    :effect (and
      (in bowl tomato)
      (under tomato bowl)
      (on cutting_board tomato)
      (under bowl table)
      (on table bowl)
      (is-chopped tomato)
    )
  )

  (:action pick-and-place_cilantro_73
    ; unit 73: pick-and-place from 07-guacamole.foon:193
    ; pick-and-place: cutting board (empty), cilantro (fresh) -> cutting board (contains {cilantro}), cilantro (fresh, on [cutting board])
    :parameters ()
    :precondition (and
      (on cutting_board air)
      (under cutting_board table)
      (on table cutting_board)
      (under cilantro table)
      (on table cilantro)
    )
    :effect (and
      (on cutting_board cilantro)
      (under cilantro cutting_board)
      (under cutting_board table)
      (on table cutting_board)
      (not (on cutting_board air))
    )
  )

  (:action chop_cilantro_74
    ; unit 74: chop from 07-guacamole.foon:204
    ; chop: cutting board (contains {cilantro}), cilantro (fresh, on [cutting board]), knife -> cutting board (contains {cilantro}), cilantro (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board cilantro)
      (under cilantro cutting_board)
      (under knife table)
      (on table knife)
    )
    :effect (and
      (is-chopped cilantro)
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board cilantro)
      (under cilantro cutting_board)
      (under knife table)
      (on table knife)
    )
  )

  (:action pick-and-place_cilantro_75
    ; unit 75: pick-and-place from 07-guacamole.foon:218
    ; pick-and-place: bowl (contains {avocado, lime juice, onion, tomato}), cilantro (chopped, on [cutting board]) -> bowl (contains {avocado, cilantro, lime juice, onion, tomato}), cilantro (chopped, in [bowl])
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (is-chopped cilantro)
      (on cutting_board cilantro)
      (under cilantro cutting_board)
    )
    :effect (and
      (in bowl cilantro)
      (under cilantro bowl)
      (on cutting_board cilantro)
      (under bowl table)
      (on table bowl)
      (is-chopped cilantro)
    )
  )

  (:action sprinkle_salt_76
    ; unit 76: sprinkle from 07-guacamole.foon:230
    ; sprinkle: bowl (contains {avocado, cilantro, lime juice, onion, tomato}), salt (granulated) -> bowl (contains {avocado, cilantro, lime juice, onion, salt, tomato}), salt (in [bowl])
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (under salt table)
      (on table salt)
    )
    :effect (and
      (in bowl salt)
      (under salt bowl)
      (under bowl table)
      (on table bowl)
    )
  )

  (:action mix_ingredients_77
    ; unit 77: mix from 07-guacamole.foon:240
    ; mix: bowl (contains {avocado, cilantro, lime juice, onion, salt, tomato}), avocado (in [bowl], mashed), lime juice (in [bowl]), onion (chopped, in [bowl]), tomato (chopped, in [bowl]), cilantro (chopped, in [bowl]), salt (in [bowl]), for...
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (in bowl avocado)
      (under avocado bowl)
      (in bowl lime_juice)
      (under lime_juice bowl)
      (is-chopped onion)
      (in bowl onion)
      (under onion bowl)
      (is-chopped tomato)
      (in bowl tomato)
      (under tomato bowl)
      (is-chopped cilantro)
      (in bowl cilantro)
      (under cilantro bowl)
      (in bowl salt)
      (under salt bowl)
      (under fork table)
      (on table fork)
    )
    :effect (and
      (in bowl guacamole)
      (under guacamole bowl)
      (under avocado bowl)
      (under lime_juice bowl)
      (is-chopped onion)
      (under onion bowl)
      (is-chopped tomato)
      (under tomato bowl)
      (is-chopped cilantro)
      (under cilantro bowl)
      (under salt bowl)
      (under bowl table)
      (on table bowl)
      (under fork table)
      (on table fork)
    )
  )

  (:action pick-and-place_cucumber_78
    ; unit 78: pick-and-place from 08-greek_salad.foon:3
    ; pick-and-place: cutting board (empty), cucumber (whole) -> cutting board (contains {cucumber}), cucumber (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (on cutting_board air)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole cucumber)
      (under cucumber table)
      (on table cucumber)
    )
    :effect (and
      (on cutting_board cucumber)
      (under cucumber cutting_board)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole cucumber)
      (not (on cutting_board air))
    )
  )

  (:action slice_cucumber_79
    ; unit 79: slice from 08-greek_salad.foon:14
    ; slice: cutting board (contains {cucumber}), cucumber (on [cutting board], whole), knife -> cutting board (contains {cucumber}), cucumber (on [cutting board], sliced), knife
    :parameters ()
    :precondition (and
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board cucumber)
      (under cucumber cutting_board)
      (is-whole cucumber)
      (under knife table)
      (on table knife)
    )
    :effect (and
      (is-sliced cucumber)
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board cucumber)
      (under cucumber cutting_board)
      (under knife table)
      (on table knife)
      (not (is-whole cucumber))
    )
  )

  (:action slice_onion_80
    ; unit 80: slice from 08-greek_salad.foon:78
    ; slice: cutting board (contains {onion}), onion (on [cutting board], peeled), knife -> cutting board (contains {onion}), onion (on [cutting board], sliced), knife
    :parameters ()
    :precondition (and
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board onion)
      (under onion cutting_board)
      (under knife table)
      (on table knife)
    )
    :effect (and
      (is-sliced onion)
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board onion)
      (under onion cutting_board)
      (under knife table)
      (on table knife)
    )
  )

  (:action pick-and-place_cucumber_81
    ; unit 81: pick-and-place from 08-greek_salad.foon:92
    ; pick-and-place: bowl (empty), cucumber (on [cutting board], sliced) -> bowl (contains {cucumber}), cucumber (in [bowl], sliced)
    :parameters ()
    :precondition (and
      (in bowl air)
      (under bowl table)
      (on table bowl)
      (on cutting_board cucumber)
      (under cucumber cutting_board)
      (is-sliced cucumber)
    )
    :effect (and
      (in bowl cucumber)
      (under cucumber bowl)
      (on cutting_board cucumber)
      (under bowl table)
      (on table bowl)
      (is-sliced cucumber)
      (not (in bowl air))
    )
  )

  (:action pick-and-place_tomato_82
    ; unit 82: pick-and-place from 08-greek_salad.foon:104
    ; pick-and-place: bowl (contains {cucumber}), tomato (chopped, on [cutting board]) -> bowl (contains {cucumber, tomato}), tomato (chopped, in [bowl])
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (is-chopped tomato)
      (on cutting_board tomato)
      (under tomato cutting_board)
    )
    :effect (and
      (in bowl tomato)
      (under tomato bowl)
      (on cutting_board tomato)
      (under bowl table)
      (on table bowl)
      (is-chopped tomato)
    )
  )

  (:action pick-and-place_onion_83
    ; unit 83: pick-and-place from 08-greek_salad.foon:116
    ; pick-and-place: bowl (contains {cucumber, tomato}), onion (on [cutting board], sliced) -> bowl (contains {cucumber, onion, tomato}), onion (in [bowl], sliced)
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (on cutting_board onion)
      (under onion cutting_board)
      (is-sliced onion)
    )
    :effect (and
      (in bowl onion)
      (under onion bowl)
      (on cutting_board onion)
      (under bowl table)
      (on table bowl)
      (is-sliced onion)
    )
  )

  (:action pick-and-place_black_olive_84
    ; unit 84: pick-and-place from 08-greek_salad.foon:128
    ; pick-and-place: bowl (contains {cucumber, onion, tomato}), black olive (pitted) -> bowl (contains {black olive, cucumber, onion, tomato}), black olive (in [bowl], pitted)
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (under black_olive table)
      (on table black_olive)
    )
    :effect (and
      (in bowl black_olive)
      (under black_olive bowl)
      (under bowl table)
      (on table bowl)
    )
  )

  (:action sprinkle_feta_cheese_85
    ; unit 85: sprinkle from 08-greek_salad.foon:139
    ; sprinkle: bowl (contains {black olive, cucumber, onion, tomato}), feta cheese (crumbled) -> bowl (contains {black olive, cucumber, feta cheese, onion, tomato}), feta cheese (crumbled, in [bowl])
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (under feta_cheese table)
      (on table feta_cheese)
    )
    :effect (and
      (in bowl feta_cheese)
      (under feta_cheese bowl)
      (under bowl table)
      (on table bowl)
    )
  )

  (:action pour_olive_oil_86
    ; unit 86: pour* from 08-greek_salad.foon:150
    ; pour: bowl (contains {black olive, cucumber, feta cheese, onion, tomato}), olive oil (in [bottle]), red wine vinegar (in [bottle]) -> bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, red wine vinegar, tomato}), olive...
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (in bottle olive_oil)
      (under olive_oil bottle)
      (in bottle red_wine_vinegar)
      (under red_wine_vinegar bottle)
    )
    :effect (and
      (in bowl olive_oil)
      (under olive_oil bowl)
      (in bowl red_wine_vinegar)
      (under red_wine_vinegar bowl)
      (in bottle olive_oil)
      (in bottle red_wine_vinegar)
      (under bowl table)
      (on table bowl)
    )
  )

  (:action sprinkle_oregano_87
    ; unit 87: sprinkle from 08-greek_salad.foon:164
    ; sprinkle: bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, red wine vinegar, tomato}), oregano (dried) -> bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, oregano, red wine vinegar, tomato}), ore...
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (under oregano table)
      (on table oregano)
    )
    :effect (and
      (in bowl oregano)
      (under oregano bowl)
      (under bowl table)
      (on table bowl)
    )
  )

  (:action toss_88
    ; unit 88: toss from 08-greek_salad.foon:174
    ; toss: bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, oregano, red wine vinegar, tomato}), cucumber (in [bowl], sliced), tomato (chopped, in [bowl]), onion (in [bowl], sliced), black olive (in [bowl], pitted), feta ...
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (in bowl cucumber)
      (under cucumber bowl)
      (is-sliced cucumber)
      (is-chopped tomato)
      (in bowl tomato)
      (under tomato bowl)
      (in bowl onion)
      (under onion bowl)
      (is-sliced onion)
      (in bowl black_olive)
      (under black_olive bowl)
      (in bowl feta_cheese)
      (under feta_cheese bowl)
      (in bowl olive_oil)
      (under olive_oil bowl)
      (in bowl red_wine_vinegar)
      (under red_wine_vinegar bowl)
      (in bowl oregano)
      (under oregano bowl)
      (under salad_tongs table)
      (on table salad_tongs)
    )
    :effect (and
      (in bowl greek_salad)
      (under greek_salad bowl)
      (under cucumber bowl)
      (is-sliced cucumber)
      (is-chopped tomato)
      (under tomato bowl)
      (under onion bowl)
      (is-sliced onion)
      (under black_olive bowl)
      (under feta_cheese bowl)
      (under olive_oil bowl)
      (under red_wine_vinegar bowl)
      (under oregano bowl)
      (under bowl table)
      (on table bowl)
      (under salad_tongs table)
      (on table salad_tongs)
    )
  )

  (:action pick-and-place_strawberry_89
    ; unit 89: pick-and-place from 09-fruit_salad.foon:3
    ; pick-and-place: cutting board (empty), strawberry (whole) -> cutting board (contains {strawberry}), strawberry (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (on cutting_board air)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole strawberry)
      (under strawberry table)
      (on table strawberry)
    )
    :effect (and
      (on cutting_board strawberry)
      (under strawberry cutting_board)
      (under cutting_board table)
      (on table cutting_board)
      (is-whole strawberry)
      (not (on cutting_board air))
    )
  )

  (:action slice_strawberry_90
    ; unit 90: slice from 09-fruit_salad.foon:14
    ; slice: cutting board (contains {strawberry}), strawberry (on [cutting board], whole), knife -> cutting board (contains {strawberry}), strawberry (on [cutting board], sliced), knife
    :parameters ()
    :precondition (and
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board strawberry)
      (under strawberry cutting_board)
      (is-whole strawberry)
      (under knife table)
      (on table knife)
    )
    :effect (and
      (is-sliced strawberry)
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board strawberry)
      (under strawberry cutting_board)
      (under knife table)
      (on table knife)
      (not (is-whole strawberry))
    )
  )

  (:action peel_91
    ; unit 91: peel from 09-fruit_salad.foon:28
    ; peel: banana (whole) -> banana (peeled)
    :parameters ()
    :precondition (and
      (is-whole banana)
      (under banana table)
      (on table banana)
    )
    :effect (and
      (is-whole banana)
      (under banana table)
      (on table banana)
    )
  )

  (:action pick-and-place_banana_92
    ; unit 92: pick-and-place from 09-fruit_salad.foon:34
    ; pick-and-place: cutting board (empty), banana (peeled) -> cutting board (contains {banana}), banana (on [cutting board], peeled)
    :parameters ()
    :precondition (and
      (on cutting_board air)
      (under cutting_board table)
      (on table cutting_board)
      (under banana table)
      (on table banana)
    )
    :effect (and
      (on cutting_board banana)
      (under banana cutting_board)
      (under cutting_board table)
      (on table cutting_board)
      (not (on cutting_board air))
    )
  )

  (:action slice_banana_93
    ; unit 93: slice from 09-fruit_salad.foon:45
    ; slice: cutting board (contains {banana}), banana (on [cutting board], peeled), knife -> cutting board (contains {banana}), banana (on [cutting board], sliced), knife
    :parameters ()
    :precondition (and
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board banana)
      (under banana cutting_board)
      (under knife table)
      (on table knife)
    )
    :effect (and
      (is-sliced banana)
      (under cutting_board table)
      (on table cutting_board)
      (on cutting_board banana)
      (under banana cutting_board)
      (under knife table)
      (on table knife)
    )
  )

  (:action pick-and-place_strawberry_94
    ; unit 94: pick-and-place from 09-fruit_salad.foon:59
    ; pick-and-place: bowl (empty), strawberry (on [cutting board], sliced) -> bowl (contains {strawberry}), strawberry (in [bowl], sliced)
    :parameters ()
    :precondition (and
      (in bowl air)
      (under bowl table)
      (on table bowl)
      (on cutting_board strawberry)
      (under strawberry cutting_board)
      (is-sliced strawberry)
    )
    :effect (and
      (in bowl strawberry)
      (under strawberry bowl)
      (on cutting_board strawberry)
      (under bowl table)
      (on table bowl)
      (is-sliced strawberry)
      (not (in bowl air))
    )
  )

  (:action pick-and-place_banana_95
    ; unit 95: pick-and-place from 09-fruit_salad.foon:71
    ; pick-and-place: bowl (contains {strawberry}), banana (on [cutting board], sliced) -> bowl (contains {banana, strawberry}), banana (in [bowl], sliced)
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (on cutting_board banana)
      (under banana cutting_board)
      (is-sliced banana)
    )
    :effect (and
      (in bowl banana)
      (under banana bowl)
      (on cutting_board banana)
      (under bowl table)
      (on table bowl)
      (is-sliced banana)
    )
  )

  (:action pour_lime_juice_96
    ; unit 96: pour from 09-fruit_salad.foon:121
    ; pour: juicer (contains {lime juice}), lime juice (in [juicer]), bowl (contains {banana, strawberry}) -> bowl (contains {banana, lime juice, strawberry}), lime juice (in [bowl])
    :parameters ()
    :precondition (and
      (under juicer table)
      (on table juicer)
      (in juicer lime_juice)
      (under lime_juice juicer)
      (under bowl table)
      (on table bowl)
    )
    :effect (and
      (in bowl lime_juice)
      (under lime_juice bowl)
      (under juicer table)
      (in juicer lime_juice)
      (under bowl table)
      (on table bowl)
    )
  )

  (:action pour_honey_97
    ; unit 97: pour from 09-fruit_salad.foon:133
    ; pour: bowl (contains {banana, lime juice, strawberry}), honey (in [jar]) -> bowl (contains {banana, honey, lime juice, strawberry}), honey (in [bowl])
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (in jar honey)
      (under honey jar)
    )
    :effect (and
      (in bowl honey)
      (under honey bowl)
      (in jar honey)
      (under bowl table)
      (on table bowl)
    )
  )

  (:action mix_ingredients_98
    ; unit 98: mix from 09-fruit_salad.foon:143
    ; mix: bowl (contains {banana, honey, lime juice, strawberry}), strawberry (in [bowl], sliced), banana (in [bowl], sliced), lime juice (in [bowl]), honey (in [bowl]), spoon -> bowl (contains {fruit salad}), fruit salad (contains {banana, h...
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (in bowl strawberry)
      (under strawberry bowl)
      (is-sliced strawberry)
      (in bowl banana)
      (under banana bowl)
      (is-sliced banana)
      (in bowl lime_juice)
      (under lime_juice bowl)
      (in bowl honey)
      (under honey bowl)
      (under spoon table)
      (on table spoon)
    )
    :effect (and
      (in bowl fruit_salad)
      (under fruit_salad bowl)
      (under strawberry bowl)
      (is-sliced strawberry)
      (under banana bowl)
      (is-sliced banana)
      (under lime_juice bowl)
      (under honey bowl)
      (under bowl table)
      (on table bowl)
      (under spoon table)
      (on table spoon)
    )
  )

  (:action whisk_99
    ; unit 99: whisk from 09-fruit_salad.foon:184
    ; whisk: mixing bowl (contains {heavy cream, sugar}), heavy cream (in [mixing bowl]), sugar (in [mixing bowl]), whisk -> mixing bowl (contains {whipped cream}), whipped cream (in [mixing bowl], whipped), whisk
    :parameters ()
    :precondition (and
      (under mixing_bowl table)
      (on table mixing_bowl)
      (in mixing_bowl heavy_cream)
      (under heavy_cream mixing_bowl)
      (in mixing_bowl sugar)
      (under sugar mixing_bowl)
      (under whisk table)
      (on table whisk)
    )
    :effect (and
      (in mixing_bowl whipped_cream)
      (under whipped_cream mixing_bowl)
      (under heavy_cream mixing_bowl)
      (under sugar mixing_bowl)
      (under mixing_bowl table)
      (on table mixing_bowl)
      (under whisk table)
      (on table whisk)
    )
  )

  (:action scoop_100
    ; unit 100: scoop from 09-fruit_salad.foon:199
    ; scoop: bowl (contains {fruit salad}), fruit salad (contains {banana, honey, lime juice, strawberry}, in [bowl]), mixing bowl (contains {whipped cream}), whipped cream (in [mixing bowl], whipped), spoon -> bowl (contains {fruit salad, whi...
    :parameters ()
    :precondition (and
      (under bowl table)
      (on table bowl)
      (in bowl fruit_salad)
      (under fruit_salad bowl)
      (under mixing_bowl table)
      (on table mixing_bowl)
      (in mixing_bowl whipped_cream)
      (under whipped_cream mixing_bowl)
      (under spoon table)
      (on table spoon)
    )
    :effect (and
      (on fruit_salad whipped_cream)
      (under whipped_cream fruit_salad)
      (under bowl table)
      (on table bowl)
      (under mixing_bowl table)
      (on table mixing_bowl)
      (in mixing_bowl whipped_cream)
      (under spoon table)
      (on table spoon)
      (in bowl fruit_salad)
      (under fruit_salad bowl)
    )
  )
)
