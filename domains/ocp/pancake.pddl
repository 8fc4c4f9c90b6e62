; foon2pddl, encoding ocp, level 3: 11 of 101 units after relevance pruning
; goal: pancake (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain foon-ocp-0f52fef6)
  (:requirements :strips)
  (:constants
    air
    baking_powder
    butter
    carton
    egg
    flour
    frying_pan
    ladle
    milk
    mixing_bowl
    pancake
    pancake_batter
    plate
    salt
    spatula
    stove
    sugar
    table
    whisk
  )
  (:predicates
    (in ?h ?x)  ; in ?h is ?x (?x is in ?h; air: ?h is empty)
    (on ?h ?x)  ; on ?h is ?x (?x is on ?h)
    (under ?x ?h)  ; under ?x is ?h (?x is on or in ?h)
    (is-whole ?o)  ; ?o is whole
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
)
