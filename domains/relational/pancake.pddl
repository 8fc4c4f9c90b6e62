; foon2pddl, encoding relational, level 3: 15 of 101 units after relevance pruning
; goal: pancake (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
; instances: 19 (baking powder 1, butter 1, egg 1, flour 1, frying pan 1, ladle 1, maple syrup 2, milk 2, mixing bowl 1, pancake 1, pancake batter 1, plate 1, salt 1, spatula 1, stove 1, sugar 1, whisk 1)
; label mismatch: 04-pancakes.foon:178: plate lists maple syrup, which the unit puts on [pancake]
(define (domain foon-relational-d6420c02)
  (:requirements :strips :typing :conditional-effects)
  (:types
    physical-object - object
    object-state - object
    baking_powder - physical-object
    bottle - physical-object
    butter - physical-object
    carton - physical-object
    egg - physical-object
    flour - physical-object
    frying_pan - physical-object
    ladle - physical-object
    maple_syrup - physical-object
    milk - physical-object
    mixing_bowl - physical-object
    pancake - physical-object
    pancake_batter - physical-object
    plate - physical-object
    salt - physical-object
    spatula - physical-object
    stove - physical-object
    sugar - physical-object
    whisk - physical-object
  )
  (:constants
    not-yet-made - object-state
    consumed - object-state
    baking_powder_in_mixing_bowl - object-state
    baking_powder_powder - object-state
    bottle_contains_maple_syrup - object-state
    butter_in_frying_pan_melted - object-state
    butter_in_frying_pan_solid - object-state
    butter_solid - object-state
    carton_contains_milk - object-state
    egg_cracked_in_mixing_bowl - object-state
    egg_whole - object-state
    flour_in_mixing_bowl - object-state
    flour_powder - object-state
    frying_pan_contains_butter_on_stove - object-state
    frying_pan_contains_butter_pancake_batter_on_stove - object-state
    frying_pan_contains_pancake_on_stove - object-state
    frying_pan_empty - object-state
    frying_pan_empty_on_stove - object-state
    ladle_plain - object-state
    maple_syrup_in_bottle - object-state
    maple_syrup_on_pancake - object-state
    milk_in_carton - object-state
    milk_in_mixing_bowl - object-state
    mixing_bowl_contains_baking_powder_egg_flour_milk_salt_sugar - object-state
    mixing_bowl_contains_baking_powder_egg_flour_salt_sugar - object-state
    mixing_bowl_contains_baking_powder_flour_salt_sugar - object-state
    mixing_bowl_contains_flour - object-state
    mixing_bowl_contains_heavy_cream - object-state
    mixing_bowl_contains_heavy_cream_sugar - object-state
    mixing_bowl_contains_pancake_batter - object-state
    mixing_bowl_empty - object-state
    pancake_cooked_in_frying_pan - object-state
    pancake_cooked_on_plate - object-state
    pancake_cooked_on_plate_topped_maple_syrup - object-state
    pancake_half-cooked_in_frying_pan - object-state
    pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_frying_pan - object-state
    pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_mixing_bowl - object-state
    plate_contains_maple_syrup_pancake - object-state
    plate_contains_pancake - object-state
    plate_empty - object-state
    salt_granulated - object-state
    salt_in_mixing_bowl - object-state
    spatula_plain - object-state
    stove_off - object-state
    stove_on - object-state
    sugar_granulated - object-state
    sugar_in_mixing_bowl - object-state
    whisk_plain - object-state
  )
  (:predicates
    (is ?x - physical-object ?s - object-state)  ; ?x is in the state of FOON node ?s
    (in ?h - physical-object ?x - physical-object)  ; ?x is in ?h
    (on ?h - physical-object ?x - physical-object)  ; ?x is on ?h
    (occupied ?s - object-state)  ; some object is in state ?s, which no action leaves
    (goal-reached)  ; a goal candidate was made
  )

  (:action pour_u10
    ; unit 10: pour from 02-whipped_cream.foon:13, 09-fruit_salad.foon:174
    ; pour: mixing bowl (contains {heavy cream}), sugar (granulated) -> mixing bowl (contains {heavy cream, sugar}), sugar (in [mixing bowl])
    :parameters (?mixing_bowl - mixing_bowl ?sugar - sugar)
    :precondition (and
      (is ?mixing_bowl mixing_bowl_contains_heavy_cream)
      (is ?sugar sugar_granulated)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_heavy_cream_sugar)
      (occupied mixing_bowl_contains_heavy_cream_sugar)
      (is ?sugar sugar_in_mixing_bowl)
      (in ?mixing_bowl ?sugar)
      (not (is ?mixing_bowl mixing_bowl_contains_heavy_cream))
      (not (is ?sugar sugar_granulated))
    )
  )

  (:action pick-and-place_u22
    ; unit 22: pick-and-place from 03-scrambled_eggs.foon:71, 04-pancakes.foon:76, 05-french_toast.foon:83
    ; pick-and-place: frying pan (empty), stove (off) -> frying pan (empty, on [stove])
    :parameters (?frying_pan - frying_pan ?stove - stove)
    :precondition (and
      (is ?frying_pan frying_pan_empty)
      (is ?stove stove_off)
    )
    :effect (and
      (is ?frying_pan frying_pan_empty_on_stove)
      (on ?stove ?frying_pan)
      (not (is ?frying_pan frying_pan_empty))
    )
  )

  (:action turn_on_u23
    ; unit 23: turn on from 03-scrambled_eggs.foon:80, 04-pancakes.foon:85, 05-french_toast.foon:92, ... (1 more)
    ; turn on: stove (off) -> stove (on)
    :parameters (?stove - stove)
    :precondition (and
      (is ?stove stove_off)
    )
    :effect (and
      (is ?stove stove_on)
      (occupied stove_on)
      (not (is ?stove stove_off))
    )
  )

  (:action pick-and-place_u24
    ; unit 24: pick-and-place from 03-scrambled_eggs.foon:86, 04-pancakes.foon:91, 05-french_toast.foon:98
    ; pick-and-place: frying pan (empty, on [stove]), butter (solid) -> frying pan (contains {butter}, on [stove]), butter (in [frying pan], solid)
    :parameters (?frying_pan - frying_pan ?butter - butter)
    :precondition (and
      (is ?frying_pan frying_pan_empty_on_stove)
      (is ?butter butter_solid)
    )
    :effect (and
      (is ?frying_pan frying_pan_contains_butter_on_stove)
      (is ?butter butter_in_frying_pan_solid)
      (in ?frying_pan ?butter)
      (not (is ?frying_pan frying_pan_empty_on_stove))
      (not (is ?butter butter_solid))
    )
  )

  (:action melt_u25
    ; unit 25: melt from 03-scrambled_eggs.foon:99, 04-pancakes.foon:104, 05-french_toast.foon:111
    ; melt: stove (on), butter (in [frying pan], solid) -> butter (in [frying pan], melted)
    :parameters (?butter - butter)
    :precondition (and
      (occupied stove_on)
      (is ?butter butter_in_frying_pan_solid)
    )
    :effect (and
      (is ?butter butter_in_frying_pan_melted)
      (not (is ?butter butter_in_frying_pan_solid))
    )
  )

  (:action pour_u29
    ; unit 29: pour from 04-pancakes.foon:3
    ; pour: mixing bowl (empty), flour (powder) -> mixing bowl (contains {flour}), flour (in [mixing bowl])
    :parameters (?mixing_bowl - mixing_bowl ?flour - flour)
    :precondition (and
      (is ?mixing_bowl mixing_bowl_empty)
      (is ?flour flour_powder)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_flour)
      (is ?flour flour_in_mixing_bowl)
      (in ?mixing_bowl ?flour)
      (not (is ?mixing_bowl mixing_bowl_empty))
      (not (is ?flour flour_powder))
    )
  )

  (:action pour_u30
    ; unit 30: pour* from 04-pancakes.foon:13
    ; pour: mixing bowl (contains {flour}), baking powder (powder), sugar (granulated), salt (granulated) -> mixing bowl (contains {baking powder, flour, salt, sugar}), baking powder (in [mixing bowl]), sugar (in [mixing bowl]), salt (in [mixi...
    :parameters (?mixing_bowl - mixing_bowl ?baking_powder - baking_powder ?sugar - sugar ?salt - salt)
    :precondition (and
      (is ?mixing_bowl mixing_bowl_contains_flour)
      (is ?baking_powder baking_powder_powder)
      (is ?sugar sugar_granulated)
      (is ?salt salt_granulated)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_baking_powder_flour_salt_sugar)
      (is ?baking_powder baking_powder_in_mixing_bowl)
      (in ?mixing_bowl ?baking_powder)
      (is ?sugar sugar_in_mixing_bowl)
      (in ?mixing_bowl ?sugar)
      (is ?salt salt_in_mixing_bowl)
      (in ?mixing_bowl ?salt)
      (not (is ?mixing_bowl mixing_bowl_contains_flour))
      (not (is ?baking_powder baking_powder_powder))
      (not (is ?sugar sugar_granulated))
      (not (is ?salt salt_granulated))
    )
  )

  (:action crack_u31
    ; unit 31: crack from 04-pancakes.foon:31
    ; crack: mixing bowl (contains {baking powder, flour, salt, sugar}), egg (whole) -> mixing bowl (contains {baking powder, egg, flour, salt, sugar}), egg (cracked, in [mixing bowl])
    :parameters (?mixing_bowl - mixing_bowl ?egg - egg)
    :precondition (and
      (is ?mixing_bowl mixing_bowl_contains_baking_powder_flour_salt_sugar)
      (is ?egg egg_whole)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_baking_powder_egg_flour_salt_sugar)
      (is ?egg egg_cracked_in_mixing_bowl)
      (in ?mixing_bowl ?egg)
      (not (is ?mixing_bowl mixing_bowl_contains_baking_powder_flour_salt_sugar))
      (not (is ?egg egg_whole))
    )
  )

  (:action pour_u32
    ; unit 32: pour from 04-pancakes.foon:42
    ; pour: mixing bowl (contains {baking powder, egg, flour, salt, sugar}), milk (in [carton]) -> mixing bowl (contains {baking powder, egg, flour, milk, salt, sugar}), milk (in [mixing bowl])
    :parameters (?mixing_bowl - mixing_bowl ?milk_portion - milk)
    :precondition (and
      (is ?mixing_bowl mixing_bowl_contains_baking_powder_egg_flour_salt_sugar)
      (is ?milk_portion not-yet-made)
      (occupied milk_in_carton)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_baking_powder_egg_flour_milk_salt_sugar)
      (is ?milk_portion milk_in_mixing_bowl)
      (in ?mixing_bowl ?milk_portion)
      (not (is ?mixing_bowl mixing_bowl_contains_baking_powder_egg_flour_salt_sugar))
      (not (is ?milk_portion not-yet-made))
    )
  )

  (:action whisk_u33
    ; unit 33: whisk from 04-pancakes.foon:52
    ; whisk: mixing bowl (contains {baking powder, egg, flour, milk, salt, sugar}), flour (in [mixing bowl]), baking powder (in [mixing bowl]), sugar (in [mixing bowl]), salt (in [mixing bowl]), egg (cracked, in [mixing bowl]), milk (in [mixin...
    :parameters (?mixing_bowl - mixing_bowl ?flour - flour ?baking_powder - baking_powder ?sugar - sugar ?salt - salt ?egg - egg ?milk - milk ?pancake_batter - pancake_batter)
    :precondition (and
      (is ?mixing_bowl mixing_bowl_contains_baking_powder_egg_flour_milk_salt_sugar)
      (is ?flour flour_in_mixing_bowl)
      (in ?mixing_bowl ?flour)
      (is ?baking_powder baking_powder_in_mixing_bowl)
      (in ?mixing_bowl ?baking_powder)
      (is ?sugar sugar_in_mixing_bowl)
      (in ?mixing_bowl ?sugar)
      (is ?salt salt_in_mixing_bowl)
      (in ?mixing_bowl ?salt)
      (is ?egg egg_cracked_in_mixing_bowl)
      (in ?mixing_bowl ?egg)
      (is ?milk milk_in_mixing_bowl)
      (in ?mixing_bowl ?milk)
      (occupied whisk_plain)
      (is ?pancake_batter not-yet-made)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_contains_pancake_batter)
      (is ?flour consumed)
      (is ?baking_powder consumed)
      (is ?sugar consumed)
      (is ?salt consumed)
      (is ?egg consumed)
      (is ?milk consumed)
      (is ?pancake_batter pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_mixing_bowl)
      (in ?mixing_bowl ?pancake_batter)
      (not (is ?mixing_bowl mixing_bowl_contains_baking_powder_egg_flour_milk_salt_sugar))
      (not (is ?flour flour_in_mixing_bowl))
      (not (in ?mixing_bowl ?flour))
      (not (is ?baking_powder baking_powder_in_mixing_bowl))
      (not (in ?mixing_bowl ?baking_powder))
      (not (is ?sugar sugar_in_mixing_bowl))
      (not (in ?mixing_bowl ?sugar))
      (not (is ?salt salt_in_mixing_bowl))
      (not (in ?mixing_bowl ?salt))
      (not (is ?egg egg_cracked_in_mixing_bowl))
      (not (in ?mixing_bowl ?egg))
      (not (is ?milk milk_in_mixing_bowl))
      (not (in ?mixing_bowl ?milk))
      (not (is ?pancake_batter not-yet-made))
      (forall (?flour_alike - flour) (when (and (in ?mixing_bowl ?flour_alike) (is ?flour_alike flour_in_mixing_bowl)) (and (is ?flour_alike consumed) (not (in ?mixing_bowl ?flour_alike)) (not (is ?flour_alike flour_in_mixing_bowl)))))
      (forall (?baking_powder_alike - baking_powder) (when (and (in ?mixing_bowl ?baking_powder_alike) (is ?baking_powder_alike baking_powder_in_mixing_bowl)) (and (is ?baking_powder_alike consumed) (not (in ?mixing_bowl ?baking_powder_alike)) (not (is ?baking_powder_alike baking_powder_in_mixing_bowl)))))
      (forall (?sugar_alike - sugar) (when (and (in ?mixing_bowl ?sugar_alike) (is ?sugar_alike sugar_in_mixing_bowl)) (and (is ?sugar_alike consumed) (not (in ?mixing_bowl ?sugar_alike)) (not (is ?sugar_alike sugar_in_mixing_bowl)))))
      (forall (?salt_alike - salt) (when (and (in ?mixing_bowl ?salt_alike) (is ?salt_alike salt_in_mixing_bowl)) (and (is ?salt_alike consumed) (not (in ?mixing_bowl ?salt_alike)) (not (is ?salt_alike salt_in_mixing_bowl)))))
      (forall (?egg_alike - egg) (when (and (in ?mixing_bowl ?egg_alike) (is ?egg_alike egg_cracked_in_mixing_bowl)) (and (is ?egg_alike consumed) (not (in ?mixing_bowl ?egg_alike)) (not (is ?egg_alike egg_cracked_in_mixing_bowl)))))
      (forall (?milk_alike - milk) (when (and (in ?mixing_bowl ?milk_alike) (is ?milk_alike milk_in_mixing_bowl)) (and (is ?milk_alike consumed) (not (in ?mixing_bowl ?milk_alike)) (not (is ?milk_alike milk_in_mixing_bowl)))))
    )
  )

  (:action pour_u34
    ; unit 34: pour from 04-pancakes.foon:114
    ; pour: mixing bowl (contains {pancake batter}), pancake batter (contains {baking powder, egg, flour, milk, salt, sugar}, in [mixing bowl]), ladle, frying pan (contains {butter}, on [stove]), butter (in [frying pan], melted) -> frying pan ...
    :parameters (?mixing_bowl - mixing_bowl ?pancake_batter - pancake_batter ?frying_pan - frying_pan ?butter - butter)
    :precondition (and
      (is ?mixing_bowl mixing_bowl_contains_pancake_batter)
      (is ?pancake_batter pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_mixing_bowl)
      (in ?mixing_bowl ?pancake_batter)
      (occupied ladle_plain)
      (is ?frying_pan frying_pan_contains_butter_on_stove)
      (is ?butter butter_in_frying_pan_melted)
      (in ?frying_pan ?butter)
    )
    :effect (and
      (is ?mixing_bowl mixing_bowl_empty)
      (is ?pancake_batter pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_frying_pan)
      (in ?frying_pan ?pancake_batter)
      (is ?frying_pan frying_pan_contains_butter_pancake_batter_on_stove)
      (not (is ?mixing_bowl mixing_bowl_contains_pancake_batter))
      (not (is ?pancake_batter pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_mixing_bowl))
      (not (in ?mixing_bowl ?pancake_batter))
      (not (is ?frying_pan frying_pan_contains_butter_on_stove))
    )
  )

  (:action cook_u35
    ; unit 35: cook from 04-pancakes.foon:135
    ; cook: stove (on), frying pan (contains {butter, pancake batter}, on [stove]), pancake batter (contains {baking powder, egg, flour, milk, salt, sugar}, in [frying pan]) -> frying pan (contains {pancake}, on [stove]), pancake (half-cooked,...
    :parameters (?stove - stove ?frying_pan - frying_pan ?pancake_batter - pancake_batter ?pancake - pancake)
    :precondition (and
      (is ?stove stove_on)
      (is ?frying_pan frying_pan_contains_butter_pancake_batter_on_stove)
      (on ?stove ?frying_pan)
      (is ?pancake_batter pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_frying_pan)
      (in ?frying_pan ?pancake_batter)
      (is ?pancake not-yet-made)
    )
    :effect (and
      (is ?frying_pan frying_pan_contains_pancake_on_stove)
      (is ?pancake_batter consumed)
      (is ?pancake pancake_half-cooked_in_frying_pan)
      (in ?frying_pan ?pancake)
      (not (is ?frying_pan frying_pan_contains_butter_pancake_batter_on_stove))
      (not (is ?pancake_batter pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_frying_pan))
      (not (in ?frying_pan ?pancake_batter))
      (not (is ?pancake not-yet-made))
      (forall (?pancake_batter_alike - pancake_batter) (when (and (in ?frying_pan ?pancake_batter_alike) (is ?pancake_batter_alike pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_frying_pan)) (and (is ?pancake_batter_alike consumed) (not (in ?frying_pan ?pancake_batter_alike)) (not (is ?pancake_batter_alike pancake_batter_contains_baking_powder_egg_flour_milk_salt_sugar_in_frying_pan)))))
      (forall (?butter_in_it - butter) (when (and (in ?frying_pan ?butter_in_it) (is ?butter_in_it butter_in_frying_pan_melted)) (and (is ?butter_in_it consumed) (not (in ?frying_pan ?butter_in_it)) (not (is ?butter_in_it butter_in_frying_pan_melted)))))
      (forall (?butter_in_it - butter) (when (and (in ?frying_pan ?butter_in_it) (is ?butter_in_it butter_in_frying_pan_solid)) (and (is ?butter_in_it consumed) (not (in ?frying_pan ?butter_in_it)) (not (is ?butter_in_it butter_in_frying_pan_solid)))))
    )
  )

  (:action flip_u36
    ; unit 36: flip from 04-pancakes.foon:151
    ; flip: pancake (half-cooked, in [frying pan]), spatula -> pancake (cooked, in [frying pan]), spatula
    :parameters (?pancake - pancake)
    :precondition (and
      (is ?pancake pancake_half-cooked_in_frying_pan)
      (occupied spatula_plain)
    )
    :effect (and
      (is ?pancake pancake_cooked_in_frying_pan)
      (not (is ?pancake pancake_half-cooked_in_frying_pan))
    )
  )

  (:action pick-and-place_u37
    ; unit 37: pick-and-place from 04-pancakes.foon:161
    ; pick-and-place: frying pan (contains {pancake}, on [stove]), pancake (cooked, in [frying pan]), spatula, plate (empty) -> plate (contains {pancake}), pancake (cooked, on [plate]), spatula
    :parameters (?frying_pan - frying_pan ?pancake - pancake ?plate - plate)
    :precondition (and
      (is ?frying_pan frying_pan_contains_pancake_on_stove)
      (is ?pancake pancake_cooked_in_frying_pan)
      (in ?frying_pan ?pancake)
      (occupied spatula_plain)
      (is ?plate plate_empty)
    )
    :effect (and
      (is ?frying_pan frying_pan_empty_on_stove)
      (is ?pancake pancake_cooked_on_plate)
      (on ?plate ?pancake)
      (is ?plate plate_contains_pancake)
      (not (is ?frying_pan frying_pan_contains_pancake_on_stove))
      (not (is ?pancake pancake_cooked_in_frying_pan))
      (not (in ?frying_pan ?pancake))
      (not (is ?plate plate_empty))
    )
  )

  (:action pour_u38
    ; unit 38: pour from 04-pancakes.foon:178
    ; pour: plate (contains {pancake}), pancake (cooked, on [plate]), maple syrup (in [bottle]) -> plate (contains {maple syrup, pancake}), pancake (cooked, on [plate], topped {maple syrup}), maple syrup (on [pancake])
    :parameters (?plate - plate ?pancake - pancake ?maple_syrup_portion - maple_syrup)
    :precondition (and
      (is ?plate plate_contains_pancake)
      (is ?pancake pancake_cooked_on_plate)
      (on ?plate ?pancake)
      (is ?maple_syrup_portion not-yet-made)
      (occupied maple_syrup_in_bottle)
    )
    :effect (and
      (is ?plate plate_contains_maple_syrup_pancake)
      (occupied plate_contains_maple_syrup_pancake)
      (is ?pancake pancake_cooked_on_plate_topped_maple_syrup)
      (occupied pancake_cooked_on_plate_topped_maple_syrup)
      (is ?maple_syrup_portion maple_syrup_on_pancake)
      (occupied maple_syrup_on_pancake)
      (on ?pancake ?maple_syrup_portion)
      (not (is ?plate plate_contains_pancake))
      (not (is ?pancake pancake_cooked_on_plate))
      (not (is ?maple_syrup_portion not-yet-made))
    )
  )

  (:action reach-goal-1
    ; goal candidate 1: pancake (cooked, on [plate], topped {maple syrup})
    :parameters ()
    :precondition (and
      (occupied pancake_cooked_on_plate_topped_maple_syrup)
    )
    :effect (and
      (goal-reached)
    )
  )
)
