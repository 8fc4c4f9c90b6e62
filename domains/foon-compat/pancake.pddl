; foon2pddl, encoding foon-compat, level 3: 16 of 101 units after relevance pruning
; goal: pancake (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain universal_foon-3ac230d8)
  (:requirements :strips :typing)
  (:types
    object_node - object
  )
  (:constants
    baking_powder_in_mixing_bowl - object_node
    baking_powder_powder - object_node
    butter_in_frying_pan_melted - object_node
    butter_in_frying_pan_solid - object_node
    butter_solid - object_node
    egg_cracked_in_mixing_bowl - object_node
    egg_whole - object_node
    flour_in_mixing_bowl - object_node
    flour_powder - object_node
    frying_pan_contains_butter_on_stove - object_node
    frying_pan_contains_butter_pancake_batter_on_stove - object_node
    frying_pan_contains_pancake_on_stove - object_node
    frying_pan_empty - object_node
    frying_pan_empty_on_stove - object_node
    heavy_cream_in_carton - object_node
    heavy_cream_in_mixing_bowl - object_node
    ladle - object_node
    maple_syrup_in_bottle - object_node
    maple_syrup_on_pancake - object_node
    milk_in_carton - object_node
    milk_in_mixing_bowl - object_node
    mixing_bowl_contains_baking_powder_egg_flour_milk_salt_sugar - object_node
    mixing_bowl_contains_baking_powder_egg_flour_salt_sugar - object_node
    mixing_bowl_contains_baking_powder_flour_salt_sugar - object_node
    mixing_bowl_contains_flour - object_node
    mixing_bowl_contains_heavy_cream - object_node
    mixing_bowl_contains_heavy_cream_sugar - object_node
    mixing_bowl_contains_pancake_batter - object_node
    mixing_bowl_empty - object_node
    pancake_cooked_in_frying_pan - object_node
    pancake_cooked_on_plate - object_node
    pancake_cooked_on_plate_topped_maple_syrup - object_node
    pancake_half-cooked_in_frying_pan - object_node
    pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_frying_pan - object_node
    pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_mixing_bowl - object_node
    plate_contains_maple_syrup_pancake - object_node
    plate_contains_pancake - object_node
    plate_empty - object_node
    salt_granulated - object_node
    salt_in_mixing_bowl - object_node
    spatula - object_node
    stove_off - object_node
    stove_on - object_node
    sugar_granulated - object_node
    sugar_in_mixing_bowl - object_node
    whisk - object_node
  )
  (:predicates
    (is_available ?obj - object_node)  ; the object node is available
  )

  (:action functional_unit_9
    ; unit 9: pour from 02-whipped_cream.foon:3, 09-fruit_salad.foon:164
    ; pour: mixing bowl (empty), heavy cream (in [carton]) -> mixing bowl (contains {heavy cream}), heavy cream (in [mixing bowl])
    :parameters ()
    :precondition (and
      (is_available heavy_cream_in_carton)
      (is_available mixing_bowl_empty)
    )
    :effect (and
      (is_available heavy_cream_in_mixing_bowl)
      (is_available mixing_bowl_contains_heavy_cream)
    )
  )

  (:action functional_unit_10
    ; unit 10: pour from 02-whipped_cream.foon:13, 09-fruit_salad.foon:174
    ; pour: mixing bowl (contains {heavy cream}), sugar (granulated) -> mixing bowl (contains {heavy cream, sugar}), sugar (in [mixing bowl])
    :parameters ()
    :precondition (and
      (is_available mixing_bowl_contains_heavy_cream)
      (is_available sugar_granulated)
    )
    :effect (and
      (is_available mixing_bowl_contains_heavy_cream_sugar)
      (is_available sugar_in_mixing_bowl)
    )
  )

  (:action functional_unit_22
    ; unit 22: pick-and-place from 03-scrambled_eggs.foon:71, 04-pancakes.foon:76, 05-french_toast.foon:83
    ; pick-and-place: frying pan (empty), stove (off) -> frying pan (empty, on [stove])
    :parameters ()
    :precondition (and
      (is_available frying_pan_empty)
      (is_available stove_off)
    )
    :effect (and
      (is_available frying_pan_empty_on_stove)
    )
  )

  (:action functional_unit_23
    ; unit 23: turn on from 03-scrambled_eggs.foon:80, 04-pancakes.foon:85, 05-french_toast.foon:92, ... (1 more)
    ; turn on: stove (off) -> stove (on)
    :parameters ()
    :precondition (and
      (is_available stove_off)
    )
    :effect (and
      (is_available stove_on)
    )
  )

  (:action functional_unit_24
    ; unit 24: pick-and-place from 03-scrambled_eggs.foon:86, 04-pancakes.foon:91, 05-french_toast.foon:98
    ; pick-and-place: frying pan (empty, on [stove]), butter (solid) -> frying pan (contains {butter}, on [stove]), butter (in [frying pan], solid)
    :parameters ()
    :precondition (and
      (is_available butter_solid)
      (is_available frying_pan_empty_on_stove)
    )
    :effect (and
      (is_available butter_in_frying_pan_solid)
      (is_available frying_pan_contains_butter_on_stove)
    )
  )

  (:action functional_unit_25
    ; unit 25: melt from 03-scrambled_eggs.foon:99, 04-pancakes.foon:104, 05-french_toast.foon:111
    ; melt: stove (on), butter (in [frying pan], solid) -> butter (in [frying pan], melted)
    :parameters ()
    :precondition (and
      (is_available butter_in_frying_pan_solid)
      (is_available stove_on)
    )
    :effect (and
      (is_available butter_in_frying_pan_melted)
    )
  )

  (:action functional_unit_29
    ; unit 29: pour from 04-pancakes.foon:3
    ; pour: mixing bowl (empty), flour (powder) -> mixing bowl (contains {flour}), flour (in [mixing bowl])
    :parameters ()
    :precondition (and
      (is_available flour_powder)
      (is_available mixing_bowl_empty)
    )
    :effect (and
      (is_available flour_in_mixing_bowl)
      (is_available mixing_bowl_contains_flour)
    )
  )

  (:action functional_unit_30
    ; unit 30: pour* from 04-pancakes.foon:13
    ; pour: mixing bowl (contains {flour}), baking powder (powder), sugar (granulated), salt (granulated) -> mixing bowl (contains {baking powder, flour, salt, sugar}), baking powder (in [mixing bowl]), sugar (in [mixing bowl]), salt (in [mixi...
    :parameters ()
    :precondition (and
      (is_available baking_powder_powder)
      (is_available mixing_bowl_contains_flour)
      (is_available salt_granulated)
      (is_available sugar_granulated)
    )
    :effect (and
      (is_available baking_powder_in_mixing_bowl)
      (is_available mixing_bowl_contains_baking_powder_flour_salt_sugar)
      (is_available salt_in_mixing_bowl)
      (is_available sugar_in_mixing_bowl)
    )
  )

  (:action functional_unit_31
    ; unit 31: crack from 04-pancakes.foon:31
    ; crack: mixing bowl (contains {baking powder, flour, salt, sugar}), egg (whole) -> mixing bowl (contains {baking powder, egg, flour, salt, sugar}), egg (cracked, in [mixing bowl])
    :parameters ()
    :precondition (and
      (is_available egg_whole)
      (is_available mixing_bowl_contains_baking_powder_flour_salt_sugar)
    )
    :effect (and
      (is_available egg_cracked_in_mixing_bowl)
      (is_available mixing_bowl_contains_baking_powder_egg_flour_salt_sugar)
    )
  )

  (:action functional_unit_32
    ; unit 32: pour from 04-pancakes.foon:42
    ; pour: mixing bowl (contains {baking powder, egg, flour, salt, sugar}), milk (in [carton]) -> mixing bowl (contains {baking powder, egg, flour, milk, salt, sugar}), milk (in [mixing bowl])
    :parameters ()
    :precondition (and
      (is_available milk_in_carton)
      (is_available mixing_bowl_contains_baking_powder_egg_flour_salt_sugar)
    )
    :effect (and
      (is_available milk_in_mixing_bowl)
      (is_available mixing_bowl_contains_baking_powder_egg_flour_milk_salt_sugar)
    )
  )

  (:action functional_unit_33
    ; unit 33: whisk from 04-pancakes.foon:52
    ; whisk: mixing bowl (contains {baking powder, egg, flour, milk, salt, sugar}), flour (in [mixing bowl]), baking powder (in [mixing bowl]), sugar (in [mixing bowl]), salt (in [mixing bowl]), egg (cracked, in [mixing bowl]), milk (in [mixin...
    :parameters ()
    :precondition (and
      (is_available baking_powder_in_mixing_bowl)
      (is_available egg_cracked_in_mixing_bowl)
      (is_available flour_in_mixing_bowl)
      (is_available milk_in_mixing_bowl)
      (is_available mixing_bowl_contains_baking_powder_egg_flour_milk_salt_sugar)
      (is_available salt_in_mixing_bowl)
      (is_available sugar_in_mixing_bowl)
      (is_available whisk)
    )
    :effect (and
      (is_available mixing_bowl_contains_pancake_batter)
      (is_available pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_mixing_bowl)
      (is_available whisk)
    )
  )

  (:action functional_unit_34
    ; unit 34: pour from 04-pancakes.foon:114
    ; pour: mixing bowl (contains {pancake batter}), pancake batter (contains {baking powder, egg, flour, milk, salt, sugar}, in [mixing bowl]), ladle, frying pan (contains {butter}, on [stove]), butter (in [frying pan], melted) -> frying pan ...
    :parameters ()
    :precondition (and
      (is_available butter_in_frying_pan_melted)
      (is_available frying_pan_contains_butter_on_stove)
      (is_available ladle)
      (is_available mixing_bowl_contains_pancake_batter)
      (is_available pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_mixing_bowl)
    )
    :effect (and
      (is_available frying_pan_contains_butter_pancake_batter_on_stove)
      (is_available ladle)
      (is_available pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_frying_pan)
    )
  )

  (:action functional_unit_35
    ; unit 35: cook from 04-pancakes.foon:135
    ; cook: stove (on), frying pan (contains {butter, pancake batter}, on [stove]), pancake batter (contains {baking powder, egg, flour, milk, salt, sugar}, in [frying pan]) -> frying pan (contains {pancake}, on [stove]), pancake (half-cooked,...
    :parameters ()
    :precondition (and
      (is_available frying_pan_contains_butter_pancake_batter_on_stove)
      (is_available pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_frying_pan)
      (is_available stove_on)
    )
    :effect (and
      (is_available frying_pan_contains_pancake_on_stove)
      (is_available pancake_half-cooked_in_frying_pan)
    )
  )

  (:action functional_unit_36
    ; unit 36: flip from 04-pancakes.foon:151
    ; flip: pancake (half-cooked, in [frying pan]), spatula -> pancake (cooked, in [frying pan]), spatula
    :parameters ()
    :precondition (and
      (is_available pancake_half-cooked_in_frying_pan)
      (is_available spatula)
    )
    :effect (and
      (is_available pancake_cooked_in_frying_pan)
      (is_available spatula)
    )
  )

  (:action functional_unit_37
    ; unit 37: pick-and-place from 04-pancakes.foon:161
    ; pick-and-place: frying pan (contains {pancake}, on [stove]), pancake (cooked, in [frying pan]), spatula, plate (empty) -> plate (contains {pancake}), pancake (cooked, on [plate]), spatula
    :parameters ()
    :precondition (and
      (is_available frying_pan_contains_pancake_on_stove)
      (is_available pancake_cooked_in_frying_pan)
      (is_available plate_empty)
      (is_available spatula)
    )
    :effect (and
      (is_available pancake_cooked_on_plate)
      (is_available plate_contains_pancake)
      (is_available spatula)
    )
  )

  (:action functional_unit_38
    ; unit 38: pour from 04-pancakes.foon:178
    ; pour: plate (contains {pancake}), pancake (cooked, on [plate]), maple syrup (in [bottle]) -> plate (contains {maple syrup, pancake}), pancake (cooked, on [plate], topped {maple syrup}), maple syrup (on [pancake])
    :parameters ()
    :precondition (and
      (is_available maple_syrup_in_bottle)
      (is_available pancake_cooked_on_plate)
      (is_available plate_contains_pancake)
    )
    :effect (and
      (is_available maple_syrup_on_pancake)
      (is_available pancake_cooked_on_plate_topped_maple_syrup)
      (is_available plate_contains_maple_syrup_pancake)
    )
  )
)
