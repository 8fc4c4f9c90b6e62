; foon2pddl, encoding tree, level 3: 16 of 101 units after relevance pruning
; goal: pancake (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain foon-tree-1ea55475)
  (:requirements :strips)
  (:predicates
    (baking_powder_in_mixing_bowl)  ; baking powder (in [mixing bowl])
    (baking_powder_powder)  ; baking powder (powder)
    (butter_in_frying_pan_melted)  ; butter (in [frying pan], melted)
    (butter_in_frying_pan_solid)  ; butter (in [frying pan], solid)
    (butter_solid)  ; butter (solid)
    (egg_cracked_in_mixing_bowl)  ; egg (cracked, in [mixing bowl])
    (egg_whole)  ; egg (whole)
    (flour_in_mixing_bowl)  ; flour (in [mixing bowl])
    (flour_powder)  ; flour (powder)
    (frying_pan_contains_butter_on_stove)  ; frying pan (contains {butter}, on [stove])
    (frying_pan_contains_butter_pancake_batter_on_stove)  ; frying pan (contains {butter, pancake batter}, on [stove])
    (frying_pan_contains_pancake_on_stove)  ; frying pan (contains {pancake}, on [stove])
    (frying_pan_empty)  ; frying pan (empty)
    (frying_pan_empty_on_stove)  ; frying pan (empty, on [stove])
    (heavy_cream_in_carton)  ; heavy cream (in [carton])
    (heavy_cream_in_mixing_bowl)  ; heavy cream (in [mixing bowl])
    (ladle)  ; ladle
    (maple_syrup_in_bottle)  ; maple syrup (in [bottle])
    (maple_syrup_on_pancake)  ; maple syrup (on [pancake])
    (milk_in_carton)  ; milk (in [carton])
    (milk_in_mixing_bowl)  ; milk (in [mixing bowl])
    (mixing_bowl_contains_baking_powder_egg_flour_milk_salt_sugar)  ; mixing bowl (contains {baking powder, egg, flour, milk, salt, sugar})
    (mixing_bowl_contains_baking_powder_egg_flour_salt_sugar)  ; mixing bowl (contains {baking powder, egg, flour, salt, sugar})
    (mixing_bowl_contains_baking_powder_flour_salt_sugar)  ; mixing bowl (contains {baking powder, flour, salt, sugar})
    (mixing_bowl_contains_flour)  ; mixing bowl (contains {flour})
    (mixing_bowl_contains_heavy_cream)  ; mixing bowl (contains {heavy cream})
    (mixing_bowl_contains_heavy_cream_sugar)  ; mixing bowl (contains {heavy cream, sugar})
    (mixing_bowl_contains_pancake_batter)  ; mixing bowl (contains {pancake batter})
    (mixing_bowl_empty)  ; mixing bowl (empty)
    (pancake_cooked_in_frying_pan)  ; pancake (cooked, in [frying pan])
    (pancake_cooked_on_plate)  ; pancake (cooked, on [plate])
    (pancake_cooked_on_plate_topped_maple_syrup)  ; pancake (cooked, on [plate], topped {maple syrup})
    (pancake_half-cooked_in_frying_pan)  ; pancake (half-cooked, in [frying pan])
    (pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_frying_pan)  ; pancake batter (contains {baking powder, egg, flour, milk, salt, sugar}, in [frying pan])
    (pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_mixing_bowl)  ; pancake batter (contains {baking powder, egg, flour, milk, salt, sugar}, in [mixing bowl])
    (plate_contains_maple_syrup_pancake)  ; plate (contains {maple syrup, pancake})
    (plate_contains_pancake)  ; plate (contains {pancake})
    (plate_empty)  ; plate (empty)
    (salt_granulated)  ; salt (granulated)
    (salt_in_mixing_bowl)  ; salt (in [mixing bowl])
    (spatula)  ; spatula
    (stove_off)  ; stove (off)
    (stove_on)  ; stove (on)
    (sugar_granulated)  ; sugar (granulated)
    (sugar_in_mixing_bowl)  ; sugar (in [mixing bowl])
    (whisk)  ; whisk
  )

  (:action pour_u9
    ; unit 9: pour from 02-whipped_cream.foon:3, 09-fruit_salad.foon:164
    ; pour: mixing bowl (empty), heavy cream (in [carton]) -> mixing bowl (contains {heavy cream}), heavy cream (in [mixing bowl])
    :parameters ()
    :precondition (and
      (heavy_cream_in_carton)
      (mixing_bowl_empty)
    )
    :effect (and
      (heavy_cream_in_mixing_bowl)
      (mixing_bowl_contains_heavy_cream)
    )
  )

  (:action pour_u10
    ; unit 10: pour from 02-whipped_cream.foon:13, 09-fruit_salad.foon:174
    ; pour: mixing bowl (contains {heavy cream}), sugar (granulated) -> mixing bowl (contains {heavy cream, sugar}), sugar (in [mixing bowl])
    :parameters ()
    :precondition (and
      (mixing_bowl_contains_heavy_cream)
      (sugar_granulated)
    )
    :effect (and
      (mixing_bowl_contains_heavy_cream_sugar)
      (sugar_in_mixing_bowl)
    )
  )

  (:action pick-and-place_u22
    ; unit 22: pick-and-place from 03-scrambled_eggs.foon:71, 04-pancakes.foon:76, 05-french_toast.foon:83
    ; pick-and-place: frying pan (empty), stove (off) -> frying pan (empty, on [stove])
    :parameters ()
    :precondition (and
      (frying_pan_empty)
      (stove_off)
    )
    :effect (and
      (frying_pan_empty_on_stove)
    )
  )

  (:action turn_on_u23
    ; unit 23: turn on from 03-scrambled_eggs.foon:80, 04-pancakes.foon:85, 05-french_toast.foon:92, ... (1 more)
    ; turn on: stove (off) -> stove (on)
    :parameters ()
    :precondition (and
      (stove_off)
    )
    :effect (and
      (stove_on)
    )
  )

  (:action pick-and-place_u24
    ; unit 24: pick-and-place from 03-scrambled_eggs.foon:86, 04-pancakes.foon:91, 05-french_toast.foon:98
    ; pick-and-place: frying pan (empty, on [stove]), butter (solid) -> frying pan (contains {butter}, on [stove]), butter (in [frying pan], solid)
    :parameters ()
    :precondition (and
      (butter_solid)
      (frying_pan_empty_on_stove)
    )
    :effect (and
      (butter_in_frying_pan_solid)
      (frying_pan_contains_butter_on_stove)
    )
  )

  (:action melt_u25
    ; unit 25: melt from 03-scrambled_eggs.foon:99, 04-pancakes.foon:104, 05-french_toast.foon:111
    ; melt: stove (on), butter (in [frying pan], solid) -> butter (in [frying pan], melted)
    :parameters ()
    :precondition (and
      (butter_in_frying_pan_solid)
      (stove_on)
    )
    :effect (and
      (butter_in_frying_pan_melted)
    )
  )

  (:action pour_u29
    ; unit 29: pour from 04-pancakes.foon:3
    ; pour: mixing bowl (empty), flour (powder) -> mixing bowl (contains {flour}), flour (in [mixing bowl])
    :parameters ()
    :precondition (and
      (flour_powder)
      (mixing_bowl_empty)
    )
    :effect (and
      (flour_in_mixing_bowl)
      (mixing_bowl_contains_flour)
    )
  )

  (:action pour_u30
    ; unit 30: pour* from 04-pancakes.foon:13
    ; pour: mixing bowl (contains {flour}), baking powder (powder), sugar (granulated), salt (granulated) -> mixing bowl (contains {baking powder, flour, salt, sugar}), baking powder (in [mixing bowl]), sugar (in [mixing bowl]), salt (in [mixi...
    :parameters ()
    :precondition (and
      (baking_powder_powder)
      (mixing_bowl_contains_flour)
      (salt_granulated)
      (sugar_granulated)
    )
    :effect (and
      (baking_powder_in_mixing_bowl)
      (mixing_bowl_contains_baking_powder_flour_salt_sugar)
      (salt_in_mixing_bowl)
      (sugar_in_mixing_bowl)
    )
  )

  (:action crack_u31
    ; unit 31: crack from 04-pancakes.foon:31
    ; crack: mixing bowl (contains {baking powder, flour, salt, sugar}), egg (whole) -> mixing bowl (contains {baking powder, egg, flour, salt, sugar}), egg (cracked, in [mixing bowl])
    :parameters ()
    :precondition (and
      (egg_whole)
      (mixing_bowl_contains_baking_powder_flour_salt_sugar)
    )
    :effect (and
      (egg_cracked_in_mixing_bowl)
      (mixing_bowl_contains_baking_powder_egg_flour_salt_sugar)
    )
  )

  (:action pour_u32
    ; unit 32: pour from 04-pancakes.foon:42
    ; pour: mixing bowl (contains {baking powder, egg, flour, salt, sugar}), milk (in [carton]) -> mixing bowl (contains {baking powder, egg, flour, milk, salt, sugar}), milk (in [mixing bowl])
    :parameters ()
    :precondition (and
      (milk_in_carton)
      (mixing_bowl_contains_baking_powder_egg_flour_salt_sugar)
    )
    :effect (and
      (milk_in_mixing_bowl)
      (mixing_bowl_contains_baking_powder_egg_flour_milk_salt_sugar)
    )
  )

  (:action whisk_u33
    ; unit 33: whisk from 04-pancakes.foon:52
    ; whisk: mixing bowl (contains {baking powder, egg, flour, milk, salt, sugar}), flour (in [mixing bowl]), baking powder (in [mixing bowl]), sugar (in [mixing bowl]), salt (in [mixing bowl]), egg (cracked, in [mixing bowl]), milk (in [mixin...
    :parameters ()
    :precondition (and
      (baking_powder_in_mixing_bowl)
      (egg_cracked_in_mixing_bowl)
      (flour_in_mixing_bowl)
      (milk_in_mixing_bowl)
      (mixing_bowl_contains_baking_powder_egg_flour_milk_salt_sugar)
      (salt_in_mixing_bowl)
      (sugar_in_mixing_bowl)
      (whisk)
    )
    :effect (and
      (mixing_bowl_contains_pancake_batter)
      (pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_mixing_bowl)
      (whisk)
    )
  )

  (:action pour_u34
    ; unit 34: pour from 04-pancakes.foon:114
    ; pour: mixing bowl (contains {pancake batter}), pancake batter (contains {baking powder, egg, flour, milk, salt, sugar}, in [mixing bowl]), ladle, frying pan (contains {butter}, on [stove]), butter (in [frying pan], melted) -> frying pan ...
    :parameters ()
    :precondition (and
      (butter_in_frying_pan_melted)
      (frying_pan_contains_butter_on_stove)
      (ladle)
      (mixing_bowl_contains_pancake_batter)
      (pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_mixing_bowl)
    )
    :effect (and
      (frying_pan_contains_butter_pancake_batter_on_stove)
      (ladle)
      (pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_frying_pan)
    )
  )

  (:action cook_u35
    ; unit 35: cook from 04-pancakes.foon:135
    ; cook: stove (on), frying pan (contains {butter, pancake batter}, on [stove]), pancake batter (contains {baking powder, egg, flour, milk, salt, sugar}, in [frying pan]) -> frying pan (contains {pancake}, on [stove]), pancake (half-cooked,...
    :parameters ()
    :precondition (and
      (frying_pan_contains_butter_pancake_batter_on_stove)
      (pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_frying_pan)
      (stove_on)
    )
    :effect (and
      (frying_pan_contains_pancake_on_stove)
      (pancake_half-cooked_in_frying_pan)
    )
  )

  (:action flip_u36
    ; unit 36: flip from 04-pancakes.foon:151
    ; flip: pancake (half-cooked, in [frying pan]), spatula -> pancake (cooked, in [frying pan]), spatula
    :parameters ()
    :precondition (and
      (pancake_half-cooked_in_frying_pan)
      (spatula)
    )
    :effect (and
      (pancake_cooked_in_frying_pan)
      (spatula)
    )
  )

  (:action pick-and-place_u37
    ; unit 37: pick-and-place from 04-pancakes.foon:161
    ; pick-and-place: frying pan (contains {pancake}, on [stove]), pancake (cooked, in [frying pan]), spatula, plate (empty) -> plate (contains {pancake}), pancake (cooked, on [plate]), spatula
    :parameters ()
    :precondition (and
      (frying_pan_contains_pancake_on_stove)
      (pancake_cooked_in_frying_pan)
      (plate_empty)
      (spatula)
    )
    :effect (and
      (pancake_cooked_on_plate)
      (plate_contains_pancake)
      (spatula)
    )
  )

  (:action pour_u38
    ; unit 38: pour from 04-pancakes.foon:178
    ; pour: plate (contains {pancake}), pancake (cooked, on [plate]), maple syrup (in [bottle]) -> plate (contains {maple syrup, pancake}), pancake (cooked, on [plate], topped {maple syrup}), maple syrup (on [pancake])
    :parameters ()
    :precondition (and
      (maple_syrup_in_bottle)
      (pancake_cooked_on_plate)
      (plate_contains_pancake)
    )
    :effect (and
      (maple_syrup_on_pancake)
      (pancake_cooked_on_plate_topped_maple_syrup)
      (plate_contains_maple_syrup_pancake)
    )
  )
)
